package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.websocket.DiagramSocketServer;
import org.kse.diagram.server.websocket.MatchLogServlet;

/**
 * The match logs a page replays (GET /logs, /logs/<name>): only with the session token, only
 * .jsonl files inside the served folder, never a file elsewhere by .., an encoded .., a link or
 * a hidden folder, and nothing but GET.
 */
class MatchLogServletTest {

	private static final String LOG = "{\"type\":\"match\",\"version\":1}\n{\"type\":\"result\",\"t\":1.00}\n";
	private static final String SECRET = "{\"secret\":\"outside the served folder\"}\n";

	@TempDir
	Path root;
	private Path folder;
	private DiagramSocketServer server;

	@BeforeEach
	void start() throws Exception {
		folder = Files.createDirectories(root.resolve("served"));
		Files.writeString(folder.resolve("m.jsonl"), LOG);
		Files.createDirectories(folder.resolve("runs/2026"));
		Files.writeString(folder.resolve("runs/2026/seed-3.jsonl"), LOG);
		Files.writeString(folder.resolve("notes.txt"), "not a log");
		Files.createDirectories(folder.resolve(".hidden"));
		Files.writeString(folder.resolve(".hidden/h.jsonl"), SECRET);
		Files.writeString(root.resolve("outside.jsonl"), SECRET);
		Files.createSymbolicLink(folder.resolve("link.jsonl"), root.resolve("outside.jsonl"));
		server = DiagramSocketServer.start(folder, 0);
	}

	@AfterEach
	void stop() throws Exception {
		server.close();
	}

	/** The status line and the body of a raw request, sent as written (no client normalises the path). */
	private String[] get(String method, String target) throws IOException {
		try (Socket socket = new Socket("127.0.0.1", server.port())) {
			socket.setSoTimeout(10_000);
			String request = method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + server.port() + "\r\nConnection: close\r\n\r\n";
			socket.getOutputStream().write(request.getBytes(StandardCharsets.US_ASCII));
			InputStream in = socket.getInputStream();
			ByteArrayOutputStream all = new ByteArrayOutputStream();
			in.transferTo(all);
			String response = all.toString(StandardCharsets.UTF_8);
			int end = response.indexOf("\r\n\r\n");
			return new String[] { response.substring(0, response.indexOf("\r\n")), end < 0 ? "" : response.substring(end + 4) };
		}
	}

	private String token() {
		return "?token=" + server.token();
	}

	@Test
	void theListNamesTheLogsOfTheFolderOnly() throws Exception {
		String[] list = get("GET", "/logs" + token());
		assertTrue(list[0].contains(" 200"), list[0]);
		// chunked or not, the array is in the body; the hidden folder's log and the link's target are not in it
		assertTrue(list[1].contains("[\"link.jsonl\",\"m.jsonl\",\"runs/2026/seed-3.jsonl\"]"), list[1]);
		assertFalse(list[1].contains("hidden"), list[1]);
		assertFalse(list[1].contains("notes.txt"), list[1]);
	}

	@Test
	void aLogIsSentAsItIsOnDisk() throws Exception {
		String[] one = get("GET", "/logs/m.jsonl" + token());
		assertTrue(one[0].contains(" 200"), one[0]);
		assertTrue(one[1].contains(LOG), one[1]);
		String[] nested = get("GET", "/logs/runs/2026/seed-3.jsonl" + token());
		assertTrue(nested[0].contains(" 200"), nested[0]);
		assertTrue(nested[1].contains(LOG), nested[1]);
	}

	@Test
	void withoutTheRightTokenNothingIsListedOrSent() throws Exception {
		assertTrue(get("GET", "/logs")[0].contains(" 403"));
		assertTrue(get("GET", "/logs/m.jsonl")[0].contains(" 403"));
		assertTrue(get("GET", "/logs/m.jsonl?token=" + server.token().substring(1))[0].contains(" 403"));
		assertFalse(get("GET", "/logs/m.jsonl?token=wrong")[1].contains("\"match\""));
	}

	@Test
	void nothingOutsideTheFolderNorOtherThanALogIsSent() throws Exception {
		String[] targets = { "/logs/../outside.jsonl", "/logs/%2e%2e/outside.jsonl", "/logs/runs/../../outside.jsonl", "/logs/link.jsonl",
				"/logs/.hidden/h.jsonl", "/logs/notes.txt", "/logs/" + root.resolve("outside.jsonl"), "/logs//m.jsonl", "/logs/m.jsonl%00.jsonl",
				"/logs/missing.jsonl", "/logs/runs" };
		for (String target : targets) {
			String[] answer = get("GET", target + token());
			assertFalse(answer[0].contains(" 200"), target + " was answered: " + answer[0]);
			assertFalse(answer[1].contains("secret"), target + " sent a file outside the folder");
			assertFalse(answer[1].contains("not a log"), target + " sent a file that is not a log");
		}
	}

	/** What a host (the workbench's replay editor) asks before it opens a page: the name the server sends a file by, or none. */
	@Test
	void aHostLearnsTheNameOfALogTheServerSendsAndOfNoOther() throws Exception {
		assertEquals("runs/2026/seed-3.jsonl", MatchLogServlet.replayName(folder, folder.resolve("runs/2026/seed-3.jsonl")));
		assertEquals("m.jsonl", MatchLogServlet.replayName(folder, folder.resolve("runs/../m.jsonl")));
		String[] answer = get("GET", "/logs/" + MatchLogServlet.replayName(folder, folder.resolve("runs/2026/seed-3.jsonl")) + token());
		assertTrue(answer[0].contains(" 200"), answer[0]);
		Files.createDirectories(folder.resolve("with space"));
		Files.writeString(folder.resolve("with space/s.jsonl"), LOG);
		for (Path refused : new Path[] { root.resolve("outside.jsonl"), folder.resolve("link.jsonl"), folder.resolve(".hidden/h.jsonl"), folder.resolve("notes.txt"),
				folder.resolve("missing.jsonl"), folder.resolve("with space/s.jsonl"), folder.resolve("runs") }) {
			assertEquals(null, MatchLogServlet.replayName(folder, refused), refused + " is not sent: it has no name");
		}
	}

	@Test
	void logsAreReadOnly() throws Exception {
		for (String method : new String[] { "PUT", "POST", "DELETE" }) {
			String[] answer = get(method, "/logs/m.jsonl" + token());
			assertTrue(answer[0].contains(" 405"), method + ": " + answer[0]);
		}
		assertEquals(LOG, Files.readString(folder.resolve("m.jsonl")));
	}
}
