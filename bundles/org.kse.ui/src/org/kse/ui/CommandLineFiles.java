package org.kse.ui;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IProjectDescription;
import org.eclipse.core.resources.IWorkspace;
import org.eclipse.core.resources.IWorkspaceRoot;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.Status;
import org.eclipse.ui.IStartup;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.statushandlers.StatusManager;

/**
 * Opens the statecharts and formulas named on the command line ({@code kse-workbench Goalie.stct}).
 * KSE's editors work on workspace files, so a file outside every project brings its folder in as
 * a KSE project (Eclipse writes its {@code .project} there), as File > Open Projects would.
 */
public final class CommandLineFiles implements IStartup {

	private static final String PLUGIN_ID = "org.kse.ui";

	@Override
	public void earlyStartup() {
		List<Path> named = named(Platform.getApplicationArgs());
		if (named.isEmpty()) {
			return;
		}
		List<IFile> files = new ArrayList<>();
		for (Path path : named) {
			try {
				files.add(inWorkspace(path));
			} catch (CoreException e) {
				report("Cannot open " + path + ": " + e.getStatus().getMessage(), e);
			}
		}
		IWorkbench workbench = PlatformUI.getWorkbench();
		workbench.getDisplay().asyncExec(() -> {
			IWorkbenchWindow window = workbench.getActiveWorkbenchWindow();
			if (window == null && workbench.getWorkbenchWindowCount() > 0) {
				window = workbench.getWorkbenchWindows()[0];
			}
			if (window == null || window.getActivePage() == null) {
				return;
			}
			for (IFile file : files) {
				try {
					IDE.openEditor(window.getActivePage(), file, true);
				} catch (PartInitException e) {
					report("Cannot open " + file.getLocation() + ": " + e.getMessage(), e);
				}
			}
		});
	}

	/** The arguments that name a statechart or a formula; a missing file is reported, not opened. */
	static List<Path> named(String[] arguments) {
		List<Path> named = new ArrayList<>();
		for (String argument : arguments) {
			if (argument.startsWith("-") || !(argument.endsWith(".stct") || argument.endsWith(".liveness"))) {
				continue;
			}
			Path path = Path.of(argument).toAbsolutePath().normalize();
			if (Files.isRegularFile(path)) {
				named.add(path);
			} else {
				report("Cannot open " + path + ": no such file", null);
			}
		}
		return named;
	}

	private static IFile inWorkspace(Path path) throws CoreException {
		IWorkspace workspace = ResourcesPlugin.getWorkspace();
		IWorkspaceRoot root = workspace.getRoot();
		for (IFile file : root.findFilesForLocationURI(path.toUri())) {
			if (file.getProject().isOpen()) {
				return file;
			}
		}
		Path folder = path.getParent();
		IProject project = root.getProject(freeName(root, folder.getFileName().toString()));
		IProjectDescription description = workspace.newProjectDescription(project.getName());
		boolean defaultLocation = folder.getParent() != null && folder.getParent().equals(root.getLocation().toPath())
				&& project.getName().equals(folder.getFileName().toString());
		description.setLocationURI(defaultLocation ? null : folder.toUri());
		description.setNatureIds(new String[] { KseProject.NATURE });
		project.create(description, null);
		project.open(null);
		return project.getFile(folder.relativize(path).toString());
	}

	private static String freeName(IWorkspaceRoot root, String wanted) {
		String name = wanted;
		for (int n = 2; root.getProject(name).exists(); n++) {
			name = wanted + " (" + n + ")";
		}
		return name;
	}

	private static void report(String message, Throwable cause) {
		StatusManager.getManager().handle(new Status(IStatus.WARNING, PLUGIN_ID, message, cause),
				StatusManager.LOG | StatusManager.SHOW);
	}
}
