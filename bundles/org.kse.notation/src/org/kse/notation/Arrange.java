package org.kse.notation;

import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.elk.alg.layered.options.LayeredMetaDataProvider;
import org.eclipse.elk.alg.layered.options.LayeredOptions;
import org.eclipse.elk.alg.layered.options.NodePlacementStrategy;
import org.eclipse.elk.core.RecursiveGraphLayoutEngine;
import org.eclipse.elk.core.data.LayoutMetaDataService;
import org.eclipse.elk.core.math.ElkPadding;
import org.eclipse.elk.core.options.CoreOptions;
import org.eclipse.elk.core.options.Direction;
import org.eclipse.elk.core.options.EdgeRouting;
import org.eclipse.elk.core.options.HierarchyHandling;
import org.eclipse.elk.core.options.SizeConstraint;
import org.eclipse.elk.core.util.BasicProgressMonitor;
import org.eclipse.elk.core.options.EdgeLabelPlacement;
import org.eclipse.elk.graph.ElkEdge;
import org.eclipse.elk.graph.ElkLabel;
import org.eclipse.elk.graph.ElkNode;
import org.eclipse.elk.graph.util.ElkGraphUtil;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/**
 * "Arrange all": places every state with ELK's layered algorithm, the whole hierarchy at once
 * (a composite grows around its children, transitions between levels are taken into account),
 * top to bottom in the order the transitions run. Transition labels take part: the layers leave
 * room for them, so that {@link TransitionLayout} finds them a free place beside their line. Top to
 * bottom because a label is wide and one line high: left to right, every label widened its layer
 * and the Goalie came out 7,000 px wide.
 */
public final class Arrange {

	/** Room above a composite's children for its name. */
	public static final double HEADER = 28;
	private static final double PADDING = 14;

	static {
		LayoutMetaDataService.getInstance().registerLayoutMetaDataProviders(new LayeredMetaDataProvider());
	}

	private Arrange() {
	}

	/** A new notation with every state of the model placed. */
	public static Notation all(Model model) {
		ElkNode graph = ElkGraphUtil.createGraph();
		configure(graph);
		graph.setProperty(CoreOptions.HIERARCHY_HANDLING, HierarchyHandling.INCLUDE_CHILDREN);
		Map<Node, ElkNode> shapes = new IdentityHashMap<>();
		for (Node root : model.getNodes()) {
			add(graph, root, shapes);
		}
		for (Transition transition : model.getTransitions()) {
			ElkNode source = shapes.get(transition.getSource());
			ElkNode target = shapes.get(transition.getTarget());
			if (source != null && target != null) {
				ElkEdge edge = ElkGraphUtil.createSimpleEdge(source, target);
				ElkGraphUtil.updateContainment(edge);
				String text = TransitionLayout.labelText(transition);
				if (!text.isEmpty()) {
					// the layers leave room for the label beside its transition
					Bounds size = TransitionLayout.labelSize(text);
					ElkLabel label = ElkGraphUtil.createLabel(text, edge);
					label.setDimensions(size.width(), size.height());
					label.setProperty(CoreOptions.EDGE_LABELS_PLACEMENT, EdgeLabelPlacement.CENTER);
				}
			}
		}
		new RecursiveGraphLayoutEngine().layout(graph, new BasicProgressMonitor());
		Notation notation = new Notation();
		shapes.forEach((node, shape) -> notation.put(node, new Bounds(shape.getX(), shape.getY(), shape.getWidth(), shape.getHeight())));
		return notation;
	}

	private static void configure(ElkNode shape) {
		shape.setProperty(CoreOptions.ALGORITHM, LayeredOptions.ALGORITHM_ID);
		shape.setProperty(CoreOptions.DIRECTION, Direction.DOWN);
		shape.setProperty(CoreOptions.EDGE_ROUTING, EdgeRouting.ORTHOGONAL);
		shape.setProperty(CoreOptions.SPACING_NODE_NODE, 24.0);
		shape.setProperty(LayeredOptions.SPACING_NODE_NODE_BETWEEN_LAYERS, 36.0);
		shape.setProperty(LayeredOptions.SPACING_EDGE_LABEL, 6.0);
		shape.setProperty(LayeredOptions.SPACING_LABEL_NODE, 8.0);
		// straighter, narrower flows than the default (Brandes-Köpf) for these nested charts
		shape.setProperty(LayeredOptions.NODE_PLACEMENT_STRATEGY, NodePlacementStrategy.NETWORK_SIMPLEX);
	}

	private static void add(ElkNode parent, Node node, Map<Node, ElkNode> shapes) {
		ElkNode shape = ElkGraphUtil.createNode(parent);
		shapes.put(node, shape);
		List<Node> children = node.getChildren();
		if (children.isEmpty()) {
			Bounds size = Shapes.size(node);
			shape.setDimensions(size.width(), size.height());
			return;
		}
		configure(shape);
		shape.setProperty(CoreOptions.PADDING, new ElkPadding(HEADER + PADDING, PADDING, PADDING, PADDING));
		shape.setProperty(CoreOptions.NODE_SIZE_CONSTRAINTS, java.util.EnumSet.of(SizeConstraint.MINIMUM_SIZE));
		shape.setProperty(CoreOptions.NODE_SIZE_MINIMUM, new org.eclipse.elk.core.math.KVector(Shapes.headerWidth(node), HEADER + 2 * PADDING));
		for (Node child : children) {
			add(shape, child, shapes);
		}
		if (NodeKind.AND.is(node)) {
			// the regions of an AND state run in parallel: side by side, not in a flow
			shape.setProperty(CoreOptions.DIRECTION, Direction.RIGHT);
		}
	}
}
