package org.kse.diagram.server;

import java.util.IdentityHashMap;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.notation.Bounds;
import org.kse.notation.Notation;
import org.kse.notation.Shapes;

/**
 * Where the states of an open diagram are, keyed by the states themselves: paths in the file
 * change as states are added and removed, the states do not, so an undone delete finds its
 * bounds again. Positions are relative to the parent state, as in the notation file.
 */
public final class DiagramLayout {

	private final Map<Node, Bounds> bounds = new IdentityHashMap<>();

	public static DiagramLayout of(Model model, Notation notation) {
		DiagramLayout layout = new DiagramLayout();
		for (var contents = model.eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node) {
				Bounds placed = notation.get(node);
				if (placed != null) {
					layout.bounds.put(node, placed);
				}
			}
		}
		return layout;
	}

	/** The state's bounds; a state never placed is drawn at its natural size at the parent's origin. */
	public Bounds get(Node node) {
		Bounds placed = bounds.get(node);
		return placed != null ? placed : Shapes.size(node);
	}

	/** The bounds the state was given, or null. */
	public Bounds placed(Node node) {
		return bounds.get(node);
	}

	/** Sets (or with null removes) a state's bounds; returns what it had. */
	public Bounds put(Node node, Bounds newBounds) {
		return newBounds == null ? bounds.remove(node) : bounds.put(node, newBounds);
	}

	/** The top-left corner of a state, or of the diagram (0, 0) for the model, in diagram coordinates. */
	public double[] absolute(EObject element) {
		double x = 0;
		double y = 0;
		for (EObject each = element; each instanceof Node node; each = node.eContainer()) {
			Bounds b = get(node);
			x += b.x();
			y += b.y();
		}
		return new double[] { x, y };
	}

	/** Room left between a composite's border and the states it holds, when it grows to hold them. */
	public static final double MARGIN = 12;

	/**
	 * The composites that must grow so that {@code owner} holds states placed at {@code placed}
	 * (relative to it), and so on up: each with its new bounds. Composites only grow, to the right
	 * and down, so that nothing else moves; empty when everything fits.
	 */
	public Map<Node, Bounds> grownToHold(EObject owner, java.util.Collection<Bounds> placed) {
		Map<Node, Bounds> grown = new java.util.LinkedHashMap<>();
		java.util.Collection<Bounds> inside = placed;
		for (EObject each = owner; each instanceof Node composite; each = composite.eContainer()) {
			Bounds current = get(composite);
			double width = current.width();
			double height = current.height();
			for (Bounds child : inside) {
				width = Math.max(width, child.x() + child.width() + MARGIN);
				height = Math.max(height, child.y() + child.height() + MARGIN);
			}
			if (width == current.width() && height == current.height()) {
				break;
			}
			Bounds larger = new Bounds(current.x(), current.y(), width, height);
			grown.put(composite, larger);
			inside = java.util.List.of(larger);
		}
		return grown;
	}

	/** The layout as a notation file holds it: every state of the model, keyed by its path now. */
	public Notation toNotation(Model model) {
		Notation notation = new Notation();
		for (var contents = model.eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node) {
				notation.put(node, get(node));
			}
		}
		return notation;
	}
}
