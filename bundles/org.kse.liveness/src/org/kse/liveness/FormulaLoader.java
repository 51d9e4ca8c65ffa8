package org.kse.liveness;

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
import org.kse.liveness.liveness.FormulaFile;

import com.google.inject.Injector;

/**
 * Parses and validates formula text outside any editor. Every problem comes back as
 * an {@link Issue} with line and column; nothing the text contains makes it throw.
 */
public final class FormulaLoader {

	/** A parsed formula file and everything wrong with it. */
	public record Result(FormulaFile file, List<Issue> issues) {
		public boolean hasErrors() {
			return issues.stream().anyMatch(issue -> issue.getSeverity() == Severity.ERROR);
		}
	}

	private static final class Holder {
		static final Injector INJECTOR = new LivenessStandaloneSetup().createInjectorAndDoEMFRegistration();
	}

	public static Injector injector() {
		return Holder.INJECTOR;
	}

	private FormulaLoader() {
	}

	/** Parses {@code text} as if read from {@code uri} (the URI only names it in messages). */
	public static Result load(String text, URI uri) {
		Injector injector = injector();
		XtextResourceSet resourceSet = injector.getInstance(XtextResourceSet.class);
		XtextResource resource = (XtextResource) resourceSet.createResource(uri.fileExtension() == null
				|| !List.of("liveness", "txt").contains(uri.fileExtension()) ? uri.appendFileExtension("liveness") : uri);
		try {
			resource.load(new ByteArrayInputStream(terminated(text).getBytes(StandardCharsets.UTF_8)), Map.of(XtextResource.OPTION_ENCODING, "UTF-8"));
			List<Issue> issues = new ArrayList<>();
			for (Issue issue : injector.getInstance(IResourceValidator.class).validate(resource, CheckMode.ALL, CancelIndicator.NullImpl)) {
				issues.add(withinText(issue, text.length()));
			}
			FormulaFile file = resource.getContents().isEmpty() ? null : (FormulaFile) resource.getContents().get(0);
			return new Result(file, issues);
		} catch (IOException | RuntimeException | StackOverflowError e) {
			// Only pathological input (thousands of nested brackets) gets here.
			return new Result(null, List.of(issue("cannot read the formulas: " + describe(e))));
		}
	}

	private static String describe(Throwable e) {
		return causedByStackOverflow(e) ? "brackets nested too deeply" : String.valueOf(e.getMessage());
	}

	/** Xtext wraps a parser's StackOverflowError in runtime exceptions. */
	static boolean causedByStackOverflow(Throwable e) {
		for (Throwable cause = e; cause != null; cause = cause.getCause() == cause ? null : cause.getCause()) {
			if (cause instanceof StackOverflowError) {
				return true;
			}
		}
		return false;
	}

	private static Issue issue(String message) {
		Issue.IssueImpl issue = new Issue.IssueImpl();
		issue.setSeverity(Severity.ERROR);
		issue.setMessage(message);
		issue.setLineNumber(1);
		issue.setColumn(1);
		issue.setOffset(0);
		issue.setLength(0);
		return issue;
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
