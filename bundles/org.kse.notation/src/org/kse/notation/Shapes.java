package org.kse.notation;

import org.kse.model.NodeKind;
import org.kse.model.statechart.Node;

/**
 * The thesis notation's sizes: START, END and CONDITION at their style's size
 * ({@link NotationStyle}), a rounded box sized to the name for the others.
 */
public final class Shapes {

	private Shapes() {
	}

	/** The size a state is drawn at when nothing else decides it (its position is 0, 0). */
	public static Bounds size(Node node) {
		NotationStyle.Size fixed = NotationStyle.get().of(NodeKind.of(node)).size();
		if (fixed != null) {
			return new Bounds(0, 0, fixed.width(), fixed.height());
		}
		String name = node.getName() == null ? "" : node.getName();
		if (!node.getChildren().isEmpty()) {
			return new Bounds(0, 0, headerWidth(node), Arrange.HEADER);
		}
		return new Bounds(0, 0, Math.max(72, 7.5 * name.length() + 24), 36);
	}

	/** A composite's header holds its caption and its label, in their styles' fonts: at least this wide. */
	public static double headerWidth(Node node) {
		NotationStyle style = NotationStyle.get();
		double caption = TextWidth.of(Captions.of(node), style.headerCaption().size(), style.headerCaption().bold());
		double label = TextWidth.of(node.getLabel() == null ? "" : node.getLabel(), style.label().size(), style.label().bold());
		return caption + label + 40;
	}
}
