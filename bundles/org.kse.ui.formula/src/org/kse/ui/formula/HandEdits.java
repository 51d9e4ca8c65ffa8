package org.kse.ui.formula;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;

/**
 * What a model holds that a fresh transform of its formulas would not: guards and actions, variables,
 * activities, and states added, renamed or removed by hand. Auxiliary states (named by their label,
 * such as {@code 0.2.1}) and transition names follow the labeling, so they are left out: comparing
 * them would list every renumbering as an edit.
 */
public final class HandEdits {

	private static final Pattern AUXILIARY = Pattern.compile("[0-9.]*");
	private static final int SHOWN_EXPRESSION = 70;

	private HandEdits() {
	}

	/** One line per edit of {@code existing} that replacing it by {@code fresh} would lose, in model order. */
	public static List<String> lostBy(Model existing, Model fresh) {
		List<String> lost = new ArrayList<>();
		Set<String> freshExpressions = new LinkedHashSet<>();
		for (Transition transition : fresh.getTransitions()) {
			if (!blank(transition.getTE())) {
				freshExpressions.add(normalized(transition.getTE()));
			}
		}
		for (Transition transition : existing.getTransitions()) {
			if (!blank(transition.getTE()) && !freshExpressions.contains(normalized(transition.getTE()))) {
				lost.add("the guard or action of " + describe(transition) + ": " + shortened(normalized(transition.getTE())));
			}
		}
		Set<String> freshVariables = new LinkedHashSet<>();
		fresh.getVariables().forEach(variable -> freshVariables.add(variable.getName() + ":" + variable.getType()));
		for (Variable variable : existing.getVariables()) {
			if (!freshVariables.contains(variable.getName() + ":" + variable.getType())) {
				lost.add("the variable " + variable.getName() + (blank(variable.getType()) ? "" : " (" + variable.getType() + ")"));
			}
		}
		Map<String, Node> freshStates = namedStates(fresh);
		Map<String, Node> existingStates = namedStates(existing);
		for (Node state : existingStates.values()) {
			Node counterpart = freshStates.get(state.getName());
			if (counterpart == null) {
				lost.add("the state " + state.getName() + " (added or renamed by hand)");
			} else if (!blank(state.getActivity()) && !state.getActivity().equals(counterpart.getActivity())) {
				lost.add("the activity of " + state.getName() + ": " + state.getActivity());
			}
		}
		for (String name : freshStates.keySet()) {
			if (!existingStates.containsKey(name)) {
				lost.add("the removal of the state " + name + " (the formulas bring it back)");
			}
		}
		return lost;
	}

	/** The states named by the formulas or by hand, in model order. */
	private static Map<String, Node> namedStates(Model model) {
		Map<String, Node> states = new LinkedHashMap<>();
		for (var contents = model.eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && !blank(node.getName()) && !AUXILIARY.matcher(node.getName()).matches()) {
				states.putIfAbsent(node.getName(), node);
			}
		}
		return states;
	}

	private static String describe(Transition transition) {
		String source = transition.getSource() == null ? "?" : transition.getSource().getName();
		String target = transition.getTarget() == null ? "?" : transition.getTarget().getName();
		return source + " \u2192 " + target;
	}

	private static String normalized(String expression) {
		return expression.strip().replaceAll("\\s+", " ");
	}

	private static String shortened(String expression) {
		return expression.length() <= SHOWN_EXPRESSION ? expression : expression.substring(0, SHOWN_EXPRESSION - 1) + "\u2026";
	}

	private static boolean blank(String text) {
		return text == null || text.isBlank();
	}
}
