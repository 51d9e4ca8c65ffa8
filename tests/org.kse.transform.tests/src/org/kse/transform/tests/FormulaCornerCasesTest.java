package org.kse.transform.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kse.labeling.Labeler;
import org.kse.liveness.validation.LivenessValidator;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.transform.FormulaTransformation;
import org.kse.validation.ModelValidation;

/**
 * Formulas the original tool turned into a model although the first rebuild refused them:
 * chained suffixes, a name defined twice. What a user checks: the model passes the
 * statechart validation of kse validate, and kse label leaves the labels as they were.
 */
class FormulaCornerCasesTest {

	@ParameterizedTest
	@ValueSource(strings = { "a = B+~", "a = |B~|2+", "a = [B]+~", "a = B*+", "a = (B.C)+~", "a = B~+", "a = B**", "a = B++~",
			"a = |B~|3~", "a = |(B|C)~|2* . [D+]~", "a = X . (Y || Z)*+ . W", "a = b+~ | C\nb = |D~|2+", "a = [B.C]*~ || D+*",
			"a = (|B~|2)+~" })
	void chainedSuffixesGiveValidModelsThatLabelAsTheyAre(String formula) {
		FormulaTransformation.Outcome outcome = Statecharts.run(formula);
		assertNotNull(outcome.model(), () -> formula + " rejected: " + outcome.issues());
		assertTrue(outcome.issues().isEmpty(), () -> formula + ": " + outcome.issues());
		Model model = outcome.model();
		assertEquals(List.of(), errors(model), formula);
		assertLabelsStay(formula, model);
	}

	@Test
	void eachSuffixNestsTheStateOfTheOneBefore() {
		Model model = Statecharts.transform("a = X . B+~");
		Node forever = node(model, "0.3");
		assertEquals("OR B_one_or_more_times__forever_", forever.getType() + " " + forever.getName());
		Node oneOrMore = node(model, "0.3.2");
		assertEquals("OR B_one_or_more_times_", oneOrMore.getType() + " " + oneOrMore.getName());
		assertEquals("BASIC B", node(model, "0.3.2.2").getType() + " " + node(model, "0.3.2.2").getName());
		// forever has no END; one-or-more has one
		assertEquals(List.of("START", "OR"), forever.getChildren().stream().map(Node::getType).toList());
		assertEquals(List.of("START", "BASIC", "END"), oneOrMore.getChildren().stream().map(Node::getType).toList());
	}

	@Test
	void aNameDefinedTwiceIsTransformedFromItsLastDefinition() {
		FormulaTransformation.Outcome outcome = Statecharts.run("a = b . b\nb = C\nb = D+");
		assertEquals(List.of(LivenessValidator.REPLACED_DEFINITION), outcome.issues().stream().map(Issue::getCode).toList());
		Model model = outcome.model();
		assertNotNull(model);
		for (String label : List.of("0.2", "0.3")) {
			Node b = node(model, label);
			assertEquals("OR b", b.getType() + " " + b.getName());
			assertEquals("BASIC D", node(model, label + ".2").getType() + " " + node(model, label + ".2").getName());
		}
		assertEquals(List.of(), errors(model));
	}

	private static List<Diagnostic> errors(Model model) {
		return ModelValidation.validate(model).getChildren().stream().filter(d -> d.getSeverity() == Diagnostic.ERROR).toList();
	}

	private static Node node(Model model, String label) {
		return Statecharts.allNodes(model).stream().filter(n -> label.equals(n.getLabel())).findFirst()
				.orElseThrow(() -> new AssertionError("no state " + label + " in\n" + Statecharts.render(model)));
	}

	/** Unique labels, and labeling (once, then again) changes no state's label, type or name. */
	private static void assertLabelsStay(String formula, Model model) {
		Set<String> labels = new HashSet<>();
		for (Node node : Statecharts.allNodes(model)) {
			assertTrue(labels.add(node.getLabel()), () -> formula + ": label " + node.getLabel() + " twice");
		}
		String transformed = Statecharts.render(model);
		Labeler.label(model);
		assertEquals(transformed, Statecharts.render(model), () -> formula + ": labeling changed the model");
		Labeler.label(model);
		assertEquals(transformed, Statecharts.render(model), () -> formula + ": labeling twice changed the model");
	}
}
