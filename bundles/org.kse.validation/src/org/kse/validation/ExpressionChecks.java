package org.kse.validation;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.expression.ExpressionParser;
import org.kse.expression.transitionExpression.Event;
import org.kse.expression.transitionExpression.TransitionExpressionPackage.Literals;
import org.kse.messages.MessageCatalog;

/**
 * One transition expression checked on its own, as an editor checks it while it is typed: the
 * grammar, then (when it parses) that it has no event (the engine has none to raise), and topics,
 * message types and fields against a message catalog.
 * The same checks as the statechart validator's, with positions inside the expression.
 */
public final class ExpressionChecks {

	/** Whether the grammar, the message catalog, or what the engine can run found it. */
	public enum Kind {
		SYNTAX, CATALOG, UNSUPPORTED
	}

	/**
	 * What is wrong, where: line and column from 1, offset from 0 in the expression; a SYNTAX
	 * problem carries the parser's issue.
	 */
	public record Problem(Kind kind, boolean error, int line, int column, int offset, String message, Issue issue) {
		@Override
		public String toString() {
			return line + ":" + column + ": " + message;
		}
	}

	private ExpressionChecks() {
	}

	public static List<Problem> check(String expression, MessageCatalog catalog) {
		return check(expression, new MessageChecks(catalog, MessageCatalog.standardTopics()), null);
	}

	/**
	 * With the message checks the statechart validator keeps for a whole model, and the parse
	 * session of its run (null: parsed on its own).
	 */
	static List<Problem> check(String expression, MessageChecks messages, ExpressionParser.Session session) {
		String text = expression == null ? "" : expression;
		List<Problem> problems = new ArrayList<>();
		ExpressionParser.Result parsed = session == null ? ExpressionParser.parse(text) : session.parse(text);
		for (Issue issue : parsed.issues()) {
			if (issue.getSeverity() == Severity.ERROR || issue.getSeverity() == Severity.WARNING) {
				int line = issue.getLineNumber() == null ? 1 : issue.getLineNumber();
				int column = issue.getColumn() == null ? 1 : issue.getColumn();
				problems.add(new Problem(Kind.SYNTAX, issue.getSeverity() == Severity.ERROR, line, column, offset(text, line, column), issue.getMessage(),
						issue));
			}
		}
		if (parsed.expression() != null && !parsed.hasErrors()) {
			Event event = parsed.expression().getEvent();
			if (event != null) {
				MessageChecks.Problem problem = MessageChecks.at(event, Literals.EVENT__NAME, text, eventMessage(event.getName()));
				problems.add(new Problem(Kind.UNSUPPORTED, true, problem.line(), problem.column(), offset(text, problem.line(), problem.column()),
						problem.message(), null));
			}
			for (MessageChecks.Problem problem : messages.check(parsed.expression(), text)) {
				problems.add(new Problem(Kind.CATALOG, true, problem.line(), problem.column(), offset(text, problem.line(), problem.column()),
						problem.message(), null));
			}
		}
		return problems;
	}

	/**
	 * The original tool generated an event as an object the engine never raised, so a transition
	 * with one silently never fired; saying so here keeps a migrated model from doing the same.
	 */
	private static String eventMessage(String name) {
		return "events are not supported: the engine never raises '" + name + "', so this transition would never fire (as in the"
				+ " original KSE); say in the condition what to wait for instead, as in [behavior.Signal.FallMessage.fall()!=0]";
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
