package org.kse.transform.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.Diagnostic;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.kse.labeling.Labeler;
import org.kse.liveness.validation.LivenessValidator;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.testing.RandomFormulas;
import org.kse.transform.FormulaTransformation;
import org.kse.validation.ModelValidation;
import org.kse.validation.StatechartValidator;

/**
 * Property: any valid formula file transforms into a model that validates with no
 * error, has unique labels, and that Label leaves labeled as it was. The one exception
 * is a root that is only |x~|n: it becomes an AND state as in the original, the formula
 * gets a warning, and the root rule is the model's only error. Formulas are generated
 * from a fixed seed per case, so a failure names a reproducible formula.
 */
class RandomFormulaPropertyTest {

	private static final int CASES = 300;

	@TestFactory
	Stream<DynamicTest> randomValidFormulasGiveValidModels() {
		return IntStream.range(0, CASES).mapToObj(seed -> {
			String formulas = new RandomFormulas(new Random(seed)).file();
			return DynamicTest.dynamicTest("seed " + seed, () -> check(formulas));
		});
	}

	private static void check(String formulas) {
		FormulaTransformation.Outcome outcome = Statecharts.run(formulas);
		assertNotNull(outcome.model(), () -> formulas + "\nrejected: " + outcome.issues());
		Model model = outcome.model();
		boolean andRoot = outcome.issues().stream().anyMatch(issue -> LivenessValidator.AND_ROOT.equals(issue.getCode()));
		assertEquals(andRoot, NodeKind.AND.is(model.getNodes().get(0)), () -> formulas + "\nwarned about an AND root: " + andRoot);
		Diagnostic diagnostic = ModelValidation.validate(model);
		for (Diagnostic child : diagnostic.getChildren()) {
			assertFalse(child.getSeverity() == Diagnostic.ERROR && !(andRoot && child.getCode() == StatechartValidator.ROOT),
					() -> formulas + "\n" + child.getMessage());
		}
		List<Node> nodes = Statecharts.allNodes(model);
		Set<String> labels = new HashSet<>();
		for (Node node : nodes) {
			assertTrue(labels.add(node.getLabel()), () -> formulas + "\nduplicate label " + node.getLabel());
		}
		List<String> before = nodes.stream().map(Node::getLabel).toList();
		Labeler.label(model);
		assertEquals(before, Statecharts.allNodes(model).stream().map(Node::getLabel).toList(),
				() -> formulas + "\nLabel changed the transformation's labels");
	}
}
