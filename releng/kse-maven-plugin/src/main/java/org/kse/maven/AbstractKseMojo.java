package org.kse.maven;

import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.apache.maven.artifact.Artifact;
import org.apache.maven.plugin.AbstractMojo;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugin.descriptor.PluginDescriptor;
import org.apache.maven.plugins.annotations.Parameter;
import org.kse.cli.Kse;

/**
 * What kse:generate and kse:validate share: the model selection, the messages folders, the
 * stamp that lets an unchanged project skip the command, and the call of the command line
 * ({@link Kse}) in the build's own JVM, its output lines in Maven's log.
 */
abstract class AbstractKseMojo extends AbstractMojo {

	/** The default of {@code <models>}: the models folder of a KSE project (File > New > KSE Project). */
	static final String DEFAULT_MODELS = "models/**/*.stct";

	/**
	 * One command at a time in a class loader. EMF's package registry, the Xtext languages'
	 * injectors and the parse caches behind {@link Kse} are static; a parallel build (-T) whose
	 * modules share this plugin's class loader would otherwise set them up from two threads at
	 * once. Builds that load the plugin twice (different plugin dependencies) get two copies of
	 * those statics, so a lock per class loader is exactly what is needed.
	 */
	private static final Object COMMAND_LOCK = new Object();

	@Parameter(defaultValue = "${project.basedir}", readonly = true, required = true)
	File basedir;

	@Parameter(defaultValue = "${project.build.directory}", readonly = true, required = true)
	File buildDirectory;

	@Parameter(defaultValue = "${plugin}", readonly = true, required = true)
	PluginDescriptor plugin;

	@Parameter(defaultValue = "${mojoExecution.executionId}", readonly = true)
	String executionId;

	/**
	 * The statechart models: files or globs relative to the project's folder ({@code *} within
	 * a folder name, {@code **} across folders). Default: {@value #DEFAULT_MODELS}. A file named
	 * without a wildcard must exist.
	 */
	@Parameter(property = "kse.models")
	List<String> models;

	/** Globs of models to leave out of {@code <models>}. */
	@Parameter
	List<String> excludes;

	/**
	 * More folders of .proto messages the models' transitions may use (every *.proto below
	 * them), besides the runtime's standard messages and the source folder's {@code messages/}.
	 */
	@Parameter(property = "kse.messages")
	List<File> messages;

	/** Skip the goal. */
	@Parameter(property = "kse.skip", defaultValue = "false")
	boolean skip;

	/** The goal's name in the messages and the stamp: "generate" or "validate". */
	abstract String goal();

	/**
	 * The models this goal runs on, or an empty list (and a line saying why) when the goal is
	 * skipped or no model matches.
	 */
	List<Path> modelsToRun() throws MojoExecutionException {
		if (skip) {
			getLog().info("KSE: skipped (kse.skip)");
			return List.of();
		}
		List<Path> modelFiles = selectModels();
		if (modelFiles.isEmpty()) {
			getLog().info("KSE: no models in " + basedir + " match " + (models == null || models.isEmpty() ? DEFAULT_MODELS : models) + ", nothing to " + goal());
		}
		return modelFiles;
	}

	List<Path> selectModels() throws MojoExecutionException {
		List<String> patterns = models == null || models.isEmpty() ? List.of(DEFAULT_MODELS) : models;
		return ModelSelection.select(basedir.toPath(), patterns, excludes == null ? List.of() : excludes);
	}

	List<Path> messagesFolders() {
		List<Path> folders = new ArrayList<>();
		if (messages != null) {
			for (File folder : messages) {
				folders.add(absolute(folder));
			}
		}
		return folders;
	}

	Path absolute(File file) {
		return file.isAbsolute() ? file.toPath().normalize() : basedir.toPath().resolve(file.toPath()).normalize();
	}

	Path stampFile() {
		String execution = executionId == null || executionId.isBlank() ? "default" : executionId.replaceAll("[^A-Za-z0-9._-]", "_");
		return buildDirectory.toPath().resolve("kse").resolve(goal() + "-" + execution + ".stamp");
	}

	/**
	 * The inputs every goal's stamp starts with: the plugin and each KSE jar it runs (a
	 * reinstalled SNAPSHOT of the generator must regenerate, though its version did not change),
	 * and the models.
	 */
	Stamp stamp(List<Path> modelFiles) throws IOException {
		Stamp stamp = new Stamp();
		stamp.input("plugin", plugin.getId());
		for (Artifact artifact : plugin.getArtifacts()) {
			File file = artifact.getFile();
			if ("org.kse".equals(artifact.getGroupId()) && file != null && file.isFile()) {
				stamp.file("jar", file.toPath());
			}
		}
		for (Path model : modelFiles) {
			stamp.file("model", model);
		}
		return stamp;
	}

	/**
	 * The .proto inputs both goals read: the source folder's messages/ (only it: the folder
	 * appearing without one is no change) and each --messages folder.
	 */
	static void stampMessages(Stamp stamp, Path sourceFolder, List<Path> messageFolders) throws IOException {
		stamp.protos(sourceFolder.resolve("messages"));
		for (Path messagesFolder : messageFolders) {
			stamp.protos(messagesFolder);
		}
	}

	/** The command's --messages options. */
	static void addMessages(List<String> args, List<Path> messageFolders) {
		for (Path messagesFolder : messageFolders) {
			args.add("--messages");
			args.add(messagesFolder.toString());
		}
	}

	static String models(int count) {
		return count + (count == 1 ? " model" : " models");
	}

	/** Runs the command line once, its output in the log, and returns its exit code. */
	int run(List<String> errors, String... args) {
		getLog().debug("KSE: kse " + String.join(" ", args));
		try (PrintStream out = LogLines.printStream(getLog(), errors); PrintStream err = LogLines.printStream(getLog(), errors)) {
			synchronized (COMMAND_LOCK) {
				return new Kse(out, err).run(args);
			}
		}
	}

	/** Exit 1 fails the build as a problem of the models, exit 2 as one of the build. */
	void check(int exitCode, String what, List<String> errors) throws MojoFailureException, MojoExecutionException {
		String diagnostics = errors.isEmpty() ? "" : ":\n" + String.join("\n", errors);
		if (exitCode == Kse.INVALID) {
			throw new MojoFailureException("KSE: " + what + diagnostics);
		}
		if (exitCode != Kse.OK) {
			throw new MojoExecutionException("KSE: kse " + goal() + " could not run" + diagnostics);
		}
	}

	static void deleteStamp(Path stampFile) throws MojoExecutionException {
		try {
			Files.deleteIfExists(stampFile);
		} catch (IOException e) {
			throw new MojoExecutionException("KSE: cannot delete " + stampFile + ": " + e.getMessage(), e);
		}
	}
}
