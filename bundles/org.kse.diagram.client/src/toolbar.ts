/*
 * The page's toolbar: each button's data-action names what it does (save, undo, redo, layout, fit,
 * zoom-in, zoom-out, grid, export-svg, export-png, print). Printing prints the diagram alone: its
 * exported SVG goes into #kse-print, which the print style shows instead of the page.
 */
import { IGridManager, LayoutOperation, RedoAction, SaveModelAction, TYPES, UndoAction } from '@eclipse-glsp/client';
import { DiagramPage, focusDiagram } from './diagram-page';
import { download, exportSvg, pngFileName, svgFileName, svgToPng } from './export';
import { failed } from './status-line';
import { showGridPressed } from './toolbar-sync';
import { fitStatesAction, zoomAction } from './viewport';

export interface Toolbar {
    /** Runs a toolbar action by its data-action name. */
    run(action: string): Promise<void>;
}

export function installToolbar(page: DiagramPage): Toolbar {
    const { container, dispatcher, editorContext } = page;

    function zoomBy(factor: number): Promise<void> {
        const action = zoomAction(editorContext.modelRoot, factor);
        return action ? dispatcher.dispatch(action) : Promise.resolve();
    }

    function gridManager(): IGridManager | undefined {
        return container.isBound(TYPES.IGridManager) ? container.get<IGridManager>(TYPES.IGridManager) : undefined;
    }

    function updateGridButton(): void {
        showGridPressed(gridManager()?.isGridVisible ?? false);
    }

    async function printDiagram(): Promise<void> {
        const holder = document.getElementById('kse-print');
        if (holder) {
            const svg = await exportSvg(page);
            const parsed = new DOMParser().parseFromString(svg, 'image/svg+xml').documentElement;
            holder.replaceChildren(document.importNode(parsed, true));
            document.body.classList.add('kse-printing');
        }
        window.print();
    }

    window.addEventListener('afterprint', () => {
        document.body.classList.remove('kse-printing');
        document.getElementById('kse-print')?.replaceChildren();
    });

    const toolbarActions: Record<string, () => Promise<void>> = {
        save: () => dispatcher.dispatch(SaveModelAction.create()),
        undo: () => dispatcher.dispatch(UndoAction.create()),
        redo: () => dispatcher.dispatch(RedoAction.create()),
        layout: () => dispatcher.dispatch(LayoutOperation.create()),
        fit: () => dispatcher.dispatch(fitStatesAction(editorContext.modelRoot, 2, true)),
        'zoom-in': () => zoomBy(1.25),
        'zoom-out': () => zoomBy(0.8),
        grid: async () => {
            gridManager()?.toggleGridVisible();
            updateGridButton();
        },
        'export-svg': async () => {
            const svg = await exportSvg(page, true);
            download(svgFileName(), new Blob([svg], { type: 'image/svg+xml;charset=utf-8' }));
        },
        'export-png': async () => {
            const png = await svgToPng(await exportSvg(page, true));
            download(pngFileName(), png);
        },
        print: () => printDiagram()
    };

    async function run(action: string): Promise<void> {
        const perform = toolbarActions[action];
        if (!perform) {
            throw new Error(`unknown toolbar action: ${action}`);
        }
        await perform();
    }

    for (const button of Array.from(document.querySelectorAll<HTMLButtonElement>('#kse-toolbar [data-action]'))) {
        const action = button.dataset.action ?? '';
        // keep the keyboard focus on the diagram, so that its shortcuts go on working after a click
        button.addEventListener('mousedown', event => event.preventDefault());
        button.addEventListener('click', () => {
            run(action)
                .catch(failed(button.title || action))
                .finally(() => {
                    if (action !== 'print') {
                        focusDiagram(page.clientId);
                    }
                });
        });
    }

    updateGridButton();
    return { run };
}
