package org.kse.languages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Function;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.kse.expression.ExpressionParser;
import org.kse.liveness.FormulaLoader;

/**
 * Whatever a user types, parsing never throws and every error points into the text: line and
 * column at least 1, offset and length inside the text, and line:column the place the offset
 * names; formula messages never use the parser's words. Inputs are random (fixed seeds, so a
 * failure repeats) or truncations of real text.
 */
class FuzzTest {

	private static final int CASES = 2000;

	private static final String[] LIVENESS_TOKENS = { "a", "b", "c", "B", "C", "Init", "goalie", "_x1", "x2y", "0", "3", "12", " ", "  ",
			"\t", "\n", "\n", "\r\n", "\r", ".", ".", "|", "|", "||", "*", "+", "~", "[", "]", "(", ")", "=", "=", " = ", "// note", "/",
			"|B~|2", "~|", "\u00A0" };
	private static final String LIVENESS_CHARS = "abcBC_09 \t\n\r.|*+~[]()=/";

	private static final String[] EXPRESSION_TOKENS = { "ev", "a", "x", "State", "Signal", "Data", "Stat", "worldstate", "behavior",
			"GameStateMessage", "player_state()", "set_x", "(", ")", "TimeoutCheck", "TimeoutAction", "publish", "publish_all",
			"process_messages", "NULL", "PLAYER_PLAYING", "0", "250", "-1", "1.5", "\"s\"", "\"", "\\", ".", ".", ".", "[", "]", "(", ")",
			"/", ";", ",", "!", "<", "<=", ">", ">=", "==", "!=", "&&", "||", "&", "|", "=", " ", " ", "\n", "\t", "\r\n", "\r" };
	private static final String EXPRESSION_CHARS = "aZ_09.[]()/;,!<>=&|\"\\- \n\t\r";

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
	void everyPrefixOfTheGoalieFormulas() {
		checkAll("Goalie formula prefixes", FuzzTest::load, prefixes(LivenessGrammarTest.GOALIE));
	}

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
	 * Brackets nested 5000 deep, parsed on a thread with a small stack so that the parser's
	 * recursion overflows whatever -Xss the build uses: the loaders must turn that into an
	 * error, and parse normally afterwards.
	 */
	@Test
	void deeplyNestedInputIsAnErrorNotACrash() throws InterruptedException {
		int depth = 5000;
		List<String> formulas = List.of( //
				"a = " + "(".repeat(depth) + "B" + ")".repeat(depth), //
				"a = " + "[".repeat(depth) + "B", //
				"a = " + "(".repeat(depth));
		List<String> expressions = List.of( //
				"[" + "(".repeat(depth) + "a" + ")".repeat(depth) + "]", //
				"[" + "!".repeat(depth) + "a]", //
				"[" + "f(".repeat(depth) + "]");
		List<Outcome> outcomes = new ArrayList<>();
		List<Throwable> thrown = new ArrayList<>();
		Thread thread = new Thread(null, () -> {
			try {
				formulas.forEach(text -> outcomes.add(load(text)));
				expressions.forEach(text -> outcomes.add(parse(text)));
			} catch (Throwable t) {
				thrown.add(t);
			}
		}, "small-stack", 256 * 1024);
		thread.start();
		thread.join(60_000);
		assertTrue(!thread.isAlive() && thrown.isEmpty(), () -> "parsing deep nesting threw " + thrown);
		List<String> texts = new ArrayList<>(formulas);
		texts.addAll(expressions);
		for (int i = 0; i < texts.size(); i++) {
			Outcome outcome = outcomes.get(i);
			String text = texts.get(i);
			assertTrue(outcome.hasErrors(), () -> "no error for nesting " + depth + " deep: " + text.substring(0, 20) + "...");
			assertEquals(null, check(text, outcome), text.substring(0, 20));
		}
		// nothing is left broken: ordinary text still parses cleanly afterwards
		assertEquals(List.of(), load("a = (B . C) | D").issues());
		assertEquals(List.of(), parse("[TimeoutCheck(behavior) && a.State.M==NULL]/publish_all").issues());
	}

	// ---------------------------------------------------------------- machinery

	/** {@code inFormulaWords}: the messages must speak of formulas, not of the parser. */
	private record Outcome(boolean hasErrors, boolean hasModel, List<Issue> issues, boolean inFormulaWords) {
	}

	private static Outcome load(String text) {
		FormulaLoader.Result result = FormulaLoader.load(text, URI.createURI("fuzz.liveness"));
		return new Outcome(result.hasErrors(), result.file() != null, result.issues(), true);
	}

	private static Outcome parse(String text) {
		ExpressionParser.Result result = ExpressionParser.parse(text);
		return new Outcome(result.hasErrors(), result.expression() != null || text.isBlank(), result.issues(), false);
	}

	private static void fuzz(String name, Function<String, Outcome> parser, Random random, Function<Random, String> generator) {
		List<String> inputs = new ArrayList<>();
		for (int i = 0; i < CASES; i++) {
			inputs.add(generator.apply(random));
		}
		checkAll(name, parser, inputs);
	}

	private static void checkAll(String name, Function<String, Outcome> parser, List<String> inputs) {
		List<String> failures = new ArrayList<>();
		int withErrors = 0;
		for (String text : inputs) {
			try {
				Outcome outcome = parser.apply(text);
				String problem = check(text, outcome);
				if (problem != null) {
					failures.add(problem + "\n    input: \"" + escape(text) + "\"");
				}
				if (outcome.hasErrors()) {
					withErrors++;
				}
			} catch (Throwable t) {
				failures.add("threw " + t + "\n    input: \"" + escape(text) + "\"");
			}
			if (failures.size() >= 10) {
				break;
			}
		}
		assertEquals(List.of(), failures, name + ": " + failures.size() + " bad results of " + inputs.size());
		// guard against a generator that only produces trivial input
		assertTrue(withErrors > 0 || inputs.size() < 10, name + ": no input had an error, the generator is broken");
	}

	/** Null if every issue is well placed, else what is wrong. */
	private static String check(String text, Outcome outcome) {
		if (!outcome.hasErrors() && !outcome.hasModel()) {
			return "no error, yet no model";
		}
		for (Issue issue : outcome.issues()) {
			String jargon = outcome.inFormulaWords() ? Issues.jargonIn(issue.getMessage()) : null;
			if (jargon != null) {
				return "parser jargon '" + jargon + "' in: " + issue.getMessage();
			}
			if (issue.getSeverity() != Severity.ERROR) {
				continue;
			}
			String where = issue.getCode() + " '" + issue.getMessage() + "' at line " + issue.getLineNumber() + " column "
					+ issue.getColumn() + " offset " + issue.getOffset() + " length " + issue.getLength();
			Integer line = issue.getLineNumber();
			Integer column = issue.getColumn();
			Integer offset = issue.getOffset();
			Integer length = issue.getLength();
			if (line == null || column == null || offset == null || length == null) {
				return "issue without position: " + where;
			}
			if (line < 1 || column < 1) {
				return "line or column below 1: " + where;
			}
			if (offset < 0 || length < 0 || offset > text.length() || offset + length > text.length()) {
				return "outside the text of length " + text.length() + ": " + where;
			}
			int[] expected = lineAndColumn(text, offset);
			if (expected[0] != line || expected[1] != column) {
				return "offset " + offset + " is line " + expected[0] + " column " + expected[1] + ": " + where;
			}
		}
		return null;
	}

	/** 1-based line and column of an offset; "\r\n", "\n" and a lone "\r" each end a line. */
	static int[] lineAndColumn(String text, int offset) {
		int line = 1;
		int lineStart = 0;
		for (int i = 0; i < offset; i++) {
			char c = text.charAt(i);
			if (c == '\n' || c == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n')) {
				line++;
				lineStart = i + 1;
			}
		}
		return new int[] { line, offset - lineStart + 1 };
	}

	private static List<String> prefixes(String text) {
		List<String> result = new ArrayList<>();
		for (int i = 0; i <= text.length(); i++) {
			result.add(text.substring(0, i));
		}
		return result;
	}

	private static String join(Random random, String[] tokens, int count) {
		StringBuilder out = new StringBuilder();
		for (int i = 0; i < count; i++) {
			out.append(tokens[random.nextInt(tokens.length)]);
		}
		return out.toString();
	}

	private static String characters(Random random, String alphabet, int count) {
		StringBuilder out = new StringBuilder();
		for (int i = 0; i < count; i++) {
			out.append(alphabet.charAt(random.nextInt(alphabet.length())));
		}
		return out.toString();
	}

	/** Printable ASCII mixed with control characters, accents, CJK, emoji and lone surrogates. */
	private static String junk(Random random, int count) {
		StringBuilder out = new StringBuilder();
		for (int i = 0; i < count; i++) {
			switch (random.nextInt(8)) {
				case 0 -> out.append((char) random.nextInt(0x20));
				case 1 -> out.append((char) (0xA0 + random.nextInt(0x60)));
				case 2 -> out.append((char) (0x4E00 + random.nextInt(0x100)));
				case 3 -> out.appendCodePoint(0x1F600 + random.nextInt(0x40));
				case 4 -> out.append((char) (0xD800 + random.nextInt(0x800)));
				case 5 -> out.append(random.nextBoolean() ? '\uFEFF' : '\u2028');
				default -> out.append((char) (0x20 + random.nextInt(0x5F)));
			}
		}
		return out.toString();
	}

	static String escape(String text) {
		StringBuilder out = new StringBuilder();
		for (char c : text.toCharArray()) {
			switch (c) {
				case '\n' -> out.append("\\n");
				case '\r' -> out.append("\\r");
				case '\t' -> out.append("\\t");
				case '"' -> out.append("\\\"");
				case '\\' -> out.append("\\\\");
				default -> {
					if (c < 0x20 || c > 0x7E) {
						out.append(String.format("\\u%04X", (int) c));
					} else {
						out.append(c);
					}
				}
			}
		}
		return out.toString();
	}
}
