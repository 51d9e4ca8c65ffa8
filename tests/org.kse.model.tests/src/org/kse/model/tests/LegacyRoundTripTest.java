package org.kse.model.tests;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.testing.Models;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/** The original tool's files load, save and load again without losing anything (docs/original-kse.md §1). */
class LegacyRoundTripTest {

	static List<Path> legacyModels() {
		return Models.legacyModels();
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("legacyModels")
	void everyLegacyModelSurvivesSaveAndLoad(Path legacy, @TempDir Path directory) throws IOException {
		Model original = StatechartResources.load(legacy);
		Path copy = directory.resolve(legacy.getFileName());
		StatechartResources.save(original, copy);
		Model reloaded = StatechartResources.load(copy);

		assertNotSame(original, reloaded);
		assertTrue(Models.equal(original, reloaded), () -> legacy + ": the model changed on save and load");
		assertTrue(Models.equal(StatechartResources.load(legacy), reloaded), () -> legacy + ": the saved model differs from a fresh load of the original");
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("legacyModels")
	void everyLegacyModelLoadsCompletely(Path legacy) throws IOException {
		String xml = Files.readString(legacy, StandardCharsets.UTF_8);
		Model model = StatechartResources.load(legacy);

		assertEquals(count(xml, "<nodes ") + count(xml, "<Children "), Models.allNodes(model).size(), "states");
		assertEquals(count(xml, "<transitions "), model.getTransitions().size(), "transitions");
		assertEquals(1, model.getNodes().size(), "roots");
		for (Transition transition : model.getTransitions()) {
			assertNotNull(transition.getSource(), () -> "unresolved source of " + transition.getName());
			assertNotNull(transition.getTarget(), () -> "unresolved target of " + transition.getName());
			assertFalse(transition.getSource().eIsProxy() || transition.getTarget().eIsProxy(), transition.getName());
			assertSame(model, transition.getSource().eResource().getContents().get(0), "source in the same model");
		}
		for (Node node : Models.allNodes(model)) {
			assertNotNull(node.getType(), () -> "untyped state " + node.getLabel());
			assertNotNull(node.getLabel(), () -> "unlabeled state " + node.getName());
		}
	}

	@Test
	void goalieContentSurvivesTheRoundTrip(@TempDir Path directory) throws IOException {
		Model original = StatechartResources.load(Models.legacy("Goalie/Goalie.stct"));
		Path copy = directory.resolve("Goalie.stct");
		StatechartResources.save(original, copy);

		for (Model model : List.of(original, StatechartResources.load(copy))) {
			assertEquals("Goalie", model.getName());
			assertEquals(1, model.getNodes().size());
			Node root = model.getNodes().get(0);
			assertEquals("goalie", root.getName());
			assertEquals("0", root.getLabel());
			assertEquals("OR", root.getType());
			assertEquals(47, Models.allNodes(model).size());
			assertEquals(45, model.getTransitions().size());
			assertEquals(List.of("0.1", "0.3", "0.4"), Models.childLabels(root));

			Node scan = Models.byName(model, "Scan");
			assertEquals("BASIC", scan.getType());
			assertEquals("0.3.2.3.3.2", scan.getLabel());
			assertEquals("file:/home/angelica/Desktop/Monas/src/activities/Scan/", scan.getActivity());
			assertEquals("Scan_one_or_more_times_", scan.getFather_of().getName());

			Transition approach = transitionNamed(model, "0.3.2.3.2TOApproachBall_one_or_more_times_");
			assertEquals("[behavior.State.HeadToBMessage.ballfound()>0 &&\n !ballAway(worldstate.Data.WorldInfo) && !readyToKick(worldstate.Data.WorldInfo)]",
					approach.getTE());
			assertEquals("CONDITION", approach.getSource().getType());
			assertEquals("0.3.2.3.2", approach.getSource().getLabel());
			assertSame(Models.byName(model, "ApproachBall_one_or_more_times_"), approach.getTarget());

			Transition scanLoop = transitionNamed(model, "ScanTOScan");
			assertSame(scan, scanLoop.getSource());
			assertSame(scan, scanLoop.getTarget());
			assertEquals("[TimeoutCheck(behavior) && \n worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING && "
					+ "(behavior.State.HeadToBMessage ==NULL || behavior.State.HeadToBMessage.ballfound()==0)]/TimeoutAction.behavior.250", scanLoop.getTE());

			Transition first = transitionNamed(model, "0_1_TO_0_3");
			assertNull(first.getTE());
			assertEquals("0.1", first.getSource().getLabel());
			assertEquals("0.3", first.getTarget().getLabel());
		}
	}

	@Test
	void otherLegacyModelsKeepTheirShape(@TempDir Path directory) throws IOException {
		for (String[] expected : new String[][] { { "GUITester/GUITester.stct", "GUITester", "tester", "16", "14" },
				{ "TestBehavior/TestBehavior.stct", "TestBehavior", "TestBehavior", "14", "13" },
				{ "TestBehavior/TestBehaviorInitial.stct", "TestBehavior", "TestBehavior", "14", "13" } }) {
			Path copy = directory.resolve(Path.of(expected[0]).getFileName());
			StatechartResources.save(StatechartResources.load(Models.legacy(expected[0])), copy);
			Model model = StatechartResources.load(copy);
			assertAll(expected[0], () -> assertEquals(expected[1], model.getName()), () -> assertEquals(expected[2], model.getNodes().get(0).getName()),
					() -> assertEquals(Integer.parseInt(expected[3]), Models.allNodes(model).size()),
					() -> assertEquals(Integer.parseInt(expected[4]), model.getTransitions().size()));
		}
		Model initial = StatechartResources.load(directory.resolve("TestBehaviorInitial.stct"));
		Node sitDown = Models.byName(initial, "SitDownAndStare");
		assertNull(sitDown.getActivity(), "a BASIC state without an activity stays without one");
		assertEquals("file:/home/aibo/Kouretes/Monas/src/activities/Scan/", Models.byName(initial, "StandUpAndScan").getActivity());
		Model tester = StatechartResources.load(directory.resolve("GUITester.stct"));
		assertEquals("[worldstate.State.GameStateMessage==NULL || \nworldstate.State.GameStateMessage.player_state()!=PLAYER_PLAYING || \n"
				+ "robotInPosition( worldstate.Data.WorldInfo, behavior.State.PositionMessage)]", transitionNamed(tester, "playTO0.2.5").getTE());
	}

	@Test
	void variablesSurviveTheRoundTrip(@TempDir Path directory) throws IOException {
		Model model = Models.simple();
		var ball = Models.variable(model, "ball", "behavior.State.HeadToBMessage");
		var game = Models.variable(model, "game", "worldstate.State.GameStateMessage");
		Node work = Models.byName(model, "Work");
		work.getVariables().add(ball);
		work.getVariables().add(game);
		model.getTransitions().get(1).setTE("[a.State.B==1 &&\n c.Signal.D!=NULL]/publish_all");
		Path file = directory.resolve("vars.stct");
		StatechartResources.save(model, file);

		Model reloaded = StatechartResources.load(file);
		assertTrue(Models.equal(model, reloaded));
		Node reloadedWork = Models.byName(reloaded, "Work");
		assertEquals(List.of("ball", "game"), reloadedWork.getVariables().stream().map(v -> v.getName()).toList());
		assertSame(reloaded.getVariables().get(0), reloadedWork.getVariables().get(0), "a state refers to the model's variable, not a copy");
		assertEquals("[a.State.B==1 &&\n c.Signal.D!=NULL]/publish_all", reloaded.getTransitions().get(1).getTE());
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("legacyModels")
	void savingTheSameModelTwiceGivesIdenticalBytes(Path legacy, @TempDir Path directory) throws IOException {
		Model model = StatechartResources.load(legacy);
		Path first = directory.resolve("first.stct");
		Path second = directory.resolve("second.stct");
		StatechartResources.save(model, first);
		StatechartResources.save(model, second);
		byte[] bytes = Files.readAllBytes(first);
		assertArrayEquals(bytes, Files.readAllBytes(second), "two saves of one model");

		Path third = directory.resolve("third.stct");
		StatechartResources.save(StatechartResources.load(first), third);
		assertArrayEquals(bytes, Files.readAllBytes(third), "save, load and save again");
		assertArrayEquals(bytes, StatechartResources.toBytes(StatechartResources.load(first)), "toBytes gives the file's bytes");

		for (byte b : bytes) {
			assertTrue(b >= 0, "the saved file is ASCII, as the original tool's files are");
		}
		assertTrue(new String(bytes, StandardCharsets.US_ASCII).startsWith("<?xml version=\"1.0\" encoding=\"ASCII\"?>"));
	}

	/** An unchanged legacy model saves as the original tool wrote it: no spurious diff in version control. */
	@ParameterizedTest(name = "{0}")
	@MethodSource("legacyModels")
	void savingAnUnchangedLegacyModelReproducesTheOriginalFile(Path legacy, @TempDir Path directory) throws IOException {
		Path copy = directory.resolve(legacy.getFileName());
		StatechartResources.save(StatechartResources.load(legacy), copy);
		// one legacy file declares UTF-8 (its content is ASCII); ours are always declared ASCII
		String original = Files.readString(legacy, StandardCharsets.UTF_8).replaceFirst("^<\\?xml version=\"1.0\" encoding=\"UTF-8\"\\?>",
				"<?xml version=\"1.0\" encoding=\"ASCII\"?>");
		assertEquals(original, Files.readString(copy, StandardCharsets.US_ASCII));
	}

	@Test
	void multiLineExpressionsAreSavedAsCharacterReferences(@TempDir Path directory) throws IOException {
		Path file = directory.resolve("Goalie.stct");
		StatechartResources.save(StatechartResources.load(Models.legacy("Goalie/Goalie.stct")), file);
		String xml = Files.readString(file, StandardCharsets.US_ASCII);
		assertTrue(xml.contains("TE=\"[behavior.State.HeadToBMessage.ballfound()>0 &amp;&amp;&#xA; !ballAway("), "newline and && written as references");
		assertTrue(xml.contains("source=\"//@nodes.0/@Children.1/@Children.1/@Children.2/@Children.1\""), "nodes referenced by XMI path, as the original");
	}

	@Test
	void saveLeavesNoTemporaryFiles(@TempDir Path directory) throws IOException {
		Path file = directory.resolve("model.stct");
		Model model = Models.simple();
		StatechartResources.save(model, file);
		assertEquals(List.of(file), list(directory));

		// overwrite with a changed model: the file holds the new content, still nothing beside it
		model.setName("Changed");
		StatechartResources.save(model);
		assertEquals(List.of(file), list(directory));
		assertEquals("Changed", StatechartResources.load(file).getName());

		StatechartResources.writeAtomically(file, "replaced".getBytes(StandardCharsets.US_ASCII));
		assertEquals("replaced", Files.readString(file));
		assertEquals(List.of(file), list(directory));
	}

	@Test
	void failedSaveLeavesNoTemporaryFilesAndKeepsWhatWasThere(@TempDir Path directory) throws IOException {
		// the target is a non-empty directory: the move over it must fail
		Path target = directory.resolve("model.stct");
		Files.createDirectory(target);
		Path inside = Files.writeString(target.resolve("keep.txt"), "keep");

		assertThrows(IOException.class, () -> StatechartResources.save(Models.simple(), target));
		assertEquals(List.of(target), list(directory), "no temporary file left behind");
		assertEquals("keep", Files.readString(inside));
	}

	@Test
	void saveCreatesMissingDirectories(@TempDir Path directory) throws IOException {
		Path file = directory.resolve("a/b/model.stct");
		StatechartResources.save(Models.simple(), file);
		assertTrue(Models.equal(Models.simple(), StatechartResources.load(file)));
		assertEquals(List.of(file), list(file.getParent()));
	}

	@Test
	void saveKeepsOrdinaryFilePermissions(@TempDir Path directory) throws IOException {
		assumeTrue(directory.getFileSystem().supportedFileAttributeViews().contains("posix"), "POSIX permissions");
		// a file written the ordinary way shows what the user's umask gives a new file
		Path ordinary = Files.writeString(directory.resolve("ordinary.txt"), "x");
		Set<PosixFilePermission> usual = Files.getPosixFilePermissions(ordinary);
		Path fresh = directory.resolve("fresh.stct");
		StatechartResources.save(Models.simple(), fresh);

		Path existing = directory.resolve("existing.stct");
		StatechartResources.save(Models.simple(), existing);
		Set<PosixFilePermission> shared = PosixFilePermissions.fromString("rw-rw-r--");
		Files.setPosixFilePermissions(existing, shared);
		StatechartResources.save(StatechartResources.load(existing));

		assertAll(() -> assertEquals(PosixFilePermissions.toString(usual), PosixFilePermissions.toString(Files.getPosixFilePermissions(fresh)),
				"a newly saved model gets the same permissions as any new file"),
				() -> assertEquals("rw-rw-r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(existing)),
						"saving over a model keeps its permissions"));
	}

	@Test
	void savingADetachedModelWithoutFileFails() {
		IOException e = assertThrows(IOException.class, () -> StatechartResources.save(Models.simple()));
		assertTrue(e.getMessage().contains("not attached"), e.getMessage());
	}

	@Test
	void loadingAMissingFileNamesIt(@TempDir Path directory) {
		Path missing = directory.resolve("nowhere.stct");
		IOException e = assertThrows(IOException.class, () -> StatechartResources.load(missing));
		assertTrue(e.getMessage().contains(missing.toString()), e.getMessage());
		assertFalse(Files.exists(missing), "loading does not create the file");
	}

	@Test
	void loadingAFormulaFileNamesIt() {
		Path formula = Models.legacy("Goalie/Goalie.txt");
		IOException e = assertThrows(IOException.class, () -> StatechartResources.load(formula));
		assertTrue(e.getMessage().contains(formula.toString()), e.getMessage());
		assertTrue(e.getMessage().contains("not a statechart model"), e.getMessage());
	}

	@Test
	void loadingOtherNonModelFilesNamesThem(@TempDir Path directory) throws IOException {
		Path diagram = Models.legacy("Goalie/Goalie.kse"); // GMF notation: XML, but not a statechart
		Path empty = Files.createFile(directory.resolve("empty.stct"));
		Path otherXml = Files.writeString(directory.resolve("other.stct"), "<?xml version=\"1.0\"?>\n<root><child/></root>\n");
		Path truncated = directory.resolve("truncated.stct");
		String goalie = Files.readString(Models.legacy("Goalie/Goalie.stct"), StandardCharsets.UTF_8);
		Files.writeString(truncated, goalie.substring(0, goalie.length() / 2));
		for (Path file : List.of(diagram, empty, otherXml, truncated, directory)) {
			IOException e = assertThrows(IOException.class, () -> StatechartResources.load(file), file.toString());
			assertTrue(e.getMessage().contains(file.toString()), e.getMessage());
		}
	}

	private static Transition transitionNamed(Model model, String name) {
		List<Transition> found = model.getTransitions().stream().filter(t -> name.equals(t.getName())).toList();
		assertEquals(1, found.size(), () -> "transitions named " + name);
		return found.get(0);
	}

	private static int count(String text, String what) {
		Matcher matcher = Pattern.compile(Pattern.quote(what)).matcher(text);
		int count = 0;
		while (matcher.find()) {
			count++;
		}
		return count;
	}

	private static List<Path> list(Path directory) throws IOException {
		try (Stream<Path> files = Files.list(directory)) {
			return files.sorted().toList();
		}
	}
}
