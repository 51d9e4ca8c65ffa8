/*
 * Dragging states into another composite. GLSP's change-bounds tool only ever sends ChangeBounds,
 * so a state dropped on another composite stayed in its old one (drawn over the other). Here the
 * drop target is the deepest state under the mouse pointer (not a dragged state or anything inside
 * one), or the canvas for the top of the model: a drop into another parent that may hold the
 * dragged states goes to the server as ChangeContainerOperation (one undoable step), a drop the
 * statechart rules forbid is refused with a message and the states snap back. While dragging, the
 * target that would take the states is outlined (refused ones in red).
 */
import {
    Action,
    ChangeBoundsListener,
    ChangeBoundsTool,
    ChangeContainerOperation,
    CompoundOperation,
    CursorCSS,
    FeedbackEmitter,
    FeedbackMoveMouseListener,
    GChildElement,
    GModelElement,
    GModelRoot,
    GParentElement,
    MessageAction,
    MouseListener,
    Operation,
    Point,
    applyCssClasses,
    cursorFeedbackAction,
    deleteCssClasses,
    getAbsolutePosition,
    isBoundsAware,
    isContainable,
    isSelected,
    toAbsoluteBounds,
    toElementAndBounds,
    ChangeBoundsOperation
} from '@eclipse-glsp/client';
import { injectable } from 'inversify';
import { StateNode, holdRefusal } from './model';

export const CSS_DROP_TARGET = 'kse-drop-target';
export const CSS_DROP_REFUSED = 'kse-drop-refused';

/** Where dragged states would go: a composite state or the top of the model (the root). */
export interface Drop {
    container: GParentElement;
    /** The states that change their parent (the others only move). */
    reparented: StateNode[];
    /** Why the drop is not allowed, when it is not. */
    refusal?: string;
}

function describe(state: StateNode): string {
    const name = state.nameLabel?.text;
    return name ? `'${name}'` : `the ${state.kind.toUpperCase()} state ${state.hierarchicalLabel}`.trim();
}

/** The dragged states: selected states whose parent is not dragged too. */
export function draggedStates(root: GModelRoot): StateNode[] {
    const selected = Array.from(root.index.all()).filter((element): element is StateNode => element instanceof StateNode && isSelected(element));
    const set = new Set<GModelElement>(selected);
    return selected.filter(state => {
        for (let parent = state.parent; parent instanceof GChildElement; parent = parent.parent) {
            if (set.has(parent)) {
                return false;
            }
        }
        return !set.has(state.parent);
    });
}

/** The deepest state under a point (diagram coordinates), skipping the dragged states and their insides. */
function deepestStateAt(parent: GParentElement, point: Point, skipped: ReadonlySet<GModelElement>): StateNode | undefined {
    // later children are drawn on top: they take the pointer first
    for (let index = parent.children.length - 1; index >= 0; index--) {
        const child = parent.children[index];
        if (child instanceof StateNode && !skipped.has(child) && isBoundsAware(child)) {
            const box = child.bounds;
            if (point.x >= box.x && point.x <= box.x + box.width && point.y >= box.y && point.y <= box.y + box.height) {
                const local = { x: point.x - box.x, y: point.y - box.y };
                return deepestStateAt(child, local, skipped) ?? child;
            }
        }
    }
    return undefined;
}

/** The drop of the dragged states at a point of the diagram (absolute coordinates). */
export function dropAt(root: GModelRoot, dragged: StateNode[], point: Point): Drop {
    const skipped = new Set<GModelElement>(dragged);
    const target = deepestStateAt(root, point, skipped);
    const container: GParentElement = target ?? root;
    const reparented = dragged.filter(state => state.parent !== container);
    if (reparented.length === 0 || !(target instanceof StateNode)) {
        return { container, reparented };
    }
    for (const state of reparented) {
        if (!isContainable(target) || !target.isContainableElement(state)) {
            const reason = holdRefusal(root, target.kind, state.kind) ?? `the ${target.kind.toUpperCase()} state cannot hold it`;
            return { container, reparented, refusal: `Cannot move ${describe(state)} into ${describe(target)}: ${reason}` };
        }
    }
    return { container, reparented };
}

/** The change-bounds tool of the statechart: a drop into another composite reparents the states. */
@injectable()
export class KseChangeBoundsTool extends ChangeBoundsTool {
    protected override createMoveMouseListener(): MouseListener {
        return new DropFeedbackMoveListener(this);
    }

    protected override createChangeBoundsListener(): MouseListener {
        return new ReparentingChangeBoundsListener(this);
    }
}

/** Moves the dragged states with the mouse; outlines the composite they would go into; snaps them back when a drop is refused. */
export class DropFeedbackMoveListener extends FeedbackMoveMouseListener {
    protected dropFeedback: FeedbackEmitter;
    protected outlined?: { id: string; refused: boolean };

    constructor(tool: ChangeBoundsTool) {
        super(tool);
        this.dropFeedback = tool.createFeedbackEmitter();
    }

    override draggingMouseMove(target: GModelElement, event: MouseEvent): Action[] {
        const actions = super.draggingMouseMove(target, event);
        if (this.tracker.isTracking()) {
            const dragged = draggedStates(target.root);
            this.outline(dragged.length > 0 ? dropAt(target.root, dragged, getAbsolutePosition(target, event)) : undefined);
        }
        return actions;
    }

    protected outline(drop: Drop | undefined): void {
        const shown = drop && drop.reparented.length > 0 ? { id: drop.container.id, refused: drop.refusal !== undefined } : undefined;
        if (shown?.id === this.outlined?.id && shown?.refused === this.outlined?.refused) {
            return;
        }
        this.dropFeedback.dispose();
        this.outlined = shown;
        if (drop && shown) {
            const css = shown.refused ? CSS_DROP_REFUSED : CSS_DROP_TARGET;
            this.dropFeedback.add(applyCssClasses(drop.container, css), deleteCssClasses(drop.container, css));
            if (shown.refused) {
                this.dropFeedback.add(cursorFeedbackAction(CursorCSS.OPERATION_NOT_ALLOWED), cursorFeedbackAction(CursorCSS.DEFAULT));
            }
            this.dropFeedback.submit();
        }
    }

    override draggingMouseUp(target: GModelElement, event: MouseEvent): Action[] {
        const dragged = this.tracker.isTracking() ? draggedStates(target.root) : [];
        const refused = dragged.length > 0 && dropAt(target.root, dragged, getAbsolutePosition(target, event)).refusal !== undefined;
        if (refused) {
            // disposing the move feedback puts the states back where the drag started
            this.dispose();
            return [];
        }
        return super.draggingMouseUp(target, event);
    }

    override dispose(): void {
        this.outline(undefined);
        super.dispose();
    }
}

/** Sends the end of a drag to the server: a move within the same parent as before, a drop into another parent as ChangeContainer. */
export class ReparentingChangeBoundsListener extends ChangeBoundsListener {
    protected pendingDrop?: Drop;

    override draggingMouseUp(target: GModelElement, event: MouseEvent): Action[] {
        const dragged = this.activeResizeHandle ? [] : draggedStates(target.root);
        this.pendingDrop = dragged.length > 0 ? dropAt(target.root, dragged, getAbsolutePosition(target, event)) : undefined;
        try {
            return super.draggingMouseUp(target, event);
        } finally {
            this.pendingDrop = undefined;
        }
    }

    protected override handleMoveOnServer(target: GModelElement): Action[] {
        const drop = this.pendingDrop;
        if (!drop || drop.reparented.length === 0) {
            return super.handleMoveOnServer(target);
        }
        if (drop.refusal) {
            return [MessageAction.create(drop.refusal, { severity: 'WARNING' })];
        }
        const operations: Operation[] = [];
        const moved = this.getElementsToMove(target).filter(element => !drop.reparented.includes(element as StateNode));
        if (moved.length > 0) {
            operations.push(ChangeBoundsOperation.create(moved.map(toElementAndBounds)));
        }
        for (const state of drop.reparented) {
            // the server expects where the state's corner lies in diagram coordinates
            const corner = toAbsoluteBounds(state);
            operations.push(ChangeContainerOperation.create({ elementId: state.id, targetContainerId: drop.container.id, location: { x: corner.x, y: corner.y } }));
        }
        return [CompoundOperation.create(operations)];
    }
}
