package org.kse.diagram.server.websocket;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.util.Collection;
import java.util.List;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

import org.apache.logging.log4j.LogManager;
import org.apache.logging.log4j.Logger;
import org.eclipse.glsp.server.gson.ServerGsonConfigurator;
import org.eclipse.glsp.server.protocol.GLSPClient;
import org.eclipse.glsp.server.protocol.GLSPServer;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.MessageConsumer;
import org.eclipse.lsp4j.jsonrpc.MessageIssueException;
import org.eclipse.lsp4j.jsonrpc.RemoteEndpoint;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.json.MessageJsonHandler;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.jsonrpc.messages.Message;
import org.eclipse.lsp4j.jsonrpc.messages.NotificationMessage;
import org.eclipse.lsp4j.jsonrpc.messages.RequestMessage;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseMessage;
import org.eclipse.lsp4j.jsonrpc.services.ServiceEndpoints;
import org.eclipse.lsp4j.websocket.jakarta.WebSocketEndpoint;
import org.eclipse.lsp4j.websocket.jakarta.WebSocketLauncherBuilder;
import org.eclipse.lsp4j.websocket.jakarta.WebSocketMessageConsumer;
import org.kse.diagram.server.Reasons;

import com.google.gson.JsonElement;
import com.google.gson.JsonNull;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.google.gson.JsonPrimitive;
import com.google.inject.Injector;

import jakarta.websocket.CloseReason;
import jakarta.websocket.EndpointConfig;
import jakarta.websocket.Session;

/**
 * One client connection: JSON-RPC over the WebSocket to a GLSP server of its own. A connection
 * that does not present the session's token ({@code ?token=…}) is closed before any message is
 * read (close code 1008, policy violation).
 * <p>
 * Whatever the client sends, the connection goes on and the terminal sees at most a line: lsp4j
 * lets a message that is not JSON-RPC escape as an exception (the container then drops the
 * connection), prints a message whose parameters do not fit, an answer nobody asked for or an
 * unknown method with a stack trace and Java's class names through java.util.logging, leaves a
 * request it could not read unanswered, and sends Java stack traces to the client. Here each
 * message is read before lsp4j sees it ({@link #receive}); what cannot be read is answered
 * with a JSON-RPC error that carries the request's id when it has one, and logged in a line.
 */
public final class DiagramEndpoint extends WebSocketEndpoint<GLSPClient> {

	private static final Logger LOG = LogManager.getLogger("org.kse.diagram");

	private final Supplier<Injector> injectors;
	private final SessionToken token;
	private GLSPServer server;

	DiagramEndpoint(Supplier<Injector> injectors, String token) {
		this.injectors = injectors;
		this.token = new SessionToken(token);
	}

	@Override
	public void onOpen(Session session, EndpointConfig config) {
		if (!token.isPresentedIn(session)) {
			LOG.warn("refused a diagram connection without the session token");
			try {
				session.close(new CloseReason(CloseReason.CloseCodes.VIOLATED_POLICY, SessionToken.REFUSAL));
			} catch (IOException e) {
				LOG.debug("closing a refused connection: " + e.getMessage());
			}
			return;
		}
		// A page may sit idle for hours: the socket never times out on the server's side, and a ping
		// every PING_SECONDS keeps proxies and NATs from closing it (and finds a peer that is gone).
		session.setMaxIdleTimeout(0);
		// A diagram of thousands of states travels as one message (the client's computed bounds).
		session.setMaxTextMessageBufferSize(MAX_MESSAGE_BYTES);
		pinger = PINGS.scheduleAtFixedRate(() -> ping(session), PING_SECONDS, PING_SECONDS, TimeUnit.SECONDS);
		// as WebSocketEndpoint.onOpen does, with a launcher that reads and sends as said above
		GuardedLauncherBuilder builder = new GuardedLauncherBuilder();
		builder.setSession(session);
		configure(builder);
		Launcher<GLSPClient> launcher = builder.create();
		connect(builder.getLocalServices(), launcher.getRemoteProxy());
	}

	@Override
	protected void configure(Launcher.Builder<GLSPClient> builder) {
		// made only once the token is checked
		Injector injector = injectors.get();
		server = injector.getInstance(GLSPServer.class);
		ServerGsonConfigurator gson = injector.getInstance(ServerGsonConfigurator.class);
		builder.setLocalService(server).setRemoteInterface(GLSPClient.class).configureGson(gson::configureGsonBuilder)
				.setExceptionHandler(DiagramEndpoint::responseError);
	}

	@Override
	protected void connect(Collection<Object> localServices, GLSPClient remoteProxy) {
		server.connect(remoteProxy);
	}

	@Override
	public void onClose(Session session, CloseReason closeReason) {
		if (pinger != null) {
			pinger.cancel(false);
		}
		if (server != null) {
			LOG.info("a diagram page disconnected (" + closeReason.getCloseCode().getCode()
					+ (closeReason.getReasonPhrase() == null || closeReason.getReasonPhrase().isEmpty() ? "" : ", " + closeReason.getReasonPhrase()) + ")");
			server.shutdown();
		}
	}

	/** The largest message a page may send: far above a 5,000-state diagram's computed bounds (about 2 MB). */
	static final int MAX_MESSAGE_BYTES = 64 * 1024 * 1024;

	private static final long PING_SECONDS = 20;

	private static final ScheduledExecutorService PINGS = Executors.newSingleThreadScheduledExecutor(runnable -> {
		Thread thread = new Thread(runnable, "kse-diagram-pings");
		thread.setDaemon(true);
		return thread;
	});

	private ScheduledFuture<?> pinger;

	private static void ping(Session session) {
		if (!session.isOpen()) {
			return;
		}
		try {
			session.getAsyncRemote().sendPing(ByteBuffer.allocate(0));
		} catch (IOException | IllegalStateException | IllegalArgumentException gone) {
			LOG.debug("a ping to a diagram page failed: " + gone.getMessage());
		}
	}

	/**
	 * A request that failed, as its answer: lsp4j's own logs the failure with its trace and sends
	 * the trace to the client; here the client gets the reason, the terminal a line.
	 */
	private static ResponseError responseError(Throwable failure) {
		Throwable cause = Reasons.unwrap(failure);
		if (cause instanceof ResponseErrorException refused) {
			ResponseError error = refused.getResponseError();
			// GLSP puts the exception itself into the data of some errors
			return error.getData() instanceof Throwable ? new ResponseError(error.getCode(), Reasons.clean(error.getMessage()), null) : error;
		}
		String reason = Reasons.of(cause);
		LOG.warn("a request of a diagram client failed: " + reason);
		LOG.debug("a request of a diagram client failed", cause);
		return new ResponseError(ResponseErrorCode.InternalError, reason, null);
	}

	/** lsp4j's WebSocket launcher, with its reading and sending replaced. */
	private static final class GuardedLauncherBuilder extends WebSocketLauncherBuilder<GLSPClient> {

		private Sender sender;

		@Override
		protected RemoteEndpoint createRemoteEndpoint(MessageJsonHandler jsonHandler) {
			sender = new Sender(session, jsonHandler);
			RemoteEndpoint remoteEndpoint = new RemoteEndpoint(wrapMessageConsumer(sender), ServiceEndpoints.toEndpoint(localServices),
					exceptionHandler != null ? exceptionHandler : RemoteEndpoint.DEFAULT_EXCEPTION_HANDLER);
			jsonHandler.setMethodProvider(remoteEndpoint);
			remoteEndpoint.setJsonHandler(jsonHandler);
			return remoteEndpoint;
		}

		@Override
		protected void addMessageHandlers(MessageJsonHandler jsonHandler, RemoteEndpoint remoteEndpoint) {
			MessageConsumer endpoint = wrapMessageConsumer(remoteEndpoint);
			Sender answers = sender;
			session.addMessageHandler(String.class, text -> receive(text, jsonHandler, endpoint, answers));
		}
	}

	/**
	 * Reads a message and hands it to lsp4j, or answers it with an error when it is not JSON-RPC,
	 * names no method this server has, or has parameters that do not fit. An answer from the
	 * client is dropped (the server asks it nothing), and so is a cancellation (every request is
	 * answered at once, and lsp4j would complain of each one that finds nothing to cancel).
	 */
	static void receive(String text, MessageJsonHandler json, MessageConsumer endpoint, Sender answers) {
		Message message;
		try {
			message = json.parseMessage(text);
		} catch (MessageIssueException issue) {
			String reason = issue.getIssues().isEmpty() || issue.getIssues().get(0).getCause() == null ? issue.getMessage()
					: Reasons.of(issue.getIssues().get(0).getCause());
			refuse(text, issue.getRpcMessage(), ResponseErrorCode.InvalidParams, Reasons.clean(String.valueOf(reason)), answers);
			return;
		} catch (RuntimeException malformed) {
			refuse(text, null, ResponseErrorCode.ParseError, Reasons.of(malformed), answers);
			return;
		}
		if (message == null) {
			refuse(text, null, ResponseErrorCode.InvalidRequest, "null is not a message", answers);
			return;
		}
		if (message instanceof ResponseMessage) {
			LOG.warn("ignored an answer from a diagram client: the server asked it nothing");
			return;
		}
		String method = message instanceof RequestMessage request ? request.getMethod() : ((NotificationMessage) message).getMethod();
		if (MessageJsonHandler.CANCEL_METHOD.getMethodName().equals(method) && message instanceof NotificationMessage) {
			return;
		}
		if (method == null || json.getJsonRpcMethod(method) == null) {
			if (message instanceof RequestMessage) {
				refuse(text, message, ResponseErrorCode.MethodNotFound, "no method " + Reasons.quote(method), answers);
			} else {
				LOG.warn("ignored a notification of a diagram client: no method " + Reasons.quote(method));
			}
			return;
		}
		if (json.getJsonRpcMethod(method).getParameterTypes().length == 0) {
			// lsp4j ignores them too, but prints the parameters and the Java method on the terminal
			if (message instanceof RequestMessage request) {
				request.setParams(null);
			} else {
				((NotificationMessage) message).setParams(null);
			}
		}
		if (message instanceof RequestMessage && json.getJsonRpcMethod(method).isNotification()) {
			// lsp4j would fail on the missing result of such a call and answer with its own words
			refuse(text, message, ResponseErrorCode.InvalidRequest, Reasons.quote(method) + " is a notification: it is sent without an id", answers);
			return;
		}
		if (message instanceof NotificationMessage && !json.getJsonRpcMethod(method).isNotification()) {
			// its answer would go nowhere, and lsp4j prints a failure of it with a stack trace
			refuse(text, message, ResponseErrorCode.InvalidRequest, Reasons.quote(method) + " is a request: it needs an id", answers);
			return;
		}
		try {
			endpoint.consume(message);
		} catch (RuntimeException failed) {
			refuse(text, message, ResponseErrorCode.InternalError, Reasons.of(failed), answers);
		}
		if ("shutdown".equals(method)) {
			// GLSP's server forgets its client on shutdown, and every later action failed on it: the connection ends here
			answers.close("the client shut the server down");
		}
	}

	/** Answers a message the server cannot take with a JSON-RPC error, with the request's id if it has one. */
	private static void refuse(String text, Message message, ResponseErrorCode code, String reason, Sender answers) {
		LOG.warn("a diagram client sent a message the server cannot take: " + reason);
		JsonObject error = new JsonObject();
		error.addProperty("code", code.getValue());
		error.addProperty("message", reason);
		JsonObject response = new JsonObject();
		response.addProperty("jsonrpc", "2.0");
		response.add("id", message instanceof RequestMessage request && request.getRawId() != null ? id(request.getRawId()) : idIn(text));
		response.add("error", error);
		answers.send(response.toString());
	}

	private static JsonElement id(Either<String, Number> id) {
		return id.isLeft() ? new JsonPrimitive(id.getLeft()) : new JsonPrimitive(id.getRight());
	}

	/** The id a text that lsp4j could not read still shows (a string or a number), or null. */
	private static JsonElement idIn(String text) {
		try {
			if (JsonParser.parseString(text) instanceof JsonObject object && object.get("id") instanceof JsonPrimitive id && (id.isString() || id.isNumber())) {
				return id;
			}
		} catch (RuntimeException notJson) {
			// no id to be found
		}
		return JsonNull.INSTANCE;
	}

	/**
	 * The JSON text with every lone surrogate written as an escape. A client may send one escaped
	 * (a request's id, a label's text); Gson writes it back as the bare character, which a
	 * WebSocket's UTF-8 cannot carry: the message was dropped, and with it every later graph that
	 * showed the label. A lone surrogate can only stand inside a JSON string, where the escape is
	 * the same character.
	 */
	static String escapeLoneSurrogates(String json) {
		StringBuilder escaped = null;
		for (int i = 0; i < json.length(); i++) {
			char c = json.charAt(i);
			boolean paired = Character.isHighSurrogate(c) ? i + 1 < json.length() && Character.isLowSurrogate(json.charAt(i + 1))
					: Character.isLowSurrogate(c) && i > 0 && Character.isHighSurrogate(json.charAt(i - 1));
			if (Character.isSurrogate(c) && !paired) {
				if (escaped == null) {
					escaped = new StringBuilder(json.length() + 16).append(json, 0, i);
				}
				escaped.append(String.format("\\u%04x", (int) c));
			} else if (escaped != null) {
				escaped.append(c);
			}
		}
		return escaped == null ? json : escaped.toString();
	}

	/**
	 * Sends to the client one whole message at a time. lsp4j sends a message asynchronously, but
	 * one longer than the session's buffer (a large model's graph) in parts through the blocking
	 * remote; when an asynchronous send is under way, that fails and the graph never arrives.
	 * A message that cannot be written as JSON (a position made infinite by a client) and one for
	 * a page that has gone are dropped with a line at most, not with lsp4j's stack trace.
	 */
	static final class Sender extends WebSocketMessageConsumer {

		private final Session session;
		private final MessageJsonHandler json;

		Sender(Session session, MessageJsonHandler json) {
			super(session, json);
			this.session = session;
			this.json = json;
		}

		@Override
		public void consume(Message message) {
			String content;
			try {
				content = json.serialize(message);
			} catch (RuntimeException unwritable) {
				LOG.warn("a message to a diagram client could not be written: " + Reasons.of(unwritable));
				return;
			}
			send(content);
		}

		synchronized void close(String reason) {
			try {
				session.close(new CloseReason(CloseReason.CloseCodes.NORMAL_CLOSURE, reason));
			} catch (IOException gone) {
				LOG.debug("closing a diagram connection: " + gone.getMessage());
			}
		}

		synchronized void send(String content) {
			if (!session.isOpen()) {
				return;
			}
			try {
				session.getBasicRemote().sendText(escapeLoneSurrogates(content));
			} catch (IOException | RuntimeException gone) {
				LOG.debug("a message to a diagram client was not sent: " + gone.getMessage());
			}
		}
	}
}
