/*
 * Keeps the page's toolbar in step with the diagram: the Grid button shows whether the grid is on,
 * also when the tool palette's grid button switched it.
 */
import { Action, IActionHandler, ShowGridAction } from '@eclipse-glsp/client';
import { injectable } from 'inversify';

export function showGridPressed(pressed: boolean): void {
    document.querySelector('[data-action="grid"]')?.setAttribute('aria-pressed', String(pressed));
}

@injectable()
export class GridButtonSync implements IActionHandler {
    handle(action: Action): void {
        if (ShowGridAction.is(action)) {
            showGridPressed(action.show);
        }
    }
}
