package org.kse.transform.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/** The worked example of docs/original-kse.md §3 and the original tool's own saved models. */
class GoalieTransformationTest {

	private static final Path LEGACY = Path.of(System.getProperty("kse.repository", "../.."), "tests", "data", "legacy-kse");

	private static Model fromLegacyFormula(String name) throws IOException {
		return Statecharts.transform(Files.readString(LEGACY.resolve(name).resolve(name + ".txt")));
	}

	private static Map<String, Node> byLabel(Model model) {
		return Statecharts.allNodes(model).stream().collect(Collectors.toMap(Node::getLabel, Function.identity()));
	}

	@Test
	void goalieHasTheLabelsOfTheWorkedExample() throws IOException {
		Model model = fromLegacyFormula("Goalie");
		Map<String, Node> nodes = byLabel(model);
		assertEquals("Goalie", model.getName(), "the model is named by the .txt file's first line");
		assertEquals("goalie", nodes.get("0").getName());
		assertEquals("Init", nodes.get("0.2").getName());
		assertEquals("BASIC", nodes.get("0.2").getType());
		assertEquals("_open_group_playing_or_nonPlaying_close_group__one_or_more_times_", nodes.get("0.3").getName());
		assertEquals("OR", nodes.get("0.3").getType());
		assertEquals("_open_group_playing_or_nonPlaying_close_group_", nodes.get("0.3.2").getName());
		assertTrue(model.getTransitions().stream().anyMatch(t -> t.getSource() == nodes.get("0.3.2") && t.getTarget() == nodes.get("0.3.2")),
				"the group loops on itself (x+)");
		assertEquals("CONDITION", nodes.get("0.3.2.2").getType());
		assertEquals("playing", nodes.get("0.3.2.3").getName());
		assertEquals("Scan_one_or_more_times_", nodes.get("0.3.2.3.3").getName());
		assertEquals("Scan", nodes.get("0.3.2.3.3.2").getName());
		assertEquals("BASIC", nodes.get("0.3.2.3.3.2").getType());
		assertEquals("followBall", nodes.get("0.3.2.3.6").getName());
		assertEquals("_open_option_SpecialAction_close_option_", nodes.get("0.3.2.3.6.3").getName());
		assertEquals("nonPlaying", nodes.get("0.3.2.4").getName());
		assertEquals("0.4", nodes.get("0.4").getName());
		assertEquals("END", nodes.get("0.4").getType());
	}

	/** The saved Goalie lost Init by hand; every other state is exactly what we produce. */
	@Test
	void goalieMatchesTheStatesTheOriginalSaved() throws IOException {
		Map<String, Node> ours = byLabel(fromLegacyFormula("Goalie"));
		Model saved = StatechartResources.load(LEGACY.resolve("Goalie/Goalie.stct"));
		List<Node> savedNodes = Statecharts.allNodes(saved);
		assertEquals(47, savedNodes.size());
		for (Node node : savedNodes) {
			Node mine = ours.get(node.getLabel());
			assertEquals(node.getName() + " " + node.getType(), mine == null ? "missing" : mine.getName() + " " + mine.getType(),
					"state " + node.getLabel());
		}
	}

	/** GUITester was saved straight from the original transformation: same states, same transitions, same order. */
	@Test
	void guiTesterIsWhatTheOriginalProduced() throws IOException {
		Model ours = fromLegacyFormula("GUITester");
		Model saved = StatechartResources.load(LEGACY.resolve("GUITester/GUITester.stct"));
		assertEquals(describeStates(saved), describeStates(ours));
		assertEquals(describeTransitions(saved), describeTransitions(ours));
	}

	@Test
	void sameFormulaGivesByteIdenticalFiles(@org.junit.jupiter.api.io.TempDir Path directory) throws IOException {
		String formulas = Files.readString(LEGACY.resolve("Goalie/Goalie.txt"));
		Path first = directory.resolve("first.stct");
		Path second = directory.resolve("second.stct");
		StatechartResources.save(Statecharts.transform(formulas), first);
		StatechartResources.save(Statecharts.transform(formulas), second);
		assertArrayEquals(Files.readAllBytes(first), Files.readAllBytes(second));
		assertTrue(Files.size(first) > 5000);
	}

	private static List<String> describeStates(Model model) {
		return Statecharts.allNodes(model).stream().map(n -> n.getLabel() + " " + n.getType() + " " + n.getName()).toList();
	}

	private static List<String> describeTransitions(Model model) {
		List<String> result = new ArrayList<>();
		for (Transition transition : model.getTransitions()) {
			result.add(transition.getName() + " " + transition.getSource().getLabel() + "->" + transition.getTarget().getLabel());
		}
		return result;
	}
}
