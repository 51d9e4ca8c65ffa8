package org.kse.simulation;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Where the KSE C++ runtime is installed (its CMake package): the simulator is built against it.
 * Named by the user (an option or a preference), else by {@code KSE_RUNTIME_PREFIX}, the variable
 * {@code kse demo} reads too.
 */
public final class RuntimePrefix {
	public static final String VARIABLE = "KSE_RUNTIME_PREFIX";

	private static final List<String> PACKAGE_FOLDERS = List.of("lib/cmake/kse_runtime", "lib64/cmake/kse_runtime",
			"lib/x86_64-linux-gnu/cmake/kse_runtime", "lib/aarch64-linux-gnu/cmake/kse_runtime");

	private RuntimePrefix() {
	}

	/** The prefix named (or {@code KSE_RUNTIME_PREFIX} when {@code named} is null or blank), checked. */
	public static Path resolve(String named) throws SimulationException {
		String value = named == null || named.isBlank() ? System.getenv(VARIABLE) : named;
		if (value == null || value.isBlank()) {
			throw new SimulationException("the simulation is built against an installed KSE runtime: name its install prefix"
					+ " (the folder given to cmake --install; ./kse demo makes one in target/demo/runtime-prefix)"
					+ " with --runtime DIR (kse simulate), Window > Preferences > KSE > Simulation (the workbench), or " + VARIABLE);
		}
		Path prefix = Path.of(value).toAbsolutePath().normalize();
		if (!Files.isDirectory(prefix)) {
			throw new SimulationException("no KSE runtime at " + prefix + ": the folder does not exist");
		}
		for (String folder : PACKAGE_FOLDERS) {
			if (Files.isRegularFile(prefix.resolve(folder).resolve("kse_runtimeConfig.cmake"))) {
				return prefix;
			}
		}
		throw new SimulationException("no KSE runtime at " + prefix + ": it has no lib/cmake/kse_runtime/kse_runtimeConfig.cmake"
				+ " (install the runtime there with cmake --install)");
	}
}
