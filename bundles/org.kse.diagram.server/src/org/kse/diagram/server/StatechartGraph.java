package org.kse.diagram.server;

import java.util.Locale;
import java.util.Map;
import java.util.function.Function;

import org.eclipse.emf.ecore.EObject;

import org.eclipse.glsp.graph.GEdge;
import org.eclipse.glsp.graph.GGraph;
import org.eclipse.glsp.graph.GModelElement;
import org.eclipse.glsp.graph.GNode;
import org.eclipse.glsp.graph.builder.impl.GEdgeBuilder;
import org.eclipse.glsp.graph.builder.impl.GEdgePlacementBuilder;
import org.eclipse.glsp.graph.builder.impl.GGraphBuilder;
import org.eclipse.glsp.graph.builder.impl.GLabelBuilder;
import org.eclipse.glsp.graph.builder.impl.GNodeBuilder;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.notation.Bounds;
import org.kse.notation.Notation;
import org.kse.notation.Shapes;

/**
 * The statechart as the diagram's graph: a node per state, typed by its kind ({@code state:basic},
 * {@code state:or}, …) so that the client draws the thesis' notation, with its children nested
 * inside it at the notation's positions, and an edge per transition labelled with the first line
 * of its expression (all of it is the edge's {@code expression} argument, shown on hover).
 * Element ids are the elements' paths in the model file, the keys of the notation too.
 */
public final class StatechartGraph {

	public static final String GRAPH = "graph";
	public static final String STATE = "state:";
	public static final String TRANSITION = "transition";
	public static final String NAME = "label:name";
	public static final String EXPRESSION = "label:expression";

	private StatechartGraph() {
	}

	/** The graph type of a state of this kind. */
	public static String type(NodeKind kind) {
		return STATE + (kind == null ? "unknown" : kind.name().toLowerCase(Locale.ROOT));
	}

	/** The id of the graph's root, which stands for the model. */
	public static final String ROOT = "statechart";

	public static GGraph of(Model model, Notation notation) {
		return of(model, node -> {
			Bounds placed = notation.get(node);
			return placed != null ? placed : Shapes.size(node);
		}, new java.util.HashMap<>());
	}

	/** The graph of the model with states where {@code bounds} says; {@code ids} receives the element of each id. */
	public static GGraph of(Model model, Function<Node, Bounds> bounds, Map<String, EObject> ids) {
		GGraphBuilder graph = new GGraphBuilder(GRAPH).id(ROOT);
		ids.put(ROOT, model);
		for (Node root : model.getNodes()) {
			graph.add(state(root, bounds, ids));
		}
		for (int i = 0; i < model.getTransitions().size(); i++) {
			Transition transition = model.getTransitions().get(i);
			if (transition.getSource() != null && transition.getTarget() != null) {
				graph.add(transition(transition, i));
				ids.put("//@transitions." + i, transition);
			}
		}
		return graph.build();
	}

	private static GNode state(Node node, Function<Node, Bounds> placement, Map<String, EObject> ids) {
		NodeKind kind = NodeKind.of(node);
		Bounds bounds = placement.apply(node);
		String id = Notation.path(node);
		ids.put(id, node);
		GNodeBuilder shape = new GNodeBuilder(type(kind)).id(id).position(bounds.x(), bounds.y()).size(bounds.width(), bounds.height())
				.addCssClass("kse-" + (kind == null ? "unknown" : kind.name().toLowerCase(Locale.ROOT)))
				.addArgument("label", node.getLabel() == null ? "" : node.getLabel());
		if (kind != NodeKind.START && kind != NodeKind.END) {
			boolean composite = !node.getChildren().isEmpty() || kind == NodeKind.OR || kind == NodeKind.AND;
			String text = kind == NodeKind.CONDITION ? "C" : node.getName() == null ? "" : node.getName();
			GLabelBuilder name = new GLabelBuilder(NAME).id(id + "#name").text(text);
			if (composite) {
				name.position(8, 6);
			} else {
				name.position(bounds.width() / 2, bounds.height() / 2).alignment(0.5, 0.5);
			}
			shape.add(name.build());
		}
		for (Node child : node.getChildren()) {
			shape.add(state(child, placement, ids));
		}
		return shape.build();
	}

	private static GEdge transition(Transition transition, int index) {
		String id = "//@transitions." + index;
		String expression = transition.getTE() == null ? "" : transition.getTE().strip();
		String firstLine = expression.lines().findFirst().orElse("").strip() + (expression.lines().count() > 1 ? " …" : "");
		GEdgeBuilder edge = new GEdgeBuilder(TRANSITION).id(id).sourceId(Notation.path(transition.getSource()))
				.targetId(Notation.path(transition.getTarget())).addArgument("expression", expression)
				.addArgument("name", transition.getName() == null ? "" : transition.getName());
		if (!firstLine.isEmpty()) {
			edge.add(new GLabelBuilder(EXPRESSION).id(id + "#expression").text(firstLine)
					.edgePlacement(new GEdgePlacementBuilder().side("top").position(0.5).offset(4).rotate(false).build()).build());
		}
		return edge.build();
	}

	/** The element of the graph with this id, or null. */
	public static GModelElement find(GModelElement root, String id) {
		if (id.equals(root.getId())) {
			return root;
		}
		for (GModelElement child : root.getChildren()) {
			GModelElement found = find(child, id);
			if (found != null) {
				return found;
			}
		}
		return null;
	}
}
