package org.kse.ui.statechart;

import java.io.IOException;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.WorkspaceJob;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.eclipse.core.runtime.jobs.IJobChangeListener;
import org.eclipse.ui.ide.IDE;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.ui.ModelFiles;

/**
 * A command's work on each selected statechart file, in a workspace job with progress that the
 * user can cancel. Editors with unsaved changes to those files are saved first (the user is
 * asked), since the work reads the files.
 */
final class ModelJob {

	/** What is done to one model; an IOException stops the job with a message naming the file. */
	interface Step {
		void run(IFile file, Model model, SubMonitor progress) throws IOException, CoreException;
	}

	private ModelJob() {
	}

	/** Null when the user kept unsaved editors; else the scheduled job. */
	static WorkspaceJob schedule(String verb, List<IFile> files, boolean wholeWorkspace, Step step) {
		return schedule(verb, files, wholeWorkspace, step, null);
	}

	/** As above; {@code listener} (if any) hears the job from before it starts, so it never misses its end. */
	static WorkspaceJob schedule(String verb, List<IFile> files, boolean wholeWorkspace, Step step, IJobChangeListener listener) {
		if (!IDE.saveAllEditors(files.toArray(IResource[]::new), true)) {
			return null;
		}
		String what = files.size() == 1 ? files.get(0).getName() : files.size() + " statecharts";
		WorkspaceJob job = new WorkspaceJob(verb + " " + what) {
			@Override
			public IStatus runInWorkspace(IProgressMonitor monitor) throws CoreException {
				SubMonitor progress = SubMonitor.convert(monitor, 10 * files.size());
				for (IFile file : files) {
					progress.subTask(file.getName());
					Model model;
					try {
						model = StatechartResources.load(ModelFiles.location(file));
					} catch (IOException e) {
						ModelMarkers.unreadable(file, e.getMessage());
						progress.worked(10);
						continue;
					}
					try {
						step.run(file, model, progress.split(10));
					} catch (IOException e) {
						return Status.error("cannot " + verb.toLowerCase() + " " + file.getFullPath() + ": " + e.getMessage(), e);
					}
				}
				return Status.OK_STATUS;
			}
		};
		job.setRule(files.size() == 1 && !wholeWorkspace ? files.get(0) : files.get(0).getWorkspace().getRoot());
		job.setUser(true);
		if (listener != null) {
			job.addJobChangeListener(listener);
		}
		job.schedule();
		return job;
	}
}
