package org.kse.ui.model;

import java.io.IOException;
import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.WorkspaceJob;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Status;
import org.eclipse.core.runtime.SubMonitor;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;

/** "Validate": the rules of the original tool and the message catalog; the results in the Problems view. */
public class ValidateHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) {
		List<IFile> files = ModelFiles.of(event);
		if (files.isEmpty()) {
			return null;
		}
		WorkspaceJob job = new WorkspaceJob("Validating " + (files.size() == 1 ? files.get(0).getName() : files.size() + " statecharts")) {
			@Override
			public IStatus runInWorkspace(IProgressMonitor monitor) throws CoreException {
				SubMonitor progress = SubMonitor.convert(monitor, files.size());
				for (IFile file : files) {
					progress.subTask(file.getName());
					try {
						Model model = StatechartResources.load(ModelFiles.location(file));
						ModelMarkers.validate(file, model);
					} catch (IOException e) {
						ModelMarkers.unreadable(file, e.getMessage());
					}
					progress.worked(1);
				}
				return Status.OK_STATUS;
			}
		};
		job.setRule(files.size() == 1 ? files.get(0) : files.get(0).getWorkspace().getRoot());
		job.setUser(true);
		job.schedule();
		return null;
	}
}
