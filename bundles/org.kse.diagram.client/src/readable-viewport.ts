/*
 * The viewport a diagram opens with: every text at least its CSS size on screen (11px for the
 * smallest, a transition's label), so a large diagram opens at its top-left corner and is scrolled
 * for the rest rather than shrunk until nothing can be read; a small one is centred.
 */
import { Bounds, GModelElement, GModelRoot, GParentElement, SetViewportAction, isBoundsAware } from '@eclipse-glsp/client';
import { STATE_PREFIX } from './model';

/** The lowest zoom a diagram opens at: its smallest text (11px) stays 11px. */
export const READABLE_ZOOM = 1;

const PADDING = 24;

export function openingViewportAction(root: GModelRoot, canvas: { width: number; height: number }): SetViewportAction | undefined {
    const states = root.children.filter(child => child.type.startsWith(STATE_PREFIX) && isBoundsAware(child));
    if (states.length === 0) {
        return undefined;
    }
    const extent = states.map(state => (isBoundsAware(state) ? state.bounds : Bounds.EMPTY)).reduce((all, each) => Bounds.combine(all, each));
    const fitting = Math.min((canvas.width - 2 * PADDING) / extent.width, (canvas.height - 2 * PADDING) / extent.height);
    const zoom = Math.max(READABLE_ZOOM, Math.min(1, fitting));
    const width = canvas.width / zoom;
    const height = canvas.height / zoom;
    let x = extent.x - (width - extent.width) / 2;
    if (extent.width * zoom + 2 * PADDING > canvas.width) {
        // too wide: the top of the diagram around its initial state, where reading starts
        const entry = initialStateCentreX(states[0]) ?? extent.x + width / 2;
        x = Math.min(Math.max(entry - width / 2, extent.x - PADDING), extent.x + extent.width + PADDING - width);
    }
    const y = extent.height * zoom + 2 * PADDING <= canvas.height ? extent.y - (height - extent.height) / 2 : extent.y - PADDING / zoom;
    const scroll = { x, y };
    return SetViewportAction.create(root.id, { scroll, zoom }, { animate: false });
}

/** The centre (x, in diagram coordinates) of the START state in a top-level state, or of the state itself. */
function initialStateCentreX(state: GModelElement): number | undefined {
    if (!isBoundsAware(state)) {
        return undefined;
    }
    const start = state instanceof GParentElement ? state.children.find(child => child.type === STATE_PREFIX + 'start') : undefined;
    if (start && isBoundsAware(start)) {
        return state.bounds.x + start.bounds.x + start.bounds.width / 2;
    }
    return state.bounds.x + state.bounds.width / 2;
}
