package org.kse.diagram.server.operations;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.edit.command.SetCommand;
import org.eclipse.glsp.server.features.directediting.ApplyLabelEditOperation;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartPackage.Literals;
import org.kse.model.statechart.Transition;

/**
 * A name or an expression edited in place. A transition's label shows only the first line of its
 * expression, but a line break may fall anywhere inside a guard, so the editor opens on the whole
 * expression and the edit replaces it whole.
 */
public class LabelEditHandler extends StatechartOperationHandler<ApplyLabelEditOperation> {

	@Override
	protected Command command(ApplyLabelEditOperation operation) {
		String problem = LabelEdits.problem(state, operation.getLabelId(), operation.getText());
		if (problem != null) {
			throw refused(problem);
		}
		Object element = element(operation.getLabelId());
		if (element instanceof Node node) {
			if (NodeKind.CONDITION.is(node) || operation.getText().strip().equals(node.getName())) {
				return null;
			}
			return SetCommand.create(state.getDomain(), node, Literals.NODE__NAME, operation.getText().strip());
		}
		Transition transition = (Transition) element;
		String expression = operation.getText().strip();
		return expression.equals(transition.getTE() == null ? "" : transition.getTE().strip()) ? null : SetCommand.create(state.getDomain(), transition, Literals.TRANSITION__TE, expression);
	}
}
