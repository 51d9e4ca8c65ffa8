package org.kse.ui.statechart;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;

/**
 * The model a robot's behaviour was built from, as the Monitor view and the replay editor find it:
 * a match names a robot's behaviour ({@code Goalie}), and its statechart is {@code Goalie.stct}
 * somewhere in the workspace's open projects.
 */
public final class BehaviourModels {

	private BehaviourModels() {
	}

	/** {@code <behaviour>.stct} in an open project of the workspace: the first by path, or null. */
	public static IFile find(String behaviour) {
		List<IFile> found = new ArrayList<>();
		String name = behaviour + ".stct";
		for (IProject project : ResourcesPlugin.getWorkspace().getRoot().getProjects()) {
			if (!project.isOpen()) {
				continue;
			}
			try {
				project.accept(resource -> {
					if (resource.getType() == IResource.FILE && resource.getName().equals(name)) {
						found.add((IFile) resource);
					}
					// derived folders (build output) hold copies, not the project's models
					return !resource.isDerived();
				});
			} catch (CoreException e) {
				// a project that cannot be read has no model to offer
			}
		}
		found.sort((a, b) -> a.getFullPath().toString().compareTo(b.getFullPath().toString()));
		return found.isEmpty() ? null : found.get(0);
	}
}
