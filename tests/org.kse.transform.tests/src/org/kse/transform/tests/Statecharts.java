package org.kse.transform.tests;

import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;

import org.eclipse.emf.common.util.URI;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.transform.FormulaTransformation;

/** Test helpers: transform formula text, and render a model as text a person can compare. */
final class Statecharts {

	private Statecharts() {
	}

	static FormulaTransformation.Outcome run(String formulas) {
		return FormulaTransformation.run(formulas, URI.createURI("test.liveness"), null);
	}

	static Model transform(String formulas) {
		FormulaTransformation.Outcome outcome = run(formulas);
		assertNotNull(outcome.model(), () -> "formulas rejected: " + outcome.issues());
		return outcome.model();
	}

	/**
	 * One line per state in document order ("label TYPE" plus the name when it is not the
	 * label), then one line per transition ("source->target" by label), sorted.
	 */
	static String render(Model model) {
		List<String> lines = new ArrayList<>();
		for (Node root : model.getNodes()) {
			states(root, lines);
		}
		TreeSet<String> transitions = new TreeSet<>();
		for (Transition transition : model.getTransitions()) {
			transitions.add(transition.getSource().getLabel() + "->" + transition.getTarget().getLabel());
		}
		lines.addAll(transitions);
		return String.join("\n", lines);
	}

	private static void states(Node node, List<String> lines) {
		String line = node.getLabel() + " " + node.getType();
		if (!node.getLabel().equals(node.getName())) {
			line += " " + node.getName();
		}
		lines.add(line);
		for (Node child : node.getChildren()) {
			states(child, lines);
		}
	}

	static List<Node> allNodes(Model model) {
		List<Node> nodes = new ArrayList<>();
		model.eAllContents().forEachRemaining(element -> {
			if (element instanceof Node node) {
				nodes.add(node);
			}
		});
		return nodes;
	}
}
