package org.kse.labeling;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;

/**
 * Copy and paste of states, the original tool's own feature: the copied states come with
 * everything inside them, the transitions between those, and the variables they read. Pasted
 * states take the next free labels of the state they are pasted into, their insides are
 * relabelled below them in the same order, and states and transitions named after labels are
 * renamed, so that labels stay unique and ordered. Pasting the same copy twice gives two
 * independent sets of states.
 */
public final class Copies {

	/** What was copied: detached copies, independent of the model they came from. */
	public static final class Fragment {
		private final List<Node> states;
		private final List<Transition> transitions;
		private final List<Variable> variables;

		private Fragment(List<Node> states, List<Transition> transitions, List<Variable> variables) {
			this.states = states;
			this.transitions = transitions;
			this.variables = variables;
		}

		public List<Node> states() {
			return List.copyOf(states);
		}

		public int transitionCount() {
			return transitions.size();
		}
	}

	/** The new elements of one paste, not yet in the model: add them to the container and the model. */
	public record Pasted(EObject container, List<Node> states, List<Transition> transitions, List<Variable> variables) {
	}

	private Copies() {
	}

	/** Copies the selected states (a state inside another selected state goes with it). */
	public static Fragment copy(Model model, Collection<Node> selected) {
		List<Node> topMost = selected.stream().filter(node -> !hasAncestorIn(node, selected)).distinct().toList();
		Set<Node> inside = new HashSet<>();
		for (Node node : topMost) {
			inside.add(node);
			node.eAllContents().forEachRemaining(each -> {
				if (each instanceof Node child) {
					inside.add(child);
				}
			});
		}
		List<Transition> transitions = model.getTransitions().stream()
				.filter(t -> inside.contains(t.getSource()) && inside.contains(t.getTarget())).toList();
		Set<Variable> variables = new LinkedHashSet<>();
		inside.forEach(node -> variables.addAll(node.getVariables()));
		return detached(topMost, transitions, new ArrayList<>(variables));
	}

	private static Fragment detached(List<Node> states, List<Transition> transitions, List<Variable> variables) {
		EcoreUtil.Copier copier = new EcoreUtil.Copier();
		List<Variable> copiedVariables = variables.stream().map(variable -> (Variable) copier.copy(variable)).toList();
		List<Node> copiedStates = states.stream().map(state -> (Node) copier.copy(state)).toList();
		List<Transition> copiedTransitions = transitions.stream().map(transition -> (Transition) copier.copy(transition)).toList();
		copier.copyReferences();
		return new Fragment(new ArrayList<>(copiedStates), new ArrayList<>(copiedTransitions), new ArrayList<>(copiedVariables));
	}

	private static boolean hasAncestorIn(Node node, Collection<Node> set) {
		for (EObject container = node.eContainer(); container != null; container = container.eContainer()) {
			if (set.contains(container)) {
				return true;
			}
		}
		return false;
	}

	/**
	 * The elements one paste of the fragment adds into {@code container} (a state, or the model
	 * for top-level states): relabelled after the container's children; variables the model has
	 * already (same name and type) are used instead of copies, others are added (renamed when
	 * their name is taken by another type).
	 */
	public static Pasted prepare(Fragment fragment, Model model, EObject container) {
		Fragment fresh = detached(fragment.states, fragment.transitions, fragment.variables);
		Map<Node, String> oldNames = new HashMap<>();
		for (Node state : fresh.states) {
			oldNames.put(state, state.getName());
			state.eAllContents().forEachRemaining(each -> {
				if (each instanceof Node inner) {
					oldNames.put(inner, inner.getName());
				}
			});
		}
		List<Node> siblings = container instanceof Node parent ? parent.getChildren() : model.getNodes();
		String prefix = container instanceof Node parent ? parent.getLabel() + "." : "";
		int next = nextNumber(siblings, prefix, container instanceof Node ? 1 : 0);
		for (Node state : fresh.states) {
			relabelTree(state, prefix + next++);
		}
		for (Transition transition : fresh.transitions) {
			Node source = transition.getSource();
			Node target = transition.getTarget();
			if (Objects.equals(transition.getName(), oldNames.get(source) + "_TO_" + oldNames.get(target))) {
				transition.setName(source.getName() + "_TO_" + target.getName());
			}
		}
		List<Variable> added = new ArrayList<>();
		for (Variable variable : fresh.variables) {
			Variable existing = model.getVariables().stream()
					.filter(each -> Objects.equals(each.getName(), variable.getName()) && Objects.equals(each.getType(), variable.getType())).findFirst()
					.orElse(null);
			if (existing != null) {
				redirect(fresh.states, variable, existing);
				continue;
			}
			String name = variable.getName();
			for (int suffix = 2; taken(model, added, name); suffix++) {
				name = variable.getName() + "_" + suffix;
			}
			variable.setName(name);
			added.add(variable);
		}
		return new Pasted(container, fresh.states, fresh.transitions, added);
	}

	private static boolean taken(Model model, List<Variable> added, String name) {
		return model.getVariables().stream().anyMatch(each -> name.equals(each.getName())) || added.stream().anyMatch(each -> name.equals(each.getName()));
	}

	private static void redirect(List<Node> states, Variable copy, Variable existing) {
		for (Node state : states) {
			replace(state, copy, existing);
			state.eAllContents().forEachRemaining(each -> {
				if (each instanceof Node inner) {
					replace(inner, copy, existing);
				}
			});
		}
	}

	private static void replace(Node node, Variable copy, Variable existing) {
		int index = node.getVariables().indexOf(copy);
		if (index >= 0) {
			node.getVariables().set(index, existing);
		}
	}

	/** The first number after every child's last label part (children labelled otherwise count by position). */
	private static int nextNumber(List<Node> siblings, String prefix, int first) {
		int next = Math.max(first, siblings.size() + first);
		for (Node sibling : siblings) {
			String label = sibling.getLabel();
			if (label != null && label.startsWith(prefix) && label.substring(prefix.length()).matches("\\d+")) {
				next = Math.max(next, Integer.parseInt(label.substring(prefix.length())) + 1);
			}
		}
		return next;
	}

	/** A pasted state's new label, its insides below it in their old order. */
	private static void relabelTree(Node state, String label) {
		String oldLabel = state.getLabel();
		Labeler.relabel(state, label);
		List<Node> children = state.getChildren();
		for (int i = 0; i < children.size(); i++) {
			Node child = children.get(i);
			String old = child.getLabel();
			String suffix = old != null && oldLabel != null && old.startsWith(oldLabel + ".") ? old.substring(oldLabel.length()) : "." + (i + 1);
			relabelTree(child, label + suffix);
		}
	}
}
