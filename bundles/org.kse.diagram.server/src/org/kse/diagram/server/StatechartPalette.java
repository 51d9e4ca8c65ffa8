package org.kse.diagram.server;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.glsp.server.actions.TriggerEdgeCreationAction;
import org.eclipse.glsp.server.actions.TriggerNodeCreationAction;
import org.eclipse.glsp.server.features.toolpalette.PaletteItem;
import org.eclipse.glsp.server.features.toolpalette.ToolPaletteItemProvider;
import org.kse.model.NodeKind;

/** The palette: every kind of state, in the order the thesis lists them, and the transition. */
public class StatechartPalette implements ToolPaletteItemProvider {

	@Override
	public List<PaletteItem> getItems(Map<String, String> args) {
		List<PaletteItem> states = new ArrayList<>();
		String[][] kinds = { { "START", "Start", "circle-filled" }, { "END", "End", "record" }, { "CONDITION", "Condition", "circle-large-outline" },
				{ "BASIC", "Basic (activity)", "symbol-method" }, { "OR", "OR (sequence)", "symbol-namespace" }, { "AND", "AND (parallel)", "split-horizontal" } };
		int order = 0;
		for (String[] kind : kinds) {
			String type = StatechartGraph.type(NodeKind.valueOf(kind[0]));
			states.add(new PaletteItem("palette-" + type, kind[1], new TriggerNodeCreationAction(type), kind[2], String.valueOf((char) ('a' + order++))));
		}
		List<PaletteItem> transitions = List.of(new PaletteItem("palette-transition", "Transition", new TriggerEdgeCreationAction(StatechartGraph.TRANSITION),
				"arrow-right", "a"));
		return List.of(PaletteItem.createPaletteGroup("states", "States", states, "symbol-structure", "a"),
				PaletteItem.createPaletteGroup("transitions", "Transitions", transitions, "arrow-right", "b"));
	}
}
