package org.kse.diagram.server;

import org.eclipse.glsp.server.di.ClientId;
import org.eclipse.glsp.server.features.core.model.ModelSubmissionHandler;
import org.eclipse.glsp.server.session.ClientSession;
import org.eclipse.glsp.server.session.ClientSessionListener;
import org.eclipse.glsp.server.session.ClientSessionManager;

import com.google.inject.Inject;

/**
 * GLSP's model submission, whose live validation runs on a thread of its own that GLSP never
 * stops: without this, every diagram page opened in {@code kse serve} would leave a thread behind
 * (and keep a JVM that opened a diagram from exiting). The thread ends with its client session.
 */
public class StatechartSubmissions extends ModelSubmissionHandler implements ClientSessionListener {

	@Inject
	@ClientId
	private String clientId;

	@Inject
	void listenTo(ClientSessionManager sessions) {
		sessions.addListener(this, clientId);
	}

	@Override
	public void sessionDisposed(ClientSession session) {
		if (liveValidationDebouncer != null) {
			liveValidationDebouncer.dispose();
			liveValidationDebouncer = null;
		}
	}
}
