package org.kse.xtext.support;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.CancelIndicator;
import org.eclipse.xtext.validation.CheckMode;
import org.eclipse.xtext.validation.IResourceValidator;
import org.eclipse.xtext.validation.Issue;

import com.google.inject.Injector;

/**
 * Parses and validates a text with one of KSE's Xtext languages outside any editor.
 * Every problem comes back as an {@link Issue} with line, column and an offset inside
 * the text; nothing the text contains makes it throw.
 */
public final class TextParsing {

	/** The root element (null when nothing could be read) and every issue. */
	public record Parsed(EObject root, List<Issue> issues) {
		public boolean hasErrors() {
			return issues.stream().anyMatch(issue -> issue.getSeverity() == Severity.ERROR);
		}
	}

	private TextParsing() {
	}

	/**
	 * @param tooDeep the message for input nested beyond what the parser's stack can take
	 */
	public static Parsed parse(Injector injector, URI uri, String text, String tooDeep) {
		return parse(injector.getInstance(XtextResourceSet.class), injector.getInstance(IResourceValidator.class), uri, text, tooDeep);
	}

	private static Parsed parse(XtextResourceSet resourceSet, IResourceValidator validator, URI uri, String text, String tooDeep) {
		XtextResource resource = (XtextResource) resourceSet.createResource(uri);
		try {
			resource.load(new ByteArrayInputStream(terminated(text).getBytes(StandardCharsets.UTF_8)),
					Map.of(XtextResource.OPTION_ENCODING, "UTF-8"));
			List<Issue> issues = new ArrayList<>();
			for (Issue issue : validator.validate(resource, CheckMode.ALL, CancelIndicator.NullImpl)) {
				issues.add(withinText(issue, text.length()));
			}
			return new Parsed(resource.getContents().isEmpty() ? null : resource.getContents().get(0), issues);
		} catch (IOException | RuntimeException | StackOverflowError e) {
			return new Parsed(null, List.of(error(causedByStackOverflow(e) ? tooDeep : "cannot read the text: " + e.getMessage())));
		}
	}

	/**
	 * Parses many texts of one language with one resource set and one validator: for a run that
	 * reads hundreds of short texts (a model's transition expressions), getting both from Guice
	 * for each text costs more than parsing it. Each text's resource leaves the set as soon as it
	 * is validated, so the set does not grow with the texts; what was parsed stays readable, node
	 * model included, as long as the language has no cross-references left to resolve.
	 * <p>
	 * A resource set is not thread-safe, so neither is this: one per run, used by one thread at a
	 * time (a validation, a generation), never a shared singleton.
	 */
	public static final class Parser {
		private final XtextResourceSet resourceSet;
		private final IResourceValidator validator;
		private final URI uri;
		private final String tooDeep;

		/**
		 * @param uri the URI every text is parsed under (issues name it), one text at a time
		 * @param tooDeep as for {@link TextParsing#parse(Injector, URI, String, String)}
		 */
		public Parser(Injector injector, URI uri, String tooDeep) {
			this.resourceSet = injector.getInstance(XtextResourceSet.class);
			this.validator = injector.getInstance(IResourceValidator.class);
			this.uri = uri;
			this.tooDeep = tooDeep;
		}

		/** As {@link TextParsing#parse(Injector, URI, String, String)}, with this parser's resource set and validator. */
		public Parsed parse(String text) {
			try {
				return TextParsing.parse(resourceSet, validator, uri, text, tooDeep);
			} finally {
				resourceSet.getResources().clear();
			}
		}
	}

	/** An error at the start of the text, for what no position can be given to. */
	public static Issue error(String message) {
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

	/** Xtext wraps a parser's StackOverflowError in runtime exceptions. */
	private static boolean causedByStackOverflow(Throwable e) {
		for (Throwable cause = e; cause != null; cause = cause.getCause() == cause ? null : cause.getCause()) {
			if (cause instanceof StackOverflowError) {
				return true;
			}
		}
		return false;
	}
}
