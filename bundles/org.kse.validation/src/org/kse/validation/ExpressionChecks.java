package org.kse.validation;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.expression.ExpressionParser;
import org.kse.messages.MessageCatalog;

/**
 * One transition expression checked on its own, as an editor checks it while it is typed: the
 * grammar, then (when it parses) topics, message types and fields against a message catalog.
 * The same checks as the statechart validator's, with positions inside the expression.
 */
public final class ExpressionChecks {

	/** What is wrong, where: line and column from 1, offset from 0 in the expression. */
	public record Problem(boolean error, int line, int column, int offset, String message) {
		@Override
		public String toString() {
			return line + ":" + column + ": " + message;
		}
	}

	private ExpressionChecks() {
	}

	public static List<Problem> check(String expression, MessageCatalog catalog) {
		String text = expression == null ? "" : expression;
		List<Problem> problems = new ArrayList<>();
		ExpressionParser.Result parsed = ExpressionParser.parse(text);
		for (Issue issue : parsed.issues()) {
			if (issue.getSeverity() == Severity.ERROR || issue.getSeverity() == Severity.WARNING) {
				int line = issue.getLineNumber() == null ? 1 : issue.getLineNumber();
				int column = issue.getColumn() == null ? 1 : issue.getColumn();
				problems.add(new Problem(issue.getSeverity() == Severity.ERROR, line, column, offset(text, line, column), issue.getMessage()));
			}
		}
		if (parsed.expression() != null && !parsed.hasErrors()) {
			for (MessageChecks.Problem problem : new MessageChecks(catalog, MessageCatalog.standardTopics()).check(parsed.expression(), text)) {
				problems.add(new Problem(true, problem.line(), problem.column(), offset(text, problem.line(), problem.column()), problem.message()));
			}
		}
		return problems;
	}

	private static int offset(String text, int line, int column) {
		int offset = 0;
		for (int current = 1; current < line && offset < text.length(); offset++) {
			if (text.charAt(offset) == '\n') {
				current++;
			}
		}
		return Math.min(text.length(), offset + column - 1);
	}
}
