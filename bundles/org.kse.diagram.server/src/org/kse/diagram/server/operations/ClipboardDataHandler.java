package org.kse.diagram.server.operations;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.glsp.server.actions.AbstractActionHandler;
import org.eclipse.glsp.server.actions.Action;
import org.eclipse.glsp.server.features.clipboard.RequestClipboardDataAction;
import org.eclipse.glsp.server.features.clipboard.SetClipboardDataAction;
import org.kse.diagram.server.StatechartModelState;
import org.kse.model.statechart.Node;

import com.google.inject.Inject;

/** Copy (and the first half of cut): the selected states go to the server's clipboard; the client keeps the key. */
public class ClipboardDataHandler extends AbstractActionHandler<RequestClipboardDataAction> {

	@Inject
	private StatechartModelState state;

	@Override
	protected List<Action> executeAction(RequestClipboardDataAction action) {
		return state.read(() -> copy(action));
	}

	private List<Action> copy(RequestClipboardDataAction action) {
		List<Node> selected = new ArrayList<>();
		for (String id : DiagramClipboard.selectedIds(action.getEditorContext())) {
			if (state.element(id) instanceof Node node && !selected.contains(node)) {
				selected.add(node);
			}
		}
		if (selected.isEmpty()) {
			return listOf(new SetClipboardDataAction(Map.of()));
		}
		String key = DiagramClipboard.copy(state.getModel(), selected, state.getLayout());
		String text = DiagramClipboard.get(key).description();
		return listOf(new SetClipboardDataAction(Map.of(DiagramClipboard.FORMAT, key, "text/plain", text)));
	}
}
