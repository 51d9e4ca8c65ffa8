package org.kse.liveness.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.testing.Issues.describe;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.liveness.FormulaLoader;
import org.kse.testing.ParserFuzz;
import org.kse.testing.Issues;

/**
 * Broken formulas as people write them: every error says in the formula's own words what is
 * wrong, at the line and column where it is, and never in the parser's words ("missing EOF
 * at '~'", "extraneous input", "expecting RULE_ID" and the like).
 */
class FormulaSyntaxMessagesTest {

	/** A broken formula, where its first error is (line:column) and what that error must say. */
	static Stream<Arguments> brokenFormulas() {
		return Stream.of(
				// unbalanced brackets
				broken("a = (B . C", "1:11", "unbalanced '(' at column 5: no matching ')'"),
				broken("a = [B", "1:7", "unbalanced '[' at column 5: no matching ']'"),
				broken("a = ((B)", "1:9", "unbalanced '(' at column 5"),
				broken("a = (", "1:6", "unbalanced '(' at column 5"),
				broken("a = B)", "1:6", "unbalanced ')': no matching '('"),
				broken("a = B.C]", "1:8", "unbalanced ']': no matching '['"),
				broken("a = (B]", "1:7", "']' cannot close the '(' at column 5: close it with ')' first"),
				broken("a = (B|[C)]", "1:10", "')' cannot close the '[' at column 8"),
				broken("Goalie\ngoalie = Init.(playing | nonPlaying+\n", "2:37", "unbalanced '(' at column 15"),
				// dangling and doubled operators
				broken("a = B.", "1:7", "expected an activity or capability name after '.'"),
				broken("a = B ||", "1:9", "expected an activity or capability name after '||'"),
				broken("a\t=\tB\t.\t", "1:9", "expected an activity or capability name after '.'"),
				broken("a = B ..C", "1:8", "expected an activity or capability name between '.' and '.'"),
				broken("a = b\r\nb = C . . D\r\n", "2:9", "between '.' and '.'"),
				broken("a = B || || C", "1:10", "between '||' and '||'"),
				broken("a = [B|]", "1:8", "expected an activity or capability name after '|', before ']'"),
				broken("a = .B", "1:5", "'.' needs a term on its left"),
				broken("a = ~B", "1:5", "'~' must follow a term: write it after an activity, a capability or a bracketed group"),
				broken("a = +B", "1:5", "'+' must follow a term"),
				broken("a = B C", "1:7", "expected an operator between 'B' and 'C': '.' (sequence), '|' (choice) or '||' (parallel)"),
				broken("a = (B)(C)", "1:8", "expected an operator before '('"),
				broken("a = B | | C", "1:12", "if you meant a choice, remove the second '|'"),
				// |x~|n half written
				broken("a = |B~|", "1:9", "|x~|n needs its count: write the number of copies after '~|', as in |B~|3"),
				broken("a = |B~|0", "1:9", "|x~|n needs n of at least 1"),
				broken("a = |B~|99999999999", "1:9", "the count 99999999999 is too large"),
				broken("a = |B|", "1:7", "expected '~|' and a count after '|B', as in |B~|3"),
				broken("a = |B~2", "1:8", "expected '|' and a count after '|B~'"),
				broken("a = |B+~|2", "1:7", "'+' cannot follow the x of |x~|n: put x and '+' in brackets, as in |(B+)~|3"),
				broken("a = |", "1:6", "expected the term to copy after '|'"),
				broken("a = |~|2", "1:6", "'~' must follow a term"),
				// the left side and '='
				broken("a =", "1:1", "'a' has an empty right side"),
				broken("a B", "1:3", "expected '=' after 'a'"),
				broken("my name = B", "1:4", "expected '=' after 'my': a name is one word"),
				broken("a = B\nc", "2:2", "'c' stands alone on its line: write 'c = expression'"),
				broken("= B", "1:1", "'=' needs the name being defined on its left"),
				broken("a = B\n  = C", "2:3", "'=' needs the name being defined on its left"),
				broken("a = B\rc = D\r= E", "3:1", "'=' needs the name being defined on its left"),
				broken("a = B = C", "1:7", "a line holds one definition"),
				broken("a = = B", "1:5", "a line holds one definition"),
				broken("a = 3", "1:5", "'3' is not a name"),
				broken("a = B 3", "1:7", "a number only counts the copies of |x~|n"),
				// characters that are not part of the language
				broken("a = Böse", "1:6", "'ö' (U+00F6) cannot be part of a name"),
				broken("Äpfel = B", "1:1", "'Ä' (U+00C4) cannot be part of a name"),
				broken("a = B $ C", "1:7", "'$' cannot appear in a formula"),
				broken("a = B & C", "1:7", "'&' is not an operator"),
				broken("a = B / C", "1:7", "a comment starts with '//'"),
				broken("a = B\u2003. C", "1:6", "U+2003, a blank or invisible character"),
				broken("a = B\uFEFF", "1:6", "U+FEFF, a blank or invisible character"),
				broken("a = B\uD83D\uDE00", "1:6", "'\uD83D\uDE00' (U+1F600) cannot appear in a formula"),
				broken("a = B\u0007C", "1:6", "U+0007 cannot appear in a formula"),
				broken("a = B\uFFFF", "1:6", "U+FFFF cannot appear in a formula"));
	}

	private static Arguments broken(String text, String firstError, String says) {
		return Arguments.of(ParserFuzz.escape(text), text, firstError, says);
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("brokenFormulas")
	void everyErrorSaysWhatIsWrongAndWhere(String shown, String text, String firstError, String says) {
		FormulaLoader.Result result = FormulaLoader.load(text, URI.createURI("broken.liveness"));
		List<Issue> errors = Issues.errors(result.issues());
		assertFalse(errors.isEmpty(), () -> "no error for " + shown);
		Issue first = errors.get(0);
		assertEquals(firstError, first.getLineNumber() + ":" + first.getColumn(), () -> "first error of " + shown + describe(result.issues()));
		assertTrue(first.getMessage().contains(says), () -> "first error of " + shown + " should say \"" + says + "\"" + describe(result.issues()));
		for (Issue issue : result.issues()) {
			assertNull(Issues.jargonIn(issue.getMessage()), () -> "parser jargon for " + shown + describe(result.issues()));
			assertPositioned(text, issue);
		}
	}

	@Test
	void theCorpusIsVaried() {
		List<Arguments> cases = brokenFormulas().toList();
		assertTrue(cases.size() >= 25, "at least 25 broken formulas, got " + cases.size());
		List<String> texts = new ArrayList<>();
		cases.forEach(arguments -> texts.add((String) arguments.get()[1]));
		assertEquals(texts.size(), texts.stream().distinct().count(), "every broken formula once");
	}

	@Test
	void jargonIsRecognised() {
		// the check above would pass vacuously if it did not know the parser's words
		for (String message : List.of("missing EOF at '~'", "extraneous input 'name' expecting '='", "mismatched input '\\n' expecting '~'",
				"no viable alternative at input '.'", "missing RULE_INT at '\\n'", "unexpected token", "at <EOF>")) {
			assertTrue(Issues.jargonIn(message) != null, message);
		}
		assertNull(Issues.jargonIn("expected an activity or capability name after '.'"));
	}

	/** Line and column at least 1 and where the offset points; offset and length inside the text. */
	private static void assertPositioned(String text, Issue issue) {
		String where = issue.getSeverity() + " '" + issue.getMessage() + "' of " + ParserFuzz.escape(text);
		assertTrue(issue.getLineNumber() != null && issue.getColumn() != null && issue.getOffset() != null && issue.getLength() != null,
				() -> "no position: " + where);
		assertTrue(issue.getLineNumber() >= 1 && issue.getColumn() >= 1, () -> "line or column below 1: " + where);
		assertTrue(issue.getOffset() >= 0 && issue.getOffset() + issue.getLength() <= text.length(), () -> "outside the text: " + where);
		int[] expected = ParserFuzz.lineAndColumn(text, issue.getOffset());
		assertEquals(expected[0] + ":" + expected[1], issue.getLineNumber() + ":" + issue.getColumn(),
				() -> "line and column do not match the offset: " + where);
	}
}
