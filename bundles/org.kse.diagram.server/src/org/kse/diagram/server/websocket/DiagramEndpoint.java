package org.kse.diagram.server.websocket;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.Collection;
import java.util.List;
import java.util.function.Supplier;
import java.util.logging.Logger;

import org.eclipse.glsp.server.gson.ServerGsonConfigurator;
import org.eclipse.glsp.server.protocol.GLSPClient;
import org.eclipse.glsp.server.protocol.GLSPServer;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.websocket.jakarta.WebSocketEndpoint;

import com.google.gson.JsonNull;
import com.google.gson.JsonObject;
import com.google.inject.Injector;

import jakarta.websocket.CloseReason;
import jakarta.websocket.EndpointConfig;
import jakarta.websocket.MessageHandler;
import jakarta.websocket.Session;

/**
 * One client connection: JSON-RPC over the WebSocket to a GLSP server of its own. A connection
 * that does not present the session's token ({@code ?token=…}) is closed before any message is
 * read (close code 1008, policy violation).
 */
public final class DiagramEndpoint extends WebSocketEndpoint<GLSPClient> {

	private static final Logger LOG = Logger.getLogger(DiagramEndpoint.class.getName());

	private final Supplier<Injector> injectors;
	private final byte[] token;
	private GLSPServer server;

	DiagramEndpoint(Supplier<Injector> injectors, String token) {
		this.injectors = injectors;
		this.token = token.getBytes(StandardCharsets.UTF_8);
	}

	@Override
	public void onOpen(Session session, EndpointConfig config) {
		List<String> presented = session.getRequestParameterMap().get("token");
		byte[] given = presented == null || presented.size() != 1 ? new byte[0] : presented.get(0).getBytes(StandardCharsets.UTF_8);
		if (!MessageDigest.isEqual(token, given)) {
			LOG.warning("refused a diagram connection without the session token");
			try {
				session.close(new CloseReason(CloseReason.CloseCodes.VIOLATED_POLICY, "the session token is missing or wrong"));
			} catch (java.io.IOException e) {
				LOG.fine("closing a refused connection: " + e.getMessage());
			}
			return;
		}
		super.onOpen(session, config);
		guardAgainstMalformedMessages(session);
	}

	/**
	 * lsp4j lets a message that is not JSON-RPC escape as an exception, which makes the container
	 * drop the connection. Such a message is answered with a JSON-RPC parse error instead, and
	 * logged; the connection goes on.
	 */
	@SuppressWarnings("unchecked")
	private static void guardAgainstMalformedMessages(Session session) {
		for (MessageHandler handler : List.copyOf(session.getMessageHandlers())) {
			if (handler instanceof MessageHandler.Whole<?> whole) {
				MessageHandler.Whole<String> text = (MessageHandler.Whole<String>) whole;
				session.removeMessageHandler(handler);
				session.addMessageHandler(String.class, message -> {
					try {
						text.onMessage(message);
					} catch (RuntimeException malformed) {
						String reason = malformed.getMessage() == null ? malformed.getClass().getSimpleName() : malformed.getMessage();
						LOG.warning("rejected a malformed message from a diagram client: " + reason);
						JsonObject error = new JsonObject();
						error.addProperty("code", ResponseErrorCode.ParseError.getValue());
						error.addProperty("message", "malformed message: " + reason);
						JsonObject response = new JsonObject();
						response.addProperty("jsonrpc", "2.0");
						response.add("id", JsonNull.INSTANCE);
						response.add("error", error);
						session.getAsyncRemote().sendText(response.toString());
					}
				});
			}
		}
	}

	@Override
	protected void configure(Launcher.Builder<GLSPClient> builder) {
		// made only once the token is checked
		Injector injector = injectors.get();
		server = injector.getInstance(GLSPServer.class);
		ServerGsonConfigurator gson = injector.getInstance(ServerGsonConfigurator.class);
		builder.setLocalService(server).setRemoteInterface(GLSPClient.class).configureGson(gson::configureGsonBuilder);
	}

	@Override
	protected void connect(Collection<Object> localServices, GLSPClient remoteProxy) {
		server.connect(remoteProxy);
	}

	@Override
	public void onClose(Session session, CloseReason closeReason) {
		if (server != null) {
			server.shutdown();
		}
	}
}
