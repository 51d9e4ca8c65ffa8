package org.kse.expression;

import java.util.HashMap;
import java.util.List;
import java.util.Map;

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
	private static final String TOO_DEEP = "parentheses nested too deeply";
	private static final Result BLANK = new Result(null, List.of());

	private static final class Holder {
		static final Injector INJECTOR = new TransitionExpressionStandaloneSetup().createInjectorAndDoEMFRegistration();
	}

	private ExpressionParser() {
	}

	public static Injector injector() {
		return Holder.INJECTOR;
	}

	/** One expression on its own (an editor's field); a run over a whole model uses a {@link #session()}. */
	public static Result parse(String text) {
		if (text == null || text.isBlank()) {
			return BLANK;
		}
		TextParsing.Parsed parsed = TextParsing.parse(injector(), SYNTHETIC_URI, text, TOO_DEEP);
		return new Result((TransitionExpression) parsed.root(), parsed.issues());
	}

	/** A new session: for one run over a model's expressions (a validation, a generation), then dropped. */
	public static Session session() {
		return new Session();
	}

	/**
	 * Parses the expressions of one run each once: one resource set and validator for the whole
	 * run instead of one per expression, and every text parsed the first time it is asked for,
	 * its result handed out again to whoever asks next (the validation, then the generation plan;
	 * the transitions of a model that share a text). The results give the same issues as
	 * {@link ExpressionParser#parse(String)}; what they hold is shared, so read it, never change it.
	 * <p>
	 * Holds every result until it is dropped: make one per run, never keep one in a field that
	 * outlives it. Callers on several threads each make their own (a resource set is not
	 * thread-safe); {@link #parse} is synchronized only so that a stray shared one stays correct.
	 */
	public static final class Session {
		private final TextParsing.Parser parser = new TextParsing.Parser(injector(), SYNTHETIC_URI, TOO_DEEP);
		private final Map<String, Result> results = new HashMap<>();

		private Session() {
		}

		public synchronized Result parse(String text) {
			if (text == null || text.isBlank()) {
				return BLANK;
			}
			Result result = results.get(text);
			if (result == null) {
				TextParsing.Parsed parsed = parser.parse(text);
				result = new Result((TransitionExpression) parsed.root(), List.copyOf(parsed.issues()));
				results.put(text, result);
			}
			return result;
		}

		/** How many different texts this session has parsed. */
		public synchronized int parsed() {
			return results.size();
		}
	}
}
