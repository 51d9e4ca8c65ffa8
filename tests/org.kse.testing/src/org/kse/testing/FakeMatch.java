package org.kse.testing;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.Base64;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.eclipse.emf.ecore.EObject;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * A {@code kse-match --monitor} as its monitor's clients see it (docs/monitor.md): a port on
 * 127.0.0.1 that speaks JSON lines and has a key, and, if asked, the match's announcement in a
 * discovery folder. Tests of what talks to a match (the relay of {@code kse serve}, the
 * workbench's Monitor view) use it where no kse-match is built, which is the case in the Maven
 * build: the C++ runtime is built after it.
 * <p>
 * Either the test speaks the match's side itself, line by line ({@link #accept()}: to check
 * exactly what a client says), or the fake plays a {@link Script} to every client that connects
 * ({@link #play}): it checks the hello's key and the subscription as kse-match does, sends the
 * {@code match} record, the robot's {@code active} configuration on subscribing, then per decision
 * cycle the {@code taken} records of real transitions of the robot's model (with their labels and
 * model indices), the new {@code active} and a {@code frame}; it holds the match there until the
 * test calls {@link #finish()} (so that a test can look at a live match for as long as it needs),
 * then sends the {@code result} and closes. What a client did wrong is collected in
 * {@link #problems()} rather than thrown on the fake's threads.
 */
public final class FakeMatch implements AutoCloseable {

	/** A robot of the match; its model (null: none) gives the counts of the {@code match} record and a script its labels and indices. */
	public record Robot(String id, String team, int number, String behaviour, Model model) {
	}

	/** How long a client may take for its hello, as kse-match allows. */
	public static final long HELLO_MILLIS = 5_000;
	/** How long a played match waits for {@link #finish()} at most, so that a forgotten one still ends. */
	public static final long HOLD_MILLIS = 180_000;
	private static final long DEFAULT_ACCEPT_MILLIS = 10_000;
	private static final int MAX_LINE = 4096;
	private static final String TICK = "0.010";

	private final String key;
	private final long seed;
	private final List<Robot> robots;
	private final long started = System.currentTimeMillis();
	private final ServerSocket listener;
	private final List<String> problems = new CopyOnWriteArrayList<>();
	private final List<String> received = new CopyOnWriteArrayList<>();
	private final List<Socket> clients = new CopyOnWriteArrayList<>();
	private final CountDownLatch end = new CountDownLatch(1);
	private Path announcement;
	private Thread acceptor;

	/** Listens on a port of 127.0.0.1 the system chooses; nobody is served until {@link #accept()} or {@link #play}. */
	public FakeMatch(String key, long seed, List<Robot> robots) throws IOException {
		this.key = key;
		this.seed = seed;
		this.robots = List.copyOf(robots);
		listener = new ServerSocket(0, 16, InetAddress.getLoopbackAddress());
	}

	/** A new key as kse-match makes them: 32 random bytes, base64url without padding (43 characters). */
	public static String newKey() {
		byte[] bytes = new byte[32];
		new SecureRandom().nextBytes(bytes);
		return Base64.getUrlEncoder().withoutPadding().encodeToString(bytes);
	}

	public int port() {
		return listener.getLocalPort();
	}

	public String key() {
		return key;
	}

	/** The pid the announcement names: this JVM's, since a reader lists only matches whose process runs. */
	public long pid() {
		return ProcessHandle.current().pid();
	}

	// ------------------------------------------------------------------ the test speaks for the match

	/** The next client, for a test that speaks the match's side itself (waits 10 s at most). */
	public Peer accept() throws IOException {
		return accept(DEFAULT_ACCEPT_MILLIS);
	}

	/** The next client; a {@link java.net.SocketTimeoutException} when none comes within {@code millis}. */
	public Peer accept(long millis) throws IOException {
		listener.setSoTimeout((int) millis);
		return new Peer(listener.accept());
	}

	/** One client of the fake match, as the test that speaks for the match sees it. */
	public static final class Peer implements AutoCloseable {
		private final Socket socket;
		private final BufferedReader in;
		private final OutputStream out;

		Peer(Socket socket) throws IOException {
			this.socket = socket;
			socket.setSoTimeout((int) DEFAULT_ACCEPT_MILLIS);
			in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8));
			out = socket.getOutputStream();
		}

		/** The client's next line; null when it closed. */
		public String readLine() throws IOException {
			return in.readLine();
		}

		public void send(String line) throws IOException {
			out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
			out.flush();
		}

		@Override
		public void close() throws IOException {
			socket.close();
		}
	}

	// ------------------------------------------------------------------ announcing

	/**
	 * Writes {@code <pid>.json} into {@code folder} as kse-match does (the folder 0700, the file 0600,
	 * written under a dot name and renamed so that a reader sees all of it or none); removed on
	 * {@link #close()}. One fake per folder: the pid is this JVM's.
	 */
	public Path announce(Path folder) throws IOException {
		boolean posix = FileSystems.getDefault().supportedFileAttributeViews().contains("posix");
		Files.createDirectories(folder);
		if (posix) {
			Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwx------"));
		}
		Path file = folder.resolve(pid() + ".json");
		if (Files.exists(file)) {
			throw new IllegalStateException(file + " exists: one fake match per discovery folder (its pid is this JVM's)");
		}
		JsonObject json = new JsonObject();
		json.addProperty("pid", pid());
		json.addProperty("port", port());
		json.addProperty("token", key);
		json.addProperty("started", started);
		matchFields(json, false);
		Path partial = folder.resolve("." + pid() + ".json");
		Files.writeString(partial, json.toString(), StandardCharsets.UTF_8);
		if (posix) {
			Files.setPosixFilePermissions(partial, PosixFilePermissions.fromString("rw-------"));
		}
		Files.move(partial, file, StandardCopyOption.ATOMIC_MOVE);
		announcement = file;
		return file;
	}

	/** The fields of the log's {@code match} record; with {@code monitor}, the robots' chart sizes as the monitor adds them. */
	private void matchFields(JsonObject json, boolean monitor) {
		json.addProperty("version", 1);
		json.addProperty("seed", seed);
		json.addProperty("tick", new BigDecimal(TICK));
		JsonObject field = new JsonObject();
		field.addProperty("length", new BigDecimal("9.000"));
		field.addProperty("width", new BigDecimal("6.000"));
		field.addProperty("goalWidth", new BigDecimal("1.500"));
		json.add("field", field);
		json.addProperty("halfSeconds", new BigDecimal("20.0"));
		JsonArray teams = new JsonArray();
		List<String> names = new ArrayList<>(List.of("home", "away"));
		robots.stream().map(Robot::team).filter(team -> !names.contains(team)).distinct().forEach(names::add);
		for (int i = 0; i < names.size(); i++) {
			JsonObject team = new JsonObject();
			team.addProperty("number", 7 + i);
			team.addProperty("name", names.get(i));
			JsonArray players = new JsonArray();
			for (Robot robot : robots) {
				if (robot.team().equals(names.get(i))) {
					JsonObject player = new JsonObject();
					player.addProperty("id", robot.id());
					player.addProperty("number", robot.number());
					player.addProperty("behaviour", robot.behaviour());
					players.add(player);
				}
			}
			team.add("players", players);
			teams.add(team);
		}
		json.add("teams", teams);
		if (monitor) {
			JsonArray list = new JsonArray();
			for (Robot robot : robots) {
				JsonObject entry = new JsonObject();
				entry.addProperty("id", robot.id());
				entry.addProperty("behaviour", robot.behaviour());
				if (robot.model() != null) {
					entry.addProperty("states", Models.allNodes(robot.model()).size());
					entry.addProperty("transitions", robot.model().getTransitions().size());
				}
				list.add(entry);
			}
			json.add("robots", list);
		}
	}

	// ------------------------------------------------------------------ playing a script

	/**
	 * What one robot does in the played match: its configuration when a client subscribes, then
	 * decision cycles of moves ({@code "0.2.2.3.1->0.2.2.3.2"}: a transition of its model from the
	 * state labelled 0.2.2.3.1 to the one labelled 0.2.2.3.2). Each move is checked against the
	 * model and the configuration as it builds, so a script can only play what the chart can do.
	 */
	public static final class Script {
		private final Robot robot;
		private final Set<Node> configuration = new LinkedHashSet<>();
		private final List<String> first;
		private final List<Cycle> cycles = new ArrayList<>();
		private long paceMillis = 300;

		/** A transition taken: its index in the model's transitions, its source's and target's labels. */
		public record Move(int tr, String from, String to) {
		}

		/** A decision cycle: the moves in the order the engine takes them, and the configuration after them. */
		public record Cycle(List<Move> moves, List<String> active) {
		}

		public Script(Robot robot, String... active) {
			if (robot.model() == null) {
				throw new IllegalArgumentException(robot.id() + " has no model to play");
			}
			this.robot = robot;
			for (String label : active) {
				configuration.add(node(label));
			}
			first = active();
		}

		/** The time between two cycles (default 300 ms): slow enough to watch, the whole script a second or two. */
		public Script pace(long millis) {
			paceMillis = millis;
			return this;
		}

		/** One decision cycle: its moves, in the order the engine takes them. */
		public Script cycle(String... moves) {
			List<Move> cycle = new ArrayList<>();
			for (String move : moves) {
				String[] ends = move.split("->", -1);
				if (ends.length != 2) {
					throw new IllegalArgumentException("a move is FROM->TO (labels): " + move);
				}
				Node from = node(ends[0].trim());
				Node to = node(ends[1].trim());
				if (!configuration.contains(from)) {
					throw new IllegalArgumentException(robot.behaviour() + ": " + move + ": " + from.getLabel() + " is not active then (active: " + active() + ")");
				}
				List<Transition> transitions = robot.model().getTransitions();
				int tr = -1;
				for (int i = 0; i < transitions.size() && tr < 0; i++) {
					if (transitions.get(i).getSource() == from && transitions.get(i).getTarget() == to) {
						tr = i;
					}
				}
				if (tr < 0) {
					throw new IllegalArgumentException(robot.behaviour() + " has no transition " + move);
				}
				take(from, to);
				cycle.add(new Move(tr, from.getLabel(), to.getLabel()));
			}
			cycles.add(new Cycle(List.copyOf(cycle), active()));
			return this;
		}

		public Robot robot() {
			return robot;
		}

		/** The configuration when a client subscribes (labels, root first, in document order). */
		public List<String> firstActive() {
			return first;
		}

		public List<Cycle> cycles() {
			return List.copyOf(cycles);
		}

		/** The configuration after the last cycle: what a watcher shows at the end. */
		public List<String> lastActive() {
			return active();
		}

		/** The states of {@link #lastActive()}. */
		public List<Node> lastActiveStates() {
			return Models.allNodes(robot.model()).stream().filter(configuration::contains).toList();
		}

		/** How many transitions the script takes. */
		public int taken() {
			return cycles.stream().mapToInt(cycle -> cycle.moves().size()).sum();
		}

		/**
		 * Leaves the source with what it contains, up to the lowest state that holds both ends (a
		 * self loop leaves its state and enters it again), and enters the target with its ancestors
		 * below that state and its start state: the engine's configuration of an OR chart.
		 */
		private void take(Node from, Node to) {
			Node common = null;
			for (EObject each = from.eContainer(); each instanceof Node state && common == null; each = state.eContainer()) {
				if (state != to && Models.isInside(to, state)) {
					common = state;
				}
			}
			Node exited = from;
			while (exited.eContainer() instanceof Node parent && parent != common) {
				exited = parent;
			}
			Node left = exited;
			configuration.removeIf(node -> Models.isInside(node, left));
			for (EObject each = to; each instanceof Node state && state != common; each = state.eContainer()) {
				configuration.add(state);
			}
			for (Node child : to.getChildren()) {
				if ("START".equals(child.getType())) {
					configuration.add(child);
				}
			}
		}

		private Node node(String label) {
			return Models.allNodes(robot.model()).stream().filter(node -> label.equals(node.getLabel())).findFirst()
					.orElseThrow(() -> new IllegalArgumentException(robot.behaviour() + " has no state labelled " + label));
		}

		private List<String> active() {
			return Models.allNodes(robot.model()).stream().filter(configuration::contains).map(Node::getLabel).toList();
		}
	}

	/** Serves every client that connects with {@code script}, each on a thread of its own, until {@link #close()}. */
	public void play(Script script) {
		if (acceptor != null) {
			throw new IllegalStateException("already playing");
		}
		acceptor = new Thread(() -> {
			int number = 0;
			while (!listener.isClosed()) {
				try {
					listener.setSoTimeout(0);
					Socket socket = listener.accept();
					clients.add(socket);
					int client = ++number;
					Thread serving = new Thread(() -> serve(socket, client, script), "fake match client " + client);
					serving.setDaemon(true);
					serving.start();
				} catch (IOException closed) {
					// close(): no more clients
				}
			}
		}, "fake match on 127.0.0.1:" + port());
		acceptor.setDaemon(true);
		acceptor.start();
	}

	/** Lets the played match end: the result is sent and the connections closed. */
	public void finish() {
		end.countDown();
	}

	/** What clients did against the protocol ("client 1: …"); empty when all spoke as docs/monitor.md says. */
	public List<String> problems() {
		return List.copyOf(problems);
	}

	/** The lines the clients sent, each as "client N: LINE", in the order received. */
	public List<String> received() {
		return List.copyOf(received);
	}

	private void serve(Socket socket, int client, Script script) {
		try (socket) {
			socket.setSoTimeout((int) HELLO_MILLIS);
			BufferedReader in = new BufferedReader(new InputStreamReader(socket.getInputStream(), StandardCharsets.UTF_8), MAX_LINE + 2);
			OutputStream out = socket.getOutputStream();
			String hello = line(in, client);
			String why = hello == null ? "closed before its hello" : helloProblem(hello);
			if (why != null) {
				// as kse-match: a wrong hello is closed at once, nothing sent
				problems.add("client " + client + ": " + why);
				return;
			}
			JsonObject match = new JsonObject();
			match.addProperty("type", "match");
			match.addProperty("monitor", 1);
			matchFields(match, true);
			send(out, match);

			socket.setSoTimeout((int) DEFAULT_ACCEPT_MILLIS);
			Set<String> subscribed = Collections.synchronizedSet(new LinkedHashSet<>());
			String first = line(in, client);
			if (!subscribe(first, client, subscribed)) {
				return;
			}
			// later subscriptions replace the first while the match plays
			Thread reader = new Thread(() -> {
				try {
					socket.setSoTimeout(0);
					for (String next = line(in, client); next != null; next = line(in, client)) {
						if (!subscribe(next, client, subscribed)) {
							socket.close();
							return;
						}
					}
				} catch (IOException closed) {
					// the connection ended
				}
			}, "fake match client " + client + " reader");
			reader.setDaemon(true);
			reader.start();

			double t = 1.00;
			String robot = script.robot().id();
			if (wants(subscribed, robot)) {
				send(out, active(t, robot, script.firstActive()));
			}
			for (Script.Cycle cycle : script.cycles()) {
				Thread.sleep(script.paceMillis);
				t += 0.10;
				if (wants(subscribed, robot)) {
					for (Script.Move move : cycle.moves()) {
						JsonObject taken = new JsonObject();
						taken.addProperty("type", "taken");
						taken.addProperty("t", time(t));
						taken.addProperty("wall", System.currentTimeMillis());
						taken.addProperty("robot", robot);
						taken.addProperty("tr", move.tr());
						taken.addProperty("from", move.from());
						taken.addProperty("to", move.to());
						send(out, taken);
					}
					send(out, active(t, robot, cycle.active()));
				}
				send(out, frame(t, "PLAYING"));
			}
			end.await(HOLD_MILLIS, TimeUnit.MILLISECONDS);
			JsonObject result = new JsonObject();
			result.addProperty("type", "result");
			result.addProperty("t", time(t));
			result.addProperty("state", "FINISHED");
			result.add("score", score());
			result.addProperty("stuck", 0);
			result.addProperty("failed", 0);
			result.addProperty("failures", 0);
			send(out, result);
			// as kse-match: the last lines are written out, then the client gets a moment to close first
			socket.shutdownOutput();
			reader.join(3_000);
		} catch (SocketException gone) {
			// the client left, or close()
		} catch (IOException | InterruptedException | RuntimeException e) {
			problems.add("client " + client + ": the fake match failed: " + e);
		}
	}

	/** A line of at most 4,096 bytes, or null at the end; a longer one is a problem and ends the connection. */
	private String line(BufferedReader in, int client) throws IOException {
		StringBuilder line = new StringBuilder();
		for (int c = in.read(); c != '\n'; c = in.read()) {
			if (c < 0) {
				return line.isEmpty() ? null : line.toString();
			}
			line.append((char) c);
			if (line.toString().getBytes(StandardCharsets.UTF_8).length > MAX_LINE) {
				problems.add("client " + client + ": a line over " + MAX_LINE + " bytes");
				throw new SocketException("line too long");
			}
		}
		received.add("client " + client + ": " + line);
		return line.toString();
	}

	private String helloProblem(String line) {
		JsonObject hello = object(line);
		if (hello == null || !hello.keySet().equals(Set.of("type", "token")) || !"hello".equals(string(hello.get("type")))) {
			return "not a hello: " + line;
		}
		return key.equals(string(hello.get("token"))) ? null : "a hello with a wrong key";
	}

	/** Takes a subscription into {@code subscribed}; false (and a problem) when the line is not one. */
	private boolean subscribe(String line, int client, Set<String> subscribed) {
		JsonObject subscription = line == null ? null : object(line);
		if (subscription == null || !subscription.keySet().equals(Set.of("type", "robots")) || !"subscribe".equals(string(subscription.get("type")))
				|| !subscription.get("robots").isJsonArray()) {
			problems.add("client " + client + ": " + (line == null ? "closed before subscribing" : "not a subscription: " + line));
			return false;
		}
		Set<String> robots = new LinkedHashSet<>();
		for (JsonElement robot : subscription.getAsJsonArray("robots")) {
			String id = string(robot);
			if (id == null) {
				problems.add("client " + client + ": a robot that is not a string: " + line);
				return false;
			}
			robots.add(id);
		}
		synchronized (subscribed) {
			subscribed.clear();
			subscribed.addAll(robots);
		}
		return true;
	}

	private static boolean wants(Set<String> subscribed, String robot) {
		return subscribed.contains("*") || subscribed.contains(robot);
	}

	private static JsonObject object(String line) {
		try {
			return JsonParser.parseString(line) instanceof JsonObject json ? json : null;
		} catch (RuntimeException notJson) {
			return null;
		}
	}

	private static String string(JsonElement element) {
		return element != null && element.isJsonPrimitive() && element.getAsJsonPrimitive().isString() ? element.getAsString() : null;
	}

	private static JsonObject active(double t, String robot, List<String> labels) {
		JsonObject active = new JsonObject();
		active.addProperty("type", "active");
		active.addProperty("t", time(t));
		active.addProperty("robot", robot);
		JsonArray list = new JsonArray();
		labels.forEach(list::add);
		active.add("active", list);
		return active;
	}

	private static JsonObject frame(double t, String state) {
		JsonObject frame = new JsonObject();
		frame.addProperty("type", "frame");
		frame.addProperty("t", time(t));
		frame.addProperty("state", state);
		frame.add("score", score());
		return frame;
	}

	/** The score the fake match plays to: 1 : 0 for home. */
	private static JsonArray score() {
		JsonArray score = new JsonArray();
		score.add(1);
		score.add(0);
		return score;
	}

	/** Match seconds as kse-match writes them (two decimals). */
	private static BigDecimal time(double t) {
		return BigDecimal.valueOf(t).setScale(2, RoundingMode.HALF_EVEN);
	}

	private static void send(OutputStream out, JsonObject record) throws IOException {
		synchronized (out) {
			out.write((record + "\n").getBytes(StandardCharsets.UTF_8));
			out.flush();
		}
	}

	/** Ends the match for everybody (a played one without its result), removes the announcement. */
	@Override
	public void close() throws IOException {
		end.countDown();
		listener.close();
		for (Socket client : clients) {
			client.close();
		}
		if (announcement != null) {
			Files.deleteIfExists(announcement);
		}
		if (acceptor != null) {
			try {
				acceptor.join(5_000);
			} catch (InterruptedException e) {
				Thread.currentThread().interrupt();
			}
		}
	}

	/** The robots and behaviours, for messages. */
	@Override
	public String toString() {
		Map<String, String> behaviours = new LinkedHashMap<>();
		robots.forEach(robot -> behaviours.put(robot.id(), robot.behaviour()));
		return "fake match on 127.0.0.1:" + port() + " " + behaviours;
	}
}
