/*
 * Saving the diagram as a picture: the SVG GLSP exports (RequestExportSvgAction → ExportSvgAction),
 * and a PNG drawn from that SVG on a canvas. Both are offered as downloads named after the model.
 */
import {
    Action,
    ExportSvgAction,
    GChildElement,
    GEdge,
    GModelElement,
    GModelRoot,
    IActionHandler,
    RequestExportSvgAction,
    SelectionService,
    isBoundsAware
} from '@eclipse-glsp/client';
import { injectable } from 'inversify';
import { DiagramPage } from './diagram-page';
import { StateNode } from './model';

let exportBaseName = 'statechart';

export function setExportBaseName(name: string): void {
    exportBaseName = name;
}

export function svgFileName(): string {
    return exportBaseName + '.svg';
}

export function pngFileName(): string {
    return exportBaseName + '.png';
}

/** Offers a file for download (the browser saves it; a test harness sees a download event). */
export function download(fileName: string, blob: Blob): void {
    const url = URL.createObjectURL(blob);
    const anchor = document.createElement('a');
    anchor.href = url;
    anchor.download = fileName;
    anchor.rel = 'noopener';
    anchor.style.display = 'none';
    document.body.appendChild(anchor);
    anchor.click();
    anchor.remove();
    window.setTimeout(() => URL.revokeObjectURL(url), 60000);
}

/** Room left around the diagram in exported pictures. */
const EXPORT_MARGIN = 12;

/** A rectangle in diagram coordinates (those of the exported SVG's viewBox). */
export interface Area {
    x: number;
    y: number;
    width: number;
    height: number;
}

/** A composite state to picture alone: where it lies, its id, and the transitions that stay inside it. */
export interface Focus {
    area: Area;
    id: string;
    innerTransitions: string[];
}

/**
 * Leaves only the focused composite in the exported SVG: on the way from its element up to the
 * root, everything beside that way goes (other states, the ancestors' own shapes and names, and
 * transitions that leave the composite), but definitions and styles stay.
 */
function keepOnly(root: Element, focus: Focus): void {
    const inside = new Set(focus.innerTransitions);
    const target = Array.from(root.querySelectorAll('[data-id]')).find(element => element.getAttribute('data-id') === focus.id);
    if (!target) {
        return;
    }
    let node: Element = target;
    while (node !== root && node.parentElement) {
        const parent: Element = node.parentElement;
        for (const sibling of Array.from(parent.children)) {
            const name = sibling.localName.toLowerCase();
            const kept = sibling === node || name === 'defs' || name === 'style' || inside.has(sibling.getAttribute('data-id') ?? '');
            if (!kept) {
                sibling.remove();
            }
        }
        node = parent;
    }
}

/**
 * Makes the exported SVG a standalone file: XML declaration, namespace, a white background and a
 * margin around the diagram (GLSP's export ends exactly at the outermost shapes). With a
 * {@link Focus} (a selected composite), the picture shows that composite only.
 */
export function standaloneSvg(svg: string, focus?: Focus): string {
    const document = new DOMParser().parseFromString(svg, 'image/svg+xml');
    const root = document.documentElement;
    if (root.nodeName.toLowerCase() !== 'svg' || document.getElementsByTagName('parsererror').length > 0) {
        return svg;
    }
    if (focus) {
        keepOnly(root, focus);
    }
    const area = focus?.area;
    const viewBox = (root.getAttribute('viewBox') ?? '').split(/[\s,]+/).map(Number);
    if (viewBox.length === 4 && viewBox.every(Number.isFinite)) {
        const [x, y, width, height] = area ? [area.x, area.y, area.width, area.height] : viewBox;
        const framed = [x - EXPORT_MARGIN, y - EXPORT_MARGIN, width + 2 * EXPORT_MARGIN, height + 2 * EXPORT_MARGIN];
        root.setAttribute('viewBox', framed.join(' '));
        root.setAttribute('width', String(framed[2]));
        root.setAttribute('height', String(framed[3]));
        // GLSP's export also fixes the size in the style (with !important): that size changes too
        const declarations = (root.getAttribute('style') ?? '')
            .split(';')
            .map(declaration => declaration.trim())
            .filter(declaration => declaration.length > 0 && !/^(width|height|inline-size|block-size)\s*:/i.test(declaration));
        declarations.push(`width: ${framed[2]}px`, `height: ${framed[3]}px`);
        root.setAttribute('style', declarations.join('; '));
        const background = document.createElementNS('http://www.w3.org/2000/svg', 'rect');
        background.setAttribute('x', String(framed[0]));
        background.setAttribute('y', String(framed[1]));
        background.setAttribute('width', String(framed[2]));
        background.setAttribute('height', String(framed[3]));
        background.setAttribute('fill', '#ffffff');
        background.setAttribute('class', 'kse-export-background');
        root.insertBefore(background, root.firstChild);
    }
    const text = new XMLSerializer().serializeToString(root);
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + text;
}

function svgSize(svgElement: SVGSVGElement): { width: number; height: number } {
    const viewBox = svgElement.viewBox?.baseVal;
    const width = parseFloat(svgElement.getAttribute('width') ?? '') || viewBox?.width || 800;
    const height = parseFloat(svgElement.getAttribute('height') ?? '') || viewBox?.height || 600;
    return { width, height };
}

/** Draws an SVG document on a canvas (white background, `scale` pixels per unit) and returns a PNG. */
export async function svgToPng(svg: string, scale = 2): Promise<Blob> {
    const parsed = new DOMParser().parseFromString(svg, 'image/svg+xml');
    const root = parsed.documentElement as unknown as SVGSVGElement;
    if (!root || root.nodeName.toLowerCase() !== 'svg') {
        throw new Error('the exported diagram is not an SVG document');
    }
    const { width, height } = svgSize(root);
    root.setAttribute('width', String(width));
    root.setAttribute('height', String(height));
    const source = new XMLSerializer().serializeToString(root);
    const url = URL.createObjectURL(new Blob([source], { type: 'image/svg+xml;charset=utf-8' }));
    try {
        const image = new Image();
        image.decoding = 'sync';
        await new Promise<void>((resolve, reject) => {
            image.onload = () => resolve();
            image.onerror = () => reject(new Error('the exported SVG could not be drawn'));
            image.src = url;
        });
        const canvas = document.createElement('canvas');
        canvas.width = Math.max(1, Math.ceil(width * scale));
        canvas.height = Math.max(1, Math.ceil(height * scale));
        const context = canvas.getContext('2d');
        if (!context) {
            throw new Error('no 2D canvas');
        }
        context.fillStyle = '#ffffff';
        context.fillRect(0, 0, canvas.width, canvas.height);
        context.setTransform(scale, 0, 0, scale, 0, 0);
        context.drawImage(image, 0, 0, width, height);
        return await new Promise<Blob>((resolve, reject) =>
            canvas.toBlob(blob => (blob ? resolve(blob) : reject(new Error('the canvas gave no PNG'))), 'image/png')
        );
    } finally {
        URL.revokeObjectURL(url);
    }
}

/**
 * The one selected composite (OR or AND) state: where it lies in diagram coordinates (children
 * are placed relative to their parent) and the transitions between its insides; undefined when
 * the selection is not a single composite. Ids are model paths: an inside's id extends its owner's.
 */
export function selectedComposite(selectionService: SelectionService): Focus | undefined {
    const selected = selectionService.getSelectedElements();
    if (selected.length !== 1 || !(selected[0] instanceof StateNode && selected[0].isComposite)) {
        return undefined;
    }
    const composite = selected[0] as unknown as GModelElement;
    if (!isBoundsAware(composite)) {
        return undefined;
    }
    const area = { ...composite.bounds };
    let parent = (composite as unknown as GChildElement).parent as GModelElement | undefined;
    while (parent && !(parent instanceof GModelRoot)) {
        if (isBoundsAware(parent)) {
            area.x += parent.bounds.x;
            area.y += parent.bounds.y;
        }
        parent = (parent as unknown as GChildElement).parent as GModelElement | undefined;
    }
    const within = (id: string | undefined) => id !== undefined && id.startsWith(composite.id + '/');
    const innerTransitions = Array.from(composite.root.index.all())
        .filter(element => element instanceof GEdge && within(element.sourceId) && within(element.targetId))
        .map(element => element.id);
    return { area, id: composite.id, innerTransitions };
}

/** The diagram as a standalone SVG; with `selected`, only the selected composite when there is one. */
export async function exportSvg(page: DiagramPage, selected = false): Promise<string> {
    const focus = selected ? selectedComposite(page.selectionService) : undefined;
    const response = await page.dispatcher.request(RequestExportSvgAction.create());
    return standaloneSvg(response.svg, focus);
}

/** An ExportSvgAction nobody asked for by request (e.g. from the Ctrl+Shift+E key) is saved as <model>.svg. */
@injectable()
export class KseExportSvgActionHandler implements IActionHandler {
    handle(action: Action): void {
        if (ExportSvgAction.is(action)) {
            download(svgFileName(), new Blob([standaloneSvg(action.svg)], { type: 'image/svg+xml;charset=utf-8' }));
        }
    }
}
