package org.kse.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.kse.cli.Kse;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Transition;
import org.kse.validation.ModelValidation;
import org.kse.testing.CommandRun;

/**
 * {@code kse new-behaviour NAME} (issue 18, item 2): the project it makes has every file, a model
 * that validates with no problem and that the formula and the README's commands reproduce, the
 * commands to build and play; a bad name or a folder in use is refused with exit 2 and nothing
 * written. (That the project builds and plays is tests/getting-started/run.sh's part.)
 */
class NewBehaviourCommandTest {

	private static final Pattern EDIT = Pattern.compile("^kse edit-transition (\\S+) (\\S+) (\\S+) --expression '(.*)'$", Pattern.MULTILINE);

	@TempDir
	Path directory;

	private static CommandRun kse(String... args) {
		return CommandLineTest.kse(args);
	}

	@Test
	void makesAProjectWhoseModelValidatesWithNoProblemAndPrintsHowToBuildAndPlay() throws IOException {
		Path project = directory.resolve("Striker");
		CommandRun run = kse("new-behaviour", "Striker", "-o", project.toString());

		assertEquals(Kse.OK, run.code(), run.all());
		for (String file : List.of("Striker.liveness", "Striker.stct", "CMakeLists.txt", "README.md", "src/activities/common/Robot.h",
				"src/activities/Wait/Wait.h", "src/activities/Wait/Wait.cpp", "src/activities/Wait/CMakeLists.txt", "src/activities/Chase/Chase.h",
				"src/activities/Chase/Chase.cpp", "src/activities/Chase/CMakeLists.txt")) {
			assertTrue(Files.isRegularFile(project.resolve(file)), file + " in the project: " + run.all());
			assertTrue(run.out().contains("wrote " + project.resolve(file)), "says it wrote " + file + ": " + run.all());
		}
		assertEquals(List.of("CMakeLists.txt", "README.md", "Striker.liveness", "Striker.stct", "src"), list(project), "nothing else");

		Model model = StatechartResources.load(project.resolve("Striker.stct"));
		assertEquals("Striker", model.getName());
		Diagnostic diagnostic = ModelValidation.validate(model);
		assertEquals(List.of(), diagnostic.getChildren().stream().map(Diagnostic::getMessage).toList(), "no error, no warning");
		CommandRun validate = kse("validate", project.resolve("Striker.stct").toString());
		assertEquals(Kse.OK, validate.code(), validate.all());
		assertTrue(validate.err().contains("Striker.stct: 0 errors, 0 warnings"), validate.all());

		// the loop waits for its timer, and the choice follows the game state
		assertEquals("[TimeoutCheck(behavior)]/TimeoutAction.behavior.250", expression(model, "play", "play"));
		assertEquals("/TimeoutAction.behavior.250", expression(model, "0.1", "play"));
		assertEquals("[worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING]", expression(model, "0.2.2", "Chase"));
		assertTrue(expression(model, "0.2.2", "Wait").contains("player_state()!=PLAYER_PLAYING"), expression(model, "0.2.2", "Wait"));

		String printed = run.out();
		assertTrue(printed.contains("cmake -S " + project + " -B " + project.resolve("build") + " -DCMAKE_PREFIX_PATH="), printed);
		assertTrue(printed.contains("cmake --build " + project.resolve("build") + " -j 2"), printed);
		assertTrue(printed.contains(project.resolve("build/kse-match") + " --home Goalie:1,Striker:2,Striker:3 --away Goalie:1,Defender:2,Attacker:3"),
				printed);

		String cmake = read(project.resolve("CMakeLists.txt"));
		for (String line : List.of("find_package(kse_runtime REQUIRED)", "find_package(kse_examples REQUIRED)", "kse_add_statechart(Striker Striker.stct)",
				"kse_add_activities(striker_activities src/activities)", "CMAKE_PREFIX_PATH",
				"target_link_libraries(kse-match PRIVATE kse::sim_main statechart_Striker ${striker_activities} kse_examples::behaviours)")) {
			assertTrue(cmake.contains(line), "CMakeLists.txt has " + line + ":\n" + cmake);
		}
		assertTrue(read(project.resolve("src/activities/Chase/Chase.cpp")).contains("ActivityRegistrar<Chase> registrar(\"Chase\")"));
		// what the generated skeletons once lacked (issue 18): PLAYER_PLAYING needs BehaviorConst.h
		assertTrue(read(project.resolve("src/activities/common/Robot.h")).contains("#include <kse/behavior/BehaviorConst.h>"));
	}

	@Test
	void theFormulaAndTheReadmesCommandsMakeTheSameModel() throws IOException {
		Path project = directory.resolve("Keeper");
		assertEquals(Kse.OK, kse("new-behaviour", "Keeper", "-o", project.toString()).code());
		Path again = directory.resolve("again.stct");
		CommandRun transform = kse("transform", "-q", project.resolve("Keeper.liveness").toString(), "-o", again.toString());
		assertEquals(Kse.OK, transform.code(), transform.all());
		assertEquals(Kse.OK, kse("label", again.toString()).code());

		Matcher edit = EDIT.matcher(read(project.resolve("README.md")));
		int edits = 0;
		while (edit.find()) {
			assertEquals("Keeper.stct", edit.group(1));
			CommandRun run = kse("edit-transition", again.toString(), edit.group(2), edit.group(3), "--expression", edit.group(4));
			assertEquals(Kse.OK, run.code(), edit.group() + ": " + run.all());
			edits++;
		}
		assertEquals(4, edits, "the README's kse edit-transition commands");
		assertEquals(transitions(StatechartResources.load(project.resolve("Keeper.stct"))), transitions(StatechartResources.load(again)));
	}

	@Test
	void aFolderInUseIsRefusedAndLeftAlone() throws IOException {
		Path used = Files.createDirectories(directory.resolve("Striker"));
		Files.writeString(used.resolve("notes.txt"), "mine");
		CommandRun run = kse("new-behaviour", "Striker", "-o", used.toString());
		assertEquals(Kse.FAILED, run.code(), run.all());
		assertTrue(run.err().contains("kse: " + used + " exists and is not empty: nothing was written"), run.all());
		assertEquals(List.of("notes.txt"), list(used));

		Path file = Files.writeString(directory.resolve("Bot"), "a file");
		CommandRun onFile = kse("new-behaviour", "Bot", "-o", file.toString());
		assertEquals(Kse.FAILED, onFile.code(), onFile.all());
		assertTrue(onFile.err().contains("is a file, not a folder"), onFile.all());

		Path empty = Files.createDirectories(directory.resolve("empty"));
		assertEquals(Kse.OK, kse("new-behaviour", "Striker", "-o", empty.toString()).code(), "an empty folder is taken");
		assertTrue(Files.isRegularFile(empty.resolve("Striker.stct")));
	}

	@ParameterizedTest
	@CsvSource(delimiter = '|', value = {
			"striker   | must be a C++ identifier starting with a capital letter",
			"1Bot      | must be a C++ identifier starting with a capital letter",
			"My-Bot    | must be a C++ identifier starting with a capital letter",
			"A__B      | C++ reserves names with '__'",
			"Goalie    | the name of an example behaviour",
			"Scan      | the name of an example activity",
			"Chase     | taken by the new project's own formula" })
	void aNameThatCannotBeABehavioursIsRefusedWithTheReason(String name, String reason) throws IOException {
		Path folder = directory.resolve("project");
		CommandRun run = kse("new-behaviour", name, "-o", folder.toString());
		assertEquals(Kse.FAILED, run.code(), run.all());
		assertTrue(run.err().contains("kse: '" + name + "' ") && run.err().contains(reason), run.all());
		assertFalse(Files.exists(folder), "nothing written");
	}

	@Test
	void usageProblemsExitWith2() {
		assertEquals(Kse.FAILED, kse("new-behaviour").code(), "no NAME");
		assertEquals(Kse.FAILED, kse("new-behaviour", "A", "B").code(), "two names");
		assertEquals(Kse.FAILED, kse("new-behaviour", "A", "--force").code(), "an unknown option");
		CommandRun help = kse("new-behaviour", "--help");
		assertEquals(Kse.OK, help.code());
		assertTrue(help.out().contains("usage: kse new-behaviour NAME [-o DIR]") && help.out().contains("-o, --output DIR"), help.all());
	}

	@Test
	void generateWithoutTheStatechartWritesOnlyTheSkeletonsOfNewActivities() throws IOException {
		Path project = directory.resolve("Striker");
		assertEquals(Kse.OK, kse("new-behaviour", "Striker", "-o", project.toString()).code());
		Path chase = project.resolve("src/activities/Chase/Chase.cpp");
		String written = read(chase);
		Files.delete(project.resolve("src/activities/Wait/Wait.cpp"));
		Files.delete(project.resolve("src/activities/Wait/Wait.h"));
		Files.delete(project.resolve("src/activities/Wait/CMakeLists.txt"));
		Files.delete(project.resolve("src/activities/Wait"));

		CommandRun run = kse("generate", project.resolve("Striker.stct").toString(), project.resolve("src").toString(), "--no-statechart");
		assertEquals(Kse.OK, run.code(), run.all());
		assertTrue(Files.isRegularFile(project.resolve("src/activities/Wait/Wait.cpp")), "the missing activity's skeleton: " + run.all());
		assertEquals(written, read(chase), "an activity that exists is never overwritten");
		assertFalse(Files.exists(project.resolve("src/statecharts")), "no statechart in src/: " + run.all());

		CommandRun both = kse("generate", project.resolve("Striker.stct").toString(), project.resolve("src").toString(), "--no-statechart", "--no-activities");
		assertEquals(Kse.FAILED, both.code(), both.all());
		assertTrue(both.err().contains("leave nothing to write"), both.all());
	}

	private static String expression(Model model, String from, String to) {
		return model.getTransitions().stream().filter(t -> is(t, from, to)).findFirst().map(Transition::getTE).orElse(null);
	}

	private static boolean is(Transition transition, String from, String to) {
		return (from.equals(transition.getSource().getLabel()) || from.equals(transition.getSource().getName()))
				&& (to.equals(transition.getTarget().getLabel()) || to.equals(transition.getTarget().getName()));
	}

	/** Each transition as source label, target label and expression, in the model's order. */
	private static Map<String, String> transitions(Model model) {
		Map<String, String> all = new LinkedHashMap<>();
		for (Transition transition : model.getTransitions()) {
			all.put(transition.getSource().getLabel() + "->" + transition.getTarget().getLabel(), String.valueOf(transition.getTE()));
		}
		return all;
	}

	private static List<String> list(Path folder) throws IOException {
		try (Stream<Path> files = Files.list(folder)) {
			List<String> names = new ArrayList<>(files.map(file -> file.getFileName().toString()).toList());
			names.sort(null);
			return names;
		}
	}

	private static String read(Path file) throws IOException {
		return Files.readString(file, StandardCharsets.UTF_8);
	}
}
