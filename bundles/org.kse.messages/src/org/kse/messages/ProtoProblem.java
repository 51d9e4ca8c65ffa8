package org.kse.messages;

import java.nio.file.Path;

/**
 * Something wrong in a {@code .proto} file, at a 1-based line and column (columns count UTF-16
 * chars, tabs as one).
 */
public record ProtoProblem(Path file, int line, int column, String message) {

	public ProtoProblem {
		// Editors and the validator place markers with these; never let a bug send them to 0.
		line = Math.max(1, line);
		column = Math.max(1, column);
	}

	@Override
	public String toString() {
		return (file == null ? "<unknown>" : file.toString()) + ":" + line + ":" + column + ": " + message;
	}
}
