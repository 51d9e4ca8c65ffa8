package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.websocket.DiagramSocketServer;
import org.kse.diagram.server.websocket.RunningMatches;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Picking a match (docs/monitor.md): kse serve lists the matches announced in the discovery folder
 * on {@code /matches} without their keys, skips and removes those whose process is gone, and its
 * relay connects to a match named by pid ({@code /monitor?match=PID}) with the key it looked up.
 * The announcements here are written as kse-match writes them; the "match" of the live one is this
 * test's own process (a live pid) with a fake monitor port.
 */
class RunningMatchesTest {

	private static final String KEY = "the-match-key_0123456789abcdefghijklmnopqrstu";

	@TempDir
	Path folder;
	@TempDir
	Path discovery;
	private DiagramSocketServer server;
	private ServerSocket fakeMatch;

	@BeforeEach
	void start() throws Exception {
		System.setProperty(RunningMatches.FOLDER_PROPERTY, discovery.toString());
		server = DiagramSocketServer.start(folder, 0);
		fakeMatch = new ServerSocket(0, 10, InetAddress.getLoopbackAddress());
		fakeMatch.setSoTimeout(10_000);
	}

	@AfterEach
	void stop() throws Exception {
		fakeMatch.close();
		server.close();
		System.clearProperty(RunningMatches.FOLDER_PROPERTY);
	}

	/** An announcement as kse-match --monitor writes it (MatchDiscovery.cpp). */
	private Path announce(long pid, int port, long startedMillis) throws Exception {
		String json = "{\"pid\":" + pid + ",\"port\":" + port + ",\"token\":\"" + KEY + "\",\"started\":" + startedMillis
				+ ",\"version\":1,\"seed\":7,\"tick\":0.010,\"field\":{\"length\":9.000,\"width\":6.000,\"goalWidth\":1.500},\"halfSeconds\":20.0,"
				+ "\"teams\":[{\"number\":7,\"name\":\"home\",\"players\":[{\"id\":\"home-1\",\"number\":1,\"behaviour\":\"Goalie\"},"
				+ "{\"id\":\"home-2\",\"number\":2,\"behaviour\":\"Defender\"}]},{\"number\":8,\"name\":\"away\",\"players\":[{\"id\":\"away-1\",\"number\":1,\"behaviour\":\"Attacker\"}]}]}\n";
		Path file = discovery.resolve(pid + ".json");
		Files.writeString(file, json);
		return file;
	}

	private static long deadPid() throws Exception {
		Process gone = new ProcessBuilder("true").start();
		gone.waitFor(10, TimeUnit.SECONDS);
		long pid = gone.pid();
		assertFalse(ProcessHandle.of(pid).map(ProcessHandle::isAlive).orElse(false), "the pid of a process that ended");
		return pid;
	}

	private HttpResponse<String> get(String path) throws Exception {
		return HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + server.port() + path)).build(),
				HttpResponse.BodyHandlers.ofString());
	}

	@Test
	void theListNeedsTheTokenAndHoldsLiveMatchesWithTheirRobotsButNoKeyNorPort() throws Exception {
		long live = ProcessHandle.current().pid();
		announce(live, fakeMatch.getLocalPort(), System.currentTimeMillis());
		Path dead = announce(deadPid(), 4242, System.currentTimeMillis());
		Files.writeString(discovery.resolve("notes.txt"), "not an announcement");
		Files.writeString(discovery.resolve(".123.json.tmp"), "{\"half\":");

		assertEquals(403, get("/matches").statusCode());
		assertEquals(403, get("/matches?token=wrong").statusCode());
		HttpResponse<String> response = get("/matches?token=" + server.token());
		assertEquals(200, response.statusCode());
		assertFalse(response.body().contains(KEY), "the list never holds a match's key: " + response.body());
		JsonArray matches = JsonParser.parseString(response.body()).getAsJsonArray();
		assertEquals(1, matches.size(), "only the match whose process runs: " + response.body());
		JsonObject match = matches.get(0).getAsJsonObject();
		assertEquals(live, match.get("pid").getAsLong());
		assertEquals(7, match.get("seed").getAsLong());
		assertFalse(match.has("port") || match.has("token") || match.has("key"), response.body());
		assertEquals("[{\"id\":\"home-1\",\"team\":\"home\",\"number\":1,\"behaviour\":\"Goalie\"},{\"id\":\"home-2\",\"team\":\"home\",\"number\":2,\"behaviour\":\"Defender\"},"
				+ "{\"id\":\"away-1\",\"team\":\"away\",\"number\":1,\"behaviour\":\"Attacker\"}]", match.get("robots").toString());
		assertFalse(Files.exists(dead), "the announcement of a match that no longer runs is removed by the first reader");
		assertTrue(Files.exists(discovery.resolve("notes.txt")), "other files are left alone");
	}

	@Test
	void aPidNowUsedByAProcessStartedAfterTheMatchIsNotThatMatch() throws Exception {
		// this process started long after 2001: a match announced then under its pid is long gone
		Path file = announce(ProcessHandle.current().pid(), fakeMatch.getLocalPort(), 1_000_000_000_000L);
		assertEquals("[]", get("/matches?token=" + server.token()).body());
		assertFalse(Files.exists(file));
	}

	@Test
	void aFileNamingAnotherPidThanItsNameIsIgnored() throws Exception {
		Path file = announce(ProcessHandle.current().pid(), fakeMatch.getLocalPort(), System.currentTimeMillis());
		Files.move(file, discovery.resolve("1.json"));
		assertEquals("[]", get("/matches?token=" + server.token()).body());
	}

	@Test
	void theRelayFindsAMatchByPidAndGreetsItWithTheKeyThePageNeverSaw() throws Exception {
		announce(ProcessHandle.current().pid(), fakeMatch.getLocalPort(), System.currentTimeMillis());
		Page page = new Page();
		open("/monitor?token=" + server.token() + "&match=" + ProcessHandle.current().pid() + "&robots=home-2", page);
		try (Socket peer = fakeMatch.accept()) {
			BufferedReader in = new BufferedReader(new InputStreamReader(peer.getInputStream(), StandardCharsets.UTF_8));
			assertEquals("{\"type\":\"hello\",\"token\":\"" + KEY + "\"}", in.readLine());
			assertEquals("{\"type\":\"subscribe\",\"robots\":[\"home-2\"]}", in.readLine());
			peer.getOutputStream().write("{\"type\":\"frame\",\"t\":0.1}\n".getBytes(StandardCharsets.UTF_8));
			peer.getOutputStream().flush();
			assertEquals("{\"type\":\"frame\",\"t\":0.1}", page.first.get(10, TimeUnit.SECONDS));
		}
		assertEquals("1000 the match ended", page.closed.get(10, TimeUnit.SECONDS));
	}

	@Test
	void aPidWithoutARunningMatchOrNotANumberIsRefusedAndSaysSo() throws Exception {
		long dead = deadPid();
		announce(dead, fakeMatch.getLocalPort(), System.currentTimeMillis());
		for (String pid : List.of(Long.toString(dead), "999999999")) {
			Page page = new Page();
			open("/monitor?token=" + server.token() + "&match=" + pid, page);
			assertEquals("1011 no running match " + pid + " (it ended, or was started without --monitor)", page.closed.get(10, TimeUnit.SECONDS));
		}
		for (String pid : List.of("0", "-1", "x", "../1", "")) {
			Page page = new Page();
			open("/monitor?token=" + server.token() + "&match=" + pid, page);
			assertTrue(page.closed.get(10, TimeUnit.SECONDS).startsWith("1008 match must be the process id"), pid);
		}
		Page noToken = new Page();
		open("/monitor?match=" + ProcessHandle.current().pid(), noToken);
		assertTrue(noToken.closed.get(10, TimeUnit.SECONDS).startsWith("1008"));
		fakeMatch.setSoTimeout(300);
		try {
			fakeMatch.accept().close();
			throw new AssertionError("the relay contacted a match it was not given");
		} catch (java.net.SocketTimeoutException expected) {
			// nobody connected
		}
	}

	private void open(String pathAndQuery, Page page) throws Exception {
		HttpClient.newHttpClient().newWebSocketBuilder().buildAsync(URI.create("ws://127.0.0.1:" + server.port() + pathAndQuery), page).get(10,
				TimeUnit.SECONDS);
	}

	/** A page: its first message and how its connection closed. */
	private static final class Page implements WebSocket.Listener {
		final CompletableFuture<String> first = new CompletableFuture<>();
		final CompletableFuture<String> closed = new CompletableFuture<>();

		@Override
		public CompletionStage<?> onText(WebSocket socket, CharSequence data, boolean last) {
			first.complete(data.toString());
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
	}
}
