package org.kse.ui.statechart.simulation;

import java.util.regex.Pattern;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IWorkspaceRoot;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.IPath;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.jface.dialogs.TitleAreaDialog;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.dialogs.ContainerSelectionDialog;

/**
 * "Save as Test Case…": where the trace goes (a folder of the workspace) and the case's name (a
 * C++ identifier: the case's statechart takes it, and a conformance program links every case's
 * statechart by its name). Both come filled in; one OK saves.
 */
public final class SaveCaseDialog extends TitleAreaDialog {

	public static final String TITLE = "Save as Test Case";
	private static final Pattern NAME = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

	private String folder;
	private String name;
	private Text folderText;
	private Text nameText;

	/** @param folder the workspace path offered; @param name the name offered */
	public SaveCaseDialog(Shell parent, IPath folder, String name) {
		super(parent);
		this.folder = folder.toString();
		this.name = name;
	}

	@Override
	protected void configureShell(Shell shell) {
		super.configureShell(shell);
		shell.setText(TITLE);
	}

	/** As wide as a path and a name need; the message above wraps. */
	@Override
	protected org.eclipse.swt.graphics.Point getInitialSize() {
		return getShell().computeSize(700, SWT.DEFAULT, true);
	}

	@Override
	protected Control createDialogArea(Composite parent) {
		Composite area = (Composite) super.createDialogArea(parent);
		setTitle("Save the trace as a conformance case");
		setMessage("The case is the statechart (a copy named as the case) and the commands with the lines each must cause: "
				+ "kse simulate --script or the conformance suite replays it.");
		Composite body = new Composite(area, SWT.NONE);
		body.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
		body.setLayout(new GridLayout(3, false));
		new Label(body, SWT.NONE).setText("&Folder:");
		folderText = new Text(body, SWT.BORDER);
		folderText.setText(folder);
		GridData wide = new GridData(SWT.FILL, SWT.CENTER, true, false);
		wide.widthHint = 360;
		folderText.setLayoutData(wide);
		Button browse = new Button(body, SWT.PUSH);
		browse.setText("&Browse…");
		browse.addListener(SWT.Selection, event -> {
			ContainerSelectionDialog choose = new ContainerSelectionDialog(getShell(), containerOf(folderText.getText().strip()), true, "The folder of the case's two files:");
			if (choose.open() == Window.OK && choose.getResult() != null && choose.getResult().length == 1) {
				folderText.setText(choose.getResult()[0].toString());
			}
		});
		new Label(body, SWT.NONE).setText("&Name:");
		nameText = new Text(body, SWT.BORDER);
		nameText.setText(name);
		nameText.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
		folderText.addListener(SWT.Modify, event -> check());
		nameText.addListener(SWT.Modify, event -> check());
		return area;
	}

	@Override
	protected void createButtonsForButtonBar(Composite parent) {
		createButton(parent, IDialogConstants.OK_ID, "&Save", true);
		createButton(parent, IDialogConstants.CANCEL_ID, IDialogConstants.CANCEL_LABEL, false);
		check();
	}

	private void check() {
		String problem = problem(folderText.getText().strip(), nameText.getText().strip());
		setErrorMessage(problem);
		Button ok = getButton(IDialogConstants.OK_ID);
		if (ok != null) {
			ok.setEnabled(problem == null);
		}
	}

	/** Why the folder and name cannot be saved to, or null. */
	static String problem(String folder, String name) {
		if (!NAME.matcher(name).matches()) {
			return "The name is a C++ identifier (letters, digits and _, not first a digit): the case's statechart is named so.";
		}
		IPath path = IPath.fromPortableString(folder);
		if (path.segmentCount() == 0) {
			return "Name a folder of an open project of the workspace (e.g. /Project/tests).";
		}
		IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject(path.segment(0));
		if (!project.isOpen()) {
			return "There is no open project " + path.segment(0) + " in the workspace.";
		}
		return null;
	}

	/** The folder the case goes to (made when missing), in the workspace. */
	public IContainer container() {
		return containerOf(folder);
	}

	private static IContainer containerOf(String folder) {
		IWorkspaceRoot root = ResourcesPlugin.getWorkspace().getRoot();
		IPath path = IPath.fromPortableString(folder);
		if (path.segmentCount() == 0) {
			return root;
		}
		return path.segmentCount() == 1 ? root.getProject(path.segment(0)) : root.getFolder(path);
	}

	public String name() {
		return name;
	}

	@Override
	protected void okPressed() {
		folder = folderText.getText().strip();
		name = nameText.getText().strip();
		super.okPressed();
	}
}
