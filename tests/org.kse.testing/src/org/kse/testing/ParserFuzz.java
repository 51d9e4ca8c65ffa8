package org.kse.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Function;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;

/**
 * Fuzzing an Xtext language: random inputs (from a seeded {@link Random}, so a failure repeats)
 * and truncations of real text, fed to a parser; whatever the input, parsing never throws and
 * every error points into the text: line and column at least 1, offset and length inside the
 * text, and line:column the place the offset names. Used by the fuzz tests of the liveness and
 * the expression language.
 */
public final class ParserFuzz {

	/** How many random inputs {@link #fuzz} tries. */
	public static final int CASES = 2000;

	/**
	 * What parsing one input gave. {@code inFormulaWords}: the messages must speak of the
	 * language, never of the parser ({@link Issues#jargonIn}).
	 */
	public record Outcome(boolean hasErrors, boolean hasModel, List<Issue> issues, boolean inFormulaWords) {
	}

	private ParserFuzz() {
	}

	/** Parses {@link #CASES} inputs of the generator and checks every outcome. */
	public static void fuzz(String name, Function<String, Outcome> parser, Random random, Function<Random, String> generator) {
		List<String> inputs = new ArrayList<>();
		for (int i = 0; i < CASES; i++) {
			inputs.add(generator.apply(random));
		}
		checkAll(name, parser, inputs);
	}

	/** Parses every input and checks every outcome; also fails if no input at all had an error. */
	public static void checkAll(String name, Function<String, Outcome> parser, List<String> inputs) {
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
	public static String check(String text, Outcome outcome) {
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

	/**
	 * Parses the texts, in order, on a thread with a small stack (256 KiB), so that a parser's
	 * recursion over deep nesting overflows whatever -Xss the build uses; fails if parsing threw
	 * or did not end within a minute.
	 */
	public static List<Outcome> parseOnSmallStack(Function<String, Outcome> parser, List<String> texts) throws InterruptedException {
		List<Outcome> outcomes = new ArrayList<>();
		List<Throwable> thrown = new ArrayList<>();
		Thread thread = new Thread(null, () -> {
			try {
				texts.forEach(text -> outcomes.add(parser.apply(text)));
			} catch (Throwable t) {
				thrown.add(t);
			}
		}, "small-stack", 256 * 1024);
		thread.start();
		thread.join(60_000);
		assertTrue(!thread.isAlive() && thrown.isEmpty(), () -> "parsing deep nesting threw " + thrown);
		return outcomes;
	}

	/** 1-based line and column of an offset; "\r\n", "\n" and a lone "\r" each end a line. */
	public static int[] lineAndColumn(String text, int offset) {
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

	/** Every prefix of the text, from the empty one to the whole text. */
	public static List<String> prefixes(String text) {
		List<String> result = new ArrayList<>();
		for (int i = 0; i <= text.length(); i++) {
			result.add(text.substring(0, i));
		}
		return result;
	}

	/** {@code count} tokens drawn at random, joined without separator. */
	public static String join(Random random, String[] tokens, int count) {
		StringBuilder out = new StringBuilder();
		for (int i = 0; i < count; i++) {
			out.append(tokens[random.nextInt(tokens.length)]);
		}
		return out.toString();
	}

	/** {@code count} characters drawn at random from the alphabet. */
	public static String characters(Random random, String alphabet, int count) {
		StringBuilder out = new StringBuilder();
		for (int i = 0; i < count; i++) {
			out.append(alphabet.charAt(random.nextInt(alphabet.length())));
		}
		return out.toString();
	}

	/** Printable ASCII mixed with control characters, accents, CJK, emoji and lone surrogates. */
	public static String junk(Random random, int count) {
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

	/** The text as a Java string literal's content: line breaks, tabs, quotes and non-ASCII escaped. */
	public static String escape(String text) {
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
