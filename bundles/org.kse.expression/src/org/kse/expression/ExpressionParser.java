package org.kse.expression;

import java.util.List;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.expression.transitionExpression.TransitionExpression;
import org.kse.xtext.support.TextParsing;

import com.google.inject.Injector;

/**
 * Parses one transition expression, as found in a model's {@code TE} attribute.
 * Lines and columns of the issues count inside the expression text (1-based).
 */
public final class ExpressionParser {

	/** A parsed expression; {@code expression} is null only when the text is blank. */
	public record Result(TransitionExpression expression, List<Issue> issues) {
		public boolean hasErrors() {
			return issues.stream().anyMatch(issue -> issue.getSeverity() == Severity.ERROR);
		}
	}

	private static final URI SYNTHETIC_URI = URI.createURI("inmemory:/transition.texpr");

	private static final class Holder {
		static final Injector INJECTOR = new TransitionExpressionStandaloneSetup().createInjectorAndDoEMFRegistration();
	}

	private ExpressionParser() {
	}

	public static Injector injector() {
		return Holder.INJECTOR;
	}

	public static Result parse(String text) {
		if (text == null || text.isBlank()) {
			return new Result(null, List.of());
		}
		TextParsing.Parsed parsed = TextParsing.parse(injector(), SYNTHETIC_URI, text, "parentheses nested too deeply");
		return new Result((TransitionExpression) parsed.root(), parsed.issues());
	}
}
