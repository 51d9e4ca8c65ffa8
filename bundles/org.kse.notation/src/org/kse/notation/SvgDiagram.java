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
 */
public final class SvgDiagram {

	private static final double MARGIN = 20;

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
				+ "font-family=\"sans-serif\" font-size=\"12\">%n", width, height, width, height));
		svg.append("<title>").append(escape(model.getName())).append("</title>\n");
		svg.append("<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"8\" markerHeight=\"8\" orient=\"auto-start-reverse\">"
				+ "<path d=\"M0,0 L10,5 L0,10 z\" fill=\"#333\"/></marker></defs>\n");
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
		svg.append(String.format(Locale.ROOT, "<g class=\"state %s\" data-label=\"%s\"><title>%s %s (%s)</title>", kindName, escape(node.getLabel()),
				escape(node.getLabel()), escape(node.getName()), kind == null ? escape(node.getType()) : kind.name()));
		double cx = b.x() + b.width() / 2;
		double cy = b.y() + b.height() / 2;
		double r = Math.min(b.width(), b.height()) / 2;
		if (kind == NodeKind.START) {
			svg.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"black\"/>", cx, cy, r));
		} else if (kind == NodeKind.END) {
			svg.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"white\" stroke=\"black\" stroke-width=\"1.5\"/>"
					+ "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"black\"/>", cx, cy, r - 1, cx, cy, r * 0.55));
		} else if (kind == NodeKind.CONDITION) {
			svg.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"white\" stroke=\"black\" stroke-width=\"1.5\"/>"
					+ "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" dominant-baseline=\"central\" font-weight=\"bold\">C</text>", cx, cy, r - 1, cx, cy));
		} else if (kind == NodeKind.BASIC) {
			svg.append(String.format(Locale.ROOT, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" rx=\"8\" fill=\"#b9e4a4\" stroke=\"#3d7a2b\"/>"
					+ "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" dominant-baseline=\"central\">%s</text>", b.x(), b.y(), b.width(), b.height(), cx, cy,
					escape(node.getName())));
		} else {
			boolean and = kind == NodeKind.AND;
			svg.append(String.format(Locale.ROOT, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" rx=\"3\" fill=\"%s\" stroke=\"%s\"/>"
					+ "<text x=\"%.1f\" y=\"%.1f\" font-weight=\"bold\">%s</text><text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" fill=\"#666\" font-size=\"11\">%s</text>",
					b.x(), b.y(), b.width(), b.height(), and ? "#d8ecff" : "#fff5c2", and ? "#4a7fb0" : "#a68b22", b.x() + 8, b.y() + 18,
					escape(Captions.of(node)), b.right() - 6, b.y() + 16, escape(node.getLabel())));
		}
		svg.append("</g>\n");
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
		svg.append("<path d=\"").append(path).append("\" fill=\"none\" stroke=\"#333\" marker-end=\"url(#arrow)\"/>");
		if (route.label() != null) {
			Bounds label = route.label();
			svg.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%.0f\" fill=\"#333\" dominant-baseline=\"text-before-edge\">%s</text>",
					label.x() + MARGIN + 2, label.y() + MARGIN + 1, TransitionLayout.LABEL_FONT_SIZE, escape(route.text())));
		}
		svg.append("</g>\n");
	}

	private static String escape(String text) {
		if (text == null) {
			return "";
		}
		return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
	}
}
