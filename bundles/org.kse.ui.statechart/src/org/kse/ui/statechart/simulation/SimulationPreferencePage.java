package org.kse.ui.statechart.simulation;

import org.eclipse.core.runtime.preferences.InstanceScope;
import org.eclipse.jface.preference.DirectoryFieldEditor;
import org.eclipse.jface.preference.FieldEditorPreferencePage;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.IWorkbenchPreferencePage;
import org.eclipse.ui.preferences.ScopedPreferenceStore;
import org.kse.simulation.RuntimePrefix;
import org.kse.ui.preferences.KsePreferences;

/** Window > Preferences > KSE > Simulation: where the C++ runtime the simulators are built against is installed. */
public class SimulationPreferencePage extends FieldEditorPreferencePage implements IWorkbenchPreferencePage {

	public SimulationPreferencePage() {
		super(GRID);
		setDescription("KSE > Simulate builds a simulator of the statechart against an installed KSE C++ runtime (the folder given to"
				+ " cmake --install; ./kse demo makes one in target/demo/runtime-prefix). Leave it empty to use the environment variable "
				+ RuntimePrefix.VARIABLE + ".");
	}

	@Override
	public void init(IWorkbench workbench) {
		setPreferenceStore(new ScopedPreferenceStore(InstanceScope.INSTANCE, KsePreferences.NODE));
	}

	@Override
	protected void createFieldEditors() {
		DirectoryFieldEditor prefix = new DirectoryFieldEditor(SimulationPreferences.RUNTIME_PREFIX, "Runtime install prefix:", getFieldEditorParent());
		// empty is a choice: the environment's variable
		prefix.setEmptyStringAllowed(true);
		addField(prefix);
	}
}
