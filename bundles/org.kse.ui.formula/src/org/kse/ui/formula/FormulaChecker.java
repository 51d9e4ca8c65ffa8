package org.kse.ui.formula;

import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.emf.common.util.URI;
import org.eclipse.jface.text.IDocument;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.liveness.FormulaLoader;
import org.kse.ui.text.ProblemMarkers;
import org.kse.ui.text.TextChecker;

/**
 * Checks the formulas when the file opens and whenever typing pauses, and shows what is wrong
 * as problem markers on the file; they follow the text, saved or not.
 */
class FormulaChecker extends TextChecker {

	static final String MARKER = "org.kse.ui.formulaProblem";

	private final FormulaEditor editor;

	FormulaChecker(FormulaEditor editor) {
		this.editor = editor;
	}

	@Override
	protected void check(IDocument document) {
		IFile file = editor.getFile();
		if (file == null) {
			return;
		}
		String text = document.get();
		List<Issue> issues = FormulaLoader.load(text, URI.createPlatformResourceURI(file.getFullPath().toString(), true)).issues();
		show(file, issues, text.length());
		editor.textChecked();
	}

	/** Replaces the file's formula markers by these issues. */
	static void show(IFile file, List<Issue> issues, int textLength) {
		ProblemMarkers.replace(file, MARKER, issues.stream().map(issue -> {
			int start = issue.getOffset() == null ? 0 : Math.min(issue.getOffset(), textLength);
			int length = issue.getLength() == null ? 0 : issue.getLength();
			return new ProblemMarkers.Problem(issue.getMessage(), severity(issue.getSeverity()), issue.getLineNumber() == null ? 1 : issue.getLineNumber(),
					issue.getColumn() == null ? 1 : issue.getColumn(), start, Math.min(textLength, start + Math.max(1, length)));
		}).toList());
	}

	private static int severity(Severity severity) {
		return switch (severity) {
			case ERROR -> IMarker.SEVERITY_ERROR;
			case WARNING -> IMarker.SEVERITY_WARNING;
			default -> IMarker.SEVERITY_INFO;
		};
	}
}
