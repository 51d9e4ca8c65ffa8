package org.kse.ui.formula;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.transform.FormulaTransformation;

/** Formulas of a workspace file (or of an editor's text) into a statechart file, with problem markers. */
public final class FormulaTransformer {

	private FormulaTransformer() {
	}

	/** The statechart file that belongs to a formula file: same folder, same name, .stct. */
	public static IFile modelOf(IFile formula) {
		return formula.getParent().getFile(org.eclipse.core.runtime.Path.fromPortableString(
				formula.getFullPath().removeFileExtension().lastSegment() + "." + StatechartResources.FILE_EXTENSION));
	}

	public static String read(IFile file) throws CoreException {
		try (InputStream in = file.getContents()) {
			ByteArrayOutputStream bytes = new ByteArrayOutputStream();
			in.transferTo(bytes);
			String charset = file.getCharset();
			return bytes.toString(charset == null ? StandardCharsets.UTF_8 : java.nio.charset.Charset.forName(charset));
		} catch (IOException e) {
			throw new CoreException(Status.error("cannot read " + file.getFullPath() + ": " + e.getMessage(), e));
		}
	}

	/** The formulas of {@code text} (the formula file's content) transformed; their problems shown as markers on the file. */
	public static FormulaTransformation.Outcome outcome(IFile formula, String text, IProgressMonitor monitor) {
		SubMonitor progress = SubMonitor.convert(monitor, "Transforming " + formula.getName(), 1);
		FormulaTransformation.Outcome outcome = FormulaTransformation.run(text, URI.createPlatformResourceURI(formula.getFullPath().toString(), true),
				null);
		progress.worked(1);
		FormulaChecker.show(formula, outcome.issues(), text.length());
		return outcome;
	}

	/** Why an outcome has no statechart, naming the first error (for a status line or a wizard page). */
	public static String problem(IFile formula, FormulaTransformation.Outcome outcome) {
		long errors = outcome.issues().stream().filter(issue -> issue.getSeverity() == Severity.ERROR).count();
		Issue first = outcome.issues().stream().filter(issue -> issue.getSeverity() == Severity.ERROR).findFirst().orElse(null);
		return formula.getName() + " has " + errors + (errors == 1 ? " error" : " errors")
				+ (first == null ? "" : "; the first, at line " + first.getLineNumber() + ", column " + first.getColumn() + ": " + first.getMessage())
				+ ". See the Problems view.";
	}

	/** Writes a transformed statechart to {@code target} (atomically) and lets the workspace see it. */
	public static void write(Model statechart, IFile target) throws IOException, CoreException {
		StatechartResources.save(statechart, Path.of(target.getLocationURI()));
		target.refreshLocal(IResource.DEPTH_ZERO, null);
	}
}
