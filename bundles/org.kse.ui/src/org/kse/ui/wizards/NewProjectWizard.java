package org.kse.ui.wizards;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.InvocationTargetException;
import java.net.URL;
import java.util.Collections;

import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IProjectDescription;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IPath;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.wizard.Wizard;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.ui.INewWizard;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.actions.WorkspaceModifyOperation;
import org.eclipse.ui.dialogs.WizardNewProjectCreationPage;
import org.eclipse.ui.wizards.newresource.BasicNewResourceWizard;
import org.kse.ui.ModelFiles;
import org.osgi.framework.Bundle;
import org.osgi.framework.FrameworkUtil;

/**
 * New KSE project: a Monas-style source tree (src/statecharts, src/activities, src/messages)
 * and a models folder, optionally filled with the example behaviours (formulas, statecharts and
 * their hand-written activities), each model connected to src for code generation.
 */
public class NewProjectWizard extends Wizard implements INewWizard {

	/** Where the examples are inside this bundle (copied there by the build from examples/). */
	static final String EXAMPLES = "org/kse/ui/examples";

	private IWorkbench workbench;
	private ProjectPage page;

	@Override
	public void init(IWorkbench workbench, IStructuredSelection selection) {
		this.workbench = workbench;
		setWindowTitle("New KSE Project");
		setNeedsProgressMonitor(true);
	}

	@Override
	public void addPages() {
		page = new ProjectPage();
		page.setTitle("KSE project");
		page.setDescription("A project for robot behaviours: formulas and statecharts in models/, their C++ in src/.");
		addPage(page);
	}

	@Override
	public boolean performFinish() {
		IProject project = page.getProjectHandle();
		IPath location = page.useDefaults() ? null : page.getLocationPath();
		boolean examples = page.examples;
		try {
			getContainer().run(true, false, new WorkspaceModifyOperation() {
				@Override
				protected void execute(IProgressMonitor monitor) throws CoreException {
					create(project, location, examples, monitor);
				}
			});
		} catch (InvocationTargetException e) {
			page.setErrorMessage("cannot create the project: " + e.getCause().getMessage());
			return false;
		} catch (InterruptedException e) {
			return false;
		}
		BasicNewResourceWizard.selectAndReveal(project.getFolder("models"), workbench.getActiveWorkbenchWindow());
		return true;
	}

	/** Creates the project; public for tests and for a command line that sets up a workspace. */
	public static void create(IProject project, IPath location, boolean examples, IProgressMonitor monitor) throws CoreException {
		SubMonitor progress = SubMonitor.convert(monitor, "Creating " + project.getName(), 10);
		IProjectDescription description = ResourcesPlugin.getWorkspace().newProjectDescription(project.getName());
		description.setLocation(location);
		description.setNatureIds(new String[] { org.kse.ui.KseProject.NATURE });
		project.create(description, progress.split(1));
		project.open(progress.split(1));
		for (String folder : new String[] { "models", "src", "src/statecharts", "src/activities", "src/messages" }) {
			IFolder handle = project.getFolder(folder);
			if (!handle.exists()) {
				handle.create(true, true, progress.split(1));
			}
		}
		if (examples) {
			copyExamples(project, progress.split(3));
		}
	}

	private static void copyExamples(IProject project, IProgressMonitor monitor) throws CoreException {
		Bundle bundle = FrameworkUtil.getBundle(NewProjectWizard.class);
		var entries = bundle.findEntries(EXAMPLES, "*", true);
		if (entries == null) {
			throw new CoreException(Status.error("this KSE build has no examples (" + EXAMPLES + " is missing)"));
		}
		SubMonitor progress = SubMonitor.convert(monitor, "Copying the examples", 100);
		for (URL entry : Collections.list(entries)) {
			String path = entry.getPath().substring(entry.getPath().indexOf(EXAMPLES) + EXAMPLES.length() + 1);
			if (path.isEmpty() || path.endsWith("/")) {
				continue;
			}
			// models/<Behaviour>/<file> go to models/, activities/<Activity>/<file> to src/activities/
			IPath target = path.startsWith("models/") ? IPath.fromPortableString("models/" + IPath.fromPortableString(path).lastSegment())
					: IPath.fromPortableString("src/" + path);
			IFile file = project.getFile(target);
			mkdirs(file.getParent(), progress);
			try (InputStream in = entry.openStream()) {
				if (file.exists()) {
					file.setContents(in, true, false, progress.split(1));
				} else {
					file.create(in, true, progress.split(1));
				}
			} catch (IOException e) {
				throw new CoreException(Status.error("cannot copy the example " + path + ": " + e.getMessage(), e));
			}
			if (ModelFiles.isModel(file)) {
				ModelFiles.remember(file, project.getFolder("src"), false);
			}
			progress.setWorkRemaining(100);
		}
	}

	private static void mkdirs(IContainer container, IProgressMonitor monitor) throws CoreException {
		if (container instanceof IFolder folder && !folder.exists()) {
			mkdirs(folder.getParent(), monitor);
			folder.create(true, true, monitor);
		}
	}

	private static final class ProjectPage extends WizardNewProjectCreationPage {
		private boolean examples = true;

		ProjectPage() {
			super("project");
		}

		@Override
		public void createControl(Composite parent) {
			super.createControl(parent);
			Composite body = (Composite) getControl();
			Button button = new Button(body, SWT.CHECK);
			button.setText("Add the example behaviours: Goalie, Attacker and Defender, with their activities");
			button.setSelection(examples);
			button.addListener(SWT.Selection, event -> examples = button.getSelection());
		}
	}
}
