/*
 * The client-side model elements of a KSE statechart diagram. The server sends one node per state
 * (type "state:<kind>"), a name label per state that has a name, and one edge per transition with
 * a label holding the first line of its expression.
 */
import {
    Args,
    Dimension,
    EditableLabel,
    ELLIPTIC_ANCHOR_KIND,
    GChildElement,
    GEdge,
    GLabel,
    GModelElement,
    GNode,
    Point,
    RECTANGULAR_ANCHOR_KIND,
    isEditableLabel,
    popupFeature,
    withEditLabelFeature
} from '@eclipse-glsp/client';
import { NOTATION, isCircle } from './notation-style';

export const DIAGRAM_TYPE = 'kse-statechart';

export const STATE_PREFIX = 'state:';
export const NAME_LABEL = 'label:name';
export const EXPRESSION_LABEL = 'label:expression';
export const TRANSITION = 'transition';

export type StateKind = 'start' | 'end' | 'condition' | 'basic' | 'or' | 'and' | 'unknown';

/** The kinds the page knows how to draw (those the notation's style draws); a kind the server adds before it has a drawing is drawn as 'unknown'. */
const DRAWN_KINDS: readonly string[] = Object.keys(NOTATION.states);

export function stateKindOf(type: string): StateKind {
    const kind = type.startsWith(STATE_PREFIX) ? type.substring(STATE_PREFIX.length) : 'unknown';
    return DRAWN_KINDS.includes(kind) ? (kind as StateKind) : 'unknown';
}

function argsOf(element: GModelElement): Args {
    const args = (element as unknown as { args?: Args }).args;
    return args ?? {};
}

function stringArg(element: GModelElement, name: string): string {
    const value = argsOf(element)[name];
    return value === undefined || value === null ? '' : String(value);
}

/**
 * Why a state of kind `child` cannot go into one of kind `parent`, as the server's rule book says
 * (sent with the graph), or undefined when it can.
 */
export function holdRefusal(root: GModelElement, parent: StateKind, child: StateKind): string | undefined {
    const refusal = argsOf(root)[`holdRefusal:${parent}/${child}`];
    return refusal === undefined || refusal === null ? undefined : String(refusal);
}

/** A state of any kind; what it looks like is decided by its kind. */
export class StateNode extends GNode {
    get kind(): StateKind {
        return stateKindOf(this.type);
    }

    get isRound(): boolean {
        // drawn as a circle (the notation's style says which kinds are): edges end on the circle
        return isCircle(this.kind);
    }

    /** Whether the state holds others (and shows its name in a header): the server's rule book says which kinds do. */
    get isComposite(): boolean {
        return stringArg(this.root, 'compositeKinds').split(' ').includes(this.kind);
    }

    /** The state's hierarchical label (e.g. "0.2.1"), shown at the top right of composites. */
    get hierarchicalLabel(): string {
        return stringArg(this, 'label');
    }

    /** The state's name in the model; its box may show a shorter caption (a formula's operators). */
    get fullName(): string {
        return stringArg(this, 'name');
    }

    override get anchorKind(): string {
        return this.isRound ? ELLIPTIC_ANCHOR_KIND : RECTANGULAR_ANCHOR_KIND;
    }

    get nameLabel(): NameLabel | undefined {
        return this.children.find((child): child is NameLabel => child instanceof NameLabel);
    }
}

/** A BASIC state: double clicking anywhere in its box edits its name. */
export class BasicStateNode extends StateNode {
    static override readonly DEFAULT_FEATURES = [...GNode.DEFAULT_FEATURES, withEditLabelFeature];

    get editableLabel(): (GChildElement & EditableLabel) | undefined {
        const label = this.nameLabel;
        return label && isEditableLabel(label) ? label : undefined;
    }
}

/** The name of a state; drawn centred in round states and BASIC boxes, in the header of composites. */
export class NameLabel extends GLabel {
    get owner(): StateNode | undefined {
        return this.parent instanceof StateNode ? this.parent : undefined;
    }

    get isCentred(): boolean {
        const owner = this.owner;
        return owner !== undefined && !owner.isComposite;
    }

    /** What the editor starts with: the state's name, not the caption shown for a formula. */
    get fullText(): string {
        const name = this.owner?.fullName;
        return name ? name : this.text;
    }

    get editControlDimension(): Dimension {
        return { width: Math.max(140, this.bounds.width + 40), height: 22 };
    }
}

/** A transition: hovering shows its whole expression, double clicking edits it. */
export class TransitionEdge extends GEdge {
    static override readonly DEFAULT_FEATURES = [...GEdge.DEFAULT_FEATURES, popupFeature, withEditLabelFeature];

    /** The whole transition expression (possibly several lines). */
    get expression(): string {
        return stringArg(this, 'expression');
    }

    get transitionName(): string {
        return stringArg(this, 'name');
    }

    get editableLabel(): (GChildElement & EditableLabel) | undefined {
        const label = this.children.find(child => child instanceof ExpressionLabel);
        return label && isEditableLabel(label) ? label : undefined;
    }
}

/** The first line of a transition's expression; edited as the whole expression, in a text area. */
export class ExpressionLabel extends GLabel {
    readonly isMultiLine = true;

    get edge(): TransitionEdge | undefined {
        return this.parent instanceof TransitionEdge ? this.parent : undefined;
    }

    /** What the editor starts with: the whole expression, not only the first line shown. */
    get fullText(): string {
        const expression = this.edge?.expression;
        return expression ? expression : this.text;
    }

    get editControlDimension(): Dimension {
        const lines = Math.min(8, Math.max(3, this.fullText.split('\n').length + 1));
        return { width: Math.max(320, this.bounds.width + 40), height: lines * 16 + 8 };
    }

    get editControlPositionCorrection(): Point {
        return { x: 0, y: 0 };
    }
}
