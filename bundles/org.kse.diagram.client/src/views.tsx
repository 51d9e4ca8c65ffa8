/*
 * Views of the thesis notation: START a black disc, END a ringed disc, CONDITION a white circle with
 * "C", BASIC a green rounded box, OR a yellow and AND a light blue box holding their children.
 * Every shape, colour, stroke and font is the notation's style (notation-style.ts, the file
 * org.kse.notation's SvgDiagram draws `kse diagram`'s SVG from): shapes get it as presentation
 * attributes, texts as inline style; kse.css only changes them for selection, hover and dragging.
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
import { NOTATION, StateStyle, textStyle } from './notation-style';

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

    /**
     * The outline's presentation attributes. GLSP's CSS sets every node's stroke width (to 0), which
     * beats an attribute: the width also goes in --kse-stroke-width, which kse.css gives the shape.
     */
    protected outline(style: StateStyle): Record<string, unknown> {
        return {
            fill: style.fill,
            stroke: style.stroke,
            'stroke-width': style.strokeWidth,
            ...(style.dash ? { 'stroke-dasharray': style.dash } : {}),
            style: { '--kse-stroke-width': `${style.strokeWidth}px` }
        };
    }

    protected renderShape(node: Readonly<StateNode>, kind: StateKind, width: number, height: number): VNode[] {
        const style = NOTATION.states[kind];
        const classes = this.shapeClasses(node);
        const cx = width / 2;
        const cy = height / 2;
        const r = Math.min(width, height) / 2;
        switch (style.shape) {
            case 'disc':
            case 'circledLetter':
                // the letter is the state's name label (the server sends it), drawn by NameLabelView
                return [<circle {...classes} cx={cx} cy={cy} r={Math.max(r - (style.inset ?? 0), 1)} {...this.outline(style)} />];
            case 'ringedDisc':
                return [
                    <circle {...classes} cx={cx} cy={cy} r={Math.max(r - (style.inset ?? 0), 1)} {...this.outline(style)} />,
                    <circle class-kse-end-centre={true} cx={cx} cy={cy} r={r * (style.innerDisc?.ratio ?? 0)} fill={style.innerDisc?.fill ?? 'none'} />
                ];
            case 'compositeBox': {
                const radius = style.cornerRadius ?? 0;
                const box = <rect {...classes} x={0} y={0} width={width} height={height} rx={radius} ry={radius} {...this.outline(style)} />;
                const label = NOTATION.captions.label;
                // the label gives way to the caption in a narrow composite (hovering shows both)
                const captionRight = NOTATION.captions.header.x + (node.nameLabel?.bounds.width ?? 0) + 10;
                const labelWidth = node.hierarchicalLabel.length * HIERARCHICAL_LABEL_CHARACTER_WIDTH;
                if (captionRight + labelWidth > width - label.right) {
                    return [box];
                }
                return [
                    box,
                    <text class-kse-hierarchical-label={true} x={Math.max(width - label.right, 0)} y={label.baseline} {...textStyle(label, 'end')}>
                        {node.hierarchicalLabel}
                    </text>
                ];
            }
            default: {
                const radius = style.cornerRadius ?? 0;
                return [
                    <rect {...classes} class-kse-unknown={kind === 'unknown'} x={0} y={0} width={width} height={height} rx={radius} ry={radius} {...this.outline(style)} />
                ];
            }
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
            const header = NOTATION.captions.header;
            // the baseline where kse diagram puts it, whatever the label's position in the header
            const caption = (
                <text class-sprotty-label={true} class-kse-name={true} class-kse-composite-name={true} x={0} y={header.baseline - label.position.y} {...textStyle(header, 'start')}>
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
        const letter = owner !== undefined && NOTATION.states[owner.kind].shape === 'circledLetter';
        const font = letter ? NOTATION.captions.letter : NOTATION.captions.centred;
        return (
            <text class-sprotty-label={true} class-kse-name={true} class-kse-centred-name={true} class-kse-condition-name={owner?.kind === 'condition'} x={x} y={y} {...textStyle(font, 'middle', 'central')}>
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
            <text class-sprotty-label={true} class-kse-expression={true} x={NOTATION.transitions.label.x} y={NOTATION.transitions.label.y} {...textStyle(NOTATION.transitions.label, 'start', 'text-before-edge')}>
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

/** A transition (TransitionEdge): a line ending in a filled arrow head at its target, in the notation's style. */
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
        const line = NOTATION.transitions.line;
        return <path class-kse-line={true} d={this.createPathForSegments(segments)} fill='none' stroke={line.colour} stroke-width={line.width} />;
    }

    protected override renderAdditionals(edge: GEdge, segments: Point[], context: RenderingContext): VNode[] {
        const additionals = super.renderAdditionals(edge, segments, context);
        if (segments.length >= 2) {
            const end = segments[segments.length - 1];
            const before = segments[segments.length - 2];
            const angle = toDegrees(angleOfPoint(Point.subtract(end, before)));
            const arrow = NOTATION.transitions.arrow;
            additionals.push(
                <path
                    class-kse-arrow={true}
                    d={`M 0,0 L ${-arrow.length},${-arrow.width / 2} L ${-arrow.length},${arrow.width / 2} Z`}
                    transform={`translate(${end.x} ${end.y}) rotate(${angle})`}
                    fill={arrow.fill}
                    stroke={arrow.stroke}
                    stroke-width={arrow.strokeWidth}
                    stroke-linejoin='round'
                />
            );
            // a wide transparent stroke along the line makes the edge easy to hover and click
            additionals.push(<path class-kse-edge-handle={true} d={this.createPathForSegments(segments)} />);
        }
        return additionals;
    }
}
