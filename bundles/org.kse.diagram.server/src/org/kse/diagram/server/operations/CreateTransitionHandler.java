package org.kse.diagram.server.operations;

import java.util.List;

import org.eclipse.emf.common.command.Command;
import org.eclipse.glsp.server.operations.CreateEdgeOperation;
import org.eclipse.glsp.server.operations.CreateOperationHandler;
import org.kse.diagram.server.StatechartGraph;
import org.kse.model.NodeKind;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Node;

/** A new transition between two states: none leaves an END state, none enters a START state. */
public class CreateTransitionHandler extends StatechartOperationHandler<CreateEdgeOperation> implements CreateOperationHandler<CreateEdgeOperation> {

	@Override
	public List<String> getHandledElementTypeIds() {
		return List.of(StatechartGraph.TRANSITION);
	}

	@Override
	public String getLabel() {
		return "Create Transition";
	}

	@Override
	protected Command command(CreateEdgeOperation operation) {
		Node source = state(operation.getSourceElementId());
		Node target = state(operation.getTargetElementId());
		if (NodeKind.END.is(source)) {
			throw refused("no transition leaves an END state (" + describe(source) + ")");
		}
		if (NodeKind.START.is(target)) {
			throw refused("no transition enters a START state (" + describe(target) + ")");
		}
		return StatechartEdits.newTransition(state.getDomain(), state.getModel(), source, target);
	}
}
