package org.kse.ui.wizards;

import java.lang.reflect.InvocationTargetException;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IAdaptable;
import org.eclipse.core.runtime.IPath;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.jface.dialogs.MessageDialog;
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
import org.eclipse.ui.actions.WorkspaceModifyOperation;
import org.eclipse.ui.dialogs.ResourceListSelectionDialog;
import org.eclipse.ui.wizards.newresource.BasicNewResourceWizard;
import org.kse.ui.formula.FormulaTransformer;

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
		IFile model = FormulaTransformer.modelOf(formula);
		if (model.exists() && !MessageDialog.openQuestion(getShell(), getWindowTitle(), model.getName() + " exists already. Replace it?")) {
			return false;
		}
		IStatus[] result = new IStatus[1];
		try {
			getContainer().run(true, false, new WorkspaceModifyOperation(formula.getParent()) {
				@Override
				protected void execute(org.eclipse.core.runtime.IProgressMonitor monitor) throws CoreException {
					result[0] = FormulaTransformer.transform(formula, FormulaTransformer.read(formula), model, monitor);
				}
			});
		} catch (InvocationTargetException e) {
			page.setErrorMessage(e.getCause().getMessage());
			return false;
		} catch (InterruptedException e) {
			return false;
		}
		if (!result[0].isOK()) {
			page.setErrorMessage(result[0].getMessage());
			return false;
		}
		BasicNewResourceWizard.selectAndReveal(model, workbench.getActiveWorkbenchWindow());
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
