package org.kse.labeling.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.testing.Models.child;
import static org.kse.testing.Models.root;
import static org.kse.testing.Models.transition;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;

import org.eclipse.emf.common.util.ECollections;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.testing.Models;
import org.kse.labeling.Labeler;
import org.kse.model.NodeKind;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/** "Labeling Diagram" (docs/original-kse.md §4): total, idempotent, in execution order. */
class LabelingTest {

	/** The models labeled here: the legacy files and models made in code. */
	record Sample(String title, Supplier<Model> model) {
		@Override
		public String toString() {
			return title;
		}
	}

	static List<Sample> samples() {
		List<Sample> samples = new ArrayList<>();
		for (Path legacy : Models.legacyModels()) {
			samples.add(new Sample(Models.LEGACY.relativize(legacy).toString(), () -> load(legacy)));
		}
		samples.add(new Sample("simple", Models::simple));
		samples.add(new Sample("document order differs from execution order", () -> shuffled().model));
		samples.add(new Sample("unreachable states", () -> unreachable().model));
		samples.add(new Sample("AND regions", () -> parallel().model));
		samples.add(new Sample("draft labels and missing names", LabelingTest::drafts));
		return samples;
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("samples")
	void labelingTwiceChangesNothing(Sample sample) throws IOException {
		Model model = sample.model().get();
		Labeler.label(model);
		Model once = EcoreUtil.copy(model);
		byte[] bytes = StatechartResources.toBytes(model);

		Labeler.label(model);
		assertTrue(Models.equal(once, model), "the second labeling changed the model");
		assertArrayEquals(bytes, StatechartResources.toBytes(model), "the second labeling changed the file's bytes");
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("samples")
	void labelsAreTotalUniqueAndInExecutionOrder(Sample sample) {
		Model model = sample.model().get();
		Labeler.label(model);
		assertWellLabeled(model);
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("samples")
	void basicStatesKeepTheirNamesAndNoStateIsLost(Sample sample) {
		Model model = sample.model().get();
		Map<Node, String> basicNames = new IdentityHashMap<>();
		for (Node node : Models.allNodes(model)) {
			if (NodeKind.BASIC.is(node) && node.getName() != null && !node.getName().equals(node.getLabel())) {
				basicNames.put(node, node.getName());
			}
		}
		List<Node> before = Models.allNodes(model);
		List<Transition> transitions = List.copyOf(model.getTransitions());
		Labeler.label(model);

		assertEquals(before, Models.allNodes(model), "labeling neither adds, removes nor moves states");
		assertEquals(transitions, model.getTransitions());
		basicNames.forEach((node, name) -> assertEquals(name, node.getName(), "BASIC state " + node.getLabel() + " renamed"));
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("samples")
	void scrambledLabelsComeBackRight(Sample sample) {
		Model model = sample.model().get();
		Labeler.label(model);
		Map<Node, String> labels = new IdentityHashMap<>();
		Map<Node, String> names = new IdentityHashMap<>();
		for (Node node : Models.allNodes(model)) {
			labels.put(node, node.getLabel());
			names.put(node, node.getName());
		}
		List<String> transitionNames = model.getTransitions().stream().map(Transition::getName).toList();

		// scramble: labels shifted round, auxiliary states renamed, transitions unnamed,
		// START moved last in document order
		List<Node> nodes = Models.allNodes(model);
		for (int i = 0; i < nodes.size(); i++) {
			Node node = nodes.get(i);
			node.setLabel(labels.get(nodes.get((i + 1) % nodes.size())));
			NodeKind kind = NodeKind.of(node);
			if (kind != null && kind.isAuxiliary()) {
				node.setName("junk" + i);
			}
		}
		model.getTransitions().forEach(transition -> transition.setName("x"));
		for (Node node : nodes) {
			node.getChildren().stream().filter(NodeKind.START::is).findFirst().ifPresent(start -> node.getChildren().move(node.getChildren().size() - 1, start));
		}

		Labeler.label(model);
		for (Node node : nodes) {
			assertEquals(labels.get(node), node.getLabel(), () -> "label of " + names.get(node));
			assertEquals(names.get(node), node.getName(), () -> "name of " + labels.get(node));
		}
		assertEquals(transitionNames, model.getTransitions().stream().map(Transition::getName).toList());
	}

	// ------------------------------------------------------------------ the legacy models in detail

	@Test
	void goalieGetsTheHoleLeftByInitClosed() throws IOException {
		// the Kouretes team removed Init (0.2) by hand: 0.3 and 0.4 move up
		Model model = load(Models.legacy("Goalie/Goalie.stct"));
		Map<Node, String> old = new IdentityHashMap<>();
		Models.allNodes(model).forEach(node -> old.put(node, node.getLabel()));
		Labeler.label(model);

		for (Node node : Models.allNodes(model)) {
			String was = old.get(node);
			String expected = was.startsWith("0.3") ? "0.2" + was.substring(3) : was.startsWith("0.4") ? "0.3" + was.substring(3) : was;
			assertEquals(expected, node.getLabel(), () -> "state " + was + " (" + node.getName() + ")");
		}
		Node root = model.getNodes().get(0);
		assertEquals("goalie", root.getName());
		assertEquals(List.of("0.1", "0.2", "0.3"), Models.childLabels(root));
		assertEquals("_open_group_playing_or_nonPlaying_close_group__one_or_more_times_", root.getChildren().get(1).getName());
		assertEquals("0.3", root.getChildren().get(2).getName(), "END named after its new label");

		Node scan = Models.byName(model, "Scan");
		assertEquals("0.2.2.3.3.2", scan.getLabel());
		assertEquals("0.2.2.3", Models.byName(model, "playing").getLabel());
		assertEquals("0.2.2.4", Models.byName(model, "nonPlaying").getLabel());
		assertEquals("CONDITION", Models.byName(model, "0.2.2.3.2").getType());

		List<String> names = model.getTransitions().stream().map(Transition::getName).toList();
		assertTrue(names.contains("0.1_TO__open_group_playing_or_nonPlaying_close_group__one_or_more_times_"), names.toString());
		assertTrue(names.contains("Scan_TO_Scan"), names.toString());
		assertTrue(names.contains("0.2.2.3.2_TO_Kick"), names.toString());
		assertTrue(names.contains("_open_group_playing_or_nonPlaying_close_group__one_or_more_times__TO_0.3"), names.toString());
		assertEquals("0.1_TO__open_group_playing_or_nonPlaying_close_group__one_or_more_times_", model.getTransitions().get(44).getName());
	}

	@Test
	void correctlyLabeledLegacyModelsKeepTheirLabels() throws IOException {
		for (String file : List.of("GUITester/GUITester.stct", "TestBehavior/TestBehavior.stct", "TestBehavior/TestBehaviorInitial.stct")) {
			Model model = load(Models.legacy(file));
			Map<Node, String> old = new IdentityHashMap<>();
			Map<Node, String> oldNames = new IdentityHashMap<>();
			Models.allNodes(model).forEach(node -> old.put(node, node.getLabel()));
			Models.allNodes(model).forEach(node -> oldNames.put(node, node.getName()));
			Labeler.label(model);
			for (Node node : Models.allNodes(model)) {
				assertEquals(old.get(node), node.getLabel(), () -> file + ": " + node.getName());
				assertEquals(oldNames.get(node), node.getName(), () -> file + ": " + node.getLabel());
			}
			// only the transitions' names change, from the original "xTOy" to "x_TO_y"
			for (Transition transition : model.getTransitions()) {
				assertEquals(transition.getSource().getName() + "_TO_" + transition.getTarget().getName(), transition.getName());
			}
		}
		Model tester = load(Models.legacy("GUITester/GUITester.stct"));
		Labeler.label(tester);
		assertEquals("0.2.3.1_TO_ChangeRobotPosition", tester.getTransitions().get(5).getName());
	}

	// ------------------------------------------------------------------ hand-built models in detail

	@Test
	void startIsFirstAndTheWalkFollowsTransitionsNotDocumentOrder() {
		Shuffled m = shuffled();
		Labeler.label(m.model);
		assertEquals("0", m.root.getLabel());
		assertEquals("0.1", m.start.getLabel());
		assertEquals("0.2", m.condition.getLabel());
		assertEquals("0.3", m.a.getLabel(), "A is reached first: its transition comes first");
		assertEquals("0.4", m.b.getLabel());
		assertEquals("0.5", m.end.getLabel());
		assertEquals("0.1", m.start.getName(), "START renamed to its label");
		assertEquals("0.2", m.condition.getName(), "CONDITION renamed to its label");
		assertEquals("0.5", m.end.getName(), "END renamed to its label");
		assertEquals("A", m.a.getName());
		assertEquals("B", m.b.getName());
		assertEquals("Main", m.root.getName());
		assertEquals(List.of("0.1_TO_0.2", "0.2_TO_A", "0.2_TO_B", "A_TO_0.5", "B_TO_0.5"), m.model.getTransitions().stream().map(Transition::getName).toList());
	}

	@Test
	void theWalkIsBreadthFirst() {
		// START -> X -> Y, START -> Z: Z is reached before Y
		Model model = Models.model("Breadth");
		Node root = root(model, "Main", "0", "OR");
		Node y = child(root, "Y", "a", "BASIC");
		Node z = child(root, "Z", "b", "BASIC");
		Node x = child(root, "X", "c", "BASIC");
		Node start = child(root, "s", "d", "START");
		transition(model, start, x);
		transition(model, x, y);
		transition(model, start, z);
		Labeler.label(model);
		assertEquals(List.of("0.1", "0.2", "0.3", "0.4"), List.of(start.getLabel(), x.getLabel(), z.getLabel(), y.getLabel()));
	}

	@Test
	void unreachableStatesComeAfterReachableOnesInDocumentOrder() {
		Unreachable m = unreachable();
		Labeler.label(m.model);
		assertEquals("0.1", m.start.getLabel());
		assertEquals("0.2", m.reached.getLabel());
		assertEquals("0.3", m.lost1.getLabel());
		assertEquals("0.4", m.lost2.getLabel(), "reached only from an unreachable state: still unreachable");
		assertEquals("0.5", m.lostCondition.getLabel());
		assertEquals("0.6", m.end.getLabel(), "END is last, after the unreachable states");
		assertEquals("0.5", m.lostCondition.getName(), "an auxiliary state is named after its label even when unreachable");
		assertEquals("Lost1", m.lost1.getName());
		assertEquals("Lost1_TO_Lost2", m.model.getTransitions().get(2).getName());
	}

	@Test
	void andRegionsKeepDocumentOrder() {
		Parallel m = parallel();
		Labeler.label(m.model);
		assertEquals("0.2", m.and.getLabel());
		assertEquals(List.of("0.2.1", "0.2.2", "0.2.3"), List.of(m.regions.get(0).getLabel(), m.regions.get(1).getLabel(), m.regions.get(2).getLabel()));
		assertEquals(List.of("Zulu", "Yankee", "Xray"), m.regions.stream().map(Node::getName).toList(), "regions keep their names");
		for (Node region : m.regions) {
			assertEquals(region.getLabel() + ".1", region.getChildren().get(0).getLabel());
			assertEquals(region.getLabel() + ".1", region.getChildren().get(0).getName());
			assertEquals(region.getLabel() + ".2", region.getChildren().get(1).getLabel());
		}
		assertEquals("0.3", m.end.getLabel());
	}

	@Test
	void endStatesAreLastInDocumentOrder() {
		Model model = Models.model("Ends");
		Node root = root(model, "Main", "0", "OR");
		Node end2 = child(root, "e2", "1", "END");
		Node start = child(root, "s", "2", "START");
		Node end1 = child(root, "e1", "3", "END");
		Node work = child(root, "Work", "4", "BASIC");
		transition(model, start, work);
		transition(model, work, end1);
		transition(model, work, end2);
		Labeler.label(model);
		assertEquals(List.of("0.1", "0.2", "0.3", "0.4"), List.of(start.getLabel(), work.getLabel(), end2.getLabel(), end1.getLabel()));
	}

	@Test
	void endIsLastEvenWithoutStart() {
		// an OR without START is invalid, but labeling is total: END still comes last
		Model model = Models.model("NoStart");
		Node root = root(model, "Main", "0", "OR");
		Node end = child(root, "e", "x", "END");
		Node work = child(root, "Work", "y", "BASIC");
		transition(model, work, end);
		Labeler.label(model);
		assertEquals("0.1", work.getLabel());
		assertEquals("0.2", end.getLabel());
	}

	@Test
	void statesNamedAfterTheirOldLabelOrUnnamedTakeTheNewLabel() {
		Model model = drafts();
		Labeler.label(model);
		Node root = model.getNodes().get(0);
		assertEquals("0", root.getName(), "unnamed root");
		Node composite = root.getChildren().get(1);
		assertEquals("0.2", composite.getLabel());
		assertEquals("0.2", composite.getName(), "an OR named after its draft label");
		Node named = root.getChildren().get(2);
		assertEquals("0.3", named.getLabel());
		assertEquals("Keep", named.getName(), "an OR with a real name keeps it");
		Node basic = composite.getChildren().get(1);
		assertEquals("Work", basic.getName());
		assertEquals("0.2.2", basic.getLabel());
	}

	@Test
	void labelingIsTotalOnBrokenModels() {
		Model model = Models.model("Broken");
		Node first = root(model, null, null, "OR");
		Node second = root(model, "Second", "0", "AND"); // a second root, with a clashing label
		Node unknown = child(first, "Odd", "0", "end"); // lower-case type, like the original's bug
		Node leaf = child(first, "Leaf", "0", "BASIC");
		Node inner = child(leaf, "Inner", null, "BASIC"); // a BASIC state holding a state
		Node startless = child(second, "", "", "OR");
		Node deep = child(startless, "Deep", "0", "CONDITION");
		transition(model, leaf, unknown);
		Transition dangling = Models.FACTORY.createTransition();
		dangling.setSource(leaf);
		dangling.setName("keep-me");
		model.getTransitions().add(dangling);

		assertDoesNotThrow(() -> Labeler.label(model));
		List<String> labels = Models.allNodes(model).stream().map(Node::getLabel).toList();
		assertEquals(labels.size(), new HashSet<>(labels).size(), () -> "labels not unique: " + labels);
		assertEquals("0", first.getLabel());
		assertEquals("1", second.getLabel());
		assertEquals("0.1", unknown.getLabel(), "no START: document order");
		assertEquals("0.2", leaf.getLabel());
		assertEquals("0.2.1", inner.getLabel());
		assertEquals("1.1", startless.getLabel());
		assertEquals("1.1", startless.getName());
		assertEquals("1.1.1", deep.getLabel());
		assertEquals("1.1.1", deep.getName());
		assertEquals("Odd", unknown.getName(), "a state of unknown type is not auxiliary: it keeps its name");
		assertEquals("keep-me", dangling.getName(), "a transition without target keeps its name");
		assertNull(dangling.getTarget());
		assertFalse(first.getName() == null || first.getName().isEmpty());

		byte[][] bytes = new byte[2][];
		assertDoesNotThrow(() -> bytes[0] = StatechartResources.toBytes(model));
		Labeler.label(model);
		assertDoesNotThrow(() -> bytes[1] = StatechartResources.toBytes(model));
		assertArrayEquals(bytes[0], bytes[1], "idempotent on a broken model too");
	}

	// ------------------------------------------------------------------ invariants

	/** What every labeled model satisfies (docs/original-kse.md §4). */
	static void assertWellLabeled(Model model) {
		List<Node> nodes = Models.allNodes(model);
		Map<String, Node> byLabel = new HashMap<>();
		for (Node node : nodes) {
			assertFalse(node.getLabel() == null || node.getLabel().isEmpty(), () -> "state without label: " + node.getName());
			Node other = byLabel.put(node.getLabel(), node);
			assertTrue(other == null, () -> "label " + node.getLabel() + " used twice");
			assertFalse(node.getName() == null || node.getName().isEmpty(), () -> "state without name: " + node.getLabel());
			NodeKind kind = NodeKind.of(node);
			if (kind != null && kind.isAuxiliary()) {
				assertEquals(node.getLabel(), node.getName(), "an auxiliary state is named after its label");
			}
		}
		for (int i = 0; i < model.getNodes().size(); i++) {
			assertEquals(String.valueOf(i), model.getNodes().get(i).getLabel(), "root label");
		}
		Map<Node, List<Node>> successors = new HashMap<>();
		for (Transition transition : model.getTransitions()) {
			assertEquals(transition.getSource().getName() + "_TO_" + transition.getTarget().getName(), transition.getName());
			successors.computeIfAbsent(transition.getSource(), key -> new ArrayList<>()).add(transition.getTarget());
		}
		for (Node parent : nodes) {
			if (parent.getChildren().isEmpty()) {
				continue;
			}
			Map<Node, Integer> number = new IdentityHashMap<>();
			Set<Integer> numbers = new HashSet<>();
			for (Node child : parent.getChildren()) {
				String prefix = parent.getLabel() + ".";
				assertTrue(child.getLabel().startsWith(prefix), () -> child.getLabel() + " under " + parent.getLabel());
				int n = Integer.parseInt(child.getLabel().substring(prefix.length()));
				number.put(child, n);
				numbers.add(n);
			}
			for (int n = 1; n <= parent.getChildren().size(); n++) {
				assertTrue(numbers.contains(n), parent.getLabel() + ": children numbered 1.." + parent.getChildren().size() + ", missing " + n);
			}
			if (NodeKind.AND.is(parent)) {
				for (int i = 0; i < parent.getChildren().size(); i++) {
					assertEquals(i + 1, number.get(parent.getChildren().get(i)), "AND regions in document order");
				}
				continue;
			}
			Node start = parent.getChildren().stream().filter(NodeKind.START::is).findFirst().orElse(null);
			if (start == null) {
				continue;
			}
			assertEquals(1, number.get(start), () -> parent.getLabel() + ": START is .1");
			int lastOther = parent.getChildren().stream().filter(child -> !NodeKind.END.is(child)).mapToInt(number::get).max().orElse(0);
			parent.getChildren().stream().filter(NodeKind.END::is)
					.forEach(end -> assertTrue(number.get(end) > lastOther, () -> parent.getLabel() + ": END " + end.getLabel() + " is last"));
			// reachable states in walk order, then unreachable ones in document order
			Set<Node> reachable = reachable(start, new HashSet<>(parent.getChildren()), successors);
			List<Node> unreachable = parent.getChildren().stream().filter(child -> !reachable.contains(child) && !NodeKind.END.is(child)).toList();
			for (Node child : parent.getChildren()) {
				if (child == start || NodeKind.END.is(child) || !reachable.contains(child)) {
					continue;
				}
				boolean reachedFromEarlier = parent.getChildren().stream()
						.anyMatch(p -> reachable.contains(p) && number.get(p) < number.get(child) && successors.getOrDefault(p, List.of()).contains(child));
				assertTrue(reachedFromEarlier, () -> child.getLabel() + " (" + child.getName() + ") is numbered before any state it is reached from");
				for (Node lost : unreachable) {
					assertTrue(number.get(child) < number.get(lost), () -> "reachable " + child.getLabel() + " after unreachable " + lost.getLabel());
				}
			}
			for (int i = 1; i < unreachable.size(); i++) {
				assertTrue(number.get(unreachable.get(i - 1)) < number.get(unreachable.get(i)), "unreachable states in document order");
			}
		}
	}

	private static Set<Node> reachable(Node start, Set<Node> siblings, Map<Node, List<Node>> successors) {
		Set<Node> reached = new LinkedHashSet<>();
		reached.add(start);
		Deque<Node> frontier = new ArrayDeque<>(List.of(start));
		while (!frontier.isEmpty()) {
			for (Node next : successors.getOrDefault(frontier.poll(), List.of())) {
				if (siblings.contains(next) && reached.add(next) && !NodeKind.END.is(next)) {
					frontier.add(next);
				}
			}
		}
		return reached;
	}

	// ------------------------------------------------------------------ the models

	private static Model load(Path file) {
		try {
			return StatechartResources.load(file);
		} catch (IOException e) {
			throw new AssertionError(e);
		}
	}

	record Shuffled(Model model, Node root, Node start, Node condition, Node a, Node b, Node end) {
	}

	/** Document order END, B, START, A, CONDITION; walk START→CONDITION→A, B→END. */
	private static Shuffled shuffled() {
		Model model = Models.model("Shuffled");
		Node root = root(model, "Main", "7", "OR");
		Node end = child(root, "end", "7.1", "END");
		Node b = child(root, "B", "7.2", "BASIC");
		Node start = child(root, "start", "7.3", "START");
		Node a = child(root, "A", "7.4", "BASIC");
		Node condition = child(root, "cond", "7.5", "CONDITION");
		transition(model, start, condition);
		transition(model, condition, a, "[a.State.B==1]");
		transition(model, condition, b);
		transition(model, a, end);
		transition(model, b, end);
		return new Shuffled(model, root, start, condition, a, b, end);
	}

	record Unreachable(Model model, Node start, Node lost1, Node reached, Node end, Node lost2, Node lostCondition) {
	}

	private static Unreachable unreachable() {
		Model model = Models.model("Unreachable");
		Node root = root(model, "Main", "0", "OR");
		Node start = child(root, "0.1", "0.1", "START");
		Node lost1 = child(root, "Lost1", "0.9", "BASIC");
		Node reached = child(root, "Reached", "0.8", "BASIC");
		Node end = child(root, "0.7", "0.7", "END");
		Node lost2 = child(root, "Lost2", "0.6", "BASIC");
		Node lostCondition = child(root, "0.5", "0.5", "CONDITION");
		transition(model, start, reached);
		transition(model, reached, end);
		transition(model, lost1, lost2);
		transition(model, lostCondition, reached);
		return new Unreachable(model, start, lost1, reached, end, lost2, lostCondition);
	}

	record Parallel(Model model, Node and, List<Node> regions, Node end) {
	}

	/** Regions named and labeled against document order, with transitions between them. */
	private static Parallel parallel() {
		Model model = Models.model("Parallel");
		Node root = root(model, "Main", "0", "OR");
		Node start = child(root, "0.1", "0.1", "START");
		Node and = child(root, "Both", "0.2", "AND");
		Node end = child(root, "0.3", "0.3", "END");
		transition(model, start, and);
		transition(model, and, end);
		List<Node> regions = new ArrayList<>();
		String[] names = { "Zulu", "Yankee", "Xray" };
		for (int k = 0; k < names.length; k++) {
			String label = "0.2." + (3 - k);
			Node region = child(and, names[k], label, "OR");
			Node regionStart = child(region, "s" + k, label + ".1", "START");
			Node work = child(region, "Work" + names[k], label + ".2", "BASIC");
			transition(model, regionStart, work);
			regions.add(region);
		}
		// invalid but possible: transitions between regions must not reorder them
		transition(model, regions.get(2), regions.get(1));
		transition(model, regions.get(1), regions.get(0));
		return new Parallel(model, and, regions, end);
	}

	/** Draft labels: an unnamed root, an OR named after its label, states without names. */
	private static Model drafts() {
		Model model = Models.model("Drafts");
		Node root = root(model, null, "9", "OR");
		Node start = child(root, null, null, "START");
		Node composite = child(root, "5.5", "5.5", "OR");
		Node named = child(root, "Keep", "5.4", "OR");
		Node end = child(root, "", "5.3", "END");
		Node innerStart = child(composite, "x", "5.5.9", "START");
		Node work = child(composite, "Work", "5.5.8", "BASIC");
		Node innerEnd = child(composite, "y", "5.5.7", "END");
		child(named, "whatever", "1", "START");
		transition(model, start, composite);
		transition(model, composite, named);
		transition(model, named, end);
		transition(model, innerStart, work);
		transition(model, work, innerEnd);
		for (Transition transition : model.getTransitions()) {
			transition.setName("draft");
		}
		ECollections.reverse(composite.getChildren());
		return model;
	}
}
