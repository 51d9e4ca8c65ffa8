package org.kse.diagram.server.operations;

import java.util.List;

import org.eclipse.emf.common.command.Command;
import org.eclipse.glsp.server.operations.CreateEdgeOperation;
import org.eclipse.glsp.server.operations.CreateOperationHandler;
import org.kse.diagram.server.StatechartGraph;
import org.kse.model.NodeKind;
import org.kse.model.StatechartRules;
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
		NodeKind from = NodeKind.of(source);
		String refusal = StatechartRules.transitionRefusal(from, NodeKind.of(target));
		if (refusal != null) {
			throw refused(refusal + " (" + describe(from != null && !StatechartRules.mayLeave(from) ? source : target) + ")");
		}
		return StatechartEdits.newTransition(state.getDomain(), state.getModel(), source, target);
	}
}
