package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.SocketTimeoutException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.net.http.WebSocketHandshakeException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.websocket.DiagramSocketServer;
import org.kse.testing.FakeMatch;

/**
 * The live monitor's relay ({@code /monitor}) between a page and a kse-match, here a fake match
 * ({@link FakeMatch}) whose side the tests speak themselves: they check what the relay says to it
 * and play a scripted stream of lines.
 */
class MonitorSocketTest {

	private static final String KEY = "match-key_0123456789abcdefghijklmnopqrstuvwx";

	@TempDir
	Path folder;
	private DiagramSocketServer server;
	private FakeMatch match;

	/** A page: queues the lines it receives (a message may carry several) and how its connection closed. */
	private static final class Page implements WebSocket.Listener {
		final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
		final CompletableFuture<String> closed = new CompletableFuture<>();
		private final StringBuilder partial = new StringBuilder();
		volatile int messages;

		@Override
		public CompletionStage<?> onText(WebSocket socket, CharSequence data, boolean last) {
			partial.append(data);
			if (last) {
				messages++;
				lines.addAll(List.of(partial.toString().split("\n", -1)));
				partial.setLength(0);
			}
			socket.request(1);
			return null;
		}

		@Override
		public CompletionStage<?> onClose(WebSocket socket, int statusCode, String reason) {
			closed.complete(statusCode + (reason == null || reason.isEmpty() ? "" : " " + reason));
			return null;
		}

		@Override
		public void onError(WebSocket socket, Throwable error) {
			closed.complete("error " + error);
		}

		String closedWith() throws Exception {
			return closed.get(15, TimeUnit.SECONDS);
		}

		String next() throws InterruptedException {
			String line = lines.poll(15, TimeUnit.SECONDS);
			if (line == null) {
				throw new AssertionError("the page received no further line");
			}
			return line;
		}
	}

	@BeforeEach
	void start() throws Exception {
		Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), folder.resolve("Goalie.stct"));
		server = DiagramSocketServer.start(folder, 0);
		match = new FakeMatch(KEY, 1, List.of());
	}

	@AfterEach
	void stop() throws Exception {
		match.close();
		server.close();
	}

	private URI monitor(String token, int port, String robots) {
		return URI.create("ws://127.0.0.1:" + server.port() + "/monitor?token=" + token + "&port=" + port + "&key=" + KEY
				+ (robots == null ? "" : "&robots=" + robots));
	}

	private static WebSocket open(URI uri, Page page) throws Exception {
		return HttpClient.newHttpClient().newWebSocketBuilder().buildAsync(uri, page).get(10, TimeUnit.SECONDS);
	}

	@Test
	void theRelayGreetsTheMatchRelaysEveryLineInOrderAndEndsAsTheMatchDoes() throws Exception {
		Page page = new Page();
		open(monitor(server.token(), match.port(), "home-1,away-3"), page);
		List<String> script = new ArrayList<>();
		script.add("{\"type\":\"match\",\"monitor\":1,\"robots\":[{\"id\":\"home-1\",\"behaviour\":\"Goalie\",\"states\":40,\"transitions\":60}]}");
		for (int i = 0; i < 2000; i++) {
			script.add("{\"type\":\"taken\",\"t\":" + i / 100.0 + ",\"robot\":\"home-1\",\"tr\":" + i % 60 + ",\"from\":\"0.1\",\"to\":\"0.2\",\"n\":" + i + "}");
		}
		script.add("{\"type\":\"result\",\"t\":20.0,\"state\":\"FINISHED\",\"score\":[1,0]}");
		try (FakeMatch.Peer peer = match.accept()) {
			assertEquals("{\"type\":\"hello\",\"token\":\"" + KEY + "\"}", peer.readLine(), "the hello carries the match's key");
			assertEquals("{\"type\":\"subscribe\",\"robots\":[\"home-1\",\"away-3\"]}", peer.readLine(), "the subscription names the page's robots");
			for (String line : script) {
				peer.send(line);
			}
		}
		List<String> received = new ArrayList<>();
		while (received.size() < script.size()) {
			received.add(page.next());
		}
		assertEquals(script, received, "every line, in order, none made up");
		assertEquals("1000 the match ended", page.closedWith());
		assertTrue(page.messages < script.size(), "lines that came together were sent in fewer messages: " + page.messages);
	}

	@Test
	void withoutRobotsThePageWatchesEveryRobotAndItsSubscriptionsAreForwarded() throws Exception {
		Page page = new Page();
		WebSocket socket = open(monitor(server.token(), match.port(), null), page);
		try (FakeMatch.Peer peer = match.accept()) {
			assertTrue(peer.readLine().contains("\"hello\""));
			assertEquals("{\"type\":\"subscribe\",\"robots\":[\"*\"]}", peer.readLine(), "no robots named: every robot");
			socket.sendText("{\"type\":\"subscribe\",\"robots\":[\"away-2\"]}", true).get(5, TimeUnit.SECONDS);
			assertEquals("{\"type\":\"subscribe\",\"robots\":[\"away-2\"]}", peer.readLine(), "the page's new subscription reaches the match");
			socket.sendText("{ \"robot\" : \"away-2\", \"type\" : \"blackboard\" }", true).get(5, TimeUnit.SECONDS);
			assertEquals("{\"type\":\"blackboard\",\"robot\":\"away-2\"}", peer.readLine(), "a blackboard request reaches the match, written anew");
			peer.send("{\"type\":\"frame\",\"t\":0.1}");
			assertEquals("{\"type\":\"frame\",\"t\":0.1}", page.next());
		}
		assertTrue(page.closedWith().startsWith("1000"));
	}

	@Test
	void aWrongServeTokenIsClosedWith1008AndTheMatchIsNotContacted() throws Exception {
		for (String token : List.of("", "wrong" + server.token().substring(5))) {
			Page page = new Page();
			open(monitor(token, match.port(), "home-1"), page);
			assertTrue(page.closedWith().startsWith("1008"), "closed for a policy violation: " + token);
		}
		assertThrows(SocketTimeoutException.class, () -> match.accept(500), "no connection to the match without the token");
	}

	@Test
	void onlyPagesOfThisServersOwnOriginMayConnect() throws Exception {
		for (String origin : List.of("http://evil.example", "http://127.0.0.1:" + (server.port() == 1 ? 2 : server.port() - 1), "null",
				"https://127.0.0.1:" + server.port())) {
			ExecutionException refused = assertThrows(ExecutionException.class, () -> HttpClient.newHttpClient().newWebSocketBuilder()
					.header("Origin", origin).buildAsync(monitor(server.token(), match.port(), "home-1"), new Page()).get(10, TimeUnit.SECONDS), origin);
			assertTrue(refused.getCause() instanceof WebSocketHandshakeException handshake && handshake.getResponse().statusCode() == 403,
					"refused with 403: " + origin + ": " + refused.getCause());
		}
		for (String origin : List.of("http://127.0.0.1:" + server.port(), "http://localhost:" + server.port())) {
			Page page = new Page();
			HttpClient.newHttpClient().newWebSocketBuilder().header("Origin", origin).buildAsync(monitor(server.token(), match.port(), "home-1"), page)
					.get(10, TimeUnit.SECONDS);
			try (FakeMatch.Peer peer = match.accept()) {
				assertTrue(peer.readLine().contains("hello"), "this server's own page is relayed: " + origin);
			}
			page.closedWith();
		}
	}

	@Test
	void anOversizedMessageClosesThatPageOnlyWhileAnotherKeepsReceiving() throws Exception {
		Page large = new Page();
		Page other = new Page();
		WebSocket largeSocket = open(monitor(server.token(), match.port(), "home-1"), large);
		try (FakeMatch.Peer first = match.accept()) {
			open(monitor(server.token(), match.port(), "home-1"), other);
			try (FakeMatch.Peer second = match.accept()) {
				first.readLine();
				first.readLine();
				second.readLine();
				second.readLine();
				first.send("{\"type\":\"frame\",\"t\":0.1}");
				second.send("{\"type\":\"frame\",\"t\":0.1}");
				assertEquals("{\"type\":\"frame\",\"t\":0.1}", large.next());
				assertEquals("{\"type\":\"frame\",\"t\":0.1}", other.next());
				String big = "{\"type\":\"subscribe\",\"robots\":[\"" + "a".repeat(5 * 1024) + "\"]}";
				largeSocket.sendText(big, true);
				assertEquals("1008 a message over 4096 bytes", large.closedWith());
				assertNull(first.readLine(), "the relay let go of that page's match connection");
				second.send("{\"type\":\"frame\",\"t\":0.2}");
				assertEquals("{\"type\":\"frame\",\"t\":0.2}", other.next(), "the other page keeps receiving");
				assertTrue(!other.closed.isDone(), "the other page is still connected");
			}
		}
		assertTrue(other.closedWith().startsWith("1000"));
	}

	@Test
	void anythingButASubscriptionOrABlackboardRequestClosesThePage() throws Exception {
		List<String> messages = List.of("{\"type\":\"hello\",\"token\":\"x\"}", "not json", "[1,2]", "{\"type\":\"subscribe\",\"robots\":\"home-1\"}",
				"{\"type\":\"blackboard\",\"robot\":\"*\"}", "{\"type\":\"blackboard\",\"robot\":[\"home-1\"]}",
				"{\"type\":\"blackboard\",\"robot\":\"home-1\",\"token\":\"x\"}", "{\"type\":\"blackboard\",\"robot\":\"a\\\"b\"}",
				"{\"type\":\"subscribe\",\"robots\":[1]}", "{\"type\":\"subscribe\",\"robots\":[\"home-1\"],\"extra\":1}",
				"{\"type\":\"subscribe\",\"robots\":[\"a\\nb\"]}", "{\"type\":\"subscribe\",\"robots\":[\"" + "x".repeat(1 << 20) + "\"]}");
		for (String message : messages) {
			Page page = new Page();
			WebSocket socket = open(monitor(server.token(), match.port(), "home-1"), page);
			try (FakeMatch.Peer peer = match.accept()) {
				peer.readLine();
				peer.readLine();
				socket.sendText(message, true);
				assertTrue(page.closedWith().startsWith("1008"), "closed for " + message.substring(0, Math.min(80, message.length())));
				assertNull(peer.readLine(), "nothing of it reaches the match: " + message.substring(0, Math.min(80, message.length())));
			}
		}
	}

	@Test
	void aPortWhereNoMatchListensClosesWith1011AndSaysSo() throws Exception {
		int free;
		try (ServerSocket probe = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
			free = probe.getLocalPort();
		}
		Page page = new Page();
		open(monitor(server.token(), free, "home-1"), page);
		assertEquals("1011 no match on 127.0.0.1:" + free, page.closedWith());
		for (String port : List.of("0", "65536", "x", "")) {
			Page bad = new Page();
			open(URI.create("ws://127.0.0.1:" + server.port() + "/monitor?token=" + server.token() + "&port=" + port + "&key=k"), bad);
			assertTrue(bad.closedWith().startsWith("1008 the match's port must be"), "port " + port);
		}
	}

	@Test
	void aPageThatLeavesLetsGoOfTheMatch() throws Exception {
		Page page = new Page();
		WebSocket socket = open(monitor(server.token(), match.port(), "home-1"), page);
		try (FakeMatch.Peer peer = match.accept()) {
			peer.readLine();
			peer.readLine();
			socket.sendClose(WebSocket.NORMAL_CLOSURE, "bye").get(5, TimeUnit.SECONDS);
			assertNull(peer.readLine(), "the match's connection is closed when its page leaves");
		}
	}
}
