package org.kse.ui.formula;

import java.io.IOException;
import java.nio.file.Path;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.WorkspaceJob;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.emf.common.util.URI;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.handlers.HandlerUtil;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.model.StatechartResources;
import org.kse.transform.FormulaTransformation;

/**
 * "Transform to Statechart": the formulas of the active editor become {@code <name>.stct} next
 * to the formula file, in a job with progress; an existing model is replaced only when the user agrees.
 */
public class TransformHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) {
		IEditorPart part = HandlerUtil.getActiveEditor(event);
		if (!(part instanceof FormulaEditor editor) || editor.getFile() == null) {
			return null;
		}
		IFile formula = editor.getFile();
		IFile model = formula.getParent().getFile(org.eclipse.core.runtime.Path.fromPortableString(
				formula.getFullPath().removeFileExtension().lastSegment() + "." + StatechartResources.FILE_EXTENSION));
		if (model.exists() && !MessageDialog.openQuestion(editor.getSite().getShell(), "Transform to Statechart",
				model.getName() + " exists already. Replace it with the statechart of these formulas?\n\n"
						+ "Its layout and any edits made to it since it was transformed are lost.")) {
			return null;
		}
		String text = editor.getText();
		WorkspaceJob job = new WorkspaceJob("Transforming " + formula.getName()) {
			@Override
			public IStatus runInWorkspace(IProgressMonitor monitor) throws CoreException {
				SubMonitor progress = SubMonitor.convert(monitor, "Transforming " + formula.getName(), 3);
				progress.subTask("reading the formulas");
				FormulaTransformation.Outcome outcome = FormulaTransformation.run(text,
						URI.createPlatformResourceURI(formula.getFullPath().toString(), true), null);
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
		};
		job.setRule(formula.getParent());
		job.setUser(true);
		job.schedule();
		return null;
	}
}
