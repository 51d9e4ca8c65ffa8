/*
 * Views of the thesis notation: START a black disc, END a ringed disc, CONDITION a white circle with
 * "C", BASIC a green rounded box, OR a yellow and AND a light blue box holding their children.
 * Colours are those of org.kse.notation's SvgDiagram, so that exported pictures match.
 */
import {
    ATTR_BBOX_ELEMENT,
    GEdge,
    GEdgeView,
    GLabel,
    Point,
    RenderingContext,
    ShapeView,
    angleOfPoint,
    svg,
    toDegrees
} from '@eclipse-glsp/client';
import { injectable } from 'inversify';
import { VNode } from 'snabbdom';
import { ExpressionLabel, NameLabel, StateKind, StateNode } from './model';

/** Fill and stroke of each kind (org.kse.notation.SvgDiagram). */
export const NOTATION_COLOURS: Record<StateKind, { fill: string; stroke: string }> = {
    start: { fill: '#000000', stroke: '#000000' },
    end: { fill: '#ffffff', stroke: '#000000' },
    condition: { fill: '#ffffff', stroke: '#000000' },
    basic: { fill: '#b9e4a4', stroke: '#3d7a2b' },
    or: { fill: '#fff5c2', stroke: '#a68b22' },
    and: { fill: '#d8ecff', stroke: '#4a7fb0' },
    unknown: { fill: '#eeeeee', stroke: '#888888' }
};

const bbox = { [ATTR_BBOX_ELEMENT]: true };

/** The widest character (px) of a hierarchical label: digits and dots at 11px (DejaVu Sans). */
const HIERARCHICAL_LABEL_CHARACTER_WIDTH = 7;

/** One view for every state kind, so that a state changing its kind keeps its DOM element. */
@injectable()
export class StateView extends ShapeView {
    render(node: Readonly<StateNode>, context: RenderingContext): VNode | undefined {
        if (!this.isVisible(node, context)) {
            return undefined;
        }
        const width = Math.max(node.size.width, 0);
        const height = Math.max(node.size.height, 0);
        const kind = node.kind;
        return (
            <g class-kse-state={true} data-kind={kind} data-id={node.id}>
                {/* the node's extent for the bounds computation, whatever its shape draws */}
                <rect class-kse-extent={true} x={0} y={0} width={width} height={height} fill='none' stroke='none' {...bbox} />
                {...this.renderShape(node, kind, width, height)}
                {context.renderChildren(node)}
            </g>
        );
    }

    protected shapeClasses(node: Readonly<StateNode>): Record<string, boolean> {
        return {
            'class-sprotty-node': true,
            'class-kse-shape': true,
            'class-selected': node.selected,
            'class-mouseover': node.hoverFeedback
        };
    }

    protected renderShape(node: Readonly<StateNode>, kind: StateKind, width: number, height: number): VNode[] {
        const colours = NOTATION_COLOURS[kind];
        const classes = this.shapeClasses(node);
        const cx = width / 2;
        const cy = height / 2;
        const r = Math.min(width, height) / 2;
        switch (kind) {
            case 'start':
                return [<circle {...classes} cx={cx} cy={cy} r={r} fill={colours.fill} stroke={colours.stroke} stroke-width={1} />];
            case 'end':
                return [
                    <circle {...classes} cx={cx} cy={cy} r={Math.max(r - 1, 1)} fill={colours.fill} stroke={colours.stroke} stroke-width={1.5} />,
                    <circle class-kse-end-centre={true} cx={cx} cy={cy} r={r * 0.55} fill='#000000' />
                ];
            case 'condition':
                return [<circle {...classes} cx={cx} cy={cy} r={Math.max(r - 1, 1)} fill={colours.fill} stroke={colours.stroke} stroke-width={1.5} />];
            case 'basic':
                return [<rect {...classes} x={0} y={0} width={width} height={height} rx={8} ry={8} fill={colours.fill} stroke={colours.stroke} stroke-width={1} />];
            case 'or':
            case 'and': {
                const box = <rect {...classes} x={0} y={0} width={width} height={height} rx={3} ry={3} fill={colours.fill} stroke={colours.stroke} stroke-width={1} />;
                // the label gives way to the caption in a narrow composite (hovering shows both)
                const captionRight = 8 + (node.nameLabel?.bounds.width ?? 0) + 10;
                const labelWidth = node.hierarchicalLabel.length * HIERARCHICAL_LABEL_CHARACTER_WIDTH;
                if (captionRight + labelWidth > width - 6) {
                    return [box];
                }
                return [
                    box,
                    <text class-kse-hierarchical-label={true} x={Math.max(width - 6, 0)} y={16}>
                        {node.hierarchicalLabel}
                    </text>
                ];
            }
            default:
                return [
                    <rect {...classes} class-kse-unknown={true} x={0} y={0} width={width} height={height} rx={2} ry={2} fill={colours.fill} stroke={colours.stroke} stroke-width={1} stroke-dasharray='4 3' />
                ];
        }
    }
}

/**
 * A state's name: centred in its shape (BASIC, CONDITION) or bold in the header of a composite.
 * The text is placed from the owner's size, so it stays centred whatever the label's position.
 */
@injectable()
export class NameLabelView extends ShapeView {
    render(label: Readonly<NameLabel>, context: RenderingContext): VNode | undefined {
        const owner = label.owner;
        if (owner !== undefined && owner.isComposite) {
            const caption = (
                <text class-sprotty-label={true} class-kse-name={true} class-kse-composite-name={true} x={0} y={12}>
                    {label.text}
                </text>
            );
            // a state named after a formula shows the formula; its spelled-out name on hover
            const fullName = owner.fullName;
            return fullName && fullName !== label.text ? (
                <g class-kse-caption={true}>
                    <title>{fullName}</title>
                    {caption}
                </g>
            ) : (
                caption
            );
        }
        const position = label.position;
        const x = owner ? owner.size.width / 2 - position.x : 0;
        const y = owner ? owner.size.height / 2 - position.y : 0;
        return (
            <text class-sprotty-label={true} class-kse-name={true} class-kse-centred-name={true} class-kse-condition-name={owner?.kind === 'condition'} x={x} y={y}>
                {label.text}
            </text>
        );
    }
}

/**
 * The first line of a transition's expression, where the server's layout placed it: its position
 * is the top-left corner of a box kept free of states and other labels (org.kse.notation's
 * TransitionLayout), so the text hangs from that corner.
 */
@injectable()
export class ExpressionLabelView extends ShapeView {
    render(label: Readonly<ExpressionLabel>, _context: RenderingContext): VNode | undefined {
        return (
            <text class-sprotty-label={true} class-kse-expression={true} x={2} y={1}>
                {label.text}
            </text>
        );
    }
}

/** A plain label (of a type the client does not know), for completeness. */
@injectable()
export class PlainLabelView extends ShapeView {
    render(label: Readonly<GLabel>, _context: RenderingContext): VNode | undefined {
        return <text class-sprotty-label={true}>{label.text}</text>;
    }
}

/** A transition (TransitionEdge): a dark grey line ending in a filled arrow head at its target. */
@injectable()
export class TransitionView extends GEdgeView {
    override render(edge: Readonly<GEdge>, context: RenderingContext): VNode {
        const vnode = super.render(edge, context);
        if (vnode.data) {
            vnode.data.class = { ...(vnode.data.class ?? {}), 'kse-transition': true, selected: edge.selected };
            vnode.data.attrs = { ...(vnode.data.attrs ?? {}), 'data-id': edge.id, 'data-kind': 'transition' };
        }
        return vnode;
    }

    protected override renderLine(_edge: GEdge, segments: Point[], _context: RenderingContext): VNode {
        return <path class-kse-line={true} d={this.createPathForSegments(segments)} />;
    }

    protected override renderAdditionals(edge: GEdge, segments: Point[], context: RenderingContext): VNode[] {
        const additionals = super.renderAdditionals(edge, segments, context);
        if (segments.length >= 2) {
            const end = segments[segments.length - 1];
            const before = segments[segments.length - 2];
            const angle = toDegrees(angleOfPoint(Point.subtract(end, before)));
            additionals.push(
                <path class-kse-arrow={true} d='M 0,0 L -10,-4.5 L -10,4.5 Z' transform={`translate(${end.x} ${end.y}) rotate(${angle})`} />
            );
            // a wide transparent stroke along the line makes the edge easy to hover and click
            additionals.push(<path class-kse-edge-handle={true} d={this.createPathForSegments(segments)} />);
        }
        return additionals;
    }
}
