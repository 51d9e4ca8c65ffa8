package org.kse.transform.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.xtext.diagnostics.Severity;
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
import org.kse.validation.StatechartValidator;

/**
 * Formulas the original tool turned into a model although the first rebuild refused or
 * changed them: chained suffixes, a root that is only |x~|n, a name defined twice. What a
 * user checks: the model passes (or, for the AND root, fails exactly as warned) the
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

	/**
	 * The original made the root of a lone |x~|n its AND state; so do we, warned at the formula.
	 * Our statechart rules want an OR root, so validation then reports exactly that, and
	 * nothing else.
	 */
	@Test
	void aRootThatIsOnlyReplicationIsTheAndStateAsInTheOriginal() {
		FormulaTransformation.Outcome outcome = Statecharts.run("team = |Player~|3");
		Issue warning = outcome.issues().stream().filter(issue -> LivenessValidator.AND_ROOT.equals(issue.getCode())).findFirst()
				.orElseThrow(() -> new AssertionError("no warning about the AND root: " + outcome.issues()));
		assertEquals(Severity.WARNING, warning.getSeverity());
		assertEquals("1:8", warning.getLineNumber() + ":" + warning.getColumn());
		Model model = outcome.model();
		assertNotNull(model, "a warning does not stop the transformation");

		Node root = model.getNodes().get(0);
		assertEquals("0 AND team", root.getLabel() + " " + root.getType() + " " + root.getName());
		assertEquals(List.of("0.1", "0.2", "0.3"), root.getChildren().stream().map(Node::getLabel).toList());
		for (Node region : root.getChildren()) {
			assertEquals("OR", region.getType());
			assertEquals(List.of("START", "BASIC Player", "END"),
					region.getChildren().stream().map(n -> n.getType() + (n.getType().equals("BASIC") ? " " + n.getName() : "")).toList());
		}
		assertEquals(6, model.getTransitions().size());

		List<Diagnostic> errors = errors(model);
		assertEquals(1, errors.size(), () -> "only the root rule is broken: " + errors);
		assertEquals(StatechartValidator.ROOT, errors.get(0).getCode());
		assertTrue(errors.get(0).getMessage().contains("must be an OR state, not AND"), errors.get(0).getMessage());
		assertLabelsStay("team = |Player~|3", model);
	}

	@Test
	void theWarningsWayToAnOrRootGivesAValidModel() {
		FormulaTransformation.Outcome outcome = Statecharts.run("team = teamCopies\nteamCopies = |Player~|3");
		assertTrue(outcome.issues().isEmpty(), () -> outcome.issues().toString());
		Model model = outcome.model();
		assertEquals(List.of(), errors(model));
		assertEquals("OR", model.getNodes().get(0).getType());
		Node copies = node(model, "0.2");
		assertEquals("AND teamCopies", copies.getType() + " " + copies.getName());
		assertEquals(3, copies.getChildren().size());
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
