package org.kse.diagram.server.operations;

import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.common.command.CompoundCommand;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.glsp.server.operations.ChangeContainerOperation;
import org.kse.diagram.server.BoundsCommand;
import org.kse.model.NodeKind;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.notation.Arrange;
import org.kse.notation.Bounds;

/** A state dragged into another composite state (or out to the top of the model), keeping its insides. */
public class ChangeContainerHandler extends StatechartOperationHandler<ChangeContainerOperation> {

	@Override
	protected Command command(ChangeContainerOperation operation) {
		Node moved = state(operation.getElementId());
		EObject target = operation.getTargetContainerId() == null ? state.getModel() : element(operation.getTargetContainerId());
		if (!(target instanceof Node) && !(target instanceof Model)) {
			throw refused(operation.getTargetContainerId() + " cannot hold states");
		}
		String refusal = StatechartEdits.refusal(target, NodeKind.of(moved));
		if (refusal != null) {
			throw refused("cannot move " + describe(moved) + " into " + describe((Node) target) + ": " + refusal);
		}
		Command move = StatechartEdits.move(state.getDomain(), state.getModel(), List.of(moved), target);
		if (!move.canExecute()) {
			throw refused("cannot move " + describe(moved) + " into " + (target instanceof Node node ? describe(node) : "the top of the model")
					+ ": it is there already or inside the state itself");
		}
		Bounds old = state.getLayout().get(moved);
		double[] origin = state.getLayout().absolute(target);
		double x = operation.getLocation().map(point -> coordinate(point.getX()) - origin[0]).orElse(old.x());
		double y = operation.getLocation().map(point -> coordinate(point.getY()) - origin[1]).orElse(old.y());
		if (target instanceof Node) {
			// a state grabbed in its middle and dropped near the composite's left or top border stays inside it
			y = Math.max(y, Arrange.HEADER);
			x = Math.max(x, 4);
		}
		CompoundCommand reparent = new CompoundCommand(CompoundCommand.MERGE_COMMAND_ALL, "Move State");
		reparent.append(move);
		Map<Node, Bounds> placed = new java.util.LinkedHashMap<>();
		placed.put(moved, new Bounds(x, y, old.width(), old.height()));
		placed.putAll(state.getLayout().grownToHold(target, List.of(placed.get(moved))));
		reparent.append(new BoundsCommand("Place", state.getLayout(), placed));
		return reparent;
	}
}
