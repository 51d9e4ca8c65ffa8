package org.kse.maven;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import org.apache.maven.plugin.logging.Log;

/**
 * A {@link PrintStream} for the command's output and error streams that hands each line to
 * Maven's log at the level the line says it has: the command writes diagnostics as
 * {@code file: label (name): error: message} (or {@code file:line:column: warning: ...} for a
 * .proto file) and its own failures as {@code kse: ...}, so a build shows them as [ERROR] and
 * [WARNING] and an IDE reading the build log can mark them. The error lines are kept for the
 * exception that fails the build, which Maven prints again at the end.
 */
final class LogLines extends OutputStream {

	private final Log log;
	private final ByteArrayOutputStream line = new ByteArrayOutputStream();
	private final List<String> errors;

	LogLines(Log log, List<String> errors) {
		this.log = log;
		this.errors = errors;
	}

	static PrintStream printStream(Log log, List<String> errors) {
		return new PrintStream(new LogLines(log, errors), true, StandardCharsets.UTF_8);
	}

	@Override
	public synchronized void write(int b) {
		if (b == '\n') {
			flushLine();
		} else if (b != '\r') {
			line.write(b);
		}
	}

	@Override
	public synchronized void write(byte[] bytes, int offset, int length) {
		for (int i = offset; i < offset + length; i++) {
			write(bytes[i]);
		}
	}

	@Override
	public synchronized void close() {
		if (line.size() > 0) {
			flushLine();
		}
	}

	private void flushLine() {
		String text = line.toString(StandardCharsets.UTF_8);
		line.reset();
		if (text.isBlank()) {
			return;
		}
		switch (level(text)) {
			case ERROR -> {
				errors.add(text);
				log.error(text);
			}
			case WARNING -> log.warn(text);
			case INFO -> log.info(text);
		}
	}

	enum Level {
		ERROR, WARNING, INFO
	}

	static Level level(String text) {
		if (text.contains(": error: ")) {
			return Level.ERROR;
		}
		if (text.contains(": warning: ")) {
			return Level.WARNING;
		}
		return text.startsWith("kse: ") ? Level.ERROR : Level.INFO;
	}
}
