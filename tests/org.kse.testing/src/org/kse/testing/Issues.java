package org.kse.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;

/** Assertions over Xtext issues (of the liveness and expression languages), with messages that show every issue of the text. */
public final class Issues {

	/** The code Xtext gives to every syntax error. */
	public static final String SYNTAX = "org.eclipse.xtext.diagnostics.Diagnostic.Syntax";

	/** Words of the parser generator that mean nothing to someone writing formulas. */
	private static final Pattern PARSER_JARGON = Pattern.compile(
			"missing EOF|extraneous input|mismatched (input|character)|no viable alternative|expecting|RULE_|EOF|token|required \\(\\.\\.\\.\\)\\+ loop",
			Pattern.CASE_INSENSITIVE);

	private Issues() {
	}

	/** The first piece of parser jargon in a message, or null when it has none. */
	public static String jargonIn(String message) {
		Matcher matcher = PARSER_JARGON.matcher(message == null ? "" : message);
		return matcher.find() ? matcher.group() : null;
	}

	/** One line per issue: "ERROR 2:7 code message". */
	public static String describe(List<Issue> issues) {
		if (issues.isEmpty()) {
			return "(no issues)";
		}
		return issues.stream()
				.map(issue -> issue.getSeverity() + " " + issue.getLineNumber() + ":" + issue.getColumn() + " " + issue.getCode() + " "
						+ issue.getMessage())
				.collect(Collectors.joining("\n  ", "\n  ", ""));
	}

	public static List<Issue> withSeverity(List<Issue> issues, Severity severity) {
		return issues.stream().filter(issue -> issue.getSeverity() == severity).toList();
	}

	public static List<Issue> errors(List<Issue> issues) {
		return withSeverity(issues, Severity.ERROR);
	}

	public static void assertNoIssues(String text, List<Issue> issues) {
		assertTrue(issues.isEmpty(), () -> "expected no issues for\n" + text + "\nbut got" + describe(issues));
	}

	public static void assertNoErrors(String text, List<Issue> issues) {
		assertTrue(errors(issues).isEmpty(), () -> "expected no errors for\n" + text + "\nbut got" + describe(issues));
	}

	/**
	 * Asserts that exactly one issue of this severity and code exists, at the given line and
	 * column (1-based), and returns it.
	 */
	public static Issue assertIssue(List<Issue> issues, Severity severity, String code, int line, int column) {
		List<Issue> matching = issues.stream().filter(issue -> issue.getSeverity() == severity && code.equals(issue.getCode())).toList();
		assertEquals(1, matching.size(), () -> "expected exactly one " + severity + " " + code + ", got" + describe(issues));
		Issue issue = matching.get(0);
		assertEquals(line + ":" + column, issue.getLineNumber() + ":" + issue.getColumn(),
				() -> "position of " + severity + " " + code + " (line:column); all issues:" + describe(issues));
		return issue;
	}

	/** Asserts that the only error is one with this code at the given line and column. */
	public static Issue assertOnlyError(List<Issue> issues, String code, int line, int column) {
		assertEquals(1, errors(issues).size(), () -> "expected exactly one error, got" + describe(issues));
		return assertIssue(issues, Severity.ERROR, code, line, column);
	}
}
