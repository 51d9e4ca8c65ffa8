package org.kse.diagram.server;

import org.eclipse.glsp.server.actions.Action;

/**
 * The model changed outside the diagram (the Properties view, the tree, an undo in the workbench):
 * a server-side action that makes the session send the changed diagram to its client.
 */
public class ExternalChangeAction extends Action {

	public static final String KIND = "kseExternalChange";

	public ExternalChangeAction() {
		super(KIND);
	}
}
