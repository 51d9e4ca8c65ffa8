package org.kse.expression.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.testing.ParserFuzz.characters;
import static org.kse.testing.ParserFuzz.checkAll;
import static org.kse.testing.ParserFuzz.escape;
import static org.kse.testing.ParserFuzz.fuzz;
import static org.kse.testing.ParserFuzz.join;
import static org.kse.testing.ParserFuzz.junk;
import static org.kse.testing.ParserFuzz.prefixes;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.kse.expression.ExpressionParser;
import org.kse.testing.ParserFuzz;
import org.kse.testing.ParserFuzz.Outcome;

/**
 * Whatever a user types as a transition expression, parsing never throws and every error
 * points into the text: line and column at least 1, offset and length inside the text, and
 * line:column the place the offset names. Inputs are random (fixed seeds, so a failure
 * repeats) or truncations of real text.
 */
class FuzzTest {

	private static final String[] EXPRESSION_TOKENS = { "ev", "a", "x", "State", "Signal", "Data", "Stat", "worldstate", "behavior",
			"GameStateMessage", "player_state()", "set_x", "(", ")", "TimeoutCheck", "TimeoutAction", "publish", "publish_all",
			"process_messages", "NULL", "PLAYER_PLAYING", "0", "250", "-1", "1.5", "\"s\"", "\"", "\\", ".", ".", ".", "[", "]", "(", ")",
			"/", ";", ",", "!", "<", "<=", ">", ">=", "==", "!=", "&&", "||", "&", "|", "=", " ", " ", "\n", "\t", "\r\n", "\r" };
	private static final String EXPRESSION_CHARS = "aZ_09.[]()/;,!<>=&|\"\\- \n\t\r";

	// ---------------------------------------------------------------- random input

	@Test
	void randomExpressionTokens() {
		fuzz("expression tokens", FuzzTest::parse, new Random(2001), random -> join(random, EXPRESSION_TOKENS, 1 + random.nextInt(40)));
	}

	@Test
	void randomExpressionCharacters() {
		fuzz("expression characters", FuzzTest::parse, new Random(2002),
				random -> characters(random, EXPRESSION_CHARS, random.nextInt(60)));
	}

	@Test
	void randomExpressionJunk() {
		fuzz("expression junk", FuzzTest::parse, new Random(2003), random -> junk(random, random.nextInt(60)));
	}

	// ---------------------------------------------------------------- truncated real text

	@Test
	void everyPrefixOfEveryLegacyExpression() {
		List<String> inputs = new ArrayList<>();
		for (String text : Legacy.goalieTransitionExpressions()) {
			inputs.addAll(prefixes(text));
		}
		assertTrue(inputs.size() > 1000, "the legacy model should give over a thousand prefixes, got " + inputs.size());
		checkAll("legacy expression prefixes", FuzzTest::parse, inputs);
	}

	@Test
	void truncatedExpressionsThatStillNeedTextAreErrors() {
		// a prefix ending inside '[...' or after '/' is not a complete expression
		for (String text : Legacy.goalieTransitionExpressions()) {
			int close = text.indexOf(']');
			if (close > 0) {
				String open = text.substring(0, close);
				assertTrue(ExpressionParser.parse(open).hasErrors(), () -> "no error for unclosed " + escape(open));
			}
			int slash = text.indexOf('/');
			if (slash >= 0) {
				String cut = text.substring(0, slash + 1);
				assertTrue(ExpressionParser.parse(cut).hasErrors(), () -> "no error for action-less " + escape(cut));
			}
		}
	}

	// ---------------------------------------------------------------- pathological nesting

	/**
	 * Brackets and negations nested 5000 deep, parsed on a thread with a small stack so that the
	 * parser's recursion overflows whatever -Xss the build uses: the parser must turn that into
	 * an error, and parse normally afterwards.
	 */
	@Test
	void deeplyNestedInputIsAnErrorNotACrash() throws InterruptedException {
		int depth = 5000;
		List<String> expressions = List.of( //
				"[" + "(".repeat(depth) + "a" + ")".repeat(depth) + "]", //
				"[" + "!".repeat(depth) + "a]", //
				"[" + "f(".repeat(depth) + "]");
		List<Outcome> outcomes = ParserFuzz.parseOnSmallStack(FuzzTest::parse, expressions);
		for (int i = 0; i < expressions.size(); i++) {
			Outcome outcome = outcomes.get(i);
			String text = expressions.get(i);
			assertTrue(outcome.hasErrors(), () -> "no error for nesting " + depth + " deep: " + text.substring(0, 20) + "...");
			assertEquals(null, ParserFuzz.check(text, outcome), text.substring(0, 20));
		}
		// nothing is left broken: ordinary text still parses cleanly afterwards
		assertEquals(List.of(), parse("[TimeoutCheck(behavior) && a.State.M==NULL]/publish_all").issues());
	}

	// ---------------------------------------------------------------- machinery

	/** Expression messages are not held to the formula language's wording. */
	private static Outcome parse(String text) {
		ExpressionParser.Result result = ExpressionParser.parse(text);
		return new Outcome(result.hasErrors(), result.expression() != null || text.isBlank(), result.issues(), false);
	}
}
