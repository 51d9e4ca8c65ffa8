/*
 * Hover popups (the server answers RequestPopupModelAction; for a transition with its whole
 * expression). A transition has no bounds of its own, so its popup opens next to the mouse.
 */
import { Bounds, GModelElement, GlspHoverMouseListener, Point, getAbsoluteBounds } from '@eclipse-glsp/client';
import { injectable } from 'inversify';

@injectable()
export class KseHoverMouseListener extends GlspHoverMouseListener {
    protected override computePopupBounds(target: GModelElement, mousePosition: Point): Bounds {
        const bounds = getAbsoluteBounds(target);
        if (bounds.width >= 0 && bounds.height >= 0) {
            return super.computePopupBounds(target, mousePosition);
        }
        const canvas = target.root.canvasBounds;
        const x = Math.min(mousePosition.x + 12, canvas.x + canvas.width - 40);
        const y = Math.min(mousePosition.y + 18, canvas.y + canvas.height - 20);
        return { x, y, width: -1, height: -1 };
    }
}
