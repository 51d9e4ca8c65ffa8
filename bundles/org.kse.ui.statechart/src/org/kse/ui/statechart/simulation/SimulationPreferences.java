package org.kse.ui.statechart.simulation;

import org.eclipse.core.runtime.preferences.InstanceScope;
import org.kse.ui.preferences.KsePreferences;

/**
 * The simulation's preference: the install prefix of the KSE C++ runtime its simulators are built
 * against. Kept with the other KSE preferences (their node), shown on KSE > Simulation.
 */
public final class SimulationPreferences {

	/** The runtime's install prefix (the folder given to cmake --install); empty: $KSE_RUNTIME_PREFIX. */
	public static final String RUNTIME_PREFIX = "simulationRuntimePrefix";

	private SimulationPreferences() {
	}

	/** The prefix the user named, or "" when the environment's KSE_RUNTIME_PREFIX is to be used. */
	public static String runtimePrefix() {
		return InstanceScope.INSTANCE.getNode(KsePreferences.NODE).get(RUNTIME_PREFIX, "").strip();
	}

	/** Names the prefix ("" for the environment's); for the preference page and tests. */
	public static void setRuntimePrefix(String prefix) {
		var node = InstanceScope.INSTANCE.getNode(KsePreferences.NODE);
		if (prefix == null || prefix.isBlank()) {
			node.remove(RUNTIME_PREFIX);
		} else {
			node.put(RUNTIME_PREFIX, prefix.strip());
		}
	}
}
