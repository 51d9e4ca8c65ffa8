package org.kse.ui.statechart.wizards;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IAdaptable;
import org.eclipse.core.runtime.IPath;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.wizard.Wizard;
import org.eclipse.jface.wizard.WizardPage;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.FileDialog;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IImportWizard;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.dialogs.ContainerSelectionDialog;
import org.eclipse.ui.ide.IDE;
import org.kse.model.StatechartResources;
import org.kse.scxml.ScxmlImport;
import org.kse.scxml.ScxmlProblem;

/**
 * File > Import... > KSE > SCXML statechart: an SCXML file (another tool's, or one the export
 * wrote) as a statechart in a project's folder, opened in the statechart editor. A chart with
 * errors gives nothing (its problems are listed); one with warnings (parts left out, the
 * validator's advice) is listed first, and a second Finish imports it. An existing model is
 * overwritten only when the user says so.
 */
public class ImportScxmlWizard extends Wizard implements IImportWizard {

	private IWorkbench workbench;
	private IStructuredSelection selection = StructuredSelection.EMPTY;
	private Page page;
	/** The file whose warnings the page shows: a second Finish on it imports it. */
	private String warned;

	@Override
	public void init(IWorkbench currentWorkbench, IStructuredSelection currentSelection) {
		this.workbench = currentWorkbench;
		this.selection = currentSelection == null ? StructuredSelection.EMPTY : currentSelection;
		setWindowTitle("Import an SCXML Statechart");
		setNeedsProgressMonitor(true);
	}

	@Override
	public void addPages() {
		page = new Page();
		addPage(page);
	}

	@Override
	public boolean performFinish() {
		Path source = Path.of(page.source.getText().strip());
		IContainer folder = page.container();
		IFile target = folder.getFile(IPath.fromOSString(page.name.getText().strip()));
		ScxmlImport.Result[] result = new ScxmlImport.Result[1];
		try {
			// one file read and mapped at once: progress without a cancel button
			getContainer().run(true, false, monitor -> {
				monitor.beginTask("Importing " + source.getFileName(), org.eclipse.core.runtime.IProgressMonitor.UNKNOWN);
				try {
					result[0] = ScxmlImport.read(source);
				} catch (IOException e) {
					throw new InvocationTargetException(e);
				} finally {
					monitor.done();
				}
			});
		} catch (InvocationTargetException e) {
			page.setErrorMessage(e.getCause().getMessage());
			return false;
		} catch (InterruptedException e) {
			return false;
		}
		List<ScxmlProblemsTable.Row> rows = new ArrayList<>();
		for (ScxmlProblem problem : result[0].problems()) {
			rows.add(new ScxmlProblemsTable.Row(source.getFileName().toString(), problem));
		}
		page.problems.show(rows);
		if (result[0].model() == null) {
			long errors = result[0].problems().stream().filter(ScxmlProblem::isError).count();
			page.setErrorMessage(source.getFileName() + ": " + errors + (errors == 1 ? " error" : " errors") + " (below); nothing was imported");
			return false;
		}
		String key = source.toAbsolutePath() + "|" + rows.size();
		if (!rows.isEmpty() && !key.equals(warned)) {
			warned = key;
			page.setErrorMessage(null);
			page.setMessage((result[0].complete() ? "The validator's advice is below" : result[0].leftOut().size() + " parts of the chart are left out (below)")
					+ ". Press Finish again to import it.", WizardPage.WARNING);
			return false;
		}
		if (target.exists() && !MessageDialog.openQuestion(getShell(), "Overwrite Statechart", target.getFullPath() + " exists. Overwrite it?")) {
			return false;
		}
		try {
			write(target, StatechartResources.toBytes(result[0].model()));
		} catch (IOException | CoreException e) {
			page.setErrorMessage("Cannot write " + target.getFullPath() + ": " + e.getMessage());
			return false;
		}
		try {
			IDE.openEditor(workbench.getActiveWorkbenchWindow().getActivePage(), target);
		} catch (PartInitException e) {
			// imported: the editor's own message says why it cannot show it
		}
		return true;
	}

	/** Beside the target and moved over it where the folder is on disk (atomic), else through the workspace. */
	private static void write(IFile target, byte[] content) throws IOException, CoreException {
		IPath location = target.getLocation();
		if (location != null) {
			Files.createDirectories(location.toPath().getParent());
			StatechartResources.writeAtomically(location.toPath(), content);
			target.refreshLocal(IResource.DEPTH_ZERO, null);
		} else if (target.exists()) {
			target.setContents(content, IResource.FORCE | IResource.KEEP_HISTORY, null);
		} else {
			target.create(content, IResource.FORCE, null);
		}
	}

	/** The selected folder or project, or the folder of a selected file. */
	private IContainer selectedContainer() {
		for (Object element : selection) {
			IResource resource = element instanceof IResource r ? r : element instanceof IAdaptable adaptable ? adaptable.getAdapter(IResource.class) : null;
			if (resource instanceof IContainer container && resource.getType() != IResource.ROOT) {
				return container;
			}
			if (resource instanceof IFile file) {
				return file.getParent();
			}
		}
		return null;
	}

	final class Page extends WizardPage {
		Text source;
		Text folder;
		Text name;
		ScxmlProblemsTable problems;

		Page() {
			super("importScxml");
			setTitle("SCXML Statechart");
			setDescription("A W3C SCXML chart as a KSE statechart; what KSE cannot run is listed per element with its line:column.");
		}

		@Override
		public void createControl(Composite parent) {
			Composite area = new Composite(parent, SWT.NONE);
			area.setLayout(new GridLayout(3, false));
			new Label(area, SWT.NONE).setText("SCXML file:");
			source = new Text(area, SWT.BORDER | SWT.SINGLE);
			source.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
			Button browseFile = new Button(area, SWT.PUSH);
			browseFile.setText("Browse...");
			browseFile.addListener(SWT.Selection, event -> {
				FileDialog dialog = new FileDialog(getShell(), SWT.OPEN);
				dialog.setFilterExtensions(new String[] { "*.scxml", "*.*" });
				String chosen = dialog.open();
				if (chosen != null) {
					source.setText(chosen);
				}
			});
			new Label(area, SWT.NONE).setText("Into folder:");
			folder = new Text(area, SWT.BORDER | SWT.SINGLE);
			folder.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
			IContainer selected = selectedContainer();
			folder.setText(selected == null ? "" : selected.getFullPath().toString());
			Button browseFolder = new Button(area, SWT.PUSH);
			browseFolder.setText("Browse...");
			browseFolder.addListener(SWT.Selection, event -> {
				ContainerSelectionDialog dialog = new ContainerSelectionDialog(getShell(), container(), false, "The project or folder of the new statechart:");
				if (dialog.open() == ContainerSelectionDialog.OK && dialog.getResult().length > 0) {
					folder.setText(dialog.getResult()[0].toString());
				}
			});
			new Label(area, SWT.NONE).setText("Model file:");
			name = new Text(area, SWT.BORDER | SWT.SINGLE);
			name.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
			new Label(area, SWT.NONE).setText("Problems:");
			new Label(area, SWT.NONE).setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
			problems = new ScxmlProblemsTable(area);
			source.addModifyListener(event -> {
				String file = Path.of(source.getText().strip()).getFileName() == null ? "" : Path.of(source.getText().strip()).getFileName().toString();
				name.setText(file.isEmpty() ? "" : file.replaceFirst("\\.[^.]*$", "") + "." + StatechartResources.FILE_EXTENSION);
				update();
			});
			folder.addModifyListener(event -> update());
			name.addModifyListener(event -> update());
			setControl(area);
			update();
		}

		/** The project or folder the path names, or null. */
		IContainer container() {
			String path = folder.getText().strip();
			if (path.isEmpty() || !IPath.ROOT.isValidPath(path)) {
				return null;
			}
			IResource resource = ResourcesPlugin.getWorkspace().getRoot().findMember(IPath.fromPortableString(path));
			return resource instanceof IContainer container && resource.getType() != IResource.ROOT && container.isAccessible() ? container : null;
		}

		private void update() {
			String file = source.getText().strip();
			String problem = file.isEmpty() ? "Choose the SCXML file to import"
					: !Files.isRegularFile(Path.of(file)) ? file + ": no such file"
					: container() == null ? "Choose an open project or folder to import into"
					: !name.getText().strip().endsWith("." + StatechartResources.FILE_EXTENSION) || name.getText().strip().contains("/")
							? "The model file's name ends with ." + StatechartResources.FILE_EXTENSION
					: null;
			setErrorMessage(problem);
			setMessage(null);
			setPageComplete(problem == null);
		}
	}
}
