package org.kse.notation;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/**
 * A statechart drawn as SVG in the thesis' notation: START a small black disc, END a white disc
 * with a black centre, CONDITION a circled "C", BASIC a green rounded box, OR a yellow box with
 * its name over its children, AND a light-blue box holding its regions. Transitions are arrows
 * labelled with the first line of their expression; the whole expression shows on hover (title).
 * Shapes, colours and fonts come from {@link NotationStyle}, as the diagram page's do; each
 * state's shape, caption and label carry the classes {@code shape}, {@code caption} and
 * {@code label}, a transition's line and text {@code line} and {@code expression}.
 */
public final class SvgDiagram {

	private static final double MARGIN = 20;
	private static final NotationStyle STYLE = NotationStyle.get();

	private SvgDiagram() {
	}

	public static String render(Model model, Notation notation) {
		Map<Node, Bounds> placed = new IdentityHashMap<>();
		List<Node> order = new ArrayList<>();
		for (Node root : model.getNodes()) {
			place(root, MARGIN, MARGIN, notation, placed, order);
		}
		// the layout's coordinates start at the diagram's corner; the picture keeps a margin round them
		Map<Transition, TransitionLayout.Placed> routes = TransitionLayout.of(model, node -> {
			Bounds relative = notation.get(node);
			return relative != null ? relative : Shapes.size(node);
		});
		double width = MARGIN;
		double height = MARGIN;
		for (Bounds bounds : placed.values()) {
			width = Math.max(width, bounds.right() + MARGIN);
			height = Math.max(height, bounds.bottom() + MARGIN);
		}
		for (TransitionLayout.Placed route : routes.values()) {
			if (route.label() != null) {
				width = Math.max(width, route.label().right() + 2 * MARGIN);
				height = Math.max(height, route.label().bottom() + 2 * MARGIN);
			}
			for (double[] bend : route.bends()) {
				width = Math.max(width, bend[0] + 2 * MARGIN);
				height = Math.max(height, bend[1] + 2 * MARGIN);
			}
		}
		StringBuilder svg = new StringBuilder();
		svg.append(String.format(Locale.ROOT, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
				+ "font-family=\"%s\" font-size=\"%s\">%n", width, height, width, height, escape(STYLE.fontFamily()), number(STYLE.centredCaption().size())));
		svg.append("<title>").append(escape(model.getName())).append("</title>\n");
		svg.append(arrowMarker());
		svg.append("<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
		for (Node node : order) {
			state(svg, node, placed.get(node));
		}
		routes.forEach((transition, route) -> transition(svg, transition, route, placed.get(transition.getSource()), placed.get(transition.getTarget())));
		svg.append("</svg>\n");
		return svg.toString();
	}

	/** Absolute bounds, parents before their children (so that children are drawn over them). */
	private static void place(Node node, double originX, double originY, Notation notation, Map<Node, Bounds> placed, List<Node> order) {
		Bounds relative = notation.get(node);
		if (relative == null) {
			relative = Shapes.size(node);
		}
		Bounds absolute = new Bounds(originX + relative.x(), originY + relative.y(), relative.width(), relative.height());
		placed.put(node, absolute);
		order.add(node);
		for (Node child : node.getChildren()) {
			place(child, absolute.x(), absolute.y(), notation, placed, order);
		}
	}

	private static void state(StringBuilder svg, Node node, Bounds b) {
		NodeKind kind = NodeKind.of(node);
		String kindName = kind == null ? "unknown" : kind.name().toLowerCase(Locale.ROOT);
		NotationStyle.StateStyle style = STYLE.of(kind);
		svg.append(String.format(Locale.ROOT, "<g class=\"state %s\" data-label=\"%s\"><title>%s %s (%s)</title>", kindName, escape(node.getLabel()),
				escape(node.getLabel()), escape(node.getName()), kind == null ? escape(node.getType()) : kind.name()));
		double cx = b.x() + b.width() / 2;
		double cy = b.y() + b.height() / 2;
		double r = Math.min(b.width(), b.height()) / 2;
		String outline = String.format(Locale.ROOT, "fill=\"%s\" stroke=\"%s\" stroke-width=\"%s\"%s", style.fill(), style.stroke(),
				number(style.strokeWidth()), style.dash() == null ? "" : " stroke-dasharray=\"" + escape(style.dash()) + "\"");
		if (style.isCircle()) {
			svg.append(String.format(Locale.ROOT, "<circle class=\"shape\" cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" %s/>", cx, cy, Math.max(r - style.inset(), 1),
					outline));
			if (style.shape() == NotationStyle.Shape.RINGED_DISC) {
				svg.append(String.format(Locale.ROOT, "<circle class=\"centre\" cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\"/>", cx, cy,
						r * style.innerDiscRatio(), style.innerDiscFill()));
			} else if (style.shape() == NotationStyle.Shape.CIRCLED_LETTER) {
				text(svg, "caption", cx, cy, "middle", "central", STYLE.letterCaption(), style.letter());
			}
		} else {
			svg.append(String.format(Locale.ROOT, "<rect class=\"shape\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" rx=\"%s\" %s/>", b.x(), b.y(),
					b.width(), b.height(), number(style.cornerRadius()), outline));
			// as the diagram page draws the name: in the header of a kind that holds others (the rule book's), else in the middle
			if (kind != null && kind.isComposite()) {
				NotationStyle.TextStyle header = STYLE.headerCaption();
				text(svg, "caption", b.x() + header.x(), b.y() + header.y(), "start", null, header, Captions.of(node));
			} else {
				text(svg, "caption", cx, cy, "middle", "central", STYLE.centredCaption(), Captions.of(node));
			}
			if (style.shape() == NotationStyle.Shape.COMPOSITE_BOX) {
				NotationStyle.TextStyle label = STYLE.label();
				text(svg, "label", b.right() - label.x(), b.y() + label.y(), "end", null, label, node.getLabel());
			}
		}
		svg.append("</g>\n");
	}

	/** A text in its style: font, weight and colour written on the element, as the diagram page writes them. */
	private static void text(StringBuilder svg, String cssClass, double x, double y, String anchor, String baseline, NotationStyle.TextStyle style,
			String text) {
		svg.append(String.format(Locale.ROOT, "<text class=\"%s\" x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\"%s font-size=\"%s\" font-weight=\"%s\" fill=\"%s\">%s</text>",
				cssClass, x, y, anchor, baseline == null ? "" : " dominant-baseline=\"" + baseline + "\"", number(style.size()), style.weight(), style.colour(),
				escape(text)));
	}

	private static void transition(StringBuilder svg, Transition transition, TransitionLayout.Placed route, Bounds source, Bounds target) {
		String expression = transition.getTE() == null ? "" : transition.getTE().strip();
		svg.append("<g class=\"transition\"><title>").append(escape(transition.getName()))
				.append(expression.isEmpty() ? "" : ": " + escape(expression)).append("</title>");
		java.util.List<double[]> bends = route.bends().stream().map(bend -> new double[] { bend[0] + MARGIN, bend[1] + MARGIN }).toList();
		double[] first = bends.isEmpty() ? new double[] { target.x() + target.width() / 2, target.y() + target.height() / 2 } : bends.get(0);
		double[] last = bends.isEmpty() ? new double[] { source.x() + source.width() / 2, source.y() + source.height() / 2 } : bends.get(bends.size() - 1);
		StringBuilder path = new StringBuilder();
		double[] from = TransitionLayout.border(source, first);
		path.append(String.format(Locale.ROOT, "M%.1f,%.1f", from[0], from[1]));
		for (double[] bend : bends) {
			path.append(String.format(Locale.ROOT, " L%.1f,%.1f", bend[0], bend[1]));
		}
		double[] to = TransitionLayout.border(target, last);
		path.append(String.format(Locale.ROOT, " L%.1f,%.1f", to[0], to[1]));
		svg.append(String.format(Locale.ROOT, "<path class=\"line\" d=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"%s\" marker-end=\"url(#arrow)\"/>", path,
				STYLE.line().colour(), number(STYLE.line().width())));
		if (route.label() != null) {
			Bounds label = route.label();
			NotationStyle.TextStyle style = STYLE.transitionLabel();
			text(svg, "expression", label.x() + MARGIN + style.x(), label.y() + MARGIN + style.y(), "start", "text-before-edge", style, route.text());
		}
		svg.append("</g>\n");
	}

	/**
	 * The arrow head as the diagram page draws it: a triangle with its tip at the line's end, in
	 * the diagram's units (not scaled by the line's width, as a marker is by default).
	 */
	private static String arrowMarker() {
		NotationStyle.Arrow arrow = STYLE.arrow();
		double half = arrow.width() / 2;
		double pad = arrow.strokeWidth();
		return String.format(Locale.ROOT,
				"<defs><marker id=\"arrow\" viewBox=\"%s %s %s %s\" refX=\"0\" refY=\"0\" markerWidth=\"%s\" markerHeight=\"%s\" markerUnits=\"userSpaceOnUse\" orient=\"auto\">"
						+ "<path class=\"arrow\" d=\"M0,0 L%s,%s L%s,%s z\" fill=\"%s\" stroke=\"%s\" stroke-width=\"%s\" stroke-linejoin=\"round\"/></marker></defs>%n",
				number(-arrow.length() - pad), number(-half - pad), number(arrow.length() + 2 * pad), number(arrow.width() + 2 * pad),
				number(arrow.length() + 2 * pad), number(arrow.width() + 2 * pad), number(-arrow.length()), number(-half), number(-arrow.length()),
				number(half), arrow.fill(), arrow.stroke(), number(arrow.strokeWidth()));
	}

	/** A length as SVG writes it: no trailing zeros ({@code 1.5}, {@code 8}). */
	private static String number(double value) {
		return value == Math.rint(value) ? String.valueOf((long) value) : String.valueOf(value);
	}

	private static String escape(String text) {
		if (text == null) {
			return "";
		}
		return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
	}
}
