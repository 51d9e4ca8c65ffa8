package org.kse.messages;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** Collects the problems of one file; capped so that a binary or garbage file stays cheap. */
final class Problems {

	static final int LIMIT = 200;

	private final Path file;
	private final List<ProtoProblem> list = new ArrayList<>();

	Problems(Path file) {
		this.file = file;
	}

	void report(int line, int column, String message) {
		if (list.size() < LIMIT) {
			list.add(new ProtoProblem(file, line, column, message));
		} else if (list.size() == LIMIT) {
			list.add(new ProtoProblem(file, line, column, "too many problems; the rest are not reported"));
		}
	}

	List<ProtoProblem> list() {
		return list;
	}
}
