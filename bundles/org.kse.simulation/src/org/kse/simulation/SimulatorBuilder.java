package org.kse.simulation;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Deque;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.kse.generator.monas.GenerationPlan;
import org.kse.generator.monas.MonasGenerator;
import org.kse.model.statechart.Model;
import org.kse.model.StatechartResources;

/**
 * Builds the simulator of a statechart: its Monas C++ (the statechart only: the activities are the
 * simulation's stand-ins), compiled with CMake against the installed runtime into a program that
 * serves a simulation session (kse_add_simulator, docs/simulation.md). The engine that runs it is
 * the one a robot runs; nothing of the rules is written again here.
 *
 * <p>Each model has its own folder; a second build writes only the files that changed, so an
 * unchanged model is ready at once and an edited one recompiles its statechart only.
 */
public final class SimulatorBuilder {

	/** A built simulator: the program, the statechart's name in it and its activities. */
	public record Simulator(Path program, String model, List<String> activities, Path folder) {
	}

	/** Reports each step of a build (of {@code total}); asked often whether to stop. */
	public interface Progress {
		Progress NONE = (done, total, what) -> {
		};

		void step(int done, int total, String what);

		default boolean isCancelled() {
			return false;
		}
	}

	/** The steps a build reports: generating (3), configuring (1), compiling (up to 100). */
	public static final int STEPS = 104;

	private static final Pattern NINJA_PROGRESS = Pattern.compile("^\\[(\\d+)/(\\d+)\\]\\s*(.*)$");
	private static final int LOG_TAIL = 25;

	private SimulatorBuilder() {
	}

	/** The folder a model's simulator is built in unless told otherwise: one per model file, in the user's cache. */
	public static Path defaultFolder(Path modelFile) {
		String base = System.getenv("XDG_CACHE_HOME");
		Path cache = base != null && !base.isBlank() ? Path.of(base) : Path.of(System.getProperty("user.home"), ".cache");
		String file = modelFile.toAbsolutePath().normalize().toString();
		String name = modelFile.getFileName().toString().replaceAll("\\.stct$", "").replaceAll("[^A-Za-z0-9_-]", "_");
		return cache.resolve("kse").resolve("simulators").resolve(name + "-" + digest(file).substring(0, 12));
	}

	/**
	 * Builds (or brings up to date) the simulator of {@code model} in {@code folder} against the
	 * runtime installed in {@code runtimePrefix}.
	 *
	 * @throws MonasGenerator.ModelHasErrorsException the model does not validate: nothing is built
	 * @throws SimulationException CMake or the compiler failed (the message has the log's end and its path)
	 * @throws CancellationException the progress asked to stop
	 */
	public static Simulator build(Model model, Path runtimePrefix, Path folder, Progress progress)
			throws IOException, SimulationException, MonasGenerator.ModelHasErrorsException {
		Files.createDirectories(folder);
		Path source = folder.resolve("src");
		GenerationPlan plan = GenerationPlan.of(model);
		String chart = plan.className();
		removeOtherStatecharts(source.resolve("statecharts"), chart);
		MonasGenerator.generate(model, source, new MonasGenerator.Options(false, List.of(), false, true),
				(step, steps, what) -> progress.step(step, STEPS, what));
		checkCancelled(progress);
		writeIfChanged(folder.resolve("CMakeLists.txt"), cmakeLists(chart));

		Path build = folder.resolve("build");
		Path prefixFile = folder.resolve("runtime-prefix.txt");
		String prefix = runtimePrefix.toString();
		if (!Files.isRegularFile(prefixFile) || !Files.readString(prefixFile).equals(prefix) || !Files.isRegularFile(build.resolve("CMakeCache.txt"))) {
			deleteTree(build);
			progress.step(4, STEPS, "configuring the simulator of " + chart + " with CMake");
			List<String> configure = new ArrayList<>(List.of("cmake", "-S", folder.toString(), "-B", build.toString(),
					"-DCMAKE_BUILD_TYPE=RelWithDebInfo", "-DCMAKE_PREFIX_PATH=" + prefix));
			if (onPath("ninja")) {
				configure.addAll(List.of("-G", "Ninja"));
			}
			run(configure, folder.resolve("configure.log"), progress, null);
			StatechartResources.writeAtomically(prefixFile, prefix.getBytes(StandardCharsets.UTF_8));
		}
		progress.step(4, STEPS, "compiling the simulator of " + chart);
		int jobs = Math.max(1, Runtime.getRuntime().availableProcessors());
		run(List.of("cmake", "--build", build.toString(), "--target", "kse-simulator", "-j", Integer.toString(jobs)),
				folder.resolve("build.log"), progress, (done, total, what) -> progress.step(4 + Math.min(100, 100 * done / Math.max(1, total)), STEPS, what));
		Path program = build.resolve("kse-simulator");
		if (!Files.isExecutable(program)) {
			throw new SimulationException("the build made no simulator program at " + program + " (log: " + folder.resolve("build.log") + ")");
		}
		return new Simulator(program, chart, List.copyOf(plan.activities().keySet()), folder);
	}

	static String cmakeLists(String chart) {
		return "# Written by KSE for the simulation of " + chart + " (docs/simulation.md); written again on each build.\n"
				+ "cmake_minimum_required(VERSION 3.20)\n"
				+ "project(kse_simulation_" + chart + " LANGUAGES CXX)\n"
				+ "set(CMAKE_CXX_STANDARD 17)\n"
				+ "set(CMAKE_CXX_STANDARD_REQUIRED ON)\n"
				+ "find_package(kse_runtime REQUIRED)\n"
				+ "kse_add_simulator(kse-simulator SOURCE_FOLDER ${CMAKE_CURRENT_SOURCE_DIR}/src)\n";
	}

	// A model renamed since the last build would leave its old statechart beside the new one.
	private static void removeOtherStatecharts(Path statecharts, String chart) throws IOException {
		if (!Files.isDirectory(statecharts)) {
			return;
		}
		try (Stream<Path> children = Files.list(statecharts)) {
			for (Path child : children.toList()) {
				if (!child.getFileName().toString().equals(chart)) {
					deleteTree(child);
				}
			}
		}
	}

	private static void run(List<String> command, Path log, Progress progress, Progress compileSteps) throws IOException, SimulationException {
		if (!onPath(command.get(0))) {
			throw new SimulationException("the simulation needs " + command.get(0) + " on the PATH (Debian: apt-get install cmake ninja-build g++)");
		}
		Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
		process.getOutputStream().close();
		Deque<String> tail = new ArrayDeque<>();
		try (BufferedReader output = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
				Writer writer = Files.newBufferedWriter(log, StandardCharsets.UTF_8)) {
			for (String line; (line = output.readLine()) != null;) {
				writer.write(line);
				writer.write('\n');
				tail.addLast(line);
				if (tail.size() > LOG_TAIL) {
					tail.removeFirst();
				}
				Matcher step = NINJA_PROGRESS.matcher(line);
				if (compileSteps != null && step.matches()) {
					compileSteps.step(Integer.parseInt(step.group(1)), Integer.parseInt(step.group(2)), step.group(3));
				}
				if (progress.isCancelled()) {
					process.destroyForcibly();
					throw new CancellationException("the simulator's build was cancelled");
				}
			}
		}
		int status;
		try {
			status = process.waitFor();
		} catch (InterruptedException e) {
			process.destroyForcibly();
			Thread.currentThread().interrupt();
			throw new CancellationException("the simulator's build was interrupted");
		}
		if (status != 0) {
			throw new SimulationException(String.join(" ", command.subList(0, 2)) + " failed (exit " + status + "); the end of its log, "
					+ log + ":\n" + String.join("\n", tail));
		}
	}

	private static void checkCancelled(Progress progress) {
		if (progress.isCancelled()) {
			throw new CancellationException("the simulator's build was cancelled");
		}
	}

	private static void writeIfChanged(Path file, String content) throws IOException {
		byte[] bytes = content.getBytes(StandardCharsets.UTF_8);
		if (!Files.isRegularFile(file) || !java.util.Arrays.equals(Files.readAllBytes(file), bytes)) {
			StatechartResources.writeAtomically(file, bytes);
		}
	}

	/** Whether a program of that name is on the PATH: the simulation's tools are looked for there. */
	public static boolean onPath(String program) {
		String path = System.getenv("PATH");
		if (path == null) {
			return false;
		}
		for (String folder : path.split(java.io.File.pathSeparator)) {
			if (!folder.isEmpty() && Files.isExecutable(Path.of(folder, program))) {
				return true;
			}
		}
		return false;
	}

	private static void deleteTree(Path root) throws IOException {
		if (!Files.exists(root)) {
			return;
		}
		try (Stream<Path> paths = Files.walk(root)) {
			for (Path path : paths.sorted(Comparator.reverseOrder()).toList()) {
				Files.delete(path);
			}
		}
	}

	private static String digest(String text) {
		try {
			return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(text.getBytes(StandardCharsets.UTF_8)));
		} catch (NoSuchAlgorithmException e) {
			throw new IllegalStateException("SHA-256 is part of every Java platform", e);
		}
	}
}
