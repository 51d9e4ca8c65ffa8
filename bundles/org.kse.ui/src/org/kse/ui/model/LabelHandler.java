package org.kse.ui.model;

import java.io.IOException;
import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.WorkspaceJob;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.kse.labeling.Labeler;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;

/** "Label": renumbers the states (the original's "Labeling Diagram") and saves the model atomically. */
public class LabelHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) {
		List<IFile> files = ModelFiles.of(event);
		if (files.isEmpty()) {
			return null;
		}
		WorkspaceJob job = new WorkspaceJob("Labeling " + (files.size() == 1 ? files.get(0).getName() : files.size() + " statecharts")) {
			@Override
			public IStatus runInWorkspace(IProgressMonitor monitor) throws CoreException {
				SubMonitor progress = SubMonitor.convert(monitor, 2 * files.size());
				for (IFile file : files) {
					progress.subTask(file.getName());
					try {
						Model model = StatechartResources.load(ModelFiles.location(file));
						Labeler.label(model);
						progress.worked(1);
						StatechartResources.save(model, ModelFiles.location(file));
						file.refreshLocal(IResource.DEPTH_ZERO, progress.split(1));
					} catch (IOException e) {
						return Status.error("cannot label " + file.getFullPath() + ": " + e.getMessage(), e);
					}
				}
				return Status.OK_STATUS;
			}
		};
		job.setRule(files.get(0).getWorkspace().getRoot());
		job.setUser(true);
		job.schedule();
		return null;
	}
}
