package org.kse.ui.formula;

import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IWorkspace;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.emf.common.util.URI;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IRegion;
import org.eclipse.jface.text.reconciler.DirtyRegion;
import org.eclipse.jface.text.reconciler.IReconcilingStrategy;
import org.eclipse.jface.text.reconciler.IReconcilingStrategyExtension;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.liveness.FormulaLoader;

/**
 * Checks the formulas whenever typing pauses and shows what is wrong as problem markers on the
 * file (Problems view, ruler, squiggles); they follow the text, saved or not. A file is also
 * checked when it opens: the reconciler checks at once only a strategy with the extension.
 */
class FormulaChecker implements IReconcilingStrategy, IReconcilingStrategyExtension {

	static final String MARKER = "org.kse.ui.formulaProblem";

	private final FormulaEditor editor;
	private IDocument document;

	FormulaChecker(FormulaEditor editor) {
		this.editor = editor;
	}

	@Override
	public void setDocument(IDocument document) {
		this.document = document;
	}

	@Override
	public void reconcile(DirtyRegion dirtyRegion, IRegion subRegion) {
		check();
	}

	@Override
	public void reconcile(IRegion partition) {
		check();
	}

	@Override
	public void initialReconcile() {
		check();
	}

	@Override
	public void setProgressMonitor(IProgressMonitor monitor) {
		// a check takes milliseconds: nothing to cancel
	}

	private void check() {
		IFile file = editor.getFile();
		if (document == null || file == null) {
			return;
		}
		String text = document.get();
		List<Issue> issues = FormulaLoader.load(text, URI.createPlatformResourceURI(file.getFullPath().toString(), true)).issues();
		show(file, issues, text.length());
		editor.textChecked();
	}

	/** Replaces the file's formula markers by these issues. */
	static void show(IFile file, List<Issue> issues, int textLength) {
		try {
			file.getWorkspace().run(monitor -> {
				if (!file.exists()) {
					return;
				}
				file.deleteMarkers(MARKER, false, 0);
				for (Issue issue : issues) {
					int start = issue.getOffset() == null ? 0 : Math.min(issue.getOffset(), textLength);
					int length = issue.getLength() == null ? 0 : issue.getLength();
					// all attributes at once: a reader never sees a marker half made
					file.createMarker(MARKER, Map.of(IMarker.MESSAGE, issue.getMessage(), IMarker.SEVERITY, severity(issue.getSeverity()),
							IMarker.LINE_NUMBER, issue.getLineNumber() == null ? 1 : issue.getLineNumber(), IMarker.CHAR_START, start,
							IMarker.CHAR_END, Math.min(textLength, start + Math.max(1, length)), IMarker.LOCATION,
							"line " + issue.getLineNumber() + ", column " + issue.getColumn()));
				}
			}, file, IWorkspace.AVOID_UPDATE, null);
		} catch (CoreException e) {
			ILog.of(FormulaChecker.class).error("cannot show the problems of " + file.getFullPath(), e);
		}
	}

	private static int severity(Severity severity) {
		return switch (severity) {
			case ERROR -> IMarker.SEVERITY_ERROR;
			case WARNING -> IMarker.SEVERITY_WARNING;
			default -> IMarker.SEVERITY_INFO;
		};
	}
}
