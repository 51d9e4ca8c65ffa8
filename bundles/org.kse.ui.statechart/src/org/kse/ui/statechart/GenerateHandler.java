package org.kse.ui.statechart;

import java.io.IOException;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IContainer;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.WorkspaceJob;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.core.runtime.jobs.IJobChangeEvent;
import org.eclipse.core.runtime.jobs.JobChangeAdapter;
import org.eclipse.jface.window.Window;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.handlers.HandlerUtil;
import org.eclipse.ui.progress.IProgressConstants;
import org.kse.generator.monas.MonasGenerator;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.ui.preferences.KsePreferences;
import org.kse.ui.ModelFiles;

/**
 * "Generate Code": Monas C++ of the model into its source folder. The first time (or with the
 * command's {@code configure} parameter) a dialog connects the model to a folder; KSE remembers it.
 * When it ends, a summary window lists what was written (with links to the files), unchanged and kept.
 */
public class GenerateHandler extends AbstractHandler {

	public static final String CONFIGURE = "org.kse.ui.generate.configure";

	@Override
	public Object execute(ExecutionEvent event) throws org.eclipse.core.commands.ExecutionException {
		List<IFile> files = ModelFiles.of(event);
		if (files.size() != 1 || org.kse.ui.statechart.KeyEchoes.isEcho(event)) {
			return null;
		}
		IFile file = files.get(0);
		// the generator reads the file: unsaved edits of an open editor are saved first (the user is asked)
		if (!org.eclipse.ui.ide.IDE.saveAllEditors(new org.eclipse.core.resources.IResource[] { file }, true)) {
			return null;
		}
		IContainer folder = ModelFiles.sourceFolder(file);
		boolean configure = Boolean.parseBoolean(event.getParameter(CONFIGURE));
		if (folder == null || configure) {
			GenerateDialog dialog = new GenerateDialog(HandlerUtil.getActiveShellChecked(event), file);
			if (dialog.open() != Window.OK) {
				return null;
			}
			folder = dialog.folder();
			try {
				ModelFiles.remember(file, folder, dialog.logger());
			} catch (CoreException e) {
				throw new org.eclipse.core.commands.ExecutionException("cannot remember the source folder of " + file.getName(), e);
			}
		}
		schedule(file, folder, ModelFiles.logger(file));
		return null;
	}

	/** The original tool let a team plug in its own generator: it gets the model and the folder. */
	private static IStatus external(IFile file, IContainer folder, IProgressMonitor monitor) throws CoreException, IOException {
		List<String> command = KsePreferences.command(KsePreferences.node().get(KsePreferences.GENERATOR_COMMAND, ""),
				Map.of("model", ModelFiles.location(file).toString(), "folder", ModelFiles.location(folder).toString()));
		Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
		String output = new String(process.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).strip();
		int exit;
		try {
			exit = process.waitFor();
		} catch (InterruptedException e) {
			process.destroy();
			Thread.currentThread().interrupt();
			return Status.CANCEL_STATUS;
		}
		folder.refreshLocal(IResource.DEPTH_INFINITE, monitor);
		String tail = output.length() > 2000 ? "..." + output.substring(output.length() - 2000) : output;
		return exit == 0 ? new Status(IStatus.OK, "org.kse.ui", "External generator " + command.get(0) + " done" + (tail.isEmpty() ? "" : ": " + tail))
				: Status.error("the external generator " + command + " failed with exit code " + exit + (tail.isEmpty() ? "" : ":\n" + tail));
	}

	/** What the headline leaves out: which activities were kept, and how many files were already up to date. */
	private static List<String> details(IStatus result, MonasGenerator.Report report) {
		List<String> details = new java.util.ArrayList<>();
		if (report != null && !report.kept().isEmpty()) {
			details.add("Activities kept (an activity that exists is never overwritten): "
					+ String.join(", ", report.kept().stream().map(kept -> kept.getFileName().toString()).toList()) + ".");
		}
		if (report != null && !report.unchanged().isEmpty()) {
			details.add(report.unchanged().size() + (report.unchanged().size() == 1 ? " file was" : " files were") + " already up to date.");
		}
		return details;
	}

	private static void createFolder(IFolder folder, IProgressMonitor monitor) throws CoreException {
		if (folder.getParent() instanceof IFolder parent && !parent.exists()) {
			createFolder(parent, monitor);
		}
		folder.create(true, true, monitor);
	}

	/** Generates in a job; public for callers that know the folder already (tests, other commands). */
	public static WorkspaceJob schedule(IFile file, IContainer folder, boolean logger) {
		AtomicReference<MonasGenerator.Report> finished = new AtomicReference<>();
		WorkspaceJob job = new WorkspaceJob("Generating code for " + file.getName()) {
			@Override
			public IStatus runInWorkspace(IProgressMonitor monitor) throws CoreException {
				SubMonitor progress = SubMonitor.convert(monitor, 100);
				try {
					if (folder instanceof IFolder newFolder && !newFolder.exists()) {
						createFolder(newFolder, progress.split(1));
					}
					Model model = StatechartResources.load(ModelFiles.location(file));
					int[] problems = ModelMarkers.validate(file, model);
					if (problems[0] > 0) {
						return Status.error(file.getName() + " has " + problems[0] + (problems[0] == 1 ? " error" : " errors")
								+ "; nothing was generated. See the Problems view.");
					}
					if (KsePreferences.externalGenerator()) {
						return external(file, folder, progress.split(100));
					}
					SubMonitor generation = progress.split(90);
					MonasGenerator.Report report = MonasGenerator.generate(model, ModelFiles.location(folder), new MonasGenerator.Options(logger),
							(step, steps, what) -> {
								generation.setWorkRemaining(Math.max(1, steps - step + 1));
								generation.subTask(what);
								generation.worked(1);
							});
					folder.refreshLocal(IResource.DEPTH_INFINITE, progress.split(10));
					finished.set(report);
					String replaced = report.replacements().isEmpty() ? ""
							: "; the source folder's messages replace the built-in " + String.join(", ",
									report.replacements().stream().map(org.kse.messages.StandardMessages.Replacement::type).toList());
					return new Status(report.warnings().isEmpty() ? IStatus.OK : IStatus.WARNING, "org.kse.ui", "Generated " + model.getName() + " into "
							+ folder.getFullPath() + ": " + report.written().size() + " written, " + report.unchanged().size() + " unchanged, "
							+ report.kept().size() + " activities kept" + (report.removed().isEmpty() ? "" : ", " + report.removed().size() + " stale removed")
							+ replaced + (report.warnings().isEmpty() ? "" : ". " + String.join("; ", report.warnings())));
				} catch (IOException e) {
					return Status.error("cannot generate " + file.getFullPath() + ": " + e.getMessage(), e);
				} catch (MonasGenerator.ModelHasErrorsException e) {
					return Status.error(file.getName() + " has errors; nothing was generated: " + String.join("; ", e.errors()));
				}
			}
		};
		job.setRule(file.getWorkspace().getRoot());
		job.setUser(true);
		job.setProperty(IProgressConstants.KEEP_PROPERTY, Boolean.TRUE);
		// the summary window says what went wrong, where the user looks; the job-error dialog would say it again
		job.setProperty(IProgressConstants.NO_IMMEDIATE_ERROR_PROMPT_PROPERTY, Boolean.TRUE);
		Display display = Display.getCurrent() != null ? Display.getCurrent() : PlatformUI.getWorkbench().getDisplay();
		job.addJobChangeListener(new JobChangeAdapter() {
			@Override
			public void done(IJobChangeEvent event) {
				IStatus result = event.getResult();
				if (result.getSeverity() == IStatus.CANCEL) {
					return;
				}
				MonasGenerator.Report report = finished.get();
				display.asyncExec(() -> GenerationSummary.open(result.getMessage(), details(result, report),
						report == null ? List.of() : report.written().stream().map(ModelFiles.location(folder)::resolve).toList()));
			}
		});
		job.schedule();
		return job;
	}
}
