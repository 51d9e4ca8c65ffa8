package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.websocket.DiagramSocketServer;

/**
 * The diagram server on its WebSocket, as a browser would reach it: only on loopback, only with
 * the session's token; a malformed message is answered with an error and the connection keeps
 * working; a client speaks GLSP's JSON-RPC and gets the Goalie.
 */
class DiagramSocketTest {

	@TempDir
	Path folder;
	private DiagramSocketServer server;

	/** A WebSocket client that queues what it receives and how the connection closed. */
	private static final class Client implements WebSocket.Listener {
		final BlockingQueue<String> messages = new LinkedBlockingQueue<>();
		final CompletableFuture<Integer> closed = new CompletableFuture<>();
		private final StringBuilder partial = new StringBuilder();

		@Override
		public CompletionStage<?> onText(WebSocket socket, CharSequence data, boolean last) {
			partial.append(data);
			if (last) {
				messages.add(partial.toString());
				partial.setLength(0);
			}
			socket.request(1);
			return null;
		}

		@Override
		public CompletionStage<?> onClose(WebSocket socket, int statusCode, String reason) {
			closed.complete(statusCode);
			return null;
		}

		@Override
		public void onError(WebSocket socket, Throwable error) {
			closed.complete(-1);
		}

		/** The next message that contains the text, or fails after 15 s. */
		String awaitContaining(String text) throws InterruptedException {
			long end = System.currentTimeMillis() + 15_000;
			while (System.currentTimeMillis() < end) {
				String message = messages.poll(200, TimeUnit.MILLISECONDS);
				if (message != null && message.contains(text)) {
					return message;
				}
			}
			throw new AssertionError("no message with " + text);
		}
	}

	@BeforeEach
	void start() throws Exception {
		Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), folder.resolve("Goalie.stct"));
		server = DiagramSocketServer.start(folder, 0);
	}

	@AfterEach
	void stop() throws Exception {
		server.close();
	}

	private static WebSocket connect(URI uri, Client client) throws Exception {
		return HttpClient.newHttpClient().newWebSocketBuilder().buildAsync(uri, client).get(10, TimeUnit.SECONDS);
	}

	@Test
	void aConnectionWithoutTheTokenIsClosedUnread() throws Exception {
		for (String query : List.of("", "?token=", "?token=wrong" + server.token().substring(5))) {
			Client client = new Client();
			WebSocket socket = connect(URI.create("ws://127.0.0.1:" + server.port() + DiagramSocketServer.PATH + query), client);
			socket.sendText("{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"initialize\",\"params\":{\"applicationId\":\"x\",\"protocolVersion\":\"1.0.0\"}}", true);
			assertEquals(1008, client.closed.get(10, TimeUnit.SECONDS), "closed for policy violation: " + query);
			assertTrue(client.messages.isEmpty(), "nothing answered without the token");
		}
	}

	@Test
	void theServerListensOnLoopbackOnly() throws Exception {
		assertTrue(server.uri().getHost().equals("127.0.0.1"));
		for (var network : java.util.Collections.list(java.net.NetworkInterface.getNetworkInterfaces())) {
			if (!network.isUp() || network.isLoopback()) {
				continue;
			}
			for (var address : java.util.Collections.list(network.getInetAddresses())) {
				if (address instanceof java.net.Inet4Address) {
					try (java.net.Socket socket = new java.net.Socket()) {
						socket.connect(new java.net.InetSocketAddress(address, server.port()), 1000);
						throw new AssertionError("the diagram server answers on " + address);
					} catch (java.net.ConnectException | java.net.SocketTimeoutException expected) {
						// loopback only
					}
				}
			}
		}
	}

	@Test
	void aClientWithTheTokenGetsTheGoalieAndAMalformedMessageDoesNotStopIt() throws Exception {
		Client client = new Client();
		WebSocket socket = connect(server.uri(), client);
		socket.sendText("{ this is not json", true);
		client.awaitContaining("\"error\"");
		socket.sendText("{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"initialize\",\"params\":{\"applicationId\":\"kse-tests\",\"protocolVersion\":\"1.0.0\"}}", true);
		String initialized = client.awaitContaining("\"result\"");
		assertTrue(initialized.contains("protocolVersion") && initialized.matches(".*\"id\":\"?1\"?[,}].*"), "initialized: " + initialized);
		socket.sendText("{\"jsonrpc\":\"2.0\",\"id\":2,\"method\":\"initializeClientSession\",\"params\":{\"clientSessionId\":\"s\","
				+ "\"diagramType\":\"kse-statechart\",\"clientActionKinds\":[\"requestBounds\",\"setModel\",\"updateModel\",\"message\",\"status\",\"setDirtyState\",\"setMarkers\"]}}", true);
		assertTrue(client.awaitContaining("\"result\"").matches(".*\"id\":\"?2\"?[,}].*"), "session initialized");
		socket.sendText("{\"jsonrpc\":\"2.0\",\"method\":\"process\",\"params\":{\"clientId\":\"s\",\"action\":{\"kind\":\"requestModel\","
				+ "\"options\":{\"sourceUri\":\"Goalie.stct\"}}}}", true);
		String model = client.awaitContaining("setModel");
		assertTrue(model.contains("state:basic") && model.contains("//@transitions.0"), "the Goalie's graph: " + model.substring(0, Math.min(300, model.length())));
		socket.sendClose(WebSocket.NORMAL_CLOSURE, "done").get(5, TimeUnit.SECONDS);
	}

	/**
	 * What the diagram fuzz suite found lsp4j and GLSP doing wrong, each answered now and the
	 * connection going on: a request before initialize (GLSP's error code is gone from lsp4j, and
	 * the NoSuchFieldError closed the connection), a notification sent as a request (answered by
	 * lsp4j with an internal error), a request whose id is a lone surrogate (its answer could not
	 * be sent), an id too large for lsp4j (the request went unanswered); shutdown ends the connection.
	 */
	@Test
	void messagesLsp4jMishandledAreAnsweredAndShutdownEndsTheConnection() throws Exception {
		Client client = new Client();
		WebSocket socket = connect(server.uri(), client);
		socket.sendText("{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"initializeClientSession\",\"params\":{\"clientSessionId\":\"s\",\"diagramType\":\"kse-statechart\"}}", true);
		assertTrue(client.awaitContaining("\"id\":1").contains("not initialized"), "refused before initialize");
		socket.sendText("{\"jsonrpc\":\"2.0\",\"id\":2,\"method\":\"process\",\"params\":{\"clientId\":\"s\",\"action\":{\"kind\":\"glspUndo\"}}}", true);
		assertTrue(client.awaitContaining("\"id\":2").contains("is a notification"), "a notification sent as a request");
		socket.sendText("{\"jsonrpc\":\"2.0\",\"id\":\"\\ud800\",\"method\":\"initialize\",\"params\":{\"applicationId\":\"x\",\"protocolVersion\":\"1.0.0\"}}", true);
		assertTrue(client.awaitContaining("\"id\":\"\\ud800\"").contains("\"result\""), "the answer to an id that is a lone surrogate");
		socket.sendText("{\"jsonrpc\":\"2.0\",\"id\":9999999999,\"method\":\"initialize\",\"params\":{}}", true);
		assertTrue(client.awaitContaining("9999999999").contains("\"error\""), "an id lsp4j cannot read is answered");
		socket.sendText("{\"jsonrpc\":\"2.0\",\"method\":\"shutdown\"}", true);
		assertEquals(1000, client.closed.get(10, TimeUnit.SECONDS), "shutdown ends the connection");
	}

	@Test
	void twoTabsAreServedSideBySide() throws Exception {
		Client first = new Client();
		Client second = new Client();
		WebSocket one = connect(server.uri(), first);
		WebSocket two = connect(server.uri(), second);
		// each tab is a client application of its own, with its own initialize
		one.sendText("{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"initialize\",\"params\":{\"applicationId\":\"tab-1\",\"protocolVersion\":\"1.0.0\"}}", true);
		two.sendText("{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"initialize\",\"params\":{\"applicationId\":\"tab-2\",\"protocolVersion\":\"1.0.0\"}}", true);
		assertTrue(first.awaitContaining("\"id\"").contains("\"result\""), "the first tab is initialized");
		String answer = second.awaitContaining("\"id\"");
		assertTrue(answer.contains("\"result\""), "the second tab is initialized as well: " + answer);
		one.sendClose(WebSocket.NORMAL_CLOSURE, "done").get(5, TimeUnit.SECONDS);
		two.sendClose(WebSocket.NORMAL_CLOSURE, "done").get(5, TimeUnit.SECONDS);
	}

	/** The status line of a raw HTTP request with the given method and Host header. */
	private String status(String method, String host) throws java.io.IOException {
		try (java.net.Socket socket = new java.net.Socket("127.0.0.1", server.port())) {
			socket.setSoTimeout(10_000);
			String request = method + " /models?token=" + server.token() + " HTTP/1.1\r\nHost: " + host + "\r\nConnection: close\r\n\r\n";
			socket.getOutputStream().write(request.getBytes(java.nio.charset.StandardCharsets.US_ASCII));
			return new java.io.BufferedReader(new java.io.InputStreamReader(socket.getInputStream(), java.nio.charset.StandardCharsets.US_ASCII)).readLine();
		}
	}

	/** Issue 14, item 7: DNS rebinding (a foreign Host that resolves to 127.0.0.1) and TRACE are refused. */
	@Test
	void onlyRequestsForThisServerAreAnsweredAndTraceIsRefused() throws Exception {
		int port = server.port();
		assertTrue(status("GET", "127.0.0.1:" + port).contains(" 200"), "this server by address");
		assertTrue(status("GET", "localhost:" + port).contains(" 200"), "this server by name");
		assertTrue(status("GET", "attacker.example:" + port).contains(" 403"), "a rebound name");
		assertTrue(status("GET", "127.0.0.1:" + (port == 1 ? 2 : port - 1)).contains(" 403"), "another port");
		assertTrue(status("TRACE", "127.0.0.1:" + port).contains(" 405"), "TRACE");
	}
}
