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
import org.eclipse.glsp.graph.builder.impl.GGraphBuilder;
import org.eclipse.glsp.graph.builder.impl.GLabelBuilder;
import org.eclipse.glsp.graph.builder.impl.GNodeBuilder;
import org.kse.model.NodeKind;
import org.kse.model.StatechartRules;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.notation.Bounds;
import org.kse.notation.Captions;
import org.kse.notation.Notation;
import org.kse.notation.NotationStyle;
import org.kse.notation.Shapes;
import org.kse.notation.TextWidth;
import org.kse.notation.TransitionLayout;

/**
 * The statechart as the diagram's graph: a node per state, typed by its kind ({@code state:basic},
 * {@code state:or}, …) so that the client draws the thesis' notation, with its children nested
 * inside it at the notation's positions, and an edge per transition, routed and labelled with the
 * first line of its expression by {@link TransitionLayout} (all of the expression is the edge's
 * {@code expression} argument, shown on hover). A state named after a formula shows the formula
 * ({@link Captions}); its name is its {@code name} argument.
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
	/** How the page draws names: the notation's style, which its views read too. */
	private static final NotationStyle STYLE = NotationStyle.get();

	public static GGraph of(Model model, Notation notation) {
		return of(model, node -> {
			Bounds placed = notation.get(node);
			return placed != null ? placed : Shapes.size(node);
		}, new java.util.HashMap<>());
	}

	/**
	 * The rule book's answers the page needs before it asks the server (ADR 0018): which kinds
	 * hold other states ({@code compositeKinds}, e.g. "or and"), and why a kind cannot go into
	 * another ({@code holdRefusal:<parent>/<child>}), so a refused drop says what the server would.
	 * The same for every graph: made once.
	 */
	private static final Map<String, String> RULES = rules();

	private static Map<String, String> rules() {
		Map<String, String> rules = new java.util.LinkedHashMap<>();
		StringBuilder composite = new StringBuilder();
		for (NodeKind parent : NodeKind.values()) {
			if (parent.isComposite()) {
				composite.append(composite.isEmpty() ? "" : " ").append(kindName(parent));
			}
			for (NodeKind child : NodeKind.values()) {
				String refusal = StatechartRules.holdRefusal(parent, child);
				if (refusal != null) {
					rules.put("holdRefusal:" + kindName(parent) + "/" + kindName(child), refusal);
				}
			}
		}
		rules.put("compositeKinds", composite.toString());
		return java.util.Collections.unmodifiableMap(rules);
	}

	private static String kindName(NodeKind kind) {
		return kind.name().toLowerCase(Locale.ROOT);
	}

	/** The graph of the model with states where {@code bounds} says; {@code ids} receives the element of each id. */
	public static GGraph of(Model model, Function<Node, Bounds> bounds, Map<String, EObject> ids) {
		GGraphBuilder graph = new GGraphBuilder(GRAPH).id(ROOT);
		RULES.forEach(graph::addArgument);
		ids.put(ROOT, model);
		for (Node root : model.getNodes()) {
			graph.add(state(root, bounds, ids));
		}
		Map<Transition, TransitionLayout.Placed> routes = TransitionLayout.of(model, bounds);
		for (int i = 0; i < model.getTransitions().size(); i++) {
			Transition transition = model.getTransitions().get(i);
			TransitionLayout.Placed route = routes.get(transition);
			if (route != null) {
				graph.add(transition(transition, i, route));
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
				.addArgument("label", node.getLabel() == null ? "" : node.getLabel())
				.addArgument("name", node.getName() == null ? "" : node.getName());
		if (kind != NodeKind.START && kind != NodeKind.END) {
			boolean composite = !node.getChildren().isEmpty() || kind != null && kind.isComposite();
			String letter = STYLE.of(kind).letter();
			String text = letter != null ? letter : Captions.of(node);
			GLabelBuilder name = new GLabelBuilder(NAME).id(id + "#name").text(text);
			// sized here, as the client would measure it: the client then has nothing to measure before it draws
			if (composite) {
				NotationStyle.TextStyle header = STYLE.headerCaption();
				name.position(header.x(), header.y() - header.size()).size(TextWidth.of(text, header.size(), header.bold()), header.size() + 4);
			} else {
				NotationStyle.TextStyle font = letter != null ? STYLE.letterCaption() : STYLE.centredCaption();
				name.position(bounds.width() / 2, bounds.height() / 2).alignment(0.5, 0.5).size(TextWidth.of(text, font.size(), font.bold()),
						font.size() + 4);
			}
			shape.add(name.build());
		}
		for (Node child : node.getChildren()) {
			shape.add(state(child, placement, ids));
		}
		return shape.build();
	}

	/** A transition along its route, its label where the route placed it (both in diagram coordinates). */
	private static GEdge transition(Transition transition, int index, TransitionLayout.Placed route) {
		String id = "//@transitions." + index;
		String expression = transition.getTE() == null ? "" : transition.getTE().strip();
		GEdgeBuilder edge = new GEdgeBuilder(TRANSITION).id(id).sourceId(Notation.path(transition.getSource()))
				.targetId(Notation.path(transition.getTarget())).addArgument("expression", expression)
				.addArgument("name", transition.getName() == null ? "" : transition.getName());
		for (double[] bend : route.bends()) {
			edge.addRoutingPoint(bend[0], bend[1]);
		}
		if (route.label() != null) {
			Bounds label = route.label();
			edge.add(new GLabelBuilder(EXPRESSION).id(id + "#expression").text(route.text()).position(label.x(), label.y())
					.size(label.width(), label.height()).build());
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
