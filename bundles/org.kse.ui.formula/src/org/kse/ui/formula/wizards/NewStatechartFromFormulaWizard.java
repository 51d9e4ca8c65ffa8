package org.kse.ui.formula.wizards;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IAdaptable;
import org.eclipse.core.runtime.IPath;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.layout.GridLayoutFactory;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.wizard.Wizard;
import org.eclipse.jface.wizard.WizardPage;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.INewWizard;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.dialogs.ResourceListSelectionDialog;
import org.eclipse.ui.wizards.newresource.BasicNewResourceWizard;
import org.kse.transform.FormulaTransformation;
import org.kse.ui.formula.FormulaTransformer;
import org.kse.ui.formula.TransformHandler;

/** The thesis' first step: a statechart from a formula file, written next to it. */
public class NewStatechartFromFormulaWizard extends Wizard implements INewWizard {

	private IWorkbench workbench;
	private IFile initial;
	private FormulaPage page;

	@Override
	public void init(IWorkbench workbench, IStructuredSelection selection) {
		this.workbench = workbench;
		Object first = selection == null ? null : selection.getFirstElement();
		IFile file = first instanceof IAdaptable adaptable ? adaptable.getAdapter(IFile.class) : null;
		initial = file != null && ("liveness".equals(file.getFileExtension()) || "txt".equals(file.getFileExtension())) ? file : null;
		setWindowTitle("New Statechart from Formulas");
		setNeedsProgressMonitor(true);
	}

	@Override
	public void addPages() {
		page = new FormulaPage();
		addPage(page);
	}

	@Override
	public boolean performFinish() {
		IFile formula = page.formula();
		FormulaTransformation.Outcome[] outcome = new FormulaTransformation.Outcome[1];
		try {
			getContainer().run(true, false, monitor -> {
				try {
					outcome[0] = FormulaTransformer.outcome(formula, FormulaTransformer.read(formula), monitor);
				} catch (CoreException e) {
					throw new InvocationTargetException(e);
				}
			});
		} catch (InvocationTargetException e) {
			page.setErrorMessage(e.getCause().getMessage());
			return false;
		} catch (InterruptedException e) {
			return false;
		}
		if (outcome[0].model() == null) {
			page.setErrorMessage(FormulaTransformer.problem(formula, outcome[0]));
			return false;
		}
		// a model with hand edits is never replaced without saying what would be lost (as Transform does)
		IFile target = TransformHandler.chooseTarget(getShell(), FormulaTransformer.modelOf(formula), outcome[0].model());
		if (target == null) {
			return false;
		}
		try {
			FormulaTransformer.write(outcome[0].model(), target);
		} catch (IOException | CoreException e) {
			page.setErrorMessage("Cannot write " + target.getFullPath() + ": " + e.getMessage());
			return false;
		}
		BasicNewResourceWizard.selectAndReveal(target, workbench.getActiveWorkbenchWindow());
		return true;
	}

	private final class FormulaPage extends WizardPage {
		private Text path;

		FormulaPage() {
			super("formula");
			setTitle("Statechart from formulas");
			setDescription("Choose the formula file; its statechart is written next to it (<name>.stct).");
		}

		@Override
		public void createControl(Composite parent) {
			Composite body = new Composite(parent, SWT.NONE);
			GridLayoutFactory.swtDefaults().numColumns(3).applyTo(body);
			new Label(body, SWT.NONE).setText("Formula file:");
			path = new Text(body, SWT.BORDER);
			GridDataFactory.fillDefaults().grab(true, false).applyTo(path);
			if (initial != null) {
				path.setText(initial.getFullPath().toString());
			}
			path.addModifyListener(event -> check());
			Button browse = new Button(body, SWT.PUSH);
			browse.setText("Browse...");
			browse.addListener(SWT.Selection, event -> {
				ResourceListSelectionDialog chooser = new ResourceListSelectionDialog(getShell(), ResourcesPlugin.getWorkspace().getRoot(), IResource.FILE);
				chooser.setTitle("Formula file");
				if (chooser.open() == org.eclipse.jface.window.Window.OK && chooser.getResult().length > 0) {
					path.setText(((IResource) chooser.getResult()[0]).getFullPath().toString());
				}
			});
			setControl(body);
			check();
		}

		IFile formula() {
			return ResourcesPlugin.getWorkspace().getRoot().getFile(IPath.fromPortableString(path.getText().trim()));
		}

		private void check() {
			String text = path.getText().trim();
			String problem = null;
			if (text.isEmpty()) {
				problem = "Choose a formula file.";
			} else if (IPath.fromPortableString(text).segmentCount() < 2 || !formula().exists()) {
				problem = text + " does not exist.";
			} else if (!"liveness".equals(formula().getFileExtension()) && !"txt".equals(formula().getFileExtension())) {
				problem = "Formulas are in .liveness or .txt files.";
			}
			setErrorMessage(problem);
			setPageComplete(problem == null);
		}
	}
}
