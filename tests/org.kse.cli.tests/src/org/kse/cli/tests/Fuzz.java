package org.kse.cli.tests;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.kse.cli.Kse;
import org.kse.testing.NetworkTrap;

/**
 * Runs the {@code kse} command in-process on hostile inputs and holds each run to what a user
 * may expect (issue 13): an exit code of 0, 1 or 2; a message with every failure and none after
 * success; no Java in sight; a position with every error about a text; an end within the time
 * budget; no connection to the network; no file written outside the output folder. A failing
 * input is saved under {@code target/fuzz-failures} with the seed that made it.
 */
final class Fuzz implements AutoCloseable {

	/** The seed of a run; KSE_FUZZ_SEED=N (or -Dkse.fuzz.seed=N) replays one. */
	static final long SEED = Long.getLong("kse.fuzz.seed", Long.parseLong(System.getenv().getOrDefault("KSE_FUZZ_SEED", "20261123")));
	/** Inputs per kind; KSE_FUZZ_INPUTS=N for a longer run. */
	static final int INPUTS = Integer.getInteger("kse.fuzz.inputs", Integer.parseInt(System.getenv().getOrDefault("KSE_FUZZ_INPUTS", "1000")));
	/** The longest one command may take on one input (a hang is a failure, not a wait). */
	static final long BUDGET_MILLIS = Long.getLong("kse.fuzz.budget", 15_000);

	static final Path REPOSITORY = Path.of(System.getProperty("kse.repository", "../.."));

	/** Java or its libraries showing through: a trace, a class name, an object's identity, a parser's own prefix. */
	private static final Pattern JAVA = Pattern.compile(
			"\\tat |\\b[A-Z]\\w*(Exception|Error)\\b|\\bjava\\.|\\bjavax\\.|\\bjdk\\.|org\\.eclipse\\.|org\\.kse\\.|com\\.google\\.|Impl@|@[0-9a-f]{6,}\\b"
					+ "|\\[Fatal Error\\]|For input string|\\bnull\\b(?! device)");
	/** A position in a text (line:column) or a model element as diagnostics name it ("0.3 (Scan)", "0.1->0.2 (name)"). */
	private static final Pattern POSITION = Pattern.compile(":\\d+:\\d+\\b|\\b\\d+:\\d+: |: .+ \\(.*\\): (error|warning): ");
	/** The one-line summary after a list of positioned errors. */
	private static final Pattern SUMMARY = Pattern.compile("^(kse: )?.*: \\d+ errors?(, .*)?$");

	final Path sandbox;
	final Path in;
	final Path out;
	private final NetworkTrap network = new NetworkTrap();
	private final ExecutorService runner = Executors.newSingleThreadExecutor(r -> {
		Thread thread = new Thread(r, "kse-fuzz");
		thread.setDaemon(true);
		return thread;
	});
	private final List<String> failures = new ArrayList<>();
	private final String kind;
	private boolean stuck;
	private int runs;
	private long started = System.nanoTime();

	Fuzz(String kind, Path sandbox) throws IOException {
		this.kind = kind;
		this.sandbox = sandbox;
		this.in = Files.createDirectories(sandbox.resolve("in"));
		this.out = Files.createDirectories(sandbox.resolve("out"));
	}

	/** An address that answers nothing; hostile inputs point at it. */
	String remote() {
		return network.remote();
	}

	record Run(int code, String out, String err) {
		String all() {
			return "exit " + code + "\n--- out:\n" + out + "--- err:\n" + err;
		}
	}

	/**
	 * Runs one command on the input that {@code index} names and checks it. Returns null when the
	 * run broke a rule (already recorded), so the caller skips what depends on it.
	 */
	Run kse(int index, byte[] input, String... args) {
		if (stuck) {
			return null;
		}
		runs++;
		Map<Path, Long> before = filesOutsideTarget();
		ByteArrayOutputStream outBytes = new ByteArrayOutputStream();
		ByteArrayOutputStream errBytes = new ByteArrayOutputStream();
		// What a library prints on the process's own streams reaches the user's terminal too.
		PrintStream systemOut = System.out;
		PrintStream systemErr = System.err;
		PrintStream outStream = new PrintStream(outBytes, true, StandardCharsets.UTF_8);
		PrintStream errStream = new PrintStream(errBytes, true, StandardCharsets.UTF_8);
		System.setOut(outStream);
		System.setErr(errStream);
		Future<Integer> future = runner.submit(() -> new Kse(outStream, errStream).run(args));
		int code;
		try {
			code = future.get(BUDGET_MILLIS, TimeUnit.MILLISECONDS);
		} catch (TimeoutException e) {
			stuck = true; // the thread cannot be stopped; no later run would be fair
			fail(index, input, "took longer than " + BUDGET_MILLIS + " ms: kse " + String.join(" ", args));
			return null;
		} catch (Exception e) {
			fail(index, input, "the command threw " + e.getCause() + ": kse " + String.join(" ", args));
			return null;
		} finally {
			System.setOut(systemOut);
			System.setErr(systemErr);
		}
		Run run = new Run(code, outBytes.toString(StandardCharsets.UTF_8), errBytes.toString(StandardCharsets.UTF_8));
		List<String> broken = new ArrayList<>();
		if (code != Kse.OK && code != Kse.INVALID && code != Kse.FAILED) {
			broken.add("exit code " + code);
		}
		String text = run.out() + run.err();
		if (code != Kse.OK && run.err().isBlank() && !run.out().contains("error")) {
			broken.add("a failure without a message");
		}
		if (code == Kse.OK && (text.contains(": error:") || text.contains(" stopped: "))) {
			broken.add("exit 0 after an error");
		}
		if (text.contains(" stopped: ")) {
			broken.add("an internal error");
		}
		var java = JAVA.matcher(text.replace(sandbox.toString(), "<sandbox>"));
		if (java.find()) {
			broken.add("Java on the terminal: '" + java.group() + "'");
		}
		for (String line : text.split("\n")) {
			if (line.contains("error") && !SUMMARY.matcher(line).matches() && !line.startsWith("kse: ") && !POSITION.matcher(line).find()) {
				broken.add("an error without a position: " + line);
				break;
			}
		}
		String reached = network.take();
		if (reached != null) {
			broken.add(reached);
		}
		if (!before.equals(filesOutsideTarget())) {
			broken.add("wrote outside " + out);
		}
		if (!broken.isEmpty()) {
			fail(index, input, String.join("; ", broken) + ": kse " + String.join(" ", args).replace(sandbox.toString(), "<sandbox>") + "\n" + run.all());
		}
		return run;
	}

	/** Empties the output folder before the next input. */
	void clearOutput() {
		delete(out);
		try {
			Files.createDirectories(out);
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}

	private Map<Path, Long> filesOutsideTarget() {
		Map<Path, Long> files = new TreeMap<>();
		try (Stream<Path> walk = Files.walk(sandbox.getParent())) {
			walk.filter(p -> !p.startsWith(out) && !p.startsWith(in) && Files.isRegularFile(p)).forEach(p -> {
				try {
					files.put(p, Files.size(p) ^ Files.getLastModifiedTime(p).toMillis());
				} catch (IOException gone) {
					files.put(p, -1L);
				}
			});
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
		return files;
	}

	void fail(int index, byte[] input, String why) {
		String name = kind + "-" + index;
		try {
			Path saved = Files.createDirectories(Path.of("target", "fuzz-failures")).resolve(name);
			Files.write(saved, input);
			Files.writeString(saved.resolveSibling(name + ".txt"), "seed " + SEED + ", input " + index + "\n" + why + "\n");
		} catch (IOException e) {
			why += " (could not save the input: " + e.getMessage() + ")";
		}
		failures.add(name + ": " + why);
	}

	/** What went wrong, and the figures of the run. */
	String summary() {
		double seconds = (System.nanoTime() - started) / 1e9;
		return String.format("[ fuzz ] %s: %d commands on %d inputs in %.1f s (%.0f commands/s), seed %d, %d failing", kind, runs, INPUTS, seconds,
				runs / seconds, SEED, failures.size());
	}

	List<String> failures() {
		return failures;
	}

	@Override
	public void close() throws IOException {
		runner.shutdownNow();
		network.close();
	}

	static void delete(Path folder) {
		if (!Files.exists(folder)) {
			return;
		}
		try (Stream<Path> walk = Files.walk(folder)) {
			for (Path path : walk.sorted(Comparator.reverseOrder()).toList()) {
				Files.delete(path);
			}
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
	}
}
