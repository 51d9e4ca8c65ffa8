package org.kse.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.kse.labeling.Labeler;
import org.kse.messages.StandardMessages;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.transform.FormulaTransformation;
import org.kse.validation.ModelValidation;

/**
 * {@code kse new-behaviour NAME}: a newcomer's own Monas-style project that builds against the
 * installed runtime and plays against the installed examples as written (issue 18, item 2;
 * ADR 0029). The formula, its statechart with the guards and timers that make it play, two
 * activities that do something visible, a CMake project with one convention, a README.
 */
final class NewBehaviour {

	/** A behaviour name: a C++ class name of the statechart, starting with a capital letter. */
	static final Pattern NAME = Pattern.compile("[A-Z][A-Za-z0-9_]*");

	/**
	 * Names the project cannot take: its own activities and subformula (the statechart class and
	 * an activity class of one name would be one C++ class), and the example behaviours' and
	 * their activities' (a project links the examples to play against them; ADR 0029).
	 */
	static final Set<String> EXAMPLE_BEHAVIOURS = Set.of("Goalie", "Attacker", "Defender");
	static final Set<String> EXAMPLE_ACTIVITIES = Set.of("Init", "Scan", "Stare", "Kick", "GoToPosition", "ApproachBall", "Guard", "NoPlay",
			"SpecialAction");
	static final List<String> ACTIVITIES = List.of("Wait", "Chase");

	/** Every 250 ms the choice is made again: Chase's walk follows the ball, Wait notices PLAYING. */
	static final String POLL = "TimeoutAction.behavior.250";
	static final String PLAYING = "[worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING]";
	static final String NOT_PLAYING = "[worldstate.State.GameStateMessage==NULL || worldstate.State.GameStateMessage.player_state()!=PLAYER_PLAYING]";

	/** The project as made: where, the model's size, what to type next. */
	record Made(Path folder, Model model, List<Path> files) {
	}

	private NewBehaviour() {
	}

	/** Why a name cannot be a behaviour's, or null when it can. */
	static String nameProblem(String name) {
		if (!NAME.matcher(name).matches()) {
			return "'" + name + "' is not a behaviour name: NAME must be a C++ identifier starting with a capital letter "
					+ "(letters, digits and _ after it), e.g. Striker";
		}
		if (name.contains("__")) {
			return "'" + name + "' is not a behaviour name: C++ reserves names with '__'";
		}
		if (EXAMPLE_BEHAVIOURS.contains(name)) {
			return "'" + name + "' is the name of an example behaviour, which the project plays against: choose another NAME";
		}
		if (EXAMPLE_ACTIVITIES.contains(name)) {
			return "'" + name + "' is the name of an example activity (names are global in a program): choose another NAME";
		}
		if (ACTIVITIES.contains(name) || name.equals("Play")) {
			return "'" + name + "' is taken by the new project's own formula (" + String.join(", ", ACTIVITIES) + ", play): choose another NAME";
		}
		return null;
	}

	static String formula(String name) {
		String root = rootName(name);
		return name + "\n"
				+ "// " + name + ": the liveness formula of the behaviour (kse transform turns it into " + name + ".stct).\n"
				+ "// Forever: choose Wait or Chase, again and again. Which one, and how often, the guards and\n"
				+ "// timers of " + name + ".stct say: Chase while the game is in PLAYING, Wait otherwise, every 250 ms.\n"
				+ root + " = play~\n"
				+ "play = Wait | Chase\n";
	}

	static String rootName(String name) {
		return Character.toLowerCase(name.charAt(0)) + name.substring(1);
	}

	/**
	 * The formula's statechart, labelled, with the expressions that make it play (what the
	 * project's README shows as kse edit-transition commands). Checked here: a model that would
	 * not validate with 0 errors and 0 warnings is an internal error, never a project.
	 */
	static Model model(String name, Path formulaFile) {
		FormulaTransformation.Outcome outcome = FormulaTransformation.run(formula(name), URI.createFileURI(formulaFile.toAbsolutePath().toString()), null);
		List<String> problems = new ArrayList<>();
		outcome.issues().stream().filter(issue -> issue.getSeverity() == Severity.ERROR || issue.getSeverity() == Severity.WARNING)
				.forEach(issue -> problems.add(issue.getMessage()));
		if (outcome.model() == null || !problems.isEmpty()) {
			throw new IllegalStateException("the formula of a new behaviour does not transform cleanly: " + problems);
		}
		Model model = outcome.model();
		Labeler.label(model);
		for (Map.Entry<String[], String> guard : expressions(model).entrySet()) {
			transition(model, guard.getKey()[0], guard.getKey()[1]).setTE(guard.getValue());
		}
		Diagnostic diagnostic = ModelValidation.validate(model, StandardMessages.catalog());
		if (!diagnostic.getChildren().isEmpty()) {
			throw new IllegalStateException("the statechart of a new behaviour has problems: "
					+ diagnostic.getChildren().stream().map(Diagnostic::getMessage).toList());
		}
		return model;
	}

	/**
	 * The four expressions, by the labels (or names) of the states each transition leaves and
	 * enters: the timer set when play starts, play restarting when it passed (a polling loop:
	 * without its guard the loop would spin), and the choice by the game state.
	 */
	static Map<String[], String> expressions(Model model) {
		Node root = model.getNodes().get(0);
		Node start = child(root, "START");
		Node play = named(root, "play");
		Node condition = child(play, "CONDITION");
		Map<String[], String> expressions = new LinkedHashMap<>();
		expressions.put(new String[] { start.getLabel(), "play" }, "/" + POLL);
		expressions.put(new String[] { "play", "play" }, "[TimeoutCheck(behavior)]/" + POLL);
		expressions.put(new String[] { condition.getLabel(), "Chase" }, PLAYING);
		expressions.put(new String[] { condition.getLabel(), "Wait" }, NOT_PLAYING);
		return expressions;
	}

	private static Node child(Node parent, String type) {
		return parent.getChildren().stream().filter(node -> type.equals(node.getType())).findFirst()
				.orElseThrow(() -> new IllegalStateException("no " + type + " state in " + parent.getName()));
	}

	private static Node named(Node parent, String name) {
		return parent.getChildren().stream().filter(node -> name.equals(node.getName())).findFirst()
				.orElseThrow(() -> new IllegalStateException("no state " + name + " in " + parent.getName()));
	}

	private static Transition transition(Model model, String from, String to) {
		return model.getTransitions().stream().filter(t -> is(t.getSource(), from) && is(t.getTarget(), to)).findFirst()
				.orElseThrow(() -> new IllegalStateException("no transition " + from + " -> " + to));
	}

	private static boolean is(Node node, String id) {
		return id.equals(node.getLabel()) || id.equals(node.getName());
	}

	/** Makes the project in {@code folder}, which the caller checked is missing or empty. */
	static Made make(String name, Path folder) throws IOException {
		Path formulaFile = folder.resolve(name + ".liveness");
		Model model = model(name, formulaFile);
		Map<Path, String> files = new LinkedHashMap<>();
		files.put(formulaFile, formula(name));
		files.put(folder.resolve("CMakeLists.txt"), ProjectFiles.cmake(name));
		files.put(folder.resolve("README.md"), ProjectFiles.readme(name, model));
		Path activities = folder.resolve("src").resolve("activities");
		files.put(activities.resolve("common").resolve("Robot.h"), ProjectFiles.robotHeader(name));
		for (String activity : ACTIVITIES) {
			Path dir = activities.resolve(activity);
			files.put(dir.resolve(activity + ".h"), ProjectFiles.activityHeader(activity));
			files.put(dir.resolve(activity + ".cpp"), activity.equals("Chase") ? ProjectFiles.chase(name) : ProjectFiles.waitActivity(name));
			files.put(dir.resolve("CMakeLists.txt"), ProjectFiles.activityCmake(activity));
		}
		Files.createDirectories(folder);
		List<Path> written = new ArrayList<>();
		for (Map.Entry<Path, String> file : files.entrySet()) {
			Files.createDirectories(file.getKey().getParent());
			Files.writeString(file.getKey(), file.getValue(), StandardCharsets.UTF_8);
			written.add(file.getKey());
		}
		Path stct = folder.resolve(name + ".stct");
		StatechartResources.save(model, stct);
		written.add(1, stct);
		return new Made(folder, model, written);
	}
}
