package org.kse.maven;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.apache.maven.plugins.annotations.LifecyclePhase;
import org.apache.maven.plugins.annotations.Mojo;
import org.apache.maven.plugins.annotations.Parameter;
import org.kse.model.StatechartResources;

/**
 * Generates the Monas C++ of the models into a Monas source folder, as {@code kse generate}
 * does: {@code statecharts/<Model>/} (rewritten when its content changes) and
 * {@code activities/<Activity>/} skeletons (written once, then the user's). Skipped when no
 * model, no .proto file the models are checked against, no option and no generated file
 * changed since the last successful run.
 */
@Mojo(name = "generate", defaultPhase = LifecyclePhase.GENERATE_SOURCES, threadSafe = true)
public class GenerateMojo extends AbstractKseMojo {

	/**
	 * The Monas source folder the code goes into (also accepted as {@code <outputDirectory>}).
	 * Not under target/: the activities written there are skeletons the user fills in, and
	 * {@code mvn clean} must not take them. Its {@code messages/} holds the tree's own .proto
	 * files. The same parameter of kse:validate, so one plugin-level setting serves both goals.
	 */
	@Parameter(property = "kse.sourceFolder", alias = "outputDirectory", defaultValue = "${project.basedir}/src", required = true)
	File sourceFolder;

	/** Conditions print their result when evaluated (kse generate --logger). */
	@Parameter(property = "kse.logger", defaultValue = "false")
	boolean logger;

	@Override
	String goal() {
		return "generate";
	}

	@Override
	public void execute() throws MojoExecutionException, MojoFailureException {
		List<Path> modelFiles = modelsToRun();
		if (modelFiles.isEmpty()) {
			return;
		}
		Path folder = absolute(sourceFolder);
		List<Path> messageFolders = messagesFolders();
		Path stampFile = stampFile();
		Stamp stamp;
		try {
			stamp = stamp(modelFiles);
			stamp.input("option", "logger=" + logger);
			stamp.input("option", "sourceFolder=" + folder);
			stampMessages(stamp, folder, messageFolders);
			if (stamp.matches(stampFile, true)) {
				getLog().info("KSE: " + models(modelFiles.size()) + " up to date, nothing to generate");
				return;
			}
		} catch (IOException e) {
			throw new MojoExecutionException("KSE: cannot read the inputs: " + e.getMessage(), e);
		}
		deleteStamp(stampFile);

		List<String> args = new ArrayList<>(List.of("generate", "--quiet"));
		if (logger) {
			args.add("--logger");
		}
		addMessages(args, messageFolders);
		modelFiles.forEach(model -> args.add(model.toString()));
		args.add(folder.toString());
		getLog().info("KSE: generating " + models(modelFiles.size()) + " into " + folder);
		List<String> errors = new ArrayList<>();
		int exitCode = run(errors, args.toArray(String[]::new));
		check(exitCode, "generation failed, a model has errors", errors);

		try {
			stamp.write(stampFile, "inputs and outputs of the last kse:generate; delete this file to generate again", generated(modelFiles, folder));
		} catch (IOException e) {
			// the code is generated; only the next build's shortcut is lost
			getLog().warn("KSE: cannot write " + stampFile + " (the next build generates again): " + e.getMessage());
		}
	}

	/**
	 * The files under statecharts/&lt;Model&gt;/ of each model: the generator's to rewrite, so
	 * the stamp records them (the activities are the user's and may change freely).
	 */
	private List<Path> generated(List<Path> modelFiles, Path folder) throws IOException {
		List<Path> files = new ArrayList<>();
		for (Path model : modelFiles) {
			Path statechart = folder.resolve("statecharts").resolve(StatechartResources.load(model).getName());
			if (!Files.isDirectory(statechart)) {
				throw new IOException("the generator wrote no " + statechart + " for " + model);
			}
			try (Stream<Path> walk = Files.walk(statechart)) {
				walk.filter(Files::isRegularFile).sorted().forEach(files::add);
			}
		}
		return files;
	}
}
