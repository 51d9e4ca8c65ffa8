package org.kse.diagram.server.operations;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.common.command.CompoundCommand;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.glsp.server.operations.CreateNodeOperation;
import org.eclipse.glsp.server.operations.CreateOperationHandler;
import org.kse.diagram.server.BoundsCommand;
import org.kse.diagram.server.StatechartGraph;
import org.kse.model.NodeKind;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Node;
import org.kse.notation.Bounds;
import org.kse.notation.Shapes;

/** A new state from the palette, where it was dropped: only into a container that may hold it. */
public class CreateStateHandler extends StatechartOperationHandler<CreateNodeOperation> implements CreateOperationHandler<CreateNodeOperation> {

	static final double NEW_COMPOSITE_WIDTH = 240;
	static final double NEW_COMPOSITE_HEIGHT = 160;

	@Override
	public List<String> getHandledElementTypeIds() {
		List<String> types = new ArrayList<>();
		for (NodeKind kind : NodeKind.values()) {
			types.add(StatechartGraph.type(kind));
		}
		return types;
	}

	@Override
	public String getLabel() {
		return "Create State";
	}

	@Override
	protected Command command(CreateNodeOperation operation) {
		NodeKind kind = kind(operation.getElementTypeId());
		EObject owner = operation.getContainerId() == null ? state.getModel() : element(operation.getContainerId());
		if (owner instanceof org.kse.model.statechart.Transition) {
			owner = state.getModel();
		}
		String refusal = StatechartEdits.refusal(owner, kind);
		if (refusal != null) {
			throw refused("cannot create the " + kind.name() + " state in " + describe((Node) owner) + ": " + refusal);
		}
		Node created = StatechartEdits.createState(state.getModel(), owner, kind);
		Bounds size = Shapes.size(created);
		if (kind.isComposite()) {
			// an empty composite is drawn to be filled: room for a few states and their arrows
			size = new Bounds(0, 0, Math.max(NEW_COMPOSITE_WIDTH, size.width()), NEW_COMPOSITE_HEIGHT);
		}
		double[] origin = state.getLayout().absolute(owner);
		double x = operation.getLocation().map(point -> coordinate(point.getX()) - origin[0]).orElse(20.0);
		double y = operation.getLocation().map(point -> coordinate(point.getY()) - origin[1]).orElse(40.0);
		if (owner instanceof Node) {
			y = Math.max(y, org.kse.notation.Arrange.HEADER);
			x = Math.max(x, 4);
		}
		CompoundCommand create = new CompoundCommand(CompoundCommand.MERGE_COMMAND_ALL, "New " + kind.name() + " State");
		create.append(StatechartEdits.add(state.getDomain(), state.getModel(), owner, created));
		java.util.Map<Node, Bounds> placed = new java.util.LinkedHashMap<>();
		placed.put(created, new Bounds(x, y, size.width(), size.height()));
		placed.putAll(state.getLayout().grownToHold(owner, List.of(placed.get(created))));
		create.append(new BoundsCommand("Place", state.getLayout(), placed));
		return create;
	}

	static NodeKind kind(String type) {
		for (NodeKind kind : NodeKind.values()) {
			if (StatechartGraph.type(kind).equals(type)) {
				return kind;
			}
		}
		throw refused("unknown state type " + type);
	}
}
