package org.kse.ui.formula;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.InvocationTargetException;
import java.nio.charset.Charset;
import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.handlers.HandlerUtil;
import org.eclipse.ui.ide.IDE;
import org.kse.formula.StatechartToFormula;
import org.kse.model.StatechartResources;
import org.kse.ui.ModelFiles;

/**
 * "Update Formula from Statechart": the formulas the statechart stands for now (after edits in
 * the diagram), shown against its formula file in a compare viewer, written into the file when
 * the user accepts (docs/how-tos.md, "Recover the formula of a statechart").
 */
public class UpdateFormulaHandler extends AbstractHandler {

	static final String TITLE = "Update Formula from Statechart";

	@Override
	public Object execute(ExecutionEvent event) throws ExecutionException {
		List<IFile> files = ModelFiles.of(event);
		if (files.size() != 1) {
			return null;
		}
		IFile model = files.get(0);
		IFile formula = FormulaFiles.existingOrNew(model);
		Shell shell = HandlerUtil.getActiveShellChecked(event);
		// the recovery reads the files, so unsaved edits in their editors are saved first (the user is asked)
		if (!IDE.saveAllEditors(new IResource[] { model, formula }, true)) {
			return null;
		}
		StatechartToFormula.Result[] recovered = new StatechartToFormula.Result[1];
		String[] current = new String[1];
		try {
			PlatformUI.getWorkbench().getProgressService().busyCursorWhile(monitor -> {
				SubMonitor progress = SubMonitor.convert(monitor, "Recovering the formulas of " + model.getName(), 3);
				try {
					current[0] = formula.exists() ? read(formula) : "";
					progress.worked(1);
					var loaded = StatechartResources.load(ModelFiles.location(model));
					progress.worked(1);
					recovered[0] = StatechartToFormula.recover(loaded);
					progress.worked(1);
				} catch (IOException | CoreException e) {
					throw new InvocationTargetException(e);
				}
			});
		} catch (InvocationTargetException e) {
			MessageDialog.openError(shell, TITLE, model.getFullPath() + ": " + e.getCause().getMessage());
			return null;
		} catch (InterruptedException e) {
			return null;
		}
		new UpdateFormulaDialog(shell, model, formula, current[0], recovered[0]).open();
		return null;
	}

	private static String read(IFile file) throws IOException, CoreException {
		try (InputStream input = file.getContents(true)) {
			return new String(input.readAllBytes(), Charset.forName(file.getCharset()));
		}
	}
}
