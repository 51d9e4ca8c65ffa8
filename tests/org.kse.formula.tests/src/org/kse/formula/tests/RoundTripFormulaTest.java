package org.kse.formula.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import java.util.stream.IntStream;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.kse.formula.StatechartToFormula;
import org.kse.model.statechart.Model;
import org.kse.testing.RandomFormulas;

/**
 * Formula → statechart → formula → statechart: for every formula of the transformation's
 * tests, the examples, the legacy .txt files and a few hundred random formulas, the formulas
 * recovered from the chart are the ones written (up to blanks, parentheses around a whole right
 * side and capabilities nothing uses), express the whole chart (no problem), and transform into
 * the same chart, state by state and transition by transition, names included.
 */
class RoundTripFormulaTest {

	private static final int RANDOM_CASES = 400;

	@Test
	void theCorpusIsThere() {
		List<String> corpus = RoundTrips.corpus();
		// the transformation's rules, corner cases and Goalie tests, three examples, three legacy models
		assertTrue(corpus.size() >= 45, () -> "only " + corpus.size() + " formulas found: " + corpus);
		assertTrue(corpus.contains("a = |B~|2+"), "the rules' cases are read from their source");
		assertTrue(corpus.stream().anyMatch(formulas -> formulas.startsWith("Goalie\ngoalie = Init.")), "the legacy and example formulas");
		// only the corner cases' formulas with errors make no chart (their tests check the message)
		assertTrue(corpus.stream().filter(formulas -> RoundTrips.run(formulas).model() == null).count() <= 5, "formulas without a chart");
	}

	@TestFactory
	Stream<DynamicTest> everyFormulaOfTheCorpusComesBack() {
		List<String> corpus = RoundTrips.corpus();
		return IntStream.range(0, corpus.size()).mapToObj(i -> DynamicTest.dynamicTest(i + ": " + corpus.get(i).replace("\n", "; "), () -> {
			// a few corner cases are formulas with errors (their test checks the message): no chart to invert
			if (RoundTrips.run(corpus.get(i)).model() != null) {
				roundTrip(corpus.get(i));
			}
		}));
	}

	@TestFactory
	Stream<DynamicTest> randomFormulasComeBack() {
		return IntStream.range(0, RANDOM_CASES).mapToObj(seed -> {
			String formulas = new RandomFormulas(new Random(seed)).file();
			return DynamicTest.dynamicTest("seed " + seed, () -> roundTrip(formulas));
		});
	}

	@Test
	void aParallelOfOneCapabilityTwiceIsNotTakenForItsCopies() {
		// B||B and |B~|2 differ only in the AND state's place and name: the names tell them apart
		roundTrip("a = X.(b || b)\nb = C.D");
		roundTrip("a = X.|b~|2\nb = C.D");
		roundTrip("a = b\nb = |C~|2");
		roundTrip("a = ((X.Y))+.(([Z]))");
	}

	static void roundTrip(String formulas) {
		Model chart = RoundTrips.transform(formulas);
		StatechartToFormula.Result recovered = StatechartToFormula.recover(chart);
		assertEquals(List.of(), recovered.problems(), () -> formulas + "\nrecovered:\n" + recovered.fileText());
		assertEquals(RoundTrips.normalize(formulas), RoundTrips.normalize(recovered.fileText()), () -> formulas + "\nrecovered:\n" + recovered.fileText());
		Model again = RoundTrips.transform(recovered.fileText());
		assertEquals(RoundTrips.render(chart), RoundTrips.render(again), () -> formulas + "\nrecovered:\n" + recovered.fileText());
	}
}
