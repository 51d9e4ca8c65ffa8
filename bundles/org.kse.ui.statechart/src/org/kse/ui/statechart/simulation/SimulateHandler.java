package org.kse.ui.statechart.simulation;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.handlers.HandlerUtil;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.progress.IProgressConstants;
import org.kse.generator.monas.MonasGenerator;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.simulation.RuntimePrefix;
import org.kse.simulation.SimulationException;
import org.kse.simulation.SimulationSession;
import org.kse.simulation.SimulatorBuilder;
import org.kse.ui.ModelFiles;
import org.kse.ui.statechart.ModelMarkers;

/**
 * KSE > Simulate: builds the simulator of the selected statechart (its C++ on the engine a robot
 * runs, compiled against the installed runtime) in a job the user can follow and cancel, starts it
 * and shows it in the {@link SimulationView}. What stops it (errors in the model, no runtime
 * named, a failed build) is said in one message window, in the words of the exception.
 */
public final class SimulateHandler extends AbstractHandler {

	/** The title of the message windows that say why there is no simulation. */
	public static final String TITLE = "Simulate";
	/** The build jobs' family (tests wait for it). */
	public static final Object FAMILY = SimulateHandler.class;
	/** How many of a model's errors the message lists; the Problems view has them all. */
	private static final int LISTED_ERRORS = 5;

	@Override
	public Object execute(ExecutionEvent event) throws ExecutionException {
		List<IFile> files = ModelFiles.of(event);
		if (files.size() != 1) {
			return null;
		}
		IFile file = files.get(0);
		// the simulator is built from the file: unsaved edits of an open editor are saved first (the user is asked)
		if (!IDE.saveAllEditors(new IResource[] { file }, true)) {
			return null;
		}
		schedule(HandlerUtil.getActiveWorkbenchWindowChecked(event), file);
		return null;
	}

	/** Builds and starts the simulation of {@code file} in a job; the view opens when it is ready. */
	public static Job schedule(IWorkbenchWindow window, IFile file) {
		Display display = window.getShell().getDisplay();
		String name = file.getName().replaceFirst("\\." + StatechartResources.FILE_EXTENSION + "$", "");
		String runtime = SimulationPreferences.runtimePrefix();
		Job job = new Job("Building the simulator of " + name) {
			@Override
			protected IStatus run(IProgressMonitor monitor) {
				SubMonitor progress = SubMonitor.convert(monitor, getName(), SimulatorBuilder.STEPS + 2);
				String failure;
				try {
					Model model = StatechartResources.load(ModelFiles.location(file));
					int[] problems = ModelMarkers.validate(file, model);
					progress.worked(1);
					if (problems[0] > 0) {
						return fail(display, window, file.getName() + " has " + count(problems[0], "error")
								+ ", so it cannot be simulated; fix them first (the Problems view lists them all):\n" + String.join("\n", errors(file)));
					}
					Path prefix = RuntimePrefix.resolve(runtime);
					SimulatorBuilder.Simulator simulator = SimulatorBuilder.build(model, prefix, SimulatorBuilder.defaultFolder(ModelFiles.location(file)),
							progressOf(progress, monitor));
					progress.subTask("starting the simulator of " + model.getName());
					SimulationSession session = SimulationSession.start(simulator);
					progress.worked(1);
					display.asyncExec(() -> show(window, file, model, simulator, session));
					return Status.OK_STATUS;
				} catch (CancellationException e) {
					return Status.CANCEL_STATUS;
				} catch (MonasGenerator.ModelHasErrorsException e) {
					failure = file.getName() + " has errors, so it cannot be simulated:\n" + String.join("\n", e.errors());
				} catch (SimulationException e) {
					failure = "The simulation of " + file.getName() + " cannot start: " + e.getMessage();
				} catch (IOException | CoreException e) {
					failure = "The simulation of " + file.getName() + " cannot start: " + e.getMessage();
				}
				return fail(display, window, failure);
			}

			@Override
			public boolean belongsTo(Object family) {
				return family == FAMILY;
			}
		};
		job.setUser(true);
		// the message window says what went wrong; the job's own error window would say it again
		job.setProperty(IProgressConstants.NO_IMMEDIATE_ERROR_PROMPT_PROPERTY, Boolean.TRUE);
		job.schedule();
		return job;
	}

	/** The build's steps, reported to the job's progress; the job's Cancel stops the build. */
	private static SimulatorBuilder.Progress progressOf(SubMonitor progress, IProgressMonitor monitor) {
		SubMonitor build = progress.split(SimulatorBuilder.STEPS);
		build.setWorkRemaining(SimulatorBuilder.STEPS);
		return new SimulatorBuilder.Progress() {
			private int reported;

			@Override
			public void step(int done, int total, String what) {
				int now = Math.min(done, SimulatorBuilder.STEPS);
				if (now > reported) {
					build.worked(now - reported);
					reported = now;
				}
				build.subTask(what);
			}

			@Override
			public boolean isCancelled() {
				return monitor.isCanceled();
			}
		};
	}

	private static void show(IWorkbenchWindow window, IFile file, Model model, SimulatorBuilder.Simulator simulator, SimulationSession session) {
		if (window.getShell().isDisposed() || window.getActivePage() == null) {
			session.close();
			return;
		}
		try {
			SimulationView.open(window.getActivePage(), file, model, simulator, session);
		} catch (Exception e) {
			session.close();
			MessageDialog.openError(window.getShell(), TITLE, "The Simulation view cannot be opened: " + e.getMessage());
		}
	}

	private static IStatus fail(Display display, IWorkbenchWindow window, String message) {
		display.asyncExec(() -> {
			if (!window.getShell().isDisposed()) {
				MessageDialog.openError(window.getShell(), TITLE, message);
			}
		});
		return Status.error(message);
	}

	/** The first errors the validation marked the file with, each where it is. */
	private static List<String> errors(IFile file) throws CoreException {
		List<String> errors = new ArrayList<>();
		IMarker[] markers = file.findMarkers(ModelMarkers.MARKER, false, IResource.DEPTH_ZERO);
		for (IMarker marker : markers) {
			if (marker.getAttribute(IMarker.SEVERITY, -1) == IMarker.SEVERITY_ERROR && errors.size() < LISTED_ERRORS) {
				String where = marker.getAttribute(IMarker.LOCATION, "");
				String what = marker.getAttribute(IMarker.MESSAGE, "");
				// most messages name their element already
				errors.add("- " + (where.isEmpty() || what.startsWith(where) ? "" : where + ": ") + what);
			}
		}
		return errors;
	}

	private static String count(int count, String noun) {
		return count + " " + noun + (count == 1 ? "" : "s");
	}
}
