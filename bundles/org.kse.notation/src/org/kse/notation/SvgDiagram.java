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
		double width = MARGIN;
		double height = MARGIN;
		for (Bounds bounds : placed.values()) {
			width = Math.max(width, bounds.right() + MARGIN);
			height = Math.max(height, bounds.bottom() + MARGIN);
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
		for (Transition transition : model.getTransitions()) {
			Bounds source = placed.get(transition.getSource());
			Bounds target = placed.get(transition.getTarget());
			if (source != null && target != null) {
				transition(svg, transition, source, target);
			}
		}
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
					+ "<text x=\"%.1f\" y=\"%.1f\" font-weight=\"bold\">%s</text><text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\" fill=\"#666\" font-size=\"10\">%s</text>",
					b.x(), b.y(), b.width(), b.height(), and ? "#d8ecff" : "#fff5c2", and ? "#4a7fb0" : "#a68b22", b.x() + 8, b.y() + 18,
					escape(node.getName()), b.right() - 6, b.y() + 16, escape(node.getLabel())));
		}
		svg.append("</g>\n");
	}

	private static void transition(StringBuilder svg, Transition transition, Bounds source, Bounds target) {
		String expression = transition.getTE() == null ? "" : transition.getTE().strip();
		String firstLine = expression.lines().findFirst().orElse("").strip();
		if (expression.lines().count() > 1) {
			firstLine += " …";
		}
		svg.append("<g class=\"transition\"><title>").append(escape(transition.getName()))
				.append(expression.isEmpty() ? "" : ": " + escape(expression)).append("</title>");
		double labelX;
		double labelY;
		if (source == target) {
			double x = source.right() - Math.min(12, source.width() / 4);
			double y = source.y();
			svg.append(String.format(Locale.ROOT, "<path d=\"M%.1f,%.1f C%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"none\" stroke=\"#333\" marker-end=\"url(#arrow)\"/>",
					x - 10, y, x - 10, y - 28, source.right() + 24, y + 4, source.right(), y + Math.min(14, source.height() / 2)));
			labelX = source.right() + 4;
			labelY = y - 16;
		} else {
			double[] from = border(source, target.x() + target.width() / 2, target.y() + target.height() / 2);
			double[] to = border(target, source.x() + source.width() / 2, source.y() + source.height() / 2);
			svg.append(String.format(Locale.ROOT, "<path d=\"M%.1f,%.1f L%.1f,%.1f\" fill=\"none\" stroke=\"#333\" marker-end=\"url(#arrow)\"/>", from[0],
					from[1], to[0], to[1]));
			labelX = (from[0] + to[0]) / 2 + 4;
			labelY = (from[1] + to[1]) / 2 - 4;
		}
		if (!firstLine.isEmpty()) {
			svg.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" fill=\"#333\">%s</text>", labelX, labelY, escape(firstLine)));
		}
		svg.append("</g>\n");
	}

	/** Where the line from the centre of a box towards a point leaves the box. */
	private static double[] border(Bounds box, double towardX, double towardY) {
		double cx = box.x() + box.width() / 2;
		double cy = box.y() + box.height() / 2;
		double dx = towardX - cx;
		double dy = towardY - cy;
		if (dx == 0 && dy == 0) {
			return new double[] { cx, cy };
		}
		double scale = 1 / Math.max(Math.abs(dx) / (box.width() / 2), Math.abs(dy) / (box.height() / 2));
		return new double[] { cx + dx * scale, cy + dy * scale };
	}

	private static String escape(String text) {
		if (text == null) {
			return "";
		}
		return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
	}
}
