package org.kse.notation;

import org.kse.model.NodeKind;
import org.kse.model.statechart.Node;

/** The thesis' notation sizes: small discs for START, END and CONDITION, a rounded box sized to the name for the others. */
public final class Shapes {

	private Shapes() {
	}

	/** The size a state is drawn at when nothing else decides it (its position is 0, 0). */
	public static Bounds size(Node node) {
		NodeKind kind = NodeKind.of(node);
		if (kind == NodeKind.START) {
			return new Bounds(0, 0, 20, 20);
		}
		if (kind == NodeKind.END) {
			return new Bounds(0, 0, 24, 24);
		}
		if (kind == NodeKind.CONDITION) {
			return new Bounds(0, 0, 28, 28);
		}
		String name = node.getName() == null ? "" : node.getName();
		if (!node.getChildren().isEmpty()) {
			return new Bounds(0, 0, headerWidth(node), Arrange.HEADER);
		}
		return new Bounds(0, 0, Math.max(72, 7.5 * name.length() + 24), 36);
	}

	/** A composite's header holds its caption (bold) and its label: at least this wide. */
	public static double headerWidth(Node node) {
		double caption = TextWidth.of(Captions.of(node), 12, true);
		double label = TextWidth.of(node.getLabel() == null ? "" : node.getLabel(), 11, false);
		return caption + label + 40;
	}
}
