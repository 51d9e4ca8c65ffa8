package org.kse.diagram.server.tests;

import java.math.BigDecimal;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.google.gson.JsonPrimitive;

/**
 * A diagram client on a real WebSocket, as the browser's: it keeps what the server sends, answers
 * the server's {@code requestBounds} with {@code computedBounds} (which makes a graph the
 * session's model), and sends one message at a time. It never asks a proxy selector, so the
 * only URL lookups a test sees are the server's.
 */
final class FuzzClient implements WebSocket.Listener, AutoCloseable {

	private static final HttpClient HTTP = HttpClient.newBuilder().proxy(HttpClient.Builder.NO_PROXY).build();

	final List<String> received = new CopyOnWriteArrayList<>();
	final CompletableFuture<String> closed = new CompletableFuture<>();
	/** The ids of the responses received, as {@link #requestId} gives them. */
	private final java.util.Set<String> answered = java.util.concurrent.ConcurrentHashMap.newKeySet();
	private final StringBuilder partial = new StringBuilder();
	private final ExecutorService sender = Executors.newSingleThreadExecutor(r -> {
		Thread thread = new Thread(r, "kse-fuzz-client");
		thread.setDaemon(true);
		return thread;
	});
	private final WebSocket socket;
	private final java.util.function.Consumer<String> listener;

	/** Connects; {@code listener} sees every whole message the server sends. */
	FuzzClient(URI uri, java.util.function.Consumer<String> listener) throws Exception {
		this.listener = listener;
		socket = HTTP.newWebSocketBuilder().connectTimeout(java.time.Duration.ofSeconds(10)).buildAsync(uri, this).get(10, TimeUnit.SECONDS);
	}

	@Override
	public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
		partial.append(data);
		if (last) {
			String message = partial.toString();
			partial.setLength(0);
			listener.accept(message);
			String answer = responseId(message);
			if (answer != null) {
				answered.add(answer);
			}
			if (message.contains("\"requestBounds\"")) {
				answerRequestBounds(message);
			}
			// a graph is large and a run receives hundreds: its beginning and end say what it is
			received.add(message.length() <= 4000 ? message : message.substring(0, 2000) + " … " + message.substring(message.length() - 2000));
		}
		webSocket.request(1);
		return null;
	}

	/** As the browser does: the graph is measured (here: as it is) and handed back, with its revision. */
	private void answerRequestBounds(String message) {
		try {
			JsonObject action = JsonParser.parseString(message).getAsJsonObject().getAsJsonObject("params").getAsJsonObject("action");
			JsonElement revision = action.getAsJsonObject("newRoot").get("revision");
			JsonObject computed = DiagramMessages.object("kind", "computedBounds", "bounds", new com.google.gson.JsonArray(), "alignments",
					new com.google.gson.JsonArray(), "routes", new com.google.gson.JsonArray(), "revision", revision == null ? 0 : revision.getAsInt());
			if (action.has("requestId")) {
				computed.add("responseId", action.get("requestId"));
			}
			sendLater(DiagramMessages.process(computed).toString());
		} catch (RuntimeException notAGraph) {
			// not the server's requestBounds: nothing to answer
		}
	}

	@Override
	public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
		closed.complete(statusCode + " " + reason);
		return null;
	}

	@Override
	public void onError(WebSocket webSocket, Throwable error) {
		closed.complete("error: " + error);
	}

	boolean isOpen() {
		return !closed.isDone() && !socket.isOutputClosed() && !socket.isInputClosed();
	}

	/** Sends the text and waits until it is sent (false: the connection is gone). */
	boolean send(String text) {
		try {
			sender.submit(() -> socket.sendText(text, true).get(10, TimeUnit.SECONDS)).get(15, TimeUnit.SECONDS);
			return true;
		} catch (Exception gone) {
			return false;
		}
	}

	private void sendLater(String text) {
		sender.submit(() -> socket.sendText(text, true).get(10, TimeUnit.SECONDS));
	}

	/** The first message after {@code from} that passes {@code test}, or null after {@code millis}. */
	String await(int from, Predicate<String> test, long millis) throws InterruptedException {
		long end = System.currentTimeMillis() + millis;
		int next = from;
		do {
			for (; next < received.size(); next++) {
				if (test.test(received.get(next))) {
					return received.get(next);
				}
			}
			if (closed.isDone()) {
				return null;
			}
			Thread.sleep(2);
		} while (System.currentTimeMillis() < end);
		return null;
	}

	/** Sends a JSON-RPC request and returns its response (the message with its id), or null after {@code millis}. */
	JsonObject call(String id, String method, JsonElement params, long millis) throws InterruptedException {
		JsonObject request = new JsonObject();
		request.addProperty("jsonrpc", "2.0");
		request.addProperty("id", id);
		request.addProperty("method", method);
		request.add("params", params);
		int from = received.size();
		if (!send(request.toString())) {
			return null;
		}
		String response = await(from, message -> message.contains("\"id\":\"" + id + "\""), millis);
		return response == null ? null : JsonParser.parseString(response).getAsJsonObject();
	}

	/** initialize, initializeClientSession: the session is ready for actions. */
	boolean handshake(String tag) throws InterruptedException {
		JsonObject initialized = call(tag + "-initialize", "initialize",
				DiagramMessages.object("applicationId", "kse-fuzz", "protocolVersion", "1.0.0"), 10_000);
		return initialized != null && initialized.has("result") && joinSession(tag);
	}

	/** Joins (or creates again) the client session; false when the server does not answer or refuses. */
	boolean joinSession(String tag) throws InterruptedException {
		JsonObject joined = call(tag + "-session", "initializeClientSession", DiagramMessages.object("clientSessionId", DiagramMessages.SESSION,
				"diagramType", DiagramMessages.DIAGRAM_TYPE, "clientActionKinds", DiagramMessages.strings(DiagramMessages.CLIENT_ACTIONS)), 10_000);
		return joined != null && joined.has("result");
	}

	/** Whether a message carries a graph: a model (the server sizes its labels) or, from a server that asks, one to measure. */
	static boolean isGraph(String message) {
		return message.contains("\"setModel\"") || message.contains("\"requestBounds\"");
	}

	/** Asks for a model and returns the graph the server sends, or null. */
	String open(String model, long millis) throws InterruptedException {
		int from = received.size();
		send(DiagramMessages.process(DiagramMessages.object("kind", "requestModel", "options",
				DiagramMessages.object("sourceUri", model, "diagramType", DiagramMessages.DIAGRAM_TYPE, "needsClientLayout", true))).toString());
		return await(from, FuzzClient::isGraph, millis);
	}

	/** The id of a JSON-RPC request (as its response carries it), or null for anything else. */
	static String requestId(String message) {
		JsonObject object = object(message);
		if (object == null || !(object.get("method") instanceof JsonPrimitive method) || !method.isString()) {
			return null;
		}
		return id(object.get("id"));
	}

	static String responseId(String message) {
		if (!message.startsWith("{\"jsonrpc\"") || message.contains("\"method\":\"process\"")) {
			return null;
		}
		JsonObject object = object(message);
		return object == null || !(object.has("result") || object.has("error")) ? null : id(object.get("id"));
	}

	private static JsonObject object(String message) {
		try {
			JsonElement element = JsonParser.parseString(message);
			return element.isJsonObject() ? element.getAsJsonObject() : null;
		} catch (RuntimeException notJson) {
			return null;
		}
	}

	private static String id(JsonElement id) {
		if (!(id instanceof JsonPrimitive primitive)) {
			return null;
		}
		if (primitive.isString()) {
			return "s:" + primitive.getAsString();
		}
		if (primitive.isNumber()) {
			try {
				return "n:" + new BigDecimal(primitive.getAsString()).stripTrailingZeros().toPlainString();
			} catch (NumberFormatException e) {
				return null;
			}
		}
		return null;
	}

	/** Whether a response with this id ({@link #requestId}) arrives within {@code millis}. */
	boolean answered(String id, long millis) throws InterruptedException {
		long end = System.currentTimeMillis() + millis;
		do {
			if (answered.contains(id)) {
				return true;
			}
			Thread.sleep(2);
		} while (System.currentTimeMillis() < end && !closed.isDone());
		return answered.contains(id);
	}

	@Override
	public void close() {
		try {
			if (isOpen()) {
				socket.sendClose(WebSocket.NORMAL_CLOSURE, "done").get(5, TimeUnit.SECONDS);
			}
		} catch (Exception gone) {
			socket.abort();
		}
		sender.shutdownNow();
	}
}
