package org.kse.diagram.server.operations;

import org.eclipse.emf.common.command.Command;
import org.eclipse.glsp.server.operations.ChangeRoutingPointsOperation;

/**
 * Bend points dragged on a transition. Transitions are routed from their states' bounds every
 * time the diagram is drawn (the notation file keeps no bend points, as the original's did not),
 * so the operation, which the client also sends along with every move, changes nothing.
 */
public class RoutingPointsHandler extends StatechartOperationHandler<ChangeRoutingPointsOperation> {

	@Override
	protected Command command(ChangeRoutingPointsOperation operation) {
		return null;
	}
}
