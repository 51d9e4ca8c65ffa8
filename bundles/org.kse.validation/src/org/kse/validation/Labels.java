package org.kse.validation;

import org.eclipse.emf.ecore.EObject;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;

/** How diagnostics name a model element: by label and name, as a user sees it. */
public final class Labels {

	private Labels() {
	}

	public static String describe(EObject element) {
		if (element instanceof Node node) {
			return text(node.getLabel(), "(no label)") + " (" + text(node.getName(), "unnamed") + ")";
		}
		if (element instanceof Transition transition) {
			return end(transition.getSource()) + "->" + end(transition.getTarget()) + " (" + text(transition.getName(), "unnamed") + ")";
		}
		if (element instanceof Variable variable) {
			return "variable (" + text(variable.getName(), "unnamed") + ")";
		}
		if (element instanceof Model model) {
			return "model (" + text(model.getName(), "unnamed") + ")";
		}
		return String.valueOf(element);
	}

	private static String end(Node node) {
		return node == null ? "?" : text(node.getLabel(), text(node.getName(), "?"));
	}

	private static String text(String value, String fallback) {
		return value == null || value.isEmpty() ? fallback : value;
	}
}
