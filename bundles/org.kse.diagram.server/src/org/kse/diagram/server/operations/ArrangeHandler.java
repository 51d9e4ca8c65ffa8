package org.kse.diagram.server.operations;

import java.util.IdentityHashMap;
import java.util.Map;

import org.eclipse.emf.common.command.Command;
import org.eclipse.glsp.server.operations.LayoutOperation;
import org.kse.diagram.server.BoundsCommand;
import org.kse.model.statechart.Node;
import org.kse.notation.Arrange;
import org.kse.notation.Bounds;
import org.kse.notation.Notation;

/** "Arrange all": every state placed anew by ELK, as one undoable step. */
public class ArrangeHandler extends StatechartOperationHandler<LayoutOperation> {

	@Override
	protected Command command(LayoutOperation operation) {
		Notation arranged = Arrange.all(state.getModel());
		Map<Node, Bounds> placed = new IdentityHashMap<>();
		for (var contents = state.getModel().eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && arranged.get(node) != null) {
				placed.put(node, arranged.get(node));
			}
		}
		return placed.isEmpty() ? null : new BoundsCommand("Arrange All", state.getLayout(), placed);
	}
}
