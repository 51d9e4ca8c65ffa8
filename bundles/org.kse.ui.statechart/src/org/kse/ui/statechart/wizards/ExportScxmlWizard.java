package org.kse.ui.statechart.wizards;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IAdaptable;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.jface.viewers.ArrayContentProvider;
import org.eclipse.jface.viewers.CheckboxTableViewer;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.viewers.LabelProvider;
import org.eclipse.jface.wizard.Wizard;
import org.eclipse.jface.wizard.WizardPage;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.DirectoryDialog;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IExportWizard;
import org.eclipse.ui.IWorkbench;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.scxml.ScxmlExport;
import org.kse.scxml.ScxmlProblem;
import org.kse.ui.ModelFiles;

/**
 * File > Export... > KSE > Statechart as SCXML: the chosen statecharts (those selected, checked
 * at the start) written as {@code <Model file>.scxml} into a folder of the file system. A
 * statechart the export refuses is not written, nor is any other of the same run: its problems
 * are listed on the page. Files that exist are overwritten only when the user says so.
 */
public class ExportScxmlWizard extends Wizard implements IExportWizard {

	private IStructuredSelection selection = StructuredSelection.EMPTY;
	private Page page;

	@Override
	public void init(IWorkbench workbench, IStructuredSelection currentSelection) {
		this.selection = currentSelection == null ? StructuredSelection.EMPTY : currentSelection;
		setWindowTitle("Export Statecharts as SCXML");
		setNeedsProgressMonitor(true);
	}

	@Override
	public void addPages() {
		page = new Page();
		addPage(page);
	}

	/** One statechart's SCXML, or why it has none. */
	private record Exported(IFile file, Path target, ScxmlExport.Result result) {
	}

	@Override
	public boolean performFinish() {
		List<IFile> files = page.checked();
		Path folder = Path.of(page.folder.getText().strip());
		List<Exported> exported = new ArrayList<>();
		try {
			getContainer().run(true, true, monitor -> {
				SubMonitor progress = SubMonitor.convert(monitor, "Exporting " + files.size() + (files.size() == 1 ? " statechart" : " statecharts"), files.size());
				for (IFile file : files) {
					progress.subTask(file.getFullPath().toString());
					Path target = folder.resolve(file.getName().replaceFirst("\\.stct$", "") + ".scxml");
					try {
						Model model = StatechartResources.load(ModelFiles.location(file));
						exported.add(new Exported(file, target, ScxmlExport.export(model)));
					} catch (IOException e) {
						exported.add(new Exported(file, target, new ScxmlExport.Result(null, List.of(ScxmlProblem.error("the file", e.getMessage())))));
					}
					if (progress.isCanceled()) {
						throw new InterruptedException();
					}
					progress.worked(1);
				}
			});
		} catch (InvocationTargetException e) {
			page.setErrorMessage("The export failed: " + e.getCause().getMessage());
			return false;
		} catch (InterruptedException e) {
			return false;
		}
		List<ScxmlProblemsTable.Row> rows = new ArrayList<>();
		int refused = 0;
		for (Exported one : exported) {
			refused += one.result().refused() ? 1 : 0;
			one.result().problems().forEach(problem -> rows.add(new ScxmlProblemsTable.Row(one.file().getName(), problem)));
		}
		page.problems.show(rows);
		if (refused > 0) {
			page.setErrorMessage(refused + (refused == 1 ? " statechart cannot be exported" : " statecharts cannot be exported")
					+ " (the problems below); nothing was written");
			return false;
		}
		List<String> existing = exported.stream().map(Exported::target).filter(Files::exists).map(target -> target.getFileName().toString()).toList();
		if (!existing.isEmpty() && !MessageDialog.openQuestion(getShell(), "Overwrite SCXML Files",
				String.join(", ", existing) + (existing.size() == 1 ? " exists" : " exist") + " in " + folder + ". Overwrite?")) {
			return false;
		}
		try {
			Files.createDirectories(folder);
			for (Exported one : exported) {
				StatechartResources.writeAtomically(one.target(), one.result().scxml().getBytes(StandardCharsets.UTF_8));
			}
		} catch (IOException e) {
			page.setErrorMessage("Cannot write into " + folder + ": " + e.getMessage());
			return false;
		}
		refreshWorkspace(folder);
		if (!rows.isEmpty()) {
			MessageDialog.openWarning(getShell(), "SCXML Exported with Warnings", exported.size() + " written into " + folder + "; "
					+ rows.size() + (rows.size() == 1 ? " warning:\n" : " warnings:\n") + String.join("\n",
							rows.stream().map(row -> row.file() + ": " + row.problem().element() + ": " + row.problem().message()).toList()));
		}
		return true;
	}

	/** A destination inside the workspace shows the new files at once. */
	private static void refreshWorkspace(Path folder) {
		for (IContainer container : ResourcesPlugin.getWorkspace().getRoot().findContainersForLocationURI(folder.toAbsolutePath().toUri())) {
			try {
				container.refreshLocal(IResource.DEPTH_ONE, null);
			} catch (CoreException e) {
				// the files are written; the workspace shows them at its next refresh
			}
		}
	}

	/** Every statechart of the workspace, the selected ones checked. */
	private List<IFile> statecharts() {
		List<IFile> all = new ArrayList<>();
		try {
			ResourcesPlugin.getWorkspace().getRoot().accept(proxy -> {
				if (proxy.getType() == IResource.FILE && proxy.getName().endsWith("." + StatechartResources.FILE_EXTENSION)) {
					all.add((IFile) proxy.requestResource());
				}
				return true;
			}, IResource.NONE);
		} catch (CoreException e) {
			// a project that cannot be read offers no statecharts
		}
		return all;
	}

	private Set<IFile> selected() {
		Set<IFile> chosen = new LinkedHashSet<>();
		for (Object element : selection) {
			IResource resource = element instanceof IResource r ? r : element instanceof IAdaptable adaptable ? adaptable.getAdapter(IResource.class) : null;
			if (resource instanceof IFile file && StatechartResources.FILE_EXTENSION.equals(file.getFileExtension())) {
				chosen.add(file);
			} else if (resource instanceof IContainer container) {
				for (IFile file : statecharts()) {
					if (container.getFullPath().isPrefixOf(file.getFullPath())) {
						chosen.add(file);
					}
				}
			}
		}
		return chosen;
	}

	final class Page extends WizardPage {
		CheckboxTableViewer models;
		Text folder;
		ScxmlProblemsTable problems;

		Page() {
			super("exportScxml");
			setTitle("Statecharts as SCXML");
			setDescription("W3C SCXML that runs as the Monas engine does, with KSE's facts kept for the way back (File > Import... > SCXML statechart).");
		}

		@Override
		public void createControl(Composite parent) {
			Composite area = new Composite(parent, SWT.NONE);
			area.setLayout(new GridLayout(3, false));
			new Label(area, SWT.NONE).setText("Statecharts:");
			new Label(area, SWT.NONE).setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
			models = CheckboxTableViewer.newCheckList(area, SWT.BORDER | SWT.V_SCROLL);
			GridData list = new GridData(SWT.FILL, SWT.FILL, true, true, 3, 1);
			list.heightHint = 140;
			models.getTable().setLayoutData(list);
			models.setContentProvider(ArrayContentProvider.getInstance());
			models.setLabelProvider(new LabelProvider() {
				@Override
				public String getText(Object element) {
					return ((IFile) element).getFullPath().makeRelative().toString();
				}
			});
			models.setInput(statecharts());
			models.setCheckedElements(selected().toArray());
			models.addCheckStateListener(event -> update());

			new Label(area, SWT.NONE).setText("To folder:");
			folder = new Text(area, SWT.BORDER | SWT.SINGLE);
			folder.setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false));
			folder.setText(defaultFolder());
			folder.addModifyListener(event -> update());
			Button browse = new Button(area, SWT.PUSH);
			browse.setText("Browse...");
			browse.addListener(SWT.Selection, event -> {
				DirectoryDialog dialog = new DirectoryDialog(getShell());
				dialog.setFilterPath(folder.getText());
				String chosen = dialog.open();
				if (chosen != null) {
					folder.setText(chosen);
				}
			});
			new Label(area, SWT.NONE).setText("Problems:");
			new Label(area, SWT.NONE).setLayoutData(new GridData(SWT.FILL, SWT.CENTER, true, false, 2, 1));
			problems = new ScxmlProblemsTable(area);
			setControl(area);
			update();
		}

		/** The folder of the first checked statechart, where its SCXML is found beside it. */
		private String defaultFolder() {
			Object[] checked = models.getCheckedElements();
			if (checked.length > 0 && ((IFile) checked[0]).getParent().getLocation() != null) {
				return ((IFile) checked[0]).getParent().getLocation().toOSString();
			}
			return System.getProperty("user.home");
		}

		List<IFile> checked() {
			List<IFile> files = new ArrayList<>();
			for (Object element : models.getCheckedElements()) {
				files.add((IFile) element);
			}
			return files;
		}

		private void update() {
			String problem = models.getCheckedElements().length == 0 ? "Check the statecharts to export"
					: folder.getText().isBlank() ? "Name the folder to write the SCXML files into"
					: Files.exists(Path.of(folder.getText().strip())) && !Files.isDirectory(Path.of(folder.getText().strip())) ? folder.getText().strip() + " is a file, not a folder"
					: null;
			setErrorMessage(problem);
			setPageComplete(problem == null);
		}
	}
}
