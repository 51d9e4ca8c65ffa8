/*
 * The diagram's keys, besides GLSP's own (Delete, Ctrl+Z, Ctrl+C/V, Ctrl+Shift+L, F2, ...): arrow
 * keys nudge the selected states by one grid step (Shift: five), or scroll when nothing is
 * selected; + and - zoom, Ctrl+0 fits the diagram to the window; Ctrl+F opens the find box. They
 * come only while the diagram has the keyboard focus, so typing in a label editor or a text field
 * never moves or zooms anything.
 */
import {
    Action,
    ChangeBoundsOperation,
    FeedbackEmitter,
    GModelElement,
    IActionDispatcher,
    IFeedbackActionDispatcher,
    KeyListener,
    MoveAction,
    Point,
    SetViewportAction,
    TYPES,
    isViewport,
    matchesKeystroke
} from '@eclipse-glsp/client';
import { inject, injectable, optional } from 'inversify';
import { FindBox } from './find';
import { StateNode } from './model';
import { draggedStates } from './reparent';
import { fitStatesAction, zoomAction } from './viewport';

/** How much farther Shift+arrow nudges than an arrow alone. */
export const SHIFT_NUDGE_FACTOR = 5;
export const ZOOM_STEP = 1.25;

const ARROWS: Record<string, Point> = {
    ArrowLeft: { x: -1, y: 0 },
    ArrowRight: { x: 1, y: 0 },
    ArrowUp: { x: 0, y: -1 },
    ArrowDown: { x: 0, y: 1 }
};

function withoutModifiers(event: KeyboardEvent): boolean {
    return !event.ctrlKey && !event.metaKey && !event.altKey;
}

/** How long the keys rest before the nudged positions go to the server (as one ChangeBounds, one undo step). */
export const NUDGE_REST_MS = 300;

/**
 * Moves states at once on the page and tells the server when the keys rest. GLSP's own handler of
 * MoveElementAction took a nested state's position (relative to its parent) for one in the window
 * and scrolled the view with every press.
 */
@injectable()
export class Nudger {
    @inject(TYPES.IActionDispatcher) protected dispatcher!: IActionDispatcher;
    @inject(TYPES.IFeedbackActionDispatcher) protected feedbackDispatcher!: IFeedbackActionDispatcher;

    /** Where each nudged state goes (relative to its parent), with its size, until the server has it. */
    protected targets = new Map<string, { position: Point; width: number; height: number }>();
    protected feedback?: FeedbackEmitter;
    protected timer?: ReturnType<typeof setTimeout>;

    nudge(states: StateNode[], offset: Point): void {
        for (const state of states) {
            const from = this.targets.get(state.id)?.position ?? state.position;
            this.targets.set(state.id, { position: Point.add(from, offset), width: state.size.width, height: state.size.height });
        }
        const moves = Array.from(this.targets, ([elementId, target]) => ({ elementId, toPosition: target.position }));
        this.feedback?.discard();
        this.feedback = this.feedbackDispatcher.createEmitter().add(MoveAction.create(moves, { animate: false })).submit();
        clearTimeout(this.timer);
        this.timer = setTimeout(() => this.send(), NUDGE_REST_MS);
    }

    protected send(): void {
        const bounds = Array.from(this.targets, ([elementId, target]) => ({
            elementId,
            newPosition: target.position,
            newSize: { width: target.width, height: target.height }
        }));
        this.targets.clear();
        // the states stay where the feedback put them until the server's model shows them there
        this.feedback?.discard();
        this.feedback = undefined;
        if (bounds.length > 0) {
            void this.dispatcher.dispatch(ChangeBoundsOperation.create(bounds));
        }
    }
}

@injectable()
export class KseKeyListener extends KeyListener {
    @inject(FindBox) protected findBox!: FindBox;
    @inject(Nudger) protected nudger!: Nudger;
    @inject(TYPES.Grid) @optional() protected grid?: Point;

    override keyDown(element: GModelElement, event: KeyboardEvent): Action[] {
        const root = element.root;
        if (matchesKeystroke(event, 'KeyF', 'ctrlCmd')) {
            event.preventDefault(); // not the browser's find
            this.findBox.open();
            return [];
        }
        if (matchesKeystroke(event, 'Digit0', 'ctrlCmd') || matchesKeystroke(event, 'Numpad0', 'ctrlCmd')) {
            return [fitStatesAction(root, 2, true)];
        }
        if (!withoutModifiers(event)) {
            return [];
        }
        if (event.key === '+' || event.key === '=' || event.code === 'NumpadAdd') {
            return this.zoom(root, ZOOM_STEP);
        }
        if (event.key === '-' || event.code === 'NumpadSubtract') {
            return this.zoom(root, 1 / ZOOM_STEP);
        }
        const direction = ARROWS[event.key];
        if (direction) {
            event.preventDefault(); // not the page's scrolling
            return this.nudge(element, direction, event.shiftKey);
        }
        return [];
    }

    protected zoom(root: GModelElement['root'], factor: number): Action[] {
        // at once: a key held down or pressed quickly zooms from where the last press left off
        const action = zoomAction(root, factor, false);
        return action ? [action] : [];
    }

    /** The step of one press: the grid's, five of them with Shift. */
    protected step(larger: boolean): Point {
        const grid = this.grid ?? { x: 10, y: 10 };
        const factor = larger ? SHIFT_NUDGE_FACTOR : 1;
        return { x: grid.x * factor, y: grid.y * factor };
    }

    protected nudge(element: GModelElement, direction: Point, larger: boolean): Action[] {
        const step = this.step(larger);
        const dx = direction.x * step.x;
        const dy = direction.y * step.y;
        // a state inside a selected composite moves with it, not once more on its own
        const states = draggedStates(element.root);
        if (states.length > 0) {
            this.nudger.nudge(states, { x: dx, y: dy });
            return [];
        }
        const root = element.root;
        if (!isViewport(root)) {
            return [];
        }
        const scroll = { x: root.scroll.x + dx / root.zoom, y: root.scroll.y + dy / root.zoom };
        return [SetViewportAction.create(root.id, { scroll, zoom: root.zoom }, { animate: false })];
    }
}
