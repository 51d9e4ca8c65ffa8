package org.kse.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.kse.simulation.Script;
import org.kse.simulation.SimulationException;
import org.kse.simulation.SimulationSession;
import org.kse.simulation.SimulatorBuilder;
import org.kse.model.statechart.Model;

/**
 * {@code kse simulate}: a statechart run on the C++ engine without a robot, driven by commands
 * typed (or read from a script) in the conformance suite's language; each command's lines are
 * printed as a case lists them, so what a user typed saves as a case (docs/simulation.md).
 */
final class Simulate {

	private final PrintStream out;
	private final PrintStream err;

	Simulate(PrintStream out, PrintStream err) {
		this.out = out;
		this.err = err;
	}

	/**
	 * Runs a script: every command in turn, its lines printed. In a case (a script that lists the
	 * lines commands cause), a command whose lines differ is reported with both. Returns whether
	 * all matched.
	 */
	boolean runScript(SimulationSession session, String origin, List<Script.Step> steps) throws IOException, SimulationException {
		// a script that lists no lines at all is a list of commands; one that lists some is a case,
		// where a command with none listed must cause none
		boolean isCase = steps.stream().anyMatch(step -> !step.expected().isEmpty());
		boolean same = true;
		for (Script.Step step : steps) {
			SimulationSession.Result result = session.execute(step.command());
			print(result);
			if (!result.ok()) {
				err.println(origin + ":" + step.line() + ": " + result.error().orElse("refused"));
				return false;
			}
			if (isCase && !step.expected().equals(result.lines())) {
				same = false;
				err.println(origin + ":" + step.line() + ": '" + step.command() + "' should give " + step.expected() + ", gave " + result.lines());
			}
		}
		return same;
	}

	/** A session on standard input: commands, `save <folder>/<Name>`, `quit`. */
	void runInteractive(SimulationSession session, Model model, Path modelFile, BufferedReader input) throws IOException, SimulationException {
		for (String raw; (raw = input.readLine()) != null;) {
			String line = raw.strip();
			if (line.isEmpty() || line.startsWith("#")) {
				continue;
			}
			if (line.equals("quit")) {
				return;
			}
			if (line.startsWith("save ")) {
				save(session, model, modelFile, Path.of(line.substring(5).strip()));
				continue;
			}
			SimulationSession.Result result = line.startsWith("breakpoints") ? breakpoints(session, line) : session.execute(line);
			print(result);
			if (!result.ok()) {
				err.println("kse simulate: " + result.error().orElse("refused"));
			}
		}
	}

	private static SimulationSession.Result breakpoints(SimulationSession session, String line) throws IOException, SimulationException {
		List<String> states = new ArrayList<>();
		List<Integer> transitions = new ArrayList<>();
		for (String word : line.substring("breakpoints".length()).strip().split("\\s+")) {
			if (word.startsWith("state:")) {
				states.add(word.substring(6));
			} else if (word.startsWith("transition:") && word.substring(11).matches("\\d{1,9}")) {
				transitions.add(Integer.parseInt(word.substring(11)));
			} else if (!word.isEmpty()) {
				throw new SimulationException("write: breakpoints [state:<label>]... [transition:<index>]..., not '" + word + "'");
			}
		}
		return session.setBreakpoints(states, transitions);
	}

	/** Saves the trace as the case {@code target}'s file name, in its folder. */
	Path save(SimulationSession session, Model model, Path modelFile, Path target) throws IOException {
		Path folder = target.toAbsolutePath().getParent();
		String name = target.getFileName().toString().replaceAll("\\.case$", "");
		try {
			Path saved = session.trace().saveCase(folder, name, model, List.of("Recorded with kse simulate on " + modelFile.getFileName() + " (statechart "
					+ session.model() + "); the lines under each command are what it must cause."));
			err.println("saved the case " + saved + " and its statechart " + folder.resolve(name + ".stct"));
			return saved;
		} catch (IllegalArgumentException | IllegalStateException e) {
			err.println("kse simulate: " + e.getMessage());
			return null;
		}
	}

	private void print(SimulationSession.Result result) {
		if (!result.ok()) {
			return;
		}
		out.println(result.command());
		for (String line : result.lines()) {
			out.println("  " + line);
		}
		result.stopped().ifPresent(stop -> out.println("# stopped at the breakpoint of " + stop + " (" + result.time() + " ms)"));
		out.flush();
	}

	static SimulatorBuilder.Progress progress(PrintStream err, boolean quiet) {
		int[] last = { -1 };
		return (done, total, what) -> {
			if (!quiet && done != last[0]) {
				last[0] = done;
				err.println("[" + done + "/" + total + "] " + what);
			}
		};
	}
}
