package org.kse.diagram.server.operations;

import java.util.LinkedHashMap;
import java.util.Map;

import org.eclipse.emf.common.command.Command;
import org.eclipse.glsp.server.operations.ChangeBoundsOperation;
import org.eclipse.glsp.server.types.ElementAndBounds;
import org.kse.diagram.server.BoundsCommand;
import org.kse.model.statechart.Node;
import org.kse.notation.Bounds;

/** Moved and resized states (positions relative to their parent state); their composites grow to hold them. */
public class ChangeBoundsHandler extends StatechartOperationHandler<ChangeBoundsOperation> {

	@Override
	protected Command command(ChangeBoundsOperation operation) {
		Map<Node, Bounds> moved = new LinkedHashMap<>();
		for (ElementAndBounds each : operation.getNewBounds()) {
			Node node = state(each.getElementId());
			Bounds old = state.getLayout().get(node);
			double x = each.getNewPosition() == null ? old.x() : coordinate(each.getNewPosition().getX());
			double y = each.getNewPosition() == null ? old.y() : coordinate(each.getNewPosition().getY());
			double width = each.getNewSize() == null ? old.width() : Math.max(8, coordinate(each.getNewSize().getWidth()));
			double height = each.getNewSize() == null ? old.height() : Math.max(8, coordinate(each.getNewSize().getHeight()));
			moved.put(node, new Bounds(x, y, width, height));
		}
		if (moved.isEmpty()) {
			return null;
		}
		// a state moved or enlarged past its composite's border: the composite grows (unless it was resized itself)
		Map<Node, java.util.List<Bounds>> byOwner = new LinkedHashMap<>();
		moved.forEach((node, bounds) -> {
			if (node.eContainer() instanceof Node owner && !moved.containsKey(owner)) {
				byOwner.computeIfAbsent(owner, key -> new java.util.ArrayList<>()).add(bounds);
			}
		});
		Map<Node, Bounds> grown = new LinkedHashMap<>();
		byOwner.forEach((owner, inside) -> grown.putAll(state.getLayout().grownToHold(owner, inside)));
		grown.keySet().removeAll(moved.keySet());
		String label = moved.size() == 1 ? "Move State" : "Move States";
		moved.putAll(grown);
		return new BoundsCommand(label, state.getLayout(), moved);
	}
}
