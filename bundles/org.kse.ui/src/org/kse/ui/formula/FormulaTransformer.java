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
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.model.StatechartResources;
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

	/** Transforms {@code text} (the formula file's content) into {@code model}; an error status names the first problem. */
	public static IStatus transform(IFile formula, String text, IFile model, IProgressMonitor monitor) throws CoreException {
		SubMonitor progress = SubMonitor.convert(monitor, "Transforming " + formula.getName(), 3);
		progress.subTask("reading the formulas");
		FormulaTransformation.Outcome outcome = FormulaTransformation.run(text, URI.createPlatformResourceURI(formula.getFullPath().toString(), true),
				null);
		progress.worked(2);
		FormulaChecker.show(formula, outcome.issues(), text.length());
		if (outcome.model() == null) {
			long errors = outcome.issues().stream().filter(issue -> issue.getSeverity() == Severity.ERROR).count();
			Issue first = outcome.issues().stream().filter(issue -> issue.getSeverity() == Severity.ERROR).findFirst().orElse(null);
			return Status.error(formula.getName() + " has " + errors + (errors == 1 ? " error" : " errors")
					+ (first == null ? "" : "; the first, at line " + first.getLineNumber() + ", column " + first.getColumn() + ": " + first.getMessage())
					+ ". See the Problems view.");
		}
		progress.subTask("writing " + model.getName());
		try {
			StatechartResources.save(outcome.model(), Path.of(model.getLocationURI()));
		} catch (IOException e) {
			return Status.error("cannot write " + model.getFullPath() + ": " + e.getMessage(), e);
		}
		model.refreshLocal(IResource.DEPTH_ZERO, progress.split(1));
		return Status.OK_STATUS;
	}
}
