package org.kse.diagram.server.operations;

import java.util.LinkedHashSet;
import java.util.Set;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.glsp.server.operations.DeleteOperation;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/** Deletes states with everything inside them and every transition attached, and transitions. */
public class DeleteHandler extends StatechartOperationHandler<DeleteOperation> {

	@Override
	protected Command command(DeleteOperation operation) {
		Set<EObject> doomed = new LinkedHashSet<>();
		for (String id : operation.getElementIds()) {
			EObject element = state.element(id);
			if (element instanceof Node || element instanceof Transition) {
				doomed.add(element);
			}
		}
		return doomed.isEmpty() ? null : StatechartEdits.delete(state.getDomain(), state.getModel(), doomed);
	}
}
