package org.kse.cli;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * The training run of the kse command's ahead-of-time cache (ADR 0023): each headless command
 * once, in one JVM, on a formula and a model, so that the cache holds the classes every command
 * loads and links. Run by the build that makes the launcher; a user never runs it.
 * <p>
 * Arguments: a scratch folder, a formula file, a model file.
 */
public final class StartupTraining {

	private StartupTraining() {
	}

	public static void main(String[] args) throws IOException {
		if (args.length != 3) {
			System.err.println("usage: StartupTraining <scratch-folder> <formula> <model.stct>");
			System.exit(Kse.FAILED);
		}
		Path scratch = Files.createDirectories(Path.of(args[0]));
		String formula = args[1];
		String model = args[2];
		String transformed = scratch.resolve("Trained.stct").toString();
		List<List<String>> commands = List.of(
				List.of("version"),
				List.of("transform", "-q", formula, "-o", transformed),
				List.of("validate", transformed),
				List.of("label", transformed),
				List.of("validate", model, "--source", scratch.toString()),
				List.of("generate", "-q", model, "-o", scratch.resolve("src").toString()),
				List.of("generate", "-q", model, "-o", scratch.resolve("src").toString()),
				List.of("diagram", model, "-o", scratch.resolve("model.svg").toString()),
				List.of("diagram", "--arrange", transformed));
		PrintStream discard = new PrintStream(OutputStream.nullOutputStream());
		PrintStream err = System.err;
		for (List<String> command : commands) {
			int code = new Kse(discard, discard).run(command.toArray(String[]::new));
			if (code != Kse.OK) {
				// a training run on a broken example would make a cache of the wrong classes
				err.println("StartupTraining: 'kse " + String.join(" ", command) + "' exited with " + code);
				System.exit(code);
			}
		}
		System.exit(Kse.OK);
	}
}
