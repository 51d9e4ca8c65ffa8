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
		int order = 0;
		for (NodeKind kind : NodeKind.THESIS_ORDER) {
			String type = StatechartGraph.type(kind);
			states.add(new PaletteItem("palette-" + type, kind.caption(), new TriggerNodeCreationAction(type), kind.icon(), String.valueOf((char) ('a' + order++))));
		}
		List<PaletteItem> transitions = List.of(new PaletteItem("palette-transition", "Transition", new TriggerEdgeCreationAction(StatechartGraph.TRANSITION),
				"arrow-right", "a"));
		return List.of(PaletteItem.createPaletteGroup("states", "States", states, "symbol-structure", "a"),
				PaletteItem.createPaletteGroup("transitions", "Transitions", transitions, "arrow-right", "b"));
	}
}
