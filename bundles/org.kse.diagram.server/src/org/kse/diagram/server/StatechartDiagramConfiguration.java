package org.kse.diagram.server;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.glsp.graph.DefaultTypes;
import org.eclipse.glsp.graph.GraphExtension;
import org.eclipse.glsp.graph.GraphPackage;
import org.eclipse.glsp.server.diagram.DiagramConfiguration;
import org.eclipse.glsp.server.types.EdgeTypeHint;
import org.eclipse.glsp.server.types.ShapeTypeHint;
import org.kse.model.NodeKind;
import org.kse.model.StatechartRules;

/**
 * What the client may do with which element: states move, resize, delete and go into composites
 * (an AND state takes only OR regions); transitions run from any state but END to any but START.
 */
public class StatechartDiagramConfiguration implements DiagramConfiguration {

	public static final String DIAGRAM_TYPE = "kse-statechart";

	@Override
	public String getDiagramType() {
		return DIAGRAM_TYPE;
	}

	@Override
	public Map<String, EClass> getTypeMappings() {
		Map<String, EClass> mappings = new HashMap<>(DefaultTypes.getDefaultTypeMappings());
		for (NodeKind kind : NodeKind.values()) {
			mappings.put(StatechartGraph.type(kind), GraphPackage.Literals.GNODE);
		}
		mappings.put(StatechartGraph.TRANSITION, GraphPackage.Literals.GEDGE);
		mappings.put(StatechartGraph.NAME, GraphPackage.Literals.GLABEL);
		mappings.put(StatechartGraph.EXPRESSION, GraphPackage.Literals.GLABEL);
		mappings.put(StatechartGraph.GRAPH, GraphPackage.Literals.GGRAPH);
		return mappings;
	}

	@Override
	public List<ShapeTypeHint> getShapeTypeHints() {
		List<ShapeTypeHint> hints = new ArrayList<>();
		for (NodeKind kind : NodeKind.values()) {
			List<String> containable = StatechartRules.mayHold(kind).stream().map(StatechartGraph::type).toList();
			hints.add(new ShapeTypeHint(StatechartGraph.type(kind), true, true, StatechartRules.isResizable(kind), true, containable));
		}
		return hints;
	}

	@Override
	public List<EdgeTypeHint> getEdgeTypeHints() {
		List<String> sources = new ArrayList<>();
		List<String> targets = new ArrayList<>();
		for (NodeKind kind : NodeKind.values()) {
			if (StatechartRules.mayLeave(kind)) {
				sources.add(StatechartGraph.type(kind));
			}
			if (StatechartRules.mayEnter(kind)) {
				targets.add(StatechartGraph.type(kind));
			}
		}
		return List.of(new EdgeTypeHint(StatechartGraph.TRANSITION, false, true, true, sources, targets));
	}

	/**
	 * Updates are drawn at once. GLSP animates every update by default: a state dropped after a
	 * drag slid back from where it had been for a third of a second, and each edit took that long
	 * to show (in a large diagram, longer: every element is interpolated).
	 */
	@Override
	public boolean animatedUpdate() {
		return false;
	}

	/**
	 * The server sizes every label (TextWidth) and the page draws names from their state's size,
	 * so the page has nothing to measure: each update is drawn as it arrives, without the round
	 * trip of the client's bounds, which doubled the wait after every edit of a large model.
	 */
	@Override
	public boolean needsClientLayout() {
		return false;
	}

	@Override
	public Optional<GraphExtension> getGraphExtension() {
		return Optional.empty();
	}
}
