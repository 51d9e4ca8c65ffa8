package org.kse.diagram.server.operations;

import java.util.LinkedHashSet;
import java.util.Set;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.glsp.server.operations.CutOperation;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Node;

/** The second half of cut: the copied states are deleted, with the transitions attached to them. */
public class CutHandler extends StatechartOperationHandler<CutOperation> {

	@Override
	protected Command command(CutOperation operation) {
		Set<EObject> cut = new LinkedHashSet<>();
		for (String id : DiagramClipboard.selectedIds(operation.getEditorContext())) {
			if (state.element(id) instanceof Node node) {
				cut.add(node);
			}
		}
		return cut.isEmpty() ? null : StatechartEdits.delete(state.getDomain(), state.getModel(), cut);
	}
}
