package org.kse.labeling;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/**
 * "Labeling Diagram" of the original tool, made total and idempotent (docs/original-kse.md §4).
 * <p>
 * The root is {@code 0}. Inside a composite, START is {@code .1}; the other children
 * follow in the order a breadth-first walk along the transitions from START reaches
 * them, then the children no walk reaches (document order), then END. Children of an
 * AND state (its regions) keep document order. Auxiliary states, and states that were
 * named after their old label or had no name, take their new label as name; transitions
 * are named {@code <source>_TO_<target>}.
 */
public final class Labeler {

	private Labeler() {
	}

	/** Labels the whole model in place. */
	public static void label(Model model) {
		Map<Node, List<Node>> successors = successors(model);
		Deque<Node> work = new ArrayDeque<>();
		List<Node> roots = model.getNodes();
		for (int i = 0; i < roots.size(); i++) {
			relabel(roots.get(i), String.valueOf(i));
			work.add(roots.get(i));
		}
		while (!work.isEmpty()) {
			Node parent = work.poll();
			List<Node> ordered = order(parent, successors);
			for (int i = 0; i < ordered.size(); i++) {
				Node child = ordered.get(i);
				relabel(child, parent.getLabel() + "." + (i + 1));
				work.add(child);
			}
		}
		for (Transition transition : model.getTransitions()) {
			Node source = transition.getSource();
			Node target = transition.getTarget();
			if (source != null && target != null) {
				transition.setName(source.getName() + "_TO_" + target.getName());
			}
		}
	}

	/** The children of a composite in label order. */
	static List<Node> order(Node parent, Map<Node, List<Node>> successors) {
		List<Node> children = parent.getChildren();
		if (NodeKind.AND.is(parent)) {
			return new ArrayList<>(children);
		}
		Node start = children.stream().filter(NodeKind.START::is).findFirst().orElse(null);
		Set<Node> siblings = new HashSet<>(children);
		LinkedHashSet<Node> ordered = new LinkedHashSet<>();
		Deque<Node> frontier = new ArrayDeque<>();
		if (start != null) {
			ordered.add(start);
			frontier.add(start);
		}
		while (!frontier.isEmpty()) {
			for (Node next : successors.getOrDefault(frontier.poll(), List.of())) {
				if (siblings.contains(next) && !NodeKind.END.is(next) && ordered.add(next)) {
					frontier.add(next);
				}
			}
		}
		for (Node child : children) {
			if (!NodeKind.END.is(child)) {
				ordered.add(child);
			}
		}
		ordered.addAll(children); // the END states, last
		return new ArrayList<>(ordered);
	}

	/** Gives a state a new label; a state named after its label (or auxiliary, or unnamed) takes the new label as name. */
	static void relabel(Node node, String label) {
		String oldLabel = node.getLabel();
		String name = node.getName();
		NodeKind kind = NodeKind.of(node);
		boolean namedByLabel = name == null || name.isBlank() || name.equals(oldLabel) || kind != null && kind.isAuxiliary();
		node.setLabel(label);
		if (namedByLabel) {
			node.setName(label);
		}
	}

	private static Map<Node, List<Node>> successors(Model model) {
		Map<Node, List<Node>> successors = new HashMap<>();
		for (Transition transition : model.getTransitions()) {
			if (transition.getSource() != null && transition.getTarget() != null) {
				successors.computeIfAbsent(transition.getSource(), key -> new ArrayList<>()).add(transition.getTarget());
			}
		}
		return successors;
	}
}
