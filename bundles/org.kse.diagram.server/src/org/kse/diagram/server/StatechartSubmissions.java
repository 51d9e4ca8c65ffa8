package org.kse.diagram.server;

import java.util.List;

import org.eclipse.emf.common.command.CommandStackListener;
import org.eclipse.glsp.server.actions.Action;
import org.eclipse.glsp.server.di.ClientId;
import org.eclipse.glsp.server.features.core.model.ModelSubmissionHandler;
import org.eclipse.glsp.server.session.ClientSession;
import org.eclipse.glsp.server.session.ClientSessionListener;
import org.eclipse.glsp.server.session.ClientSessionManager;

import com.google.inject.Inject;

/**
 * GLSP's model submission, made to follow a model that others edit too, and to end with its
 * session:
 * <ul>
 * <li>the diagram is built where the model may be read ({@link StatechartSources.Source#access}),
 * before GLSP's model lock is taken: its handler of computed bounds holds that lock while it
 * submits, so the other order would deadlock with a workbench's UI thread;
 * <li>a change of the command stack that the session did not make (the Properties view, the
 * tree, the workbench's undo) sends the changed diagram to the client;
 * <li>the live validation runs on a thread of its own that GLSP never stops: without this, every
 * diagram page would leave a thread behind (and keep a JVM that opened a diagram from exiting).
 * </ul>
 */
public class StatechartSubmissions extends ModelSubmissionHandler implements ClientSessionListener {

	@Inject
	@ClientId
	private String clientId;

	@Inject
	private StatechartModelState state;

	private final CommandStackListener externalChanges = event -> {
		if (!state.isOwnChange()) {
			actionDispatcher.dispatch(new ExternalChangeAction());
		}
	};

	@Inject
	void listenTo(ClientSessionManager sessions) {
		sessions.addListener(this, clientId);
	}

	/**
	 * The command stack the session listens to. A session may ask for a model again (a page
	 * reloads, a client repeats itself), and its file may be read again (changed on disk): it
	 * listens once, to the stack of the model it shows now. Added at each request, the listeners
	 * piled up on a stack that pages share, and outlived their session: every later edit
	 * dispatched to stopped sessions (the diagram fuzz suite found it).
	 */
	private org.eclipse.emf.common.command.CommandStack listened;

	@Override
	public List<Action> submitModel(String reason) {
		List<Action> actions = state.read(() -> super.submitModel(reason));
		org.eclipse.emf.common.command.CommandStack stack = state.getDomain() == null ? null : state.getDomain().getCommandStack();
		if (listened != stack) {
			if (listened != null) {
				listened.removeCommandStackListener(externalChanges);
			}
			if (stack != null) {
				stack.addCommandStackListener(externalChanges);
			}
			listened = stack;
		}
		return actions;
	}

	@Override
	public void sessionDisposed(ClientSession session) {
		if (liveValidationDebouncer != null) {
			liveValidationDebouncer.dispose();
			liveValidationDebouncer = null;
		}
		if (listened != null) {
			listened.removeCommandStackListener(externalChanges);
			listened = null;
		}
		if (state.getSource() != null) {
			state.getSource().close();
		}
	}
}
