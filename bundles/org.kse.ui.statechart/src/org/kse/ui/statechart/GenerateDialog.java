package org.kse.ui.statechart;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.IPath;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.jface.dialogs.TitleAreaDialog;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.layout.GridLayoutFactory;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.dialogs.ContainerSelectionDialog;
import org.kse.ui.ModelFiles;

/** Connects a model to the Monas source folder its code goes into (once; KSE remembers it). */
class GenerateDialog extends TitleAreaDialog {

	private final IFile model;
	private Text folderText;
	private Button loggerButton;
	private IContainer folder;
	private boolean logger;

	GenerateDialog(Shell shell, IFile model) {
		super(shell);
		this.model = model;
		this.folder = ModelFiles.sourceFolder(model);
		this.logger = ModelFiles.logger(model);
	}

	@Override
	protected Control createDialogArea(Composite parent) {
		setTitle("Generate Monas C++ for " + model.getName());
		setMessage("The statechart goes to <folder>/statecharts, activity skeletons to <folder>/activities;\n"
				+ "activities that exist are never overwritten.");
		Composite area = (Composite) super.createDialogArea(parent);
		Composite body = new Composite(area, SWT.NONE);
		GridLayoutFactory.swtDefaults().numColumns(3).applyTo(body);
		GridDataFactory.fillDefaults().grab(true, true).applyTo(body);
		new Label(body, SWT.NONE).setText("Source folder:");
		folderText = new Text(body, SWT.BORDER);
		GridDataFactory.fillDefaults().grab(true, false).hint(360, SWT.DEFAULT).applyTo(folderText);
		folderText.setText(folder != null ? folder.getFullPath().toString() : model.getProject().getFullPath().append("src").toString());
		folderText.addModifyListener(event -> check());
		Button browse = new Button(body, SWT.PUSH);
		browse.setText("Browse...");
		browse.addListener(SWT.Selection, event -> {
			ContainerSelectionDialog chooser = new ContainerSelectionDialog(getShell(), model.getProject(), true, "The Monas source folder:");
			if (chooser.open() == OK && chooser.getResult().length > 0) {
				folderText.setText(((IPath) chooser.getResult()[0]).toString());
			}
		});
		loggerButton = new Button(body, SWT.CHECK);
		loggerButton.setText("Log every condition evaluated (the generator's logger variant)");
		loggerButton.setSelection(logger);
		GridDataFactory.swtDefaults().span(3, 1).applyTo(loggerButton);
		return area;
	}

	@Override
	protected void createButtonsForButtonBar(Composite parent) {
		createButton(parent, IDialogConstants.OK_ID, "Generate", true);
		createButton(parent, IDialogConstants.CANCEL_ID, IDialogConstants.CANCEL_LABEL, false);
		check();
	}

	private void check() {
		String path = folderText.getText().trim();
		String problem = null;
		if (path.isEmpty() || IPath.fromPortableString(path).segmentCount() == 0) {
			problem = "Choose the source folder.";
		} else {
			IResource existing = ResourcesPlugin.getWorkspace().getRoot().findMember(path);
			if (existing != null && !(existing instanceof IContainer)) {
				problem = path + " is a file, not a folder.";
			} else if (ResourcesPlugin.getWorkspace().getRoot().getProject(IPath.fromPortableString(path).segment(0)).exists() == false) {
				problem = "There is no project " + IPath.fromPortableString(path).segment(0) + ".";
			}
		}
		setErrorMessage(problem);
		Button ok = getButton(IDialogConstants.OK_ID);
		if (ok != null) {
			ok.setEnabled(problem == null);
		}
	}

	@Override
	protected void okPressed() {
		IPath path = IPath.fromPortableString(folderText.getText().trim());
		folder = path.segmentCount() == 1 ? ResourcesPlugin.getWorkspace().getRoot().getProject(path.segment(0))
				: ResourcesPlugin.getWorkspace().getRoot().getFolder(path);
		logger = loggerButton.getSelection();
		super.okPressed();
	}

	IContainer folder() {
		return folder;
	}

	boolean logger() {
		return logger;
	}
}
