package org.kse.expression;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;
import org.kse.expression.transitionExpression.TransitionExpression;

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

	/** Xtext wraps a parser's StackOverflowError in runtime exceptions. */
	private static boolean causedByStackOverflow(Throwable e) {
		for (Throwable cause = e; cause != null; cause = cause.getCause() == cause ? null : cause.getCause()) {
			if (cause instanceof StackOverflowError) {
				return true;
			}
		}
		return false;
	}

	public static Result parse(String text) {
		if (text == null || text.isBlank()) {
			return new Result(null, List.of());
		}
		Injector injector = injector();
		XtextResourceSet resourceSet = injector.getInstance(XtextResourceSet.class);
		XtextResource resource = (XtextResource) resourceSet.createResource(SYNTHETIC_URI);
		try {
			resource.load(new ByteArrayInputStream(terminated(text).getBytes(StandardCharsets.UTF_8)), Map.of(XtextResource.OPTION_ENCODING, "UTF-8"));
			List<Issue> issues = new ArrayList<>();
			for (Issue issue : injector.getInstance(IResourceValidator.class).validate(resource, CheckMode.ALL, CancelIndicator.NullImpl)) {
				issues.add(withinText(issue, text.length()));
			}
			TransitionExpression expression = resource.getContents().isEmpty() ? null
					: (TransitionExpression) resource.getContents().get(0);
			return new Result(expression, issues);
		} catch (IOException | RuntimeException | StackOverflowError e) {
			Issue.IssueImpl issue = new Issue.IssueImpl();
			issue.setSeverity(Severity.ERROR);
			issue.setMessage(causedByStackOverflow(e) ? "parentheses nested too deeply" : String.valueOf(e.getMessage()));
			issue.setLineNumber(1);
			issue.setColumn(1);
			issue.setOffset(0);
			issue.setLength(0);
			return new Result(null, List.of(issue));
		}
	}

	/**
	 * Xtext 2.42 drops (and logs) a syntax error whose end is the last character of a text
	 * without a final line break; a final line break changes no position and avoids it.
	 */
	private static String terminated(String text) {
		return text.endsWith("\n") ? text : text + "\n";
	}

	/** An issue at the end of the text (reported against the added line break) ends at the text's end. */
	private static Issue withinText(Issue issue, int length) {
		if (issue.getOffset() == null || issue.getLength() == null || issue.getOffset() + issue.getLength() <= length) {
			return issue;
		}
		Issue.IssueImpl clamped = new Issue.IssueImpl();
		clamped.setSeverity(issue.getSeverity());
		clamped.setMessage(issue.getMessage());
		clamped.setCode(issue.getCode());
		clamped.setType(issue.getType());
		clamped.setUriToProblem(issue.getUriToProblem());
		clamped.setData(issue.getData());
		clamped.setSyntaxError(issue.isSyntaxError());
		clamped.setLineNumber(issue.getLineNumber());
		clamped.setColumn(issue.getColumn());
		clamped.setLineNumberEnd(issue.getLineNumberEnd());
		clamped.setColumnEnd(issue.getColumnEnd());
		clamped.setOffset(Math.min(issue.getOffset(), length));
		clamped.setLength(Math.max(0, length - clamped.getOffset()));
		return clamped;
	}
}
