/*
 * Fit and zoom of the diagram, shared by the toolbar and the keyboard (+, -, Ctrl+0).
 */
import { FitToScreenAction, GModelRoot, SetViewportAction, isViewport } from '@eclipse-glsp/client';
import { STATE_PREFIX } from './model';

/**
 * Fits the states into the window. The states are named: with no ids, sprotty's fit takes every
 * element's bounds, edges included, whose bounds are not always valid (then it does nothing).
 */
export function fitStatesAction(root: GModelRoot | undefined, maxZoom: number, animate: boolean): FitToScreenAction {
    const ids = root ? root.children.filter(child => child.type.startsWith(STATE_PREFIX)).map(child => child.id) : [];
    return FitToScreenAction.create(ids, { padding: 24, maxZoom, animate });
}

/** Zooms by a factor around the centre of the window (undefined before a diagram is shown). */
export function zoomAction(root: GModelRoot | undefined, factor: number, animate = true): SetViewportAction | undefined {
    if (!root || !isViewport(root)) {
        return undefined;
    }
    const canvas = root.canvasBounds;
    const centre = { x: root.scroll.x + canvas.width / 2 / root.zoom, y: root.scroll.y + canvas.height / 2 / root.zoom };
    const zoom = Math.min(20, Math.max(0.1, root.zoom * factor));
    const scroll = { x: centre.x - canvas.width / 2 / zoom, y: centre.y - canvas.height / 2 / zoom };
    return SetViewportAction.create(root.id, { scroll, zoom }, { animate });
}
