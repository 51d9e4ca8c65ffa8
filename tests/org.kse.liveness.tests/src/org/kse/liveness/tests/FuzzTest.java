package org.kse.liveness.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.testing.ParserFuzz.characters;
import static org.kse.testing.ParserFuzz.checkAll;
import static org.kse.testing.ParserFuzz.fuzz;
import static org.kse.testing.ParserFuzz.join;
import static org.kse.testing.ParserFuzz.junk;
import static org.kse.testing.ParserFuzz.prefixes;

import java.util.List;
import java.util.Random;

import org.eclipse.emf.common.util.URI;
import org.junit.jupiter.api.Test;
import org.kse.liveness.FormulaLoader;
import org.kse.testing.ParserFuzz;
import org.kse.testing.ParserFuzz.Outcome;

/**
 * Whatever a user types as a formula, loading never throws and every error points into the
 * text: line and column at least 1, offset and length inside the text, and line:column the
 * place the offset names; the messages never use the parser's words. Inputs are random (fixed
 * seeds, so a failure repeats) or truncations of real text.
 */
class FuzzTest {

	private static final String[] LIVENESS_TOKENS = { "a", "b", "c", "B", "C", "Init", "goalie", "_x1", "x2y", "0", "3", "12", " ", "  ",
			"\t", "\n", "\n", "\r\n", "\r", ".", ".", "|", "|", "||", "*", "+", "~", "[", "]", "(", ")", "=", "=", " = ", "// note", "/",
			"|B~|2", "~|", "\u00A0" };
	private static final String LIVENESS_CHARS = "abcBC_09 \t\n\r.|*+~[]()=/";

	// ---------------------------------------------------------------- random input

	@Test
	void randomFormulaTokens() {
		fuzz("liveness tokens", FuzzTest::load, new Random(1001), random -> join(random, LIVENESS_TOKENS, 1 + random.nextInt(40)));
	}

	@Test
	void randomFormulaCharacters() {
		fuzz("liveness characters", FuzzTest::load, new Random(1002), random -> characters(random, LIVENESS_CHARS, random.nextInt(60)));
	}

	@Test
	void randomFormulaJunk() {
		fuzz("liveness junk", FuzzTest::load, new Random(1003), random -> junk(random, random.nextInt(60)));
	}

	// ---------------------------------------------------------------- truncated real text

	@Test
	void everyPrefixOfTheGoalieFormulas() {
		checkAll("Goalie formula prefixes", FuzzTest::load, prefixes(LivenessGrammarTest.GOALIE));
	}

	// ---------------------------------------------------------------- pathological nesting

	/**
	 * Brackets nested 5000 deep, loaded on a thread with a small stack so that the parser's
	 * recursion overflows whatever -Xss the build uses: the loader must turn that into an error,
	 * and load normally afterwards.
	 */
	@Test
	void deeplyNestedInputIsAnErrorNotACrash() throws InterruptedException {
		int depth = 5000;
		List<String> formulas = List.of( //
				"a = " + "(".repeat(depth) + "B" + ")".repeat(depth), //
				"a = " + "[".repeat(depth) + "B", //
				"a = " + "(".repeat(depth));
		List<Outcome> outcomes = ParserFuzz.parseOnSmallStack(FuzzTest::load, formulas);
		for (int i = 0; i < formulas.size(); i++) {
			Outcome outcome = outcomes.get(i);
			String text = formulas.get(i);
			assertTrue(outcome.hasErrors(), () -> "no error for nesting " + depth + " deep: " + text.substring(0, 20) + "...");
			assertEquals(null, ParserFuzz.check(text, outcome), text.substring(0, 20));
		}
		// nothing is left broken: ordinary text still loads cleanly afterwards
		assertEquals(List.of(), load("a = (B . C) | D").issues());
	}

	// ---------------------------------------------------------------- machinery

	/** Formula messages must speak of formulas, not of the parser. */
	private static Outcome load(String text) {
		FormulaLoader.Result result = FormulaLoader.load(text, URI.createURI("fuzz.liveness"));
		return new Outcome(result.hasErrors(), result.file() != null, result.issues(), true);
	}
}
