package org.kse.ui.formula;

import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.core.resources.IFile;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.handlers.HandlerUtil;
import org.eclipse.ui.ide.IDE;
import org.kse.ui.ModelFiles;

/** "Open Formula": the formula file a statechart was transformed from (same folder and name). */
public class OpenFormulaHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) throws ExecutionException {
		List<IFile> files = ModelFiles.of(event);
		if (files.size() != 1) {
			return null;
		}
		IFile model = files.get(0);
		IFile formula = FormulaFiles.existing(model);
		if (formula != null) {
			try {
				IDE.openEditor(HandlerUtil.getActiveWorkbenchWindowChecked(event).getActivePage(), formula, FormulaEditor.ID);
			} catch (PartInitException e) {
				throw new ExecutionException("cannot open " + formula.getFullPath() + ": " + e.getMessage(), e);
			}
			return null;
		}
		String name = FormulaFiles.baseName(model);
		MessageDialog.openInformation(HandlerUtil.getActiveShellChecked(event), "Open Formula",
				"There is no " + name + ".liveness or " + name + ".txt next to " + model.getName() + ".");
		return null;
	}
}
