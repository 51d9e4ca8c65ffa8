package org.kse.maven;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;

/**
 * Checks the models against the statechart rules and the transition grammar, as
 * {@code kse validate} does, and fails the build when one has an error. Skipped when the same
 * models, messages and options passed last time.
 */
@Mojo(name = "validate", defaultPhase = LifecyclePhase.VALIDATE, threadSafe = true)
public class ValidateMojo extends AbstractKseMojo {

	/**
	 * The Monas source folder whose {@code messages/*.proto} the models are checked against
	 * (as kse:generate reads them). Default: {@code src}, the source folder of kse:generate,
	 * used when it exists.
	 */
	@Parameter(property = "kse.sourceFolder", alias = "outputDirectory")
	File sourceFolder;

	@Override
	String goal() {
		return "validate";
	}

	@Override
	public void execute() throws MojoExecutionException, MojoFailureException {
		List<Path> modelFiles = modelsToRun();
		if (modelFiles.isEmpty()) {
			return;
		}
		Path folder = sourceFolder();
		List<Path> messageFolders = messagesFolders();
		Path stampFile = stampFile();
		Stamp stamp;
		try {
			stamp = stamp(modelFiles);
			stampMessages(stamp, folder, messageFolders);
			if (stamp.matches(stampFile, false)) {
				getLog().info("KSE: " + models(modelFiles.size()) + " up to date, nothing to validate");
				return;
			}
		} catch (IOException e) {
			throw new MojoExecutionException("KSE: cannot read the inputs: " + e.getMessage(), e);
		}
		deleteStamp(stampFile);

		// all models in one call: the standard and the tree's messages are read once
		List<String> args = new ArrayList<>(List.of("validate"));
		if (Files.isDirectory(folder)) {
			args.add("--source");
			args.add(folder.toString());
		}
		addMessages(args, messageFolders);
		modelFiles.forEach(model -> args.add(model.toString()));
		List<String> errors = new ArrayList<>();
		int exitCode = run(errors, args.toArray(String[]::new));
		long invalid = modelFiles.stream().filter(model -> errors.stream().anyMatch(line -> line.startsWith(model + ": "))).count();
		check(exitCode, invalid == 0 ? "validation failed" : invalid + " of " + models(modelFiles.size()) + (invalid == 1 ? " has" : " have") + " errors", errors);
		getLog().info("KSE: " + models(modelFiles.size()) + " valid");

		try {
			stamp.write(stampFile, "inputs of the last kse:validate that passed; delete this file to validate again", List.of());
		} catch (IOException e) {
			getLog().warn("KSE: cannot write " + stampFile + " (the next build validates again): " + e.getMessage());
		}
	}

	/** The folder named in the pom, which must exist, else the project's src (when it exists). */
	private Path sourceFolder() throws MojoExecutionException {
		if (sourceFolder == null) {
			return basedir.toPath().resolve("src").normalize();
		}
		Path folder = absolute(sourceFolder);
		// named in the pom, so meant to be there: say so rather than check without its messages
		if (!Files.isDirectory(folder)) {
			throw new MojoExecutionException("KSE: the source folder " + folder + " (from <sourceFolder>) is not a folder");
		}
		return folder;
	}
}
