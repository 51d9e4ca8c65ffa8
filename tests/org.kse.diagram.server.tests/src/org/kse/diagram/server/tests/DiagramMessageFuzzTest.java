package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.SimpleFormatter;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.glsp.graph.GGraph;
import org.junit.jupiter.api.Test;
import org.kse.diagram.server.websocket.DiagramSocketServer;
import org.kse.model.StatechartResources;
import org.kse.notation.NotationFiles;
import org.kse.testing.NetworkTrap;

import com.google.gson.JsonObject;

/**
 * Issue 13's fuzz suite, the diagram JSON-RPC message kind: {@link #INPUTS} seeded hostile
 * messages ({@link DiagramMessages}) sent over a real WebSocket to a running diagram server, the
 * one {@code kse serve} runs. The run fails when the server stops answering (a request without a
 * response, a session that no longer handles actions: each within {@link #WAIT_MILLIS}), stops
 * accepting connections, no longer serves a well-behaved client its graph, prints Java (a stack
 * trace, a class name) on the terminal (standard output and error, and the loggers that write
 * there), reaches for the network, creates or changes a file outside the served folder, leaves a
 * model or a notation in the folder that does not load, or takes longer than
 * {@link #BUDGET_MILLIS}. {@code KSE_FUZZ_SEED=N} replays a run; failing messages are kept in
 * {@code target/fuzz-failures}.
 */
class DiagramMessageFuzzTest {

	static final long SEED = Long.parseLong(System.getenv().getOrDefault("KSE_FUZZ_SEED", "20261123"));
	static final int INPUTS = Integer.parseInt(System.getenv().getOrDefault("KSE_FUZZ_INPUTS", "1000"));
	/** The whole run, connections and final checks included. */
	static final long BUDGET_MILLIS = 120_000;
	/** A message longer than this may be over the server's limit: it may end the connection (1009), or a send may fail as it ends. */
	private static final int LARGEST_MESSAGE = 65_536;
	/** The longest the server may take to answer one message. */
	static final long WAIT_MILLIS = 5_000;
	/** A well-formed request for the model is sent every so many messages: the session keeps a model to edit, and the file must still open. */
	private static final int RELOAD_EVERY = 20;
	/** The served models are checked every so many messages (and an emptied Goalie put back: a run may well delete every state and save). */
	private static final int CHECK_EVERY = 250;

	/**
	 * Java showing through (as in the command line's fuzz suite): a trace, a class name, an
	 * object's identity, a parser's own prefix; and a logger named for its class ("[DefaultGLSPServer] ERROR").
	 */
	private static final Pattern JAVA = Pattern.compile(
			"\\tat |\\b[A-Z]\\w*(Exception|Error)\\b|\\bjava\\.|\\bjavax\\.|\\bjdk\\.|org\\.eclipse\\.|org\\.kse\\.|com\\.google\\.|Impl@|@[0-9a-f]{6,}\\b"
					+ "|\\[Fatal Error\\]|For input string|(?m)^\\[[A-Z]\\w*\\] ");

	/** Characters that make a terminal do things (escape sequences), when a client's text reaches it unfiltered. */
	private static final Pattern CONTROL = Pattern.compile("[\\x00-\\x08\\x0b\\x0c\\x0e-\\x1f\\x7f-\\x9f]");

	/** What the terminal showed during the run. */
	private static final Path TERMINAL = Path.of("target", "fuzz-diagram-terminal.txt");
	/** A file outside any folder of the test that messages name as a place to save to. */
	private static final Path ESCAPED = Path.of("/tmp/kse-fuzz-escaped.stct");

	/**
	 * The folders of a run, in the same place each time: the hostile paths contain it, and a
	 * mutation's place in a message depends on their length, so a seed replays only there.
	 */
	private final Path sandbox = Path.of("target", "fuzz-diagram").toAbsolutePath();

	private final List<String> failures = new ArrayList<>();
	private Path served;
	private Path outside;

	@Test
	void hostileMessagesNeitherStopTheServerNorReachOutsideItsFolder() throws Exception {
		deleteTree(sandbox);
		served = Files.createDirectories(sandbox.resolve("served"));
		outside = Files.createDirectories(sandbox.resolve("outside"));
		Path examples = Path.of(System.getProperty("kse.examples"));
		Files.copy(examples.resolve("Goalie/Goalie.stct"), served.resolve("Goalie.stct"));
		Files.copy(examples.resolve("Attacker/Attacker.stct"), Files.createDirectories(served.resolve("sub")).resolve("Attacker.stct"));
		Files.createDirectories(served.resolve("folder.stct"));
		Files.copy(examples.resolve("Defender/Defender.stct"), outside.resolve("Outside.stct"));
		Files.writeString(outside.resolve("secret.txt"), "not for the diagram server\n");
		Files.createSymbolicLink(served.resolve("link.stct"), outside.resolve("Outside.stct"));
		Files.createSymbolicLink(served.resolve("linkdir"), outside);
		Path workingDirectory = Path.of("").toAbsolutePath();
		Map<Path, String> outsideBefore = files(sandbox, served);
		Map<Path, String> workingBefore = files(workingDirectory, workingDirectory.resolve("target"));

		byte[] goalie = Files.readAllBytes(served.resolve("Goalie.stct"));
		boolean escapedBefore = Files.exists(ESCAPED, LinkOption.NOFOLLOW_LINKS);
		long started = System.nanoTime();
		int sent = 0;
		Tally closes = new Tally();
		int terminalLines = 0;
		int saves = 0;
		String choices = "";
		byte[] stretch = goalie;
		java.util.PriorityQueue<long[]> slowest = new java.util.PriorityQueue<>(java.util.Comparator.comparingLong(each -> each[0]));
		try (Terminal terminal = new Terminal(); NetworkTrap network = new NetworkTrap();
				DiagramSocketServer server = DiagramSocketServer.start(served, 0)) {
			Choices random = new Choices(SEED);
			DiagramMessages messages = new DiagramMessages(random, served, outside.resolve("Outside.stct"), network.remote());
			FuzzClient client = null;
			for (int i = 0; i < INPUTS; i++) {
				if (millisSince(started) > BUDGET_MILLIS) {
					failures.add("over the time budget of " + BUDGET_MILLIS / 1000 + " s after " + i + " messages");
					break;
				}
				String message = messages.next();
				if (client == null || !client.isOpen()) {
					client = connect(server, messages, "after " + i);
					if (client == null) {
						fail(i, message, "the server no longer accepts a connection and a handshake");
						break;
					}
				}
				sent++;
				long before = System.nanoTime();
				exchange(client, i, message, closes);
				slowest.add(new long[] { millisSince(before), i, message.length() });
				if (slowest.size() > 3) {
					slowest.poll();
				}
				String printed = terminal.take();
				if (JAVA.matcher(withoutSandbox(printed, sandbox)).find()) {
					fail(i, message, "Java on the terminal:\n" + excerpt(printed, 3000));
				}
				if (CONTROL.matcher(printed).find()) {
					fail(i, message, "a control character on the terminal (a client could drive it):\n" + excerpt(printed, 3000));
				}
				String reached = network.take();
				if (reached != null) {
					fail(i, message, reached);
				}
				if (i % CHECK_EVERY == CHECK_EVERY - 1 && i < INPUTS - 1) {
					// what the messages saved must load; a Goalie they emptied is put back, so that later messages have states to edit
					checkServedModels("after " + (i + 1) + " messages");
					byte[] now = Files.readAllBytes(served.resolve("Goalie.stct"));
					saves += java.util.Arrays.equals(stretch, now) ? 0 : 1;
					stretch = now;
					if (states(served.resolve("Goalie.stct")) < 10) {
						Files.write(served.resolve("Goalie.stct"), goalie);
						Files.deleteIfExists(NotationFiles.beside(served.resolve("Goalie.stct")));
						stretch = goalie;
					}
				}
				if (!files(sandbox, served).equals(outsideBefore)) {
					fail(i, message, "a file outside the served folder was created or changed: " + difference(outsideBefore, files(sandbox, served)));
					outsideBefore = files(sandbox, served);
				}
			}
			if (client != null) {
				client.close();
			}
			// a well-behaved client, on a new connection, still gets its graphs
			for (String model : List.of("Goalie.stct", "sub/Attacker.stct")) {
				StringBuilder graph = new StringBuilder();
				try (FuzzClient normal = new FuzzClient(server.uri(), full -> {
					if (FuzzClient.isGraph(full)) {
						graph.append(full);
					}
				})) {
					// its graph, whatever the messages made of the model (pages share a model with unsaved edits)
					if (!normal.handshake("final") || normal.open(model, 15_000) == null || !graph.toString().contains("\"id\":\"statechart\"")) {
						failures.add("after the run, a well-behaved client does not get the graph of " + model + ": " + lastMessages(normal));
					}
				}
			}
			String printed = terminal.take();
			if (JAVA.matcher(withoutSandbox(printed, sandbox)).find()) {
				failures.add("Java on the terminal at the end:\n" + excerpt(printed, 3000));
			}
			terminalLines = terminal.keep(TERMINAL);
			choices = random.digest();
		}
		double seconds = millisSince(started) / 1000.0;
		if (!files(sandbox, served).equals(outsideBefore)) {
			failures.add("a file outside the served folder was created or changed: " + difference(outsideBefore, files(sandbox, served)));
		}
		if (!files(workingDirectory, workingDirectory.resolve("target")).equals(workingBefore)) {
			failures.add("a file in the working directory was created or changed: "
					+ difference(workingBefore, files(workingDirectory, workingDirectory.resolve("target"))));
		}
		if (Files.exists(ESCAPED, LinkOption.NOFOLLOW_LINKS) && !escapedBefore) {
			failures.add("the server wrote " + ESCAPED + ", a file a message named");
		}
		checkServedFolder();
		if (seconds * 1000 > BUDGET_MILLIS) {
			failures.add(String.format("the run took %.1f s, over its budget of %d s", seconds, BUDGET_MILLIS / 1000));
		}
		String summary = String.format("[ fuzz ] diagram: %d messages in %.1f s, seed %d", sent, seconds, SEED);
		System.out.println(summary);
		saves += java.util.Arrays.equals(stretch, Files.readAllBytes(served.resolve("Goalie.stct"))) ? 0 : 1;
		System.out.println("[ fuzz ] diagram: choices " + choices + ", Goalie.stct saved changed in " + saves + " of "
				+ ((INPUTS + CHECK_EVERY - 1) / CHECK_EVERY) + " stretches, " + terminalLines
				+ " lines on the terminal (kept in " + TERMINAL + "); slowest: "
				+ slowest.stream().sorted(java.util.Comparator.comparingLong(each -> -each[0]))
						.map(each -> String.format("message %d (%d characters) %.1f s", each[1], each[2], each[0] / 1000.0)).toList()
				+ (closes.isEmpty() ? "" : "; connections the server closed: " + closes));
		assertEquals(List.of(), failures.stream().limit(20).toList(), summary + ", " + failures.size() + " failing; messages saved in target/fuzz-failures");
	}

	/**
	 * Sends one message and holds the server to it: a request is answered, the connection and
	 * the session still work afterwards, every so often the Goalie still opens; the connection
	 * ends only for a message over the size limit, or for shutdown.
	 */
	private void exchange(FuzzClient client, int i, String message, Tally closes) throws Exception {
		boolean oversized = message.getBytes(StandardCharsets.UTF_8).length > LARGEST_MESSAGE;
		if (!client.send(message)) {
			// the server may close a connection whose message is too long while it is still being sent
			if (!oversized && closedWithin(client, 2) == null) {
				fail(i, message, "the client could not send the message, yet the connection is open");
			}
			client.close();
			return;
		}
		String id = FuzzClient.requestId(message);
		if (id != null && client.isOpen() && !client.answered(id, WAIT_MILLIS) && client.isOpen()) {
			fail(i, message, "a request went unanswered for " + WAIT_MILLIS + " ms");
		}
		if (client.isOpen()) {
			String stuck = sync(client, i);
			if (stuck != null) {
				fail(i, message, stuck);
				client.close();
			} else if (i % RELOAD_EVERY == RELOAD_EVERY - 1 && client.open("Goalie.stct", 15_000) == null && client.isOpen()) {
				fail(i, message, "a well-formed request for Goalie.stct got no graph: " + lastMessages(client));
			}
			return;
		}
		String closed = closedWithin(client, 1);
		String code = closed == null ? "unknown" : closed.replaceAll("\\s.*", "");
		closes.add(code, message.length());
		if (!code.equals("1000") && !code.equals("1009") && !oversized) {
			fail(i, message, "the server dropped the connection: " + closed);
		}
	}

	/** How the connection closed ("1009 reason", "error: …"), or null when it is still open after {@code seconds}. */
	private static String closedWithin(FuzzClient client, int seconds) throws Exception {
		try {
			return client.closed.get(seconds, java.util.concurrent.TimeUnit.SECONDS);
		} catch (java.util.concurrent.TimeoutException open) {
			return null;
		}
	}

	/**
	 * After a message: the connection still answers a request (the session is joined again, and
	 * the server initialized again, when the message ended them) and the session still handles an
	 * action. Returns why not, or null.
	 */
	private static String sync(FuzzClient client, int index) throws InterruptedException {
		String tag = "sync-" + index;
		JsonObject joined = client.call(tag, "initializeClientSession", DiagramMessages.object("clientSessionId", DiagramMessages.SESSION, "diagramType",
				DiagramMessages.DIAGRAM_TYPE, "clientActionKinds", DiagramMessages.strings(DiagramMessages.CLIENT_ACTIONS)), WAIT_MILLIS);
		if (joined == null) {
			return client.isOpen() ? "the connection stopped answering requests (no answer within " + WAIT_MILLIS + " ms)" : null;
		}
		if (!joined.has("result") && !client.handshake(tag + "-again")) {
			// the message made the connection's server serve another application: a new connection starts afresh
			client.close();
			return null;
		}
		int from = client.received.size();
		client.send(DiagramMessages.process(DiagramMessages.object("kind", "requestTypeHints", "requestId", tag)).toString());
		if (client.await(from, message -> message.contains("\"responseId\":\"" + tag + "\""), WAIT_MILLIS) == null && client.isOpen()) {
			return "the session stopped handling actions (no answer to requestTypeHints within " + WAIT_MILLIS + " ms): " + lastMessages(client);
		}
		return null;
	}

	private static FuzzClient connect(DiagramSocketServer server, DiagramMessages messages, String when) {
		try {
			FuzzClient client = new FuzzClient(server.uri(), messages::hear);
			if (client.handshake("connect " + when) && client.open("Goalie.stct", 15_000) != null) {
				return client;
			}
			client.close();
		} catch (Exception e) {
			// no connection: reported by the caller
		}
		return null;
	}

	/** The number of states of a model on disk, -1 when it does not load. */
	private static int states(Path model) {
		try {
			int states = 0;
			for (var contents = StatechartResources.load(model).eAllContents(); contents.hasNext();) {
				if (contents.next() instanceof org.kse.model.statechart.Node) {
					states++;
				}
			}
			return states;
		} catch (IOException | RuntimeException e) {
			return -1;
		}
	}

	/** Every model in the served folder loads, every notation the server wrote reads, and nothing else appeared. */
	private void checkServedModels(String when) throws IOException {
		try (Stream<Path> walk = Files.walk(served)) {
			for (Path file : walk.filter(path -> Files.isRegularFile(path, LinkOption.NOFOLLOW_LINKS)).toList()) {
				String name = served.relativize(file).toString();
				try {
					if (name.endsWith(".stct")) {
						StatechartResources.load(file);
					} else if (name.endsWith(".notation.json")) {
						NotationFiles.read(file);
					} else {
						failures.add(when + ", the server has left " + name + " in the served folder");
					}
				} catch (IOException | RuntimeException e) {
					failures.add(when + ", " + name + " does not load: " + e.getMessage());
				}
			}
		}
	}

	/** The served models load, and a session (in-process) draws the Goalie as it is on disk. */
	private void checkServedFolder() throws Exception {
		checkServedModels("after the run");
		try (GlspSession session = new GlspSession(served)) {
			// a session of its own reads the file the messages left: all its states are drawn
			GGraph graph = session.open("Goalie.stct");
			int drawn = 0;
			for (var contents = graph.eAllContents(); contents.hasNext();) {
				if (contents.next() instanceof org.eclipse.glsp.graph.GNode) {
					drawn++;
				}
			}
			if (drawn != states(served.resolve("Goalie.stct"))) {
				failures.add("after the run, a session draws " + drawn + " of the Goalie's " + states(served.resolve("Goalie.stct")) + " states");
			}
		} catch (AssertionError | Exception e) {
			failures.add("after the run, a session cannot open the Goalie: " + e.getMessage());
		}
	}

	private void fail(int index, String message, String why) {
		String name = "diagram-" + index;
		try {
			Path saved = Files.createDirectories(Path.of("target", "fuzz-failures")).resolve(name + ".json");
			Files.writeString(saved, message);
			Files.writeString(saved.resolveSibling(name + ".txt"), "seed " + SEED + ", message " + index + "\n" + why + "\n", StandardCharsets.UTF_8,
					java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.APPEND);
		} catch (IOException e) {
			why += " (could not save the message: " + e.getMessage() + ")";
		}
		failures.add(name + ": " + why + "\n    message: " + excerpt(message, 300));
	}

	private static String lastMessages(FuzzClient client) {
		List<String> received = client.received;
		return received.subList(Math.max(0, received.size() - 3), received.size()).stream().map(message -> excerpt(message, 300)).toList().toString();
	}

	private static String excerpt(String text, int length) {
		String escaped = text.replace("\n", "\\n");
		return escaped.length() <= length ? escaped : escaped.substring(0, length) + "… (" + text.length() + " characters)";
	}

	private static long millisSince(long nanos) {
		return (System.nanoTime() - nanos) / 1_000_000;
	}

	private static void deleteTree(Path root) throws IOException {
		if (Files.exists(root, LinkOption.NOFOLLOW_LINKS)) {
			try (Stream<Path> walk = Files.walk(root)) {
				for (Path path : walk.sorted(java.util.Comparator.reverseOrder()).toList()) {
					Files.delete(path);
				}
			}
		}
	}

	/** The files under {@code root} but not under {@code except}, each with its size and time of change. */
	private static Map<Path, String> files(Path root, Path except) {
		Map<Path, String> files = new TreeMap<>();
		try (Stream<Path> walk = Files.walk(root)) {
			walk.filter(path -> !path.startsWith(except)).forEach(path -> {
				try {
					files.put(path, Files.isDirectory(path, LinkOption.NOFOLLOW_LINKS) ? "folder"
							: Files.size(path) + " " + Files.getLastModifiedTime(path, LinkOption.NOFOLLOW_LINKS).toMillis());
				} catch (IOException gone) {
					files.put(path, "gone");
				}
			});
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
		return files;
	}

	private static String difference(Map<Path, String> before, Map<Path, String> after) {
		List<String> changes = new ArrayList<>();
		after.forEach((path, state) -> {
			if (!state.equals(before.get(path))) {
				changes.add((before.containsKey(path) ? "changed " : "created ") + path);
			}
		});
		before.keySet().stream().filter(path -> !after.containsKey(path)).forEach(path -> changes.add("removed " + path));
		return String.join(", ", changes);
	}

	/**
	 * The terminal's text with the sandbox's path (where this checkout lies, say in a folder named
	 * after a bundle) taken out, also where a message cut it short ("/tmp/…/fuzz-diagr…"), so that
	 * only what the server itself printed is held against it.
	 */
	static String withoutSandbox(String printed, Path sandbox) {
		String path = sandbox.toString();
		String text = printed.replace(path, "<sandbox>");
		java.util.regex.Matcher cut = Pattern.compile("[^\\s'\"]+…").matcher(text);
		StringBuilder out = new StringBuilder();
		while (cut.find()) {
			String token = cut.group();
			String kept = token;
			for (int slash = token.indexOf('/'); slash >= 0; slash = token.indexOf('/', slash + 1)) {
				if (path.startsWith(token.substring(slash, token.length() - 1))) {
					kept = token.substring(0, slash) + "<sandbox>…";
					break;
				}
			}
			cut.appendReplacement(out, java.util.regex.Matcher.quoteReplacement(kept));
		}
		cut.appendTail(out);
		return out.toString();
	}

	/**
	 * The run's random numbers, and a digest of every one drawn: a replay that makes the same
	 * choices (the same messages, but for the server's copy keys and the trap's port) shows the same digest.
	 */
	private static final class Choices extends Random {
		private static final long serialVersionUID = 1L;
		private final java.util.zip.CRC32 digest = new java.util.zip.CRC32();

		Choices(long seed) {
			super(seed);
		}

		@Override
		protected int next(int bits) {
			int value = super.next(bits);
			digest.update(new byte[] { (byte) (value >>> 24), (byte) (value >>> 16), (byte) (value >>> 8), (byte) value });
			return value;
		}

		String digest() {
			return String.format("%08x", digest.getValue());
		}
	}

	/** How often the server closed the connection, by close code, with the shortest message that made it. */
	private static final class Tally {
		private final Map<String, int[]> counts = new TreeMap<>();

		void add(String code, int length) {
			int[] count = counts.computeIfAbsent(code, key -> new int[] { 0, Integer.MAX_VALUE });
			count[0]++;
			count[1] = Math.min(count[1], length);
		}

		boolean isEmpty() {
			return counts.isEmpty();
		}

		@Override
		public String toString() {
			List<String> parts = new ArrayList<>();
			counts.forEach((code, count) -> parts.add(count[0] + " × " + code + " (shortest message " + count[1] + " characters)"));
			return String.join(", ", parts);
		}
	}

	/**
	 * What reaches the terminal while the server runs: standard output and error (log4j's console
	 * follows them), and java.util.logging, whose console handler holds the stream it started with
	 * and is replaced by one that writes here, formatted as it would be.
	 */
	private static final class Terminal implements AutoCloseable {
		private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
		private final PrintStream stream = new PrintStream(bytes, true, StandardCharsets.UTF_8);
		private final PrintStream out = System.out;
		private final PrintStream err = System.err;
		private final java.util.logging.Logger root = java.util.logging.Logger.getLogger("");
		private final Handler[] handlers = root.getHandlers();
		private final Handler console = new Handler() {
			private final SimpleFormatter format = new SimpleFormatter();

			@Override
			public void publish(LogRecord record) {
				if (isLoggable(record)) {
					stream.print(format.format(record));
				}
			}

			@Override
			public void flush() {
			}

			@Override
			public void close() {
			}
		};
		private int taken;
		private int lines;

		Terminal() {
			System.setOut(stream);
			System.setErr(stream);
			console.setLevel(Level.INFO);
			for (Handler handler : handlers) {
				root.removeHandler(handler);
			}
			root.addHandler(console);
		}

		/** What was printed since the last call. */
		synchronized String take() {
			String all = bytes.toString(StandardCharsets.UTF_8);
			String printed = all.substring(Math.min(taken, all.length()));
			taken = all.length();
			lines += (int) printed.lines().count();
			return printed;
		}

		/** Everything printed, kept in target/ for a look at what a user would see. */
		int keep(Path file) throws IOException {
			Files.createDirectories(file.getParent());
			Files.writeString(file, bytes.toString(StandardCharsets.UTF_8));
			return lines;
		}

		@Override
		public void close() {
			System.setOut(out);
			System.setErr(err);
			root.removeHandler(console);
			for (Handler handler : handlers) {
				root.addHandler(handler);
			}
		}
	}
}
