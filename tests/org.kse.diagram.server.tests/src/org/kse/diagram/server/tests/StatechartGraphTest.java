package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.glsp.graph.GEdge;
import org.eclipse.glsp.graph.GGraph;
import org.eclipse.glsp.graph.GLabel;
import org.eclipse.glsp.graph.GModelElement;
import org.eclipse.glsp.graph.GNode;
import org.junit.jupiter.api.Test;
import org.kse.diagram.server.StatechartGraph;
import org.kse.model.NodeKind;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.notation.Arrange;
import org.kse.notation.Bounds;
import org.kse.notation.Notation;

/**
 * The diagram server's graph of a statechart: a node per state typed by its kind and nested as
 * in the model at the notation's positions, an edge per transition with its expression's first
 * line as label and all of it as an argument for the hover.
 */
class StatechartGraphTest {

	private static Model goalie() throws IOException {
		return StatechartResources.load(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"));
	}

	private static List<GModelElement> all(GModelElement root, Class<?> type) {
		List<GModelElement> found = new ArrayList<>();
		for (GModelElement child : root.getChildren()) {
			if (type.isInstance(child)) {
				found.add(child);
			}
			found.addAll(all(child, type));
		}
		return found;
	}

	@Test
	void everyStateIsANodeOfItsKindNestedAsInTheModelAtItsPlace() throws IOException {
		Model model = goalie();
		Notation notation = Arrange.all(model);
		GGraph graph = StatechartGraph.of(model, notation);
		List<Node> states = new ArrayList<>();
		model.eAllContents().forEachRemaining(each -> {
			if (each instanceof Node node) {
				states.add(node);
			}
		});
		assertEquals(states.size(), all(graph, GNode.class).size(), "a node per state");
		for (Node state : states) {
			GNode shape = assertInstanceOf(GNode.class, StatechartGraph.find(graph, Notation.path(state)), state.getLabel());
			assertEquals(StatechartGraph.type(NodeKind.of(state)), shape.getType());
			Bounds bounds = notation.get(state);
			assertEquals(bounds.x(), shape.getPosition().getX());
			assertEquals(bounds.width(), shape.getSize().getWidth());
			Object parent = shape.getParent();
			if (state.eContainer() instanceof Node container) {
				assertEquals(Notation.path(container), ((GModelElement) parent).getId(), state.getLabel() + " inside its parent");
			} else {
				assertEquals(graph, parent);
			}
			List<GLabel> names = shape.getChildren().stream().filter(GLabel.class::isInstance).map(GLabel.class::cast).toList();
			if (NodeKind.START.is(state) || NodeKind.END.is(state)) {
				assertTrue(names.isEmpty(), "START and END are discs without text");
			} else {
				// a state named after a formula shows the formula, its name is kept for the hover
				assertEquals(NodeKind.CONDITION.is(state) ? "C" : org.kse.notation.Captions.of(state), names.get(0).getText());
			}
			assertEquals(state.getName(), shape.getArgs().get("name"), "the whole name for the hover and the editor");
		}
	}

	@Test
	void everyTransitionIsAnEdgeLabelledWithTheFirstLineOfItsExpression() throws IOException {
		Model model = goalie();
		GGraph graph = StatechartGraph.of(model, Arrange.all(model));
		List<GModelElement> edges = all(graph, GEdge.class);
		assertEquals(model.getTransitions().size(), edges.size());
		Transition multiLine = model.getTransitions().stream().filter(t -> t.getTE() != null && t.getTE().strip().contains("\n")).findFirst()
				.orElseThrow();
		GEdge edge = (GEdge) edges.get(model.getTransitions().indexOf(multiLine));
		assertEquals(Notation.path(multiLine.getSource()), edge.getSourceId());
		assertEquals(Notation.path(multiLine.getTarget()), edge.getTargetId());
		GLabel label = (GLabel) edge.getChildren().get(0);
		String firstLine = multiLine.getTE().strip().lines().findFirst().orElseThrow().strip();
		assertTrue(label.getText().endsWith(" …") && firstLine.startsWith(label.getText().substring(0, label.getText().length() - 2)),
				"the start of the first line: " + label.getText());
		assertEquals(multiLine.getTE().strip(), edge.getArgs().get("expression"), "the whole expression for the hover");
		Transition empty = model.getTransitions().stream().filter(t -> t.getTE() == null || t.getTE().isBlank()).findFirst().orElseThrow();
		assertNotNull(StatechartGraph.find(graph, "//@transitions." + model.getTransitions().indexOf(empty)));
		assertTrue(((GEdge) edges.get(model.getTransitions().indexOf(empty))).getChildren().isEmpty(), "no label without an expression");
	}
}
