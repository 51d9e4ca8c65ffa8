package org.kse.notation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.eclipse.emf.ecore.EObject;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.testing.Models;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.notation.Arrange;
import org.kse.notation.Bounds;
import org.kse.notation.Captions;
import org.kse.notation.LegacyNotation;
import org.kse.notation.Notation;
import org.kse.notation.NotationFiles;
import org.kse.notation.Shapes;
import org.kse.notation.TransitionLayout;

/**
 * Transition labels are readable in every example and legacy model, as opened and after "Arrange
 * all": no label lies on another, and none on a state other than those holding both ends of its
 * transition (nor on their header, where their name is). States named after a formula show it.
 */
class TransitionLayoutTest {

	static Stream<Path> models() throws IOException {
		List<Path> all = new ArrayList<>();
		try (Stream<Path> examples = Files.walk(Path.of(System.getProperty("kse.examples")), 2)) {
			examples.filter(file -> file.toString().endsWith(".stct")).sorted().forEach(all::add);
		}
		all.addAll(Models.legacyFiles(".stct"));
		return all.stream();
	}

	@ParameterizedTest
	@MethodSource("models")
	void labelsLieOnNoStateAndNoOtherLabelAsOpenedAndArranged(Path modelFile, @TempDir Path directory) throws IOException {
		Path copy = directory.resolve(modelFile.getFileName());
		Files.copy(modelFile, copy);
		if (Files.isRegularFile(LegacyNotation.beside(modelFile))) {
			Files.copy(LegacyNotation.beside(modelFile), LegacyNotation.beside(copy));
		}
		Model model = StatechartResources.load(copy);
		Notation opened = NotationFiles.open(copy, model).notation();
		assertEquals(List.of(), overlaps(model, opened), modelFile + " as opened");
		Notation arranged = Arrange.all(model);
		assertEquals(List.of(), overlaps(model, arranged), modelFile + " arranged");
		assertEquals(List.of(), crossings(model, arranged), modelFile + " arranged: lines go round the states");
	}

	/** The states a transition's line passes over (other than those it starts in, ends in or runs inside), one line each. */
	private static List<String> crossings(Model model, Notation notation) {
		Map<Node, Bounds> boxes = new IdentityHashMap<>();
		for (Node root : model.getNodes()) {
			absolute(root, 0, 0, notation, boxes);
		}
		List<String> found = new ArrayList<>();
		TransitionLayout.of(model, node -> notation.get(node)).forEach((transition, route) -> {
			Node source = transition.getSource();
			Node target = transition.getTarget();
			List<double[]> line = new ArrayList<>();
			line.add(centre(boxes.get(source)));
			line.addAll(route.bends());
			line.add(centre(boxes.get(target)));
			for (Map.Entry<Node, Bounds> state : boxes.entrySet()) {
				Node each = state.getKey();
				boolean exempt = holds(each, source) && holds(each, target) || holds(source, each) || holds(target, each);
				for (int i = 0; !exempt && i + 1 < line.size(); i++) {
					if (passesThrough(line.get(i), line.get(i + 1), state.getValue())) {
						found.add(transition.getName() + " over " + each.getLabel());
						break;
					}
				}
			}
		});
		return found;
	}

	private static double[] centre(Bounds box) {
		return new double[] { box.x() + box.width() / 2, box.y() + box.height() / 2 };
	}

	/** Whether the segment passes through the inside of the box, sampled every pixel. */
	private static boolean passesThrough(double[] a, double[] b, Bounds box) {
		int steps = (int) Math.ceil(Math.hypot(b[0] - a[0], b[1] - a[1]));
		for (int k = 0; k <= steps; k++) {
			double x = a[0] + (b[0] - a[0]) * k / Math.max(steps, 1);
			double y = a[1] + (b[1] - a[1]) * k / Math.max(steps, 1);
			if (x > box.x() + 1 && x < box.right() - 1 && y > box.y() + 1 && y < box.bottom() - 1) {
				return true;
			}
		}
		return false;
	}

	@Test
	void statesNamedAfterAFormulaShowTheFormula() {
		assertEquals("(playing | nonPlaying)+", Captions.formula("_open_group_playing_or_nonPlaying_close_group__one_or_more_times_"));
		assertEquals("[GoToPosition+]", Captions.formula("_open_option_GoToPosition_one_or_more_times__close_option_"));
		assertEquals("Scan*", Captions.formula("Scan_zero_or_more_times_"));
		assertEquals("(A . B || C)~", Captions.formula("_open_group_A_sequence_B_parallel_C_close_group__forever_"));
		Node named = Models.newNode("left_or_right", "0.1", "BASIC");
		assertEquals("left_or_right", Captions.of(named), "a name a user gave is shown as given");
	}

	/** What overlaps, one line each ("label A / label B", "label A / state 0.2"). */
	private static List<String> overlaps(Model model, Notation notation) {
		Map<Node, Bounds> boxes = new IdentityHashMap<>();
		for (Node root : model.getNodes()) {
			absolute(root, 0, 0, notation, boxes);
		}
		Map<Transition, TransitionLayout.Placed> routes = TransitionLayout.of(model, node -> {
			Bounds placed = notation.get(node);
			return placed != null ? placed : Shapes.size(node);
		});
		List<String> found = new ArrayList<>();
		List<Map.Entry<Transition, TransitionLayout.Placed>> labelled = routes.entrySet().stream().filter(entry -> entry.getValue().label() != null).toList();
		for (int i = 0; i < labelled.size(); i++) {
			Transition transition = labelled.get(i).getKey();
			Bounds label = labelled.get(i).getValue().label();
			for (int j = i + 1; j < labelled.size(); j++) {
				if (label.overlaps(labelled.get(j).getValue().label())) {
					found.add("label " + transition.getName() + " / label " + labelled.get(j).getKey().getName());
				}
			}
			for (Map.Entry<Node, Bounds> state : boxes.entrySet()) {
				Bounds box = state.getValue();
				// a transition from a state to itself runs outside that state
				boolean holdsTransition = holds(state.getKey(), transition.getSource()) && holds(state.getKey(), transition.getTarget())
						&& !(transition.getSource() == transition.getTarget() && state.getKey() == transition.getSource());
				Bounds forbidden = holdsTransition ? new Bounds(box.x(), box.y(), box.width(), Arrange.HEADER) : box;
				if (label.overlaps(forbidden)) {
					found.add("label " + transition.getName() + " / state " + state.getKey().getLabel() + (holdsTransition ? " (header)" : ""));
				}
			}
		}
		return found;
	}

	private static boolean holds(Node holder, Node state) {
		for (EObject each = state; each instanceof Node node; each = node.eContainer()) {
			if (node == holder) {
				return true;
			}
		}
		return false;
	}

	private static void absolute(Node node, double x, double y, Notation notation, Map<Node, Bounds> boxes) {
		Bounds relative = notation.get(node) != null ? notation.get(node) : Shapes.size(node);
		Bounds box = new Bounds(x + relative.x(), y + relative.y(), relative.width(), relative.height());
		boxes.put(node, box);
		for (Node child : node.getChildren()) {
			absolute(child, box.x(), box.y(), notation, boxes);
		}
	}
}
