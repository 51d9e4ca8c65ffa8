/*
 * The client's current model as plain JSON (for tests and for the page's host): ids, types,
 * children, arguments, bounds, texts, edge ends.
 */
import { GModelElement, GParentElement, isBoundsAware, isViewport } from '@eclipse-glsp/client';

export interface ElementJson {
    id: string;
    type: string;
    children: ElementJson[];
    args?: Record<string, unknown>;
    bounds?: { x: number; y: number; width: number; height: number };
    text?: string;
    sourceId?: string;
    targetId?: string;
    cssClasses?: string[];
    selected?: boolean;
    revision?: number;
    viewport?: { scroll: { x: number; y: number }; zoom: number; canvasBounds?: { x: number; y: number; width: number; height: number } };
}

export function toJson(element: Readonly<GModelElement>): ElementJson {
    const json: ElementJson = { id: element.id, type: element.type, children: [] };
    const loose = element as unknown as Record<string, unknown>;
    if (loose.args && typeof loose.args === 'object') {
        json.args = { ...(loose.args as Record<string, unknown>) };
    }
    if (isBoundsAware(element as GModelElement)) {
        const bounds = (element as unknown as { bounds: { x: number; y: number; width: number; height: number } }).bounds;
        json.bounds = { x: bounds.x, y: bounds.y, width: bounds.width, height: bounds.height };
    }
    if (typeof loose.text === 'string') {
        json.text = loose.text;
    }
    if (typeof loose.sourceId === 'string') {
        json.sourceId = loose.sourceId;
    }
    if (typeof loose.targetId === 'string') {
        json.targetId = loose.targetId;
    }
    if (Array.isArray(element.cssClasses) && element.cssClasses.length > 0) {
        json.cssClasses = [...element.cssClasses];
    }
    if (loose.selected === true) {
        json.selected = true;
    }
    if (typeof loose.revision === 'number') {
        json.revision = loose.revision;
    }
    if (isViewport(element as GModelElement)) {
        const viewport = element as unknown as {
            scroll: { x: number; y: number };
            zoom: number;
            canvasBounds?: { x: number; y: number; width: number; height: number };
        };
        json.viewport = { scroll: { ...viewport.scroll }, zoom: viewport.zoom };
        if (viewport.canvasBounds) {
            json.viewport.canvasBounds = { ...viewport.canvasBounds };
        }
    }
    if (element instanceof GParentElement) {
        json.children = element.children.map(child => toJson(child));
    }
    return json;
}
