package org.kse.ui;

import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IProjectNature;
import org.eclipse.core.runtime.CoreException;

/**
 * The nature of a project made by the New KSE Project wizard. It is how the workbench tells a KSE
 * project from any other: there, a {@code .txt} that holds formulas opens in the formula editor.
 */
public class KseProject implements IProjectNature {

	public static final String NATURE = "org.kse.ui.kseNature";

	private IProject project;

	/** Whether the project is open and a KSE project; false for a closed or missing one. */
	public static boolean is(IProject project) {
		try {
			return project != null && project.isOpen() && project.hasNature(NATURE);
		} catch (CoreException e) {
			return false;
		}
	}

	@Override
	public void configure() {
		// no builder: formulas are checked while typed, statecharts when validated
	}

	@Override
	public void deconfigure() {
		// nothing was configured
	}

	@Override
	public IProject getProject() {
		return project;
	}

	@Override
	public void setProject(IProject project) {
		this.project = project;
	}
}
