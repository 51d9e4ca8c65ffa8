package org.kse.ui.formula;


import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.WorkspaceJob;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.handlers.HandlerUtil;

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
		IFile model = FormulaTransformer.modelOf(formula);
		if (model.exists() && !MessageDialog.openQuestion(editor.getSite().getShell(), "Transform to Statechart",
				model.getName() + " exists already. Replace it with the statechart of these formulas?\n\n"
						+ "Its layout and any edits made to it since it was transformed are lost.")) {
			return null;
		}
		String text = editor.getText();
		WorkspaceJob job = new WorkspaceJob("Transforming " + formula.getName()) {
			@Override
			public IStatus runInWorkspace(IProgressMonitor monitor) throws CoreException {
				return FormulaTransformer.transform(formula, text, model, monitor);
			}
		};
		job.setRule(formula.getParent());
		job.setUser(true);
		job.schedule();
		return null;
	}
}
