package org.kse.simulation;

import java.io.BufferedReader;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * A script in the conformance suite's format (tests/conformance/README.md), read: the format
 * {@link Trace} writes. Commands start at the first column; the lines a command must cause are
 * indented below it; comments and the {@code model} line are not steps.
 */
public final class Script {

	/** A command, the line of the file it is on, and the lines listed under it (none: not checked). */
	public record Step(int line, String command, List<String> expected) {
	}

	private Script() {
	}

	/** Reads a script; an indented line before any command is an error naming its line. */
	public static List<Step> read(BufferedReader input) throws IOException {
		List<Step> steps = new ArrayList<>();
		int number = 0;
		for (String raw; (raw = input.readLine()) != null;) {
			number++;
			String line = raw.strip();
			if (line.isEmpty() || line.startsWith("#")) {
				continue;
			}
			if (Character.isWhitespace(raw.charAt(0))) {
				if (steps.isEmpty()) {
					throw new IOException("line " + number + ": an expected line before any command");
				}
				steps.get(steps.size() - 1).expected().add(line);
			} else if (!line.startsWith("model ")) {
				steps.add(new Step(number, line, new ArrayList<>()));
			}
		}
		return steps;
	}
}
