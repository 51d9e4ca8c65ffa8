package org.kse.simulation;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.kse.model.statechart.Model;
import org.kse.model.StatechartResources;

/**
 * What a simulation did, command by command, in the conformance suite's script format
 * (tests/conformance/README.md): the commands and, indented under each, the lines it caused.
 * Saved with a copy of the model, it is a conformance case: the bug a user found becomes a test.
 */
public final class Trace {

	/** One command as it ran and the lines it caused. */
	public record Entry(String command, List<String> lines) {
	}

	private static final Pattern ADVANCE = Pattern.compile("advance (\\d+)");
	private static final Pattern CASE_NAME = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");

	private final String model;
	private final List<Entry> entries = new ArrayList<>();

	public Trace(String model) {
		this.model = model;
	}

	/**
	 * Adds a command that ran. An advance right after one that caused nothing is merged into it:
	 * the engine looks only when something is due (the suite's eager runs show that extra looks
	 * change nothing), so a run of small steps reads as the one advance it amounts to.
	 */
	public synchronized void add(SimulationSession.Result result) {
		var now = ADVANCE.matcher(result.command());
		if (now.matches() && !entries.isEmpty()) {
			Entry previous = entries.get(entries.size() - 1);
			var before = ADVANCE.matcher(previous.command());
			if (before.matches() && previous.lines().isEmpty()) {
				long total = Long.parseLong(before.group(1)) + Long.parseLong(now.group(1));
				entries.set(entries.size() - 1, new Entry("advance " + total, result.lines()));
				return;
			}
		}
		entries.add(new Entry(result.command(), result.lines()));
	}

	public synchronized List<Entry> entries() {
		return List.copyOf(entries);
	}

	/** The script of a case whose statechart is named {@code caseModel}, headed by {@code comment} lines. */
	public synchronized String caseText(String caseModel, List<String> comment) {
		StringBuilder text = new StringBuilder();
		for (String line : comment) {
			text.append("# ").append(line).append('\n');
		}
		text.append("model ").append(caseModel).append('\n');
		for (Entry entry : entries) {
			text.append(entry.command()).append('\n');
			for (String line : entry.lines()) {
				text.append("  ").append(line).append('\n');
			}
		}
		return text.toString();
	}

	/**
	 * Saves the trace as the conformance case {@code name} in {@code folder}: {@code name.stct}, a
	 * copy of {@code statechart} named {@code name} (case names are the suite's statechart names,
	 * unique in a program), and {@code name.case}, the script with the lines it must give. Both
	 * written atomically; an existing case of that name is replaced.
	 *
	 * @return the case file
	 */
	public Path saveCase(Path folder, String name, Model statechart, List<String> comment) throws IOException {
		if (!CASE_NAME.matcher(name).matches()) {
			throw new IllegalArgumentException("a case's name is a C++ identifier (letters, digits, _), not '" + name + "'");
		}
		if (!started()) {
			throw new IllegalStateException("the trace has no start: start the simulation first");
		}
		Files.createDirectories(folder);
		Model copy = EcoreUtil.copy(statechart);
		copy.setName(name);
		StatechartResources.save(copy, folder.resolve(name + "." + StatechartResources.FILE_EXTENSION));
		Path caseFile = folder.resolve(name + ".case");
		StatechartResources.writeAtomically(caseFile, caseText(name, comment).getBytes(StandardCharsets.UTF_8));
		return caseFile;
	}

	public synchronized boolean started() {
		return entries.stream().anyMatch(entry -> entry.command().equals("start"));
	}

	public String model() {
		return model;
	}
}
