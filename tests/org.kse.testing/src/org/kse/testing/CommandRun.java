package org.kse.testing;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

/** A command run in-process with its output captured: how the tests run {@code kse}. */
public record CommandRun(int code, String out, String err) {

	/** A command that prints to the streams it is given and returns its exit code. */
	public interface Command {
		int run(PrintStream out, PrintStream err);
	}

	public static CommandRun capture(Command command) {
		ByteArrayOutputStream out = new ByteArrayOutputStream();
		ByteArrayOutputStream err = new ByteArrayOutputStream();
		int code;
		try (PrintStream outStream = new PrintStream(out, true, StandardCharsets.UTF_8);
				PrintStream errStream = new PrintStream(err, true, StandardCharsets.UTF_8)) {
			code = command.run(outStream, errStream);
		}
		return new CommandRun(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
	}

	/** Everything a failed assertion should show. */
	public String all() {
		return "exit " + code + "\n--- out:\n" + out + "--- err:\n" + err;
	}
}
