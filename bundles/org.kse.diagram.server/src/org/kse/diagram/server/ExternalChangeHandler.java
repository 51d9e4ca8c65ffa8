package org.kse.diagram.server;

import java.util.List;

import org.eclipse.glsp.server.actions.AbstractActionHandler;
import org.eclipse.glsp.server.actions.Action;
import org.eclipse.glsp.server.features.core.model.ModelSubmissionHandler;

import com.google.inject.Inject;

/** Sends the diagram of a model changed elsewhere to the client, with its dirty state. */
public class ExternalChangeHandler extends AbstractActionHandler<ExternalChangeAction> {

	@Inject
	private ModelSubmissionHandler submissions;

	@Override
	protected List<Action> executeAction(ExternalChangeAction action) {
		return submissions.submitModel();
	}
}
