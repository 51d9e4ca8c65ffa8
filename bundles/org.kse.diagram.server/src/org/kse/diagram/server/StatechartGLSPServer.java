package org.kse.diagram.server;

import java.util.concurrent.CompletableFuture;

import org.apache.logging.log4j.LogManager;
import org.apache.logging.log4j.Logger;
import org.eclipse.glsp.server.actions.Action;
import org.eclipse.glsp.server.actions.ActionMessage;
import org.eclipse.glsp.server.protocol.DefaultGLSPServer;
import org.eclipse.glsp.server.protocol.InitializeClientSessionParameters;
import org.eclipse.glsp.server.protocol.InitializeParameters;
import org.eclipse.glsp.server.protocol.InitializeResult;
import org.eclipse.glsp.server.session.ClientSession;
import org.eclipse.glsp.server.types.GLSPServerException;
import org.eclipse.glsp.server.utils.MessageActionUtil;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;

/**
 * GLSP's server as a diagram client may speak to it, whatever it sends. GLSP logs every action
 * that fails with its stack trace, and lets a {@code process} notification without a session or
 * an action throw, which lsp4j prints with its own trace: on the terminal of {@code kse serve},
 * a refused edit or a stray message showed pages of Java. Here an action that fails is reported
 * to its page as GLSP does (a message whose details begin with the cause), without a stack
 * trace; the terminal gets one line for what is not a plain refusal, and the trace only at debug
 * level. A request without its parameters is answered with an error that says which.
 */
public class StatechartGLSPServer extends DefaultGLSPServer {

	private static final Logger LOG = LogManager.getLogger("org.kse.diagram");

	@Override
	public CompletableFuture<InitializeResult> initialize(InitializeParameters params) {
		if (params == null || params.getApplicationId() == null || params.getProtocolVersion() == null) {
			throw invalid("initialize needs an applicationId and a protocolVersion");
		}
		return super.initialize(params);
	}

	@Override
	public CompletableFuture<Void> initializeClientSession(InitializeClientSessionParameters params) {
		if (params == null || params.getClientSessionId() == null || params.getDiagramType() == null) {
			throw invalid("initializeClientSession needs a clientSessionId and a diagramType");
		}
		return super.initializeClientSession(params);
	}

	@Override
	public CompletableFuture<Void> disposeClientSession(org.eclipse.glsp.server.protocol.DisposeClientSessionParameters params) {
		if (params == null || params.getClientSessionId() == null) {
			throw invalid("disposeClientSession needs a clientSessionId");
		}
		return super.disposeClientSession(params);
	}

	/**
	 * GLSP 2.3 answers a request before {@code initialize} with lsp4j's old error code
	 * {@code serverNotInitialized}, which lsp4j 1.0 no longer has: the NoSuchFieldError closed the
	 * connection. Here it is the code lsp4j has now.
	 */
	@Override
	protected void validateServerInitialized() {
		if (!isInitialized()) {
			throw new ResponseErrorException(new ResponseError(ResponseErrorCode.ServerNotInitialized, "the server is not initialized: send initialize first", null));
		}
	}

	private static ResponseErrorException invalid(String message) {
		return new ResponseErrorException(new ResponseError(ResponseErrorCode.InvalidParams, message, null));
	}

	@Override
	public void process(ActionMessage message) {
		// a notification has no answer: what cannot be processed is said once on the terminal
		String clientId = message == null ? null : message.getClientId();
		Action action = message == null ? null : message.getAction();
		ClientSession session = clientId == null ? null : clientSessions.get(clientId);
		if (!isInitialized() || session == null || action == null) {
			LOG.warn("ignored a message of a diagram client: " + (!isInitialized() ? "the connection is not initialized"
					: action == null ? "it holds no action" : "no session " + Reasons.quote(clientId) + " was initialized"));
			return;
		}
		try {
			action.setReceivedFromClient(true);
			session.getActionDispatcher().dispatch(action).exceptionally(failure -> {
				failed(clientId, action, failure);
				return null;
			});
		} catch (RuntimeException e) {
			failed(clientId, action, e);
		}
	}

	/** Tells the page why its action failed; a failure that is not a refusal gets a line on the terminal too. */
	private void failed(String clientId, Action action, Throwable failure) {
		Throwable cause = Reasons.unwrap(failure);
		String reason = Reasons.of(cause);
		String kind = action.getKind();
		if (!(cause instanceof GLSPServerException)) {
			LOG.warn("a diagram action (" + Reasons.quote(kind) + ") failed: " + reason);
		}
		LOG.debug("a diagram action failed", cause);
		try {
			if (getClient() != null) {
				// the page shows the details' first line (status-line.ts); the rest is no business of a browser
				getClient().process(new ActionMessage(clientId,
						MessageActionUtil.error("[GLSP-Server] Could not process message:ActionMessage [action=" + kind + ", clientId=" + clientId + "]", reason)));
			}
		} catch (RuntimeException closed) {
			LOG.debug("the page could not be told", closed);
		}
	}
}
