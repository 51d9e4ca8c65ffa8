package org.kse.cli.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.testing.Models.child;
import static org.kse.testing.Models.root;
import static org.kse.testing.Models.transition;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kse.testing.CommandRun;
import org.kse.testing.Models;
import org.kse.cli.Kse;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.validation.ModelValidation;

/** The {@code kse} command line, run in-process on files in a temporary directory. */
class CommandLineTest {

	@TempDir
	Path directory;

	static CommandRun kse(String... args) {
		return CommandRun.capture((out, err) -> new Kse(out, err).run(args));
	}

	// ------------------------------------------------------------------ transform

	@Test
	void transformWritesTheModelNextToTheFormula() throws IOException {
		Path formula = copyLegacy("Goalie/Goalie.txt");
		CommandRun run = kse("transform", formula.toString());

		Path model = directory.resolve("Goalie.stct");
		assertEquals(Kse.OK, run.code(), run.all());
		assertTrue(run.out().contains("wrote " + model), run.all());
		assertTrue(run.out().contains("48 states, 46 transitions"), run.all());
		assertTrue(run.err().contains("[1/3]") && run.err().contains("[3/3]"), "progress lines: " + run.all());
		assertTrue(Files.isRegularFile(model), "the model next to the formula");

		Model goalie = StatechartResources.load(model);
		assertEquals("Goalie", goalie.getName(), "the model's name from the file's first line");
		Node root = goalie.getNodes().get(0);
		assertEquals("goalie", root.getName());
		assertEquals("0", root.getLabel());
		assertEquals(48, Models.allNodes(goalie).size());
		assertEquals(46, goalie.getTransitions().size());
		Node init = Models.byLabel(goalie, "0.2");
		assertEquals("Init", init.getName());
		assertEquals("BASIC", init.getType());
		assertEquals("_open_group_playing_or_nonPlaying_close_group__one_or_more_times_", Models.byLabel(goalie, "0.3").getName());
		assertEquals("Scan", Models.byLabel(goalie, "0.3.2.3.3.2").getName());
		Diagnostic validation = ModelValidation.validate(goalie);
		assertTrue(validation.getSeverity() < Diagnostic.ERROR, "the transformed model is valid:" + Models.render(validation));
	}

	@Test
	void transformWritesWhereOutputSays() throws IOException {
		Path formula = copyLegacy("Goalie/Goalie.txt");
		Path output = directory.resolve("out/models/keeper.stct");
		CommandRun run = kse("transform", formula.toString(), "-o", output.toString(), "--name", "Keeper", "--quiet");

		assertEquals(Kse.OK, run.code(), run.all());
		assertTrue(run.out().contains("wrote " + output), run.all());
		assertFalse(run.err().contains("[1/3]"), "--quiet: no progress lines: " + run.all());
		assertTrue(Files.isRegularFile(output));
		assertFalse(Files.exists(directory.resolve("Goalie.stct")), "no model at the default place");
		assertEquals("Keeper", StatechartResources.load(output).getName());

		Path other = directory.resolve("other.stct");
		CommandRun longOption = kse("transform", "--output", other.toString(), formula.toString());
		assertEquals(Kse.OK, longOption.code(), longOption.all());
		Model byDefaultName = StatechartResources.load(other);
		assertEquals("Goalie", byDefaultName.getName());
		Model keeper = StatechartResources.load(output);
		keeper.setName("Goalie");
		assertTrue(Models.equal(byDefaultName, keeper), "-o and --name change nothing else");
	}

	@Test
	void transformingTwiceGivesIdenticalFiles() throws IOException {
		Path formula = copyLegacy("Goalie/Goalie.txt");
		Path first = directory.resolve("first.stct");
		Path second = directory.resolve("second.stct");
		assertEquals(Kse.OK, kse("transform", formula.toString(), "-o", first.toString(), "-q").code());
		assertEquals(Kse.OK, kse("transform", formula.toString(), "-o", second.toString(), "-q").code());
		assertArrayEquals(Files.readAllBytes(first), Files.readAllBytes(second));
	}

	@Test
	void formulaWithSyntaxErrorIsReportedAtItsPositionAndNothingIsWritten() throws IOException {
		Path formula = Files.writeString(directory.resolve("broken.txt"), "Broken\nA = B . (C | D\n");
		CommandRun run = kse("transform", formula.toString());

		assertEquals(Kse.INVALID, run.code(), run.all());
		assertTrue(run.err().contains(formula + ":2:15: error: "), "the end of line 2, where ')' is missing: " + run.all());
		assertTrue(Pattern.compile("(?m)^" + Pattern.quote(formula.toString()) + ":\\d+:\\d+: error: \\S.*$").matcher(run.err()).find(), run.all());
		assertFalse(run.out().contains("wrote"), run.all());
		assertEquals(List.of(formula), list(directory), "nothing written");
	}

	@Test
	void mixedOperatorsAreAnErrorWithTheirColumn() throws IOException {
		Path formula = Files.writeString(directory.resolve("mixed.txt"), "A = B . C | D\n");
		Path output = directory.resolve("mixed-out.stct");
		CommandRun run = kse("transform", formula.toString(), "-o", output.toString());

		assertEquals(Kse.INVALID, run.code(), run.all());
		assertTrue(run.err().contains(formula + ":1:11: error: "), "the '|' at column 11: " + run.all());
		assertFalse(Files.exists(output), "nothing written at -o");
		assertEquals(List.of(formula), list(directory));
	}

	@Test
	void formulaThatIsNotTextCannotBeRead() throws IOException {
		Path formula = Files.write(directory.resolve("binary.txt"), new byte[] { (byte) 0xff, (byte) 0xfe, 0, 1, (byte) 0xc3 });
		CommandRun run = kse("transform", formula.toString());
		assertEquals(Kse.FAILED, run.code(), run.all());
		assertTrue(run.err().contains(formula.toString()), run.all());
		assertEquals(List.of(formula), list(directory));
	}

	// ------------------------------------------------------------------ validate

	@Test
	void validateAcceptsTheLegacyGoalie() {
		Path goalie = Models.legacy("Goalie/Goalie.stct");
		CommandRun run = kse("validate", goalie.toString());
		assertEquals(Kse.OK, run.code(), run.all());
		assertFalse(run.out().contains("error"), run.all());
		assertTrue(run.err().contains(goalie + ": 0 errors, 0 warnings"), run.all());
	}

	@Test
	void validateReportsEachProblemAsFileLabelNameSeverityMessage() throws IOException {
		Model model = Models.model("Parallel");
		Node root = root(model, "Main", "0", "AND");
		Node region = child(root, "Region", "0.1", "OR");
		Node start = child(region, "0.1.1", "0.1.1", "START");
		Node work = child(region, "Work", "0.1.2", "BASIC");
		transition(model, start, work, "[a.Stat.B==1]");
		Path file = directory.resolve("and-root.stct");
		StatechartResources.save(model, file);

		CommandRun run = kse("validate", file.toString());
		assertEquals(Kse.INVALID, run.code(), run.all());
		List<String> lines = run.out().lines().toList();
		assertEquals(List.of(file + ": 0 (Main): error: the root state must be an OR state, not AND",
				file + ": 0.1.1->0.1.2 (0.1.1_TO_Work): error: expression 1:4: 'Stat' is not a message kind: use Signal, State or Data"), lines, run.all());
		Pattern format = Pattern.compile(Pattern.quote(file.toString()) + ": \\S+ \\([^)]*\\): (error|warning): \\S.*");
		lines.forEach(line -> assertTrue(format.matcher(line).matches(), line));
		assertTrue(run.err().contains(file + ": 2 errors, 0 warnings"), run.all());
	}

	@Test
	void validateWithOnlyWarningsSucceeds() throws IOException {
		Model model = Models.simple();
		Models.byName(model, "Work").setLabel("0.1");
		Path file = directory.resolve("warned.stct");
		StatechartResources.save(model, file);

		CommandRun run = kse("validate", file.toString());
		assertEquals(Kse.OK, run.code(), run.all());
		assertEquals(List.of(file + ": 0.1 (Work): warning: the label is also used by 0.1 (0.1); run Label to renumber"), run.out().lines().toList(),
				run.all());
		assertTrue(run.err().contains("0 errors, 1 warning"), run.all());
	}

	@Test
	void validateFindsTheTypoInTheLegacyGuiTester() {
		Path tester = Models.legacy("GUITester/GUITester.stct");
		CommandRun run = kse("validate", tester.toString());
		assertEquals(Kse.INVALID, run.code(), run.all());
		assertTrue(run.out().startsWith(tester + ": 0.2.3.3.2->0.2.3.3.3 (GoToPositionTO0.2.3.3.3): error: expression 1:45: "), run.all());
	}

	@Test
	void validateDoesNotChangeTheFile() throws IOException {
		Path copy = copyLegacy("TestBehavior/TestBehaviorInitial.stct");
		byte[] before = Files.readAllBytes(copy);
		assertEquals(Kse.OK, kse("validate", copy.toString()).code());
		assertArrayEquals(before, Files.readAllBytes(copy));
		assertEquals(List.of(copy), list(directory));
	}

	// ------------------------------------------------------------------ label

	@Test
	void labelWritesTheFileAndLabelingAgainChangesNoByte() throws IOException {
		Path file = copyLegacy("Goalie/Goalie.stct");
		byte[] original = Files.readAllBytes(file);

		CommandRun first = kse("label", file.toString());
		assertEquals(Kse.OK, first.code(), first.all());
		assertTrue(first.out().contains("labeled " + file), first.all());
		byte[] labeled = Files.readAllBytes(file);
		assertFalse(java.util.Arrays.equals(original, labeled), "Goalie's labels had a hole (Init removed): labeling changes the file");
		Model model = StatechartResources.load(file);
		assertEquals("0.2.2.3.3.2", Models.byName(model, "Scan").getLabel());
		assertTrue(model.getTransitions().stream().anyMatch(t -> "Scan_TO_Scan".equals(t.getName())));

		CommandRun second = kse("label", file.toString());
		assertEquals(Kse.OK, second.code(), second.all());
		assertArrayEquals(labeled, Files.readAllBytes(file), "labeling a labeled file changes nothing");
		assertEquals(List.of(file), list(directory), "no temporary files left");
	}

	@Test
	void labelWithOutputLeavesTheInputAlone() throws IOException {
		Path file = copyLegacy("Goalie/Goalie.stct");
		byte[] original = Files.readAllBytes(file);
		Path output = directory.resolve("labeled.stct");

		CommandRun run = kse("label", file.toString(), "-o", output.toString());
		assertEquals(Kse.OK, run.code(), run.all());
		assertTrue(run.out().contains("labeled " + output), run.all());
		assertArrayEquals(original, Files.readAllBytes(file), "the input is not touched");
		byte[] labeled = Files.readAllBytes(output);

		Path again = directory.resolve("again.stct");
		assertEquals(Kse.OK, kse("label", output.toString(), "--output", again.toString()).code());
		assertArrayEquals(labeled, Files.readAllBytes(again));
	}

	@Test
	void transformThenLabelIsStable() throws IOException {
		Path formula = copyLegacy("Goalie/Goalie.txt");
		Path model = directory.resolve("Goalie.stct");
		assertEquals(Kse.OK, kse("transform", formula.toString(), "-q").code());
		Model transformed = StatechartResources.load(model);

		assertEquals(Kse.OK, kse("label", model.toString()).code());
		byte[] labeled = Files.readAllBytes(model);
		Model relabeled = StatechartResources.load(model);
		for (int i = 0; i < Models.allNodes(transformed).size(); i++) {
			assertEquals(Models.allNodes(transformed).get(i).getLabel(), Models.allNodes(relabeled).get(i).getLabel(),
					"the transformation already numbers states in execution order");
		}
		assertEquals(Kse.OK, kse("label", model.toString()).code());
		assertArrayEquals(labeled, Files.readAllBytes(model));
	}

	// ------------------------------------------------------------------ failures and help

	@ParameterizedTest
	@ValueSource(strings = { "transform", "validate", "label" })
	void missingFileIsNamedAndExitsWithTwo(String command) throws IOException {
		Path missing = directory.resolve("nowhere." + (command.equals("transform") ? "txt" : "stct"));
		CommandRun run = kse(command, missing.toString());
		assertEquals(Kse.FAILED, run.code(), run.all());
		assertTrue(run.err().contains(missing.toString()), run.all());
		assertEquals(List.of(), list(directory), "nothing written");
	}

	@Test
	void aFileThatIsNotAModelCannotBeValidatedOrLabeled() throws IOException {
		Path formula = copyLegacy("Goalie/Goalie.txt");
		for (String command : List.of("validate", "label")) {
			CommandRun run = kse(command, formula.toString());
			assertEquals(Kse.FAILED, run.code(), run.all());
			assertTrue(run.err().contains(formula + ":1:1: not a statechart model: the file is not XML"), run.all());
		}
		assertEquals(List.of(formula), list(directory));
	}

	@Test
	void unknownCommandExitsWithTwo() {
		CommandRun run = kse("frobnicate", "x.stct");
		assertEquals(Kse.FAILED, run.code(), run.all());
		assertTrue(run.err().contains("unknown command 'frobnicate'"), run.all());
		assertTrue(run.err().contains("--help"), run.all());
	}

	@ParameterizedTest
	@ValueSource(strings = { "transform", "validate", "label" })
	void unknownOptionExitsWithTwo(String command) {
		CommandRun run = kse(command, "--frobnicate", directory.resolve("x").toString());
		assertEquals(Kse.FAILED, run.code(), run.all());
		assertTrue(run.err().contains("unknown option --frobnicate"), run.all());
	}

	@Test
	void badUsageExitsWithTwo() {
		Path file = directory.resolve("a.stct");
		for (String[] args : new String[][] { {}, { "validate" }, { "label" }, { "transform" }, { "validate", file.toString(), file.toString() },
				{ "label", file.toString(), "-o" }, { "transform", "f.txt", "--name" } }) {
			CommandRun run = kse(args);
			assertEquals(Kse.FAILED, run.code(), () -> String.join(" ", args) + "\n" + run.all());
			assertFalse(run.err().isBlank(), () -> String.join(" ", args) + ": says why");
		}
		assertTrue(kse().err().contains("usage: kse <command>"), "no arguments: the usage");
	}

	@ParameterizedTest
	@ValueSource(strings = { "transform", "validate", "label" })
	void helpOfEachCommand(String command) {
		for (String[] args : new String[][] { { command, "--help" }, { command, "-h" }, { "help", command } }) {
			CommandRun run = kse(args);
			assertEquals(Kse.OK, run.code(), run.all());
			assertTrue(run.out().startsWith("usage: kse " + command + " "), run.all());
		}
		// help wins over a missing file argument
		assertEquals(Kse.OK, kse(command, directory.resolve("missing").toString(), "--help").code());
	}

	@Test
	void generalHelpListsTheCommands() {
		for (String[] args : new String[][] { { "--help" }, { "-h" }, { "help" } }) {
			CommandRun run = kse(args);
			assertEquals(Kse.OK, run.code(), run.all());
			assertTrue(run.out().startsWith("usage: kse <command>"), run.all());
			for (String command : List.of("transform", "validate", "label")) {
				assertTrue(run.out().contains(command), run.all());
			}
		}
	}

	// ------------------------------------------------------------------ many files in one run (issue 17, item 1)

	@Test
	void validateTakesManyModelsAndReportsEachOneEvenWhenOneCannotBeRead() throws IOException {
		Path goalie = copyLegacy("Goalie/Goalie.stct");
		Path tester = copyLegacy("TestBehavior/TestBehavior.stct");
		Path broken = directory.resolve("Broken.stct");
		Model model = Models.model("Broken");
		Node main = root(model, "Main", "0", "OR");
		transition(model, child(main, "0.1", "0.1", "START"), child(main, "0.2", "0.2", "END"), "[(");
		StatechartResources.save(model, broken);
		Path missing = directory.resolve("Missing.stct");

		CommandRun run = kse("validate", goalie.toString(), broken.toString(), missing.toString(), tester.toString());
		assertEquals(Kse.FAILED, run.code(), "a model that cannot be read makes the run fail: " + run.all());
		assertTrue(run.err().contains(goalie + ": 0 errors"), run.all());
		assertTrue(run.err().contains(tester + ": 0 errors"), "the model after the missing one is still checked: " + run.all());
		assertTrue(run.out().contains(broken + ": ") && run.out().contains(": error: "), run.all());
		assertTrue(run.err().contains("kse: " + missing), run.all());

		CommandRun withoutMissing = kse("validate", goalie.toString(), broken.toString());
		assertEquals(Kse.INVALID, withoutMissing.code(), "errors in one of the models: " + withoutMissing.all());
		CommandRun good = kse("validate", goalie.toString(), tester.toString(), "--source", directory.toString());
		assertEquals(Kse.OK, good.code(), good.all());
	}

	@Test
	void generateTakesManyModelsIntoTheFolderOfOptionO() throws IOException {
		Path goalie = copyLegacy("Goalie/Goalie.stct");
		Path tester = copyLegacy("TestBehavior/TestBehavior.stct");
		Path tree = directory.resolve("src");
		CommandRun run = kse("generate", "-q", goalie.toString(), tester.toString(), "-o", tree.toString());
		assertEquals(Kse.OK, run.code(), run.all());
		assertTrue(Files.isRegularFile(tree.resolve("statecharts/Goalie/Goalie.cpp")), run.all());
		assertTrue(Files.isRegularFile(tree.resolve("statecharts/TestBehavior/TestBehavior.cpp")), run.all());
		assertTrue(Files.isDirectory(tree.resolve("activities")), "skeletons of the activities: " + run.all());

		Path buildTree = directory.resolve("build");
		CommandRun statechartsOnly = kse("generate", "-q", "--no-activities", goalie.toString(), "-o", buildTree.toString());
		assertEquals(Kse.OK, statechartsOnly.code(), statechartsOnly.all());
		assertTrue(Files.isRegularFile(buildTree.resolve("statecharts/Goalie/Goalie.cpp")), statechartsOnly.all());
		assertFalse(Files.exists(buildTree.resolve("activities")), "--no-activities writes no skeleton: " + statechartsOnly.all());
		assertTrue(statechartsOnly.out().contains("0 activities kept"), statechartsOnly.all());
	}

	@Test
	void transformAndLabelTakeManyFiles() throws IOException {
		Path goalie = copyLegacy("Goalie/Goalie.txt");
		Path tester = copyLegacy("GUITester/GUITester.txt");
		Path models = directory.resolve("models");
		CommandRun run = kse("transform", "-q", goalie.toString(), tester.toString(), "-o", models.toString());
		assertEquals(Kse.OK, run.code(), run.all());
		assertEquals(List.of(models.resolve("GUITester.stct"), models.resolve("Goalie.stct")), list(models), run.all());

		CommandRun named = kse("transform", "-q", goalie.toString(), tester.toString(), "--name", "One");
		assertEquals(Kse.FAILED, named.code(), named.all());
		assertTrue(named.err().contains("--name names one model"), named.all());

		CommandRun label = kse("label", models.resolve("Goalie.stct").toString(), models.resolve("GUITester.stct").toString());
		assertEquals(Kse.OK, label.code(), label.all());
		assertTrue(label.out().contains("labeled " + models.resolve("Goalie.stct")) && label.out().contains("labeled " + models.resolve("GUITester.stct")),
				label.all());
		CommandRun oneOutputForTwo = kse("label", models.resolve("Goalie.stct").toString(), models.resolve("GUITester.stct").toString(), "-o", "x.stct");
		assertEquals(Kse.FAILED, oneOutputForTwo.code(), oneOutputForTwo.all());
	}

	// ------------------------------------------------------------------ edit-transition (issue 18, item 4)

	@Test
	void editTransitionSetsACheckedExpressionAndRefusesABrokenOne() throws IOException {
		Path goalie = copyLegacy("Goalie/Goalie.stct");
		org.kse.model.statechart.Transition guarded = StatechartResources.load(goalie).getTransitions().stream()
				.filter(t -> t.getTE() != null && t.getTE().contains("ballfound()>0")).findFirst().orElseThrow();
		String from = guarded.getSource().getLabel();
		String to = guarded.getTarget().getLabel();
		String expression = "[behavior.State.HeadToBMessage.ballfound()>2]/TimeoutAction.behavior.400";

		CommandRun set = kse("edit-transition", goalie.toString(), from, to, "--expression", expression);
		assertEquals(Kse.OK, set.code(), set.all());
		assertTrue(set.out().startsWith("set " + from), set.all());
		assertTrue(set.out().contains("(was " + guarded.getTE().replace("\n", " ")), set.all());
		Model changed = StatechartResources.load(goalie);
		assertEquals(1, changed.getTransitions().stream().filter(t -> expression.equals(t.getTE())).count());
		assertEquals(Kse.OK, kse("validate", goalie.toString()).code(), "the edited model still validates");

		byte[] before = Files.readAllBytes(goalie);
		CommandRun broken = kse("edit-transition", goalie.toString(), from, to, "--expression", "[behavior.State.HeadToBMesage.ballfound()>0]");
		assertEquals(Kse.INVALID, broken.code(), broken.all());
		assertTrue(broken.err().contains(": error: expression 1:17: unknown message type 'HeadToBMesage'"), broken.all());
		assertTrue(broken.err().contains("did you mean 'HeadToBMessage'"), broken.all());
		assertArrayEquals(before, Files.readAllBytes(goalie), "a refused expression leaves the file as it was");

		CommandRun syntax = kse("edit-transition", goalie.toString(), from, to, "--expression", "[(");
		assertEquals(Kse.INVALID, syntax.code(), syntax.all());
		assertArrayEquals(before, Files.readAllBytes(goalie));

		CommandRun cleared = kse("edit-transition", goalie.toString(), from, to, "--expression", "");
		assertEquals(Kse.OK, cleared.code(), cleared.all());
		assertEquals(0, StatechartResources.load(goalie).getTransitions().stream().filter(t -> expression.equals(t.getTE())).count());
	}

	@Test
	void editTransitionNamesWhatItCannotFindOrTellApart() throws IOException {
		Model model = Models.model("Twice");
		Node main = root(model, "Main", "0", "OR");
		Node start = child(main, "0.1", "0.1", "START");
		Node work = child(main, "Work", "0.2", "BASIC");
		Node end = child(main, "0.3", "0.3", "END");
		transition(model, start, work);
		transition(model, work, end, "[TimeoutCheck(behavior)]");
		transition(model, work, end);
		Path file = directory.resolve("Twice.stct");
		StatechartResources.save(model, file);

		CommandRun missing = kse("edit-transition", file.toString(), "Work", "Nowhere", "--expression", "");
		assertEquals(Kse.INVALID, missing.code(), missing.all());
		assertTrue(missing.err().contains("no state labeled or named 'Nowhere'"), missing.all());

		CommandRun none = kse("edit-transition", file.toString(), "0.3", "Work", "--expression", "");
		assertEquals(Kse.INVALID, none.code(), none.all());
		assertTrue(none.err().contains("no transition from 0.3 to 0.2 (Work)"), none.all());

		CommandRun two = kse("edit-transition", file.toString(), "Work", "0.3", "--expression", "[TimeoutCheck(motion)]");
		assertEquals(Kse.INVALID, two.code(), two.all());
		assertTrue(two.err().contains("2 transitions from 0.2 (Work) to 0.3; say which with --index:"), two.all());
		assertTrue(two.err().contains("--index 1: [TimeoutCheck(behavior)]") && two.err().contains("--index 2: (no expression)"), two.all());

		CommandRun second = kse("edit-transition", file.toString(), "Work", "0.3", "--index", "2", "--expression", "[TimeoutCheck(motion)]");
		assertEquals(Kse.OK, second.code(), second.all());
		assertEquals("[TimeoutCheck(motion)]", StatechartResources.load(file).getTransitions().get(2).getTE());

		CommandRun usage = kse("edit-transition", file.toString(), "Work", "0.3");
		assertEquals(Kse.FAILED, usage.code(), usage.all());
		assertTrue(usage.err().contains("--expression TEXT is required"), usage.all());
	}

	// ------------------------------------------------------------------ helpers

	private Path copyLegacy(String relative) throws IOException {
		Path copy = directory.resolve(Path.of(relative).getFileName().toString());
		Files.write(copy, Files.readAllBytes(Models.legacy(relative)));
		return copy;
	}

	private static List<Path> list(Path directory) throws IOException {
		try (Stream<Path> files = Files.list(directory)) {
			return files.sorted().toList();
		}
	}

	@Test
	void generateWritesMonasCodeAndRefusesModelsWithErrors() throws IOException {
		Path legacy = Models.LEGACY;
		Path source = directory.resolve("src");
		CommandRun run = kse("generate", "--quiet", legacy.resolve("Goalie/Goalie.stct").toString(), source.toString());
		assertEquals(0, run.code(), run::all);
		assertTrue(run.out().contains("generated Goalie into"), run::all);
		assertTrue(Files.isRegularFile(source.resolve("statecharts/Goalie/Goalie.cpp")));
		assertTrue(Files.isRegularFile(source.resolve("activities/Scan/Scan.cpp")));
		CommandRun again = kse("generate", "-q", legacy.resolve("Goalie/Goalie.stct").toString(), source.toString());
		assertTrue(again.out().contains(" 0 written,"), again::all);
		assertTrue(again.out().contains("7 activities kept"), again::all);

		Model broken = StatechartResources.load(legacy.resolve("Goalie/Goalie.stct"));
		broken.getNodes().get(0).setType("AND");
		Path brokenFile = directory.resolve("Broken.stct");
		StatechartResources.save(broken, brokenFile);
		CommandRun refused = kse("generate", brokenFile.toString(), directory.resolve("other").toString());
		assertEquals(1, refused.code(), refused::all);
		assertTrue(refused.err().contains(": error: the root state must be an OR state"), refused::all);
		assertTrue(refused.err().contains("nothing generated"), refused::all);
		assertFalse(Files.exists(directory.resolve("other")));

		// Several models into one folder in one call: the valid ones are generated, the broken
		// one is refused, and the exit code says so.
		Path several = directory.resolve("several");
		CommandRun both = kse("generate", "-q", legacy.resolve("Goalie/Goalie.stct").toString(), brokenFile.toString(),
				legacy.resolve("TestBehavior/TestBehavior.stct").toString(), several.toString());
		assertEquals(1, both.code(), both::all);
		assertTrue(both.out().contains("generated Goalie into"), both::all);
		assertTrue(both.out().contains("generated TestBehavior into"), both::all);
		assertTrue(both.err().contains("Broken.stct: ") && both.err().contains("nothing generated"), both::all);
		assertTrue(Files.isDirectory(several.resolve("statecharts/Goalie")));
		assertTrue(Files.isDirectory(several.resolve("statecharts/TestBehavior")));
	}

	// ------------------------------------------------------------------ a Monas tree and events

	/** tests/data/monas-tree copied, since generating writes into its source folder. */
	private Path monasTree() throws IOException {
		Path original = Models.LEGACY.getParent().resolve("monas-tree");
		Path copy = directory.resolve("monas-tree");
		try (Stream<Path> walk = Files.walk(original)) {
			for (Path file : walk.filter(Files::isRegularFile).toList()) {
				Path target = copy.resolve(original.relativize(file).toString());
				Files.createDirectories(target.getParent());
				Files.copy(file, target);
			}
		}
		return copy;
	}

	@Test
	void generateMigratesAMonasTreeAndNotesTheBuiltInsItsMessagesReplace() throws IOException {
		Path tree = monasTree();
		Path model = tree.resolve("models/Localizer.stct");
		Path source = tree.resolve("src");
		CommandRun run = kse("generate", "-q", model.toString(), source.toString());
		assertEquals(Kse.OK, run.code(), run::all);
		assertTrue(run.out().contains("generated Localizer into " + source), run::all);
		List<String> notes = run.err().lines().filter(line -> line.contains("note:")).toList();
		assertEquals(List.of(model + ": note: built-in messages replaced by the source tree's own: GameStateMessage by "
				+ source.resolve("messages/Gamecontroller.proto")
				+ " (the generated C++ uses the runtime's definitions: see the statechart's CMakeLists.txt)"), notes, run::all);
		assertFalse(run.err().contains("error"), run::all);
		assertTrue(run.err().contains(model + ": 0.3->0.4 (Approach_TO_0.4): warning: expression 1:36: the generated C++ will not compile:"
				+ " 'GameStateMessage' has no field 'penalty_secs_left' in the KSE runtime's messages, which it is built with"), run::all);
		assertTrue(Files.isRegularFile(source.resolve("statecharts/Localizer/Localizer.cpp")));
		assertTrue(Files.readString(source.resolve("activities/Localize/Localize.cpp")).contains("done.set_moveon(1);"), "the tree's own activity is kept");
		assertTrue(Files.isRegularFile(source.resolve("activities/Approach/Approach.cpp")), "a skeleton for the missing one");
	}

	/**
	 * Issue 13, item 2: a model from someone else must not make KSE reach the network. An external
	 * XML entity, a reference into another document, a state variable there and an unknown nsURI
	 * all point at a server
	 * that accepts connections and never answers (validate used to hang on it): each command
	 * ends at once, says what is wrong, and the server sees no connection.
	 */
	@Test
	void theCommandLineNeverReachesTheNetwork() throws Exception {
		try (ServerSocket server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress())) {
			AtomicInteger connections = new AtomicInteger();
			Thread listener = new Thread(() -> {
				while (!server.isClosed()) {
					try {
						server.accept();
						connections.incrementAndGet();
					} catch (IOException closed) {
						return;
					}
				}
			});
			listener.setDaemon(true);
			listener.start();
			String remote = "http://127.0.0.1:" + server.getLocalPort();
			String goalie = Files.readString(Models.LEGACY.resolve("Goalie/Goalie.stct"));
			String allKinds = Files.readString(Path.of(System.getProperty("kse.repository", "../.."), "tests/org.kse.generator.monas.tests/models/AllKinds.stct"));
			Path crossDocument = directory.resolve("CrossDocument.stct");
			Files.writeString(crossDocument, goalie.replaceFirst("target=\"//@nodes.0/@Children.2\"", "target=\"" + remote + "/other.stct#//@nodes.0\""));
			Path remoteVariable = directory.resolve("RemoteVariable.stct");
			Files.writeString(remoteVariable, allKinds.replace("variables=\"//@variables.0 //@variables.1\"", "variables=\"" + remoteVariable.getFileName() + "#//@variables.0 " + remote + "/vars.stct#//@variables.0\""));
			Path unknownPackage = directory.resolve("UnknownPackage.stct");
			Files.writeString(unknownPackage, goalie.replace("xmlns:statechart=\"http://statechart/1.0\"", "xmlns:statechart=\"" + remote + "/statechart\""));

			Path externalEntity = directory.resolve("ExternalEntity.stct");
			Files.writeString(externalEntity, allKinds.replace("<?xml version=\"1.0\" encoding=\"ASCII\"?>",
					"<?xml version=\"1.0\" encoding=\"ASCII\"?>\n<!DOCTYPE m [ <!ENTITY x SYSTEM \"" + remote + "/entity\"> ]>")
					.replaceFirst("  <variables ", "  <variables>&x;</variables>\n  <variables "));

			Path externalDtd = directory.resolve("ExternalDtd.stct");
			Files.writeString(externalDtd, goalie.replaceFirst("\\?>", "?><!DOCTYPE x SYSTEM \"" + remote + "/model.dtd\">"));

			// a DOCTYPE is refused where it begins, before its entity or DTD is fetched
			CommandRun entity = assertTimeoutPreemptively(Duration.ofSeconds(30), () -> kse("validate", externalEntity.toString(), externalDtd.toString()));
			assertEquals(Kse.FAILED, entity.code(), entity::all);
			assertTrue(entity.err().contains(externalEntity + ":2:10: a model file may not declare a DOCTYPE (KSE files have none)"), entity::all);
			assertTrue(entity.err().contains(externalDtd + ":1:48: a model file may not declare a DOCTYPE (KSE files have none)"), entity::all);
			CommandRun cross = assertTimeoutPreemptively(Duration.ofSeconds(30), () -> kse("validate", crossDocument.toString()));
			assertEquals(Kse.INVALID, cross.code(), cross::all);
			assertTrue(cross.out().contains("error: the transition's target is in another document (" + remote + "/other.stct#//@nodes.0), which KSE does not open"), cross::all);
			CommandRun variable = assertTimeoutPreemptively(Duration.ofSeconds(30), () -> kse("validate", remoteVariable.toString()));
			assertEquals(Kse.INVALID, variable.code(), variable::all);
			assertTrue(variable.out().contains("error: a variable of the state is in another document (" + remote + "/vars.stct#//@variables.0)"), variable::all);
			CommandRun generate = assertTimeoutPreemptively(Duration.ofSeconds(30), () -> kse("generate", "-q", crossDocument.toString(), directory.resolve("src").toString()));
			assertEquals(Kse.INVALID, generate.code(), generate::all);
			assertFalse(Files.exists(directory.resolve("src")), "nothing generated from a model with a reference into another document");
			CommandRun unknown = assertTimeoutPreemptively(Duration.ofSeconds(30), () -> kse("validate", unknownPackage.toString()));
			assertEquals(Kse.FAILED, unknown.code(), unknown::all);
			assertTrue(unknown.err().contains(unknownPackage + ": not a statechart model"), unknown::all);
			assertEquals(0, connections.get(), "a command opened a connection");
		}
	}

	/**
	 * Issue 13, item 4: a model nested deeper than the XML parser's default limit (100 elements)
	 * was written by transform, then refused by validate. Everything KSE writes it reads back.
	 */
	@Test
	void aDeeplyNestedModelThatTransformWritesValidates() throws IOException {
		int depth = 150;
		Path formula = directory.resolve("Deep.txt");
		Files.writeString(formula, "Deep\ndeep = " + "(".repeat(depth) + "B" + ")+".repeat(depth) + "\n");
		Path model = directory.resolve("Deep.stct");
		CommandRun transform = kse("transform", "-q", formula.toString(), "-o", model.toString());
		assertEquals(Kse.OK, transform.code(), transform::all);
		CommandRun validate = kse("validate", model.toString());
		assertEquals(Kse.OK, validate.code(), validate::all);
		CommandRun label = kse("label", model.toString());
		assertEquals(Kse.OK, label.code(), label::all);
	}

	/**
	 * Issue 13, items 3 and 9: a folder or a device given as the input used to print "kse: Is a
	 * directory", "no such file" for /dev/null, or read /dev/zero until memory ran out.
	 */
	@Test
	void anInputThatIsNotAFileIsNamedForWhatItIs() throws IOException {
		for (String command : List.of("transform", "validate", "label")) {
			CommandRun folder = kse(command, directory.toString());
			assertEquals(Kse.FAILED, folder.code(), folder::all);
			assertTrue(folder.err().contains("kse: " + directory + ": is a folder, not a file"), folder::all);
			if (Files.exists(Path.of("/dev/zero"))) {
				CommandRun device = assertTimeoutPreemptively(Duration.ofSeconds(30), () -> kse(command, "/dev/zero"));
				assertEquals(Kse.FAILED, device.code(), device::all);
				assertTrue(device.err().contains("kse: /dev/zero: not a regular file"), device::all);
			}
		}
	}

	/** Issue 13, item 9: an output that is a folder, or a source folder that is a file, used to give Java's "Is a directory". */
	@Test
	void anOutputThatIsNotWhatTheCommandWritesIsNamed() throws IOException {
		Path goalie = Models.LEGACY.resolve("Goalie/Goalie.stct");
		Path folder = Files.createDirectories(directory.resolve("pictures"));
		CommandRun diagram = kse("diagram", goalie.toString(), "-o", folder.toString());
		assertEquals(Kse.FAILED, diagram.code(), diagram::all);
		assertEquals("kse: " + folder + ": is a folder; give the name of a file to write\n", diagram.err(), diagram::all);
		Path file = Files.writeString(directory.resolve("notes.txt"), "mine");
		CommandRun generate = kse("generate", "-q", goalie.toString(), file.toString());
		assertEquals(Kse.FAILED, generate.code(), generate::all);
		assertTrue(generate.err().endsWith("kse: " + file + ": not a folder (generate writes into a source folder)\n"), generate::all);
		CommandRun label = kse("label", goalie.toString(), "-o", file.resolve("Goalie.stct").toString());
		assertEquals(Kse.FAILED, label.code(), label::all);
		assertTrue(label.err().endsWith("kse: " + file + ": not a folder, so Goalie.stct cannot be written in it\n"), label::all);
		assertEquals("mine", Files.readString(file));
	}

	/** Issue 13, item 3: a .proto that is not UTF-8 in the source tree used to end the command with exit 0 and no word. */
	@Test
	void aSourceTreeFileThatIsNotTextIsNamedAndTheCommandFails() throws IOException {
		Path tree = monasTree();
		Path model = tree.resolve("models/Localizer.stct");
		Path source = tree.resolve("src");
		Path binary = source.resolve("messages/Binary.proto");
		Files.write(binary, new byte[] { 'm', 'e', 's', (byte) 0xC3, (byte) 0x28, (byte) 0xFF, '\n' });
		for (String command : List.of("generate", "validate")) {
			CommandRun run = kse(command, model.toString(), source.toString());
			assertEquals(Kse.FAILED, run.code(), run::all);
			assertTrue(run.err().contains("kse: " + binary + ": not a text file (it is not UTF-8)"), run::all);
			assertFalse(run.err().contains("Exception"), run::all);
		}
	}

	/** Issue 13, item 9: a .proto file that cannot be read used to be skipped without a word. */
	@Test
	void aGarbageProtoFileInTheSourceTreeIsReportedWithItsPosition() throws IOException {
		Path source = directory.resolve("src");
		Path messages = Files.createDirectories(source.resolve("messages"));
		Files.writeString(messages.resolve("Bad.proto"), "syntax = \"proto2\";\nmessage Broken {\n  optional int32 = 1;\n}\n");
		Path goalie = Models.LEGACY.resolve("Goalie/Goalie.stct");
		CommandRun validate = kse("validate", goalie.toString(), source.toString());
		assertEquals(Kse.OK, validate.code(), validate::all);
		assertTrue(Pattern.compile(Pattern.quote(messages.resolve("Bad.proto").toString()) + ":3:\\d+: warning: ").matcher(validate.out()).find(), validate::all);
		assertTrue(validate.err().contains("0 errors, 1 warning"), validate::all);
		CommandRun generate = kse("generate", "-q", goalie.toString(), source.toString());
		assertEquals(Kse.OK, generate.code(), generate::all);
		assertTrue(generate.err().startsWith(messages.resolve("Bad.proto") + ":3:"), generate::all);
	}

	/**
	 * Issue 13, item 9: a file that EMF cannot place (a reference to the model where a state
	 * belongs, two states where one is expected, a malformed number) used to print Java's text
	 * (class names, "For input string") without a position.
	 */
	@Test
	void aBrokenReferenceInAModelIsNamedAtItsLineAndColumn() throws IOException {
		String goalie = Files.readString(Models.LEGACY.resolve("Goalie/Goalie.stct"));
		Path toTheModel = directory.resolve("ToTheModel.stct");
		Files.writeString(toTheModel, goalie.replaceFirst("source=\"//@nodes.0/@Children.1\"", "source=\"/\""));
		Path twoSources = directory.resolve("TwoSources.stct");
		Files.writeString(twoSources, goalie.replaceFirst("source=\"//@nodes.0/@Children.1\"", "source=\"start kick\""));
		Path badNumber = directory.resolve("BadNumber.stct");
		Files.writeString(badNumber, goalie.replaceFirst("source=\"//@nodes.0/@Children.1\"", "source=\"//@nodes.0/@Children.1e999\""));
		for (Path model : List.of(toTheModel, twoSources, badNumber)) {
			CommandRun run = kse("validate", model.toString());
			assertEquals(Kse.FAILED, run.code(), run::all);
			assertTrue(Pattern.compile("^kse: " + Pattern.quote(model.toString()) + ":\\d+:\\d+: not a statechart model: ").matcher(run.err()).find(), run::all);
			assertFalse(Pattern.compile("Exception|Impl|For input string|java\\.").matcher(run.err()).find(), run::all);
		}
		assertTrue(kse("validate", toTheModel.toString()).err().endsWith(": not a statechart model: the reference '/' in source does not lead to a Node\n"));
		assertTrue(kse("validate", twoSources.toString()).err().endsWith(": not a statechart model: Unresolved reference 'start'.\n"));
		assertTrue(kse("validate", badNumber.toString()).err().endsWith(": the reference '//@nodes.0/@Children.1e999' in source does not lead to a Node\n"));
	}

	@Test
	void validateChecksAgainstTheSourceFoldersMessagesWhenGivenOne() throws IOException {
		Path tree = monasTree();
		Path model = tree.resolve("models/Localizer.stct");
		CommandRun alone = kse("validate", model.toString());
		assertEquals(Kse.INVALID, alone.code(), alone::all);
		assertTrue(alone.out().contains(model + ": 0.2->0.3 (Localize_TO_Approach): error: expression 1:17: unknown message type 'LocalizeDone'"), alone::all);
		assertTrue(alone.out().contains(model + ": 0.3->0.4 (Approach_TO_0.4): error: expression 1:36: 'GameStateMessage' has no field 'penalty_secs_left'"),
				alone::all);
		assertFalse(alone.err().contains("note:"), alone::all);

		CommandRun withTree = kse("validate", model.toString(), tree.resolve("src").toString());
		assertEquals(Kse.OK, withTree.code(), withTree::all);
		assertTrue(withTree.err().contains(model + ": 0 errors, 0 warnings"), withTree::all);
		assertTrue(withTree.err().contains(model + ": note: built-in messages replaced by the source tree's own: GameStateMessage by "
				+ tree.resolve("src/messages/Gamecontroller.proto") + "\n"), withTree::all);

		CommandRun missing = kse("validate", model.toString(), tree.resolve("nowhere").toString());
		assertEquals(Kse.FAILED, missing.code(), missing::all);
		assertTrue(missing.err().contains(tree.resolve("nowhere") + " (not a folder)"), missing::all);
	}

	@Test
	void misspeltNamesInAMonasTreesModelGetTheNearestKnownOne() throws IOException {
		Path tree = monasTree();
		Path model = tree.resolve("models/Localizer.stct");
		Files.writeString(model, Files.readString(model).replace("[worldstate.State.GameStateMessage.penalty", "[wordstate.State.GameStateMessage.penalty")
				.replace("[behavior.State.LocalizeDone", "[behavior.State.LocaliseDone"));
		CommandRun run = kse("validate", model.toString(), tree.resolve("src").toString());
		assertEquals(Kse.INVALID, run.code(), run::all);
		assertEquals(List.of(model + ": 0.2->0.3 (Localize_TO_Approach): error: expression 1:17: unknown message type 'LocaliseDone'; did you mean 'LocalizeDone'?",
				model + ": 0.3->0.4 (Approach_TO_0.4): error: expression 1:2: unknown topic 'wordstate'; did you mean 'worldstate'?"), run.out().lines().toList(),
				run::all);
		CommandRun generate = kse("generate", "-q", model.toString(), tree.resolve("src").toString());
		assertEquals(Kse.INVALID, generate.code(), generate::all);
		assertTrue(generate.err().contains("did you mean 'worldstate'?"), generate::all);
	}

	@Test
	void anEventIsAPositionedErrorAndGenerationRefusesIt() throws IOException {
		Model model = Models.simple();
		model.getTransitions().get(1).setTE("[behavior.State.FallMessage==NULL ||\n behavior.State.FallMessage.fall()==0]");
		model.getTransitions().get(0).setTE("\n  BallSeen[behavior.State.HeadToBMessage.ballfound()>0]/TimeoutAction.behavior.100");
		Path file = directory.resolve("events.stct");
		StatechartResources.save(model, file);
		String transition = model.getTransitions().get(0).getSource().getLabel() + "->" + model.getTransitions().get(0).getTarget().getLabel() + " ("
				+ model.getTransitions().get(0).getName() + ")";

		CommandRun validate = kse("validate", file.toString());
		assertEquals(Kse.INVALID, validate.code(), validate::all);
		assertEquals(List.of(file + ": " + transition + ": error: expression 2:3: events are not supported: the engine never raises 'BallSeen', so this"
				+ " transition would never fire (as in the original KSE); say in the condition what to wait for instead, as in"
				+ " [behavior.Signal.FallMessage.fall()!=0]"), validate.out().lines().toList(), validate::all);

		Path source = directory.resolve("src");
		CommandRun generate = kse("generate", file.toString(), source.toString());
		assertEquals(Kse.INVALID, generate.code(), generate::all);
		assertTrue(generate.err().contains(file + ": " + transition + ": error: expression 2:3: events are not supported"), generate::all);
		assertTrue(generate.err().contains("nothing generated"), generate::all);
		assertFalse(Files.exists(source), "nothing written");
	}

	@Test
	void versionNamesKseAndWhatItRunsOn() {
		CommandRun run = kse("--version");
		assertEquals(0, run.code(), run::all);
		assertTrue(run.out().startsWith("kse "), run::all);
		assertTrue(run.out().contains("Xtext ") && run.out().contains("Java " + System.getProperty("java.version")), run::all);
	}
}
