package org.kse.diagram.server.websocket;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ConnectException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.IntSupplier;
import java.util.function.Predicate;
import java.util.regex.Pattern;

import org.apache.logging.log4j.LogManager;
import org.apache.logging.log4j.Logger;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.google.gson.JsonPrimitive;

import jakarta.websocket.CloseReason;
import jakarta.websocket.Endpoint;
import jakarta.websocket.EndpointConfig;
import jakarta.websocket.MessageHandler;
import jakarta.websocket.Session;

/**
 * The live monitor's relay ({@code /monitor}): a page watches a running {@code kse-match --monitor}
 * through this server, which connects to the match's loopback port, says hello with the match's
 * key, subscribes to the robots the page names and hands each line the match writes to the page.
 * <p>
 * The match speaks plain JSON lines and knows nothing of browsers: everything a web page could
 * abuse is checked here, where the diagram endpoint's checks already live. The page needs this
 * server's token; only pages of this server's own origin may connect (unlike {@code /kse}, which
 * an embedding host's page on another local port uses); the relay reaches 127.0.0.1 only, so a
 * page cannot make it a port scanner of other hosts; a page may only change the subscription or ask
 * for a robot's blackboard, each in one small message that the relay writes anew for the match:
 * anything else closes its connection (1008) and no other.
 * <p>
 * A page names the match by its port and key ({@code ?port=P&key=K}, as kse-match printed them) or
 * by its process id ({@code ?match=PID}), which is looked up among the {@link RunningMatches}.
 * <p>
 * Each connection has two virtual threads: one reads the match's lines, one sends them to the page,
 * several in one message when they come faster than {@link #BATCH_MILLIS} apart (at 10x a robot
 * takes hundreds of transitions a second, and a message each would cost the page more than the lines).
 */
public final class MonitorEndpoint extends Endpoint {

	public static final String PATH = "/monitor";

	/** The largest message a page may send: a subscription to a few teams' robots fits many times. */
	static final int MAX_PAGE_MESSAGE_BYTES = 4096;
	/** Lines that come within this many milliseconds of the last message to the page wait for the next one. */
	static final long BATCH_MILLIS = 16;
	/** What may wait for a page that does not keep up, as the match allows each of its clients. */
	static final int MAX_UNSENT_CHARS = 8 * 1024 * 1024;
	/** The longest line accepted from the match (its first line, the match record, is a few KiB). */
	static final int MAX_MATCH_LINE_BYTES = 1024 * 1024;

	private static final Logger LOG = LogManager.getLogger("org.kse.diagram");
	private static final Pattern ROBOT = Pattern.compile("\\*|[A-Za-z0-9_.-]{1,64}");
	private static final int MAX_ROBOTS = 64;

	private final SessionToken token;

	private Session session;
	private Socket match;
	private OutputStream toMatch;
	private int port;

	private final ReentrantLock lock = new ReentrantLock();
	private final Condition changed = lock.newCondition();
	private final StringBuilder unsent = new StringBuilder();
	/** Set when the match's stream ended: the close code and reason the page gets once all is sent. */
	private CloseReason ending;
	private boolean closed;
	private final StringBuilder fromPage = new StringBuilder();
	private int fromPageBytes;

	MonitorEndpoint(String token) {
		this.token = new SessionToken(token);
	}

	@Override
	public void onOpen(Session session, EndpointConfig config) {
		this.session = session;
		if (!token.isPresentedIn(session)) {
			LOG.warn("refused a monitor connection without the session token");
			close(CloseReason.CloseCodes.VIOLATED_POLICY, SessionToken.REFUSAL);
			return;
		}
		String key = single(session, "key");
		String portText = single(session, "port");
		List<String> robots = robots(single(session, "robots"));
		String pid = single(session, "match");
		if (pid != null) {
			// a match picked from /matches: its port and key are looked up here, so the page never holds the key
			if (!pid.matches("[1-9][0-9]{0,9}")) {
				refuse("match must be the process id of a running kse-match (?match=PID, as /matches lists it)");
				return;
			}
			Optional<RunningMatches.Match> running = RunningMatches.find(RunningMatches.folder(), Long.parseLong(pid));
			if (running.isEmpty()) {
				LOG.warn("a monitor page asked for match " + pid + ", which is not running (or not announced)");
				close(CloseReason.CloseCodes.UNEXPECTED_CONDITION, "no running match " + pid + " (it ended, or was started without --monitor)");
				return;
			}
			key = running.get().key();
			portText = Integer.toString(running.get().port());
		}
		if (portText == null || !portText.matches("[0-9]{1,5}") || Integer.parseInt(portText) < 1 || Integer.parseInt(portText) > 65535) {
			refuse("the match's port must be a number from 1 to 65535 (?port=P)");
			return;
		}
		if (key == null || key.isEmpty() || key.length() > 256) {
			refuse("the match's key is missing (?key=K, printed by kse-match --monitor)");
			return;
		}
		if (robots == null) {
			refuse("robots must be a comma separated list of up to " + MAX_ROBOTS + " robot ids (letters, digits, '.', '_', '-') or *");
			return;
		}
		port = Integer.parseInt(portText);
		session.setMaxIdleTimeout(0);
		// whole messages would be gathered first, up to the container's limit, and one over it closes with 1009:
		// reading parts, this endpoint closes any message over its own limit with 1008, as the protocol says
		session.addMessageHandler(String.class, (MessageHandler.Partial<String>) this::receive);
		JsonObject hello = new JsonObject();
		hello.addProperty("type", "hello");
		hello.addProperty("token", key);
		Thread.ofVirtual().name("kse-monitor-relay-" + port).start(() -> relay(hello.toString(), subscription(robots)));
	}

	private static String single(Session session, String name) {
		List<String> values = session.getRequestParameterMap().get(name);
		return values == null || values.size() != 1 ? null : values.get(0);
	}

	/** The robots of {@code ?robots=a,b}: every robot when there is none; null when the list is not one. */
	private static List<String> robots(String list) {
		if (list == null || list.isEmpty()) {
			return List.of("*");
		}
		List<String> robots = new ArrayList<>();
		for (String robot : list.split(",", -1)) {
			if (!ROBOT.matcher(robot).matches() || robots.size() == MAX_ROBOTS) {
				return null;
			}
			robots.add(robot);
		}
		return robots;
	}

	private static String subscription(List<String> robots) {
		JsonObject subscribe = new JsonObject();
		subscribe.addProperty("type", "subscribe");
		JsonArray names = new JsonArray();
		robots.forEach(names::add);
		subscribe.add("robots", names);
		return subscribe.toString();
	}

	/** Connects to the match, greets it, and hands what it writes to the sender until it closes. */
	private void relay(String hello, String subscribe) {
		try {
			Socket socket = new Socket();
			lock.lock();
			try {
				if (closed) {
					return;
				}
				match = socket;
			} finally {
				lock.unlock();
			}
			// the loopback address only, whatever the page asks for: the relay must not reach other hosts
			socket.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 5000);
			toMatch = socket.getOutputStream();
			writeToMatch(hello);
			writeToMatch(subscribe);
			LOG.info("a monitor page watches the match on 127.0.0.1:" + port);
		} catch (ConnectException refused) {
			LOG.warn("a monitor page asked for a match on 127.0.0.1:" + port + ", and none listens there");
			close(CloseReason.CloseCodes.UNEXPECTED_CONDITION, "no match on 127.0.0.1:" + port);
			return;
		} catch (IOException failed) {
			if (!isClosed()) {
				LOG.warn("cannot reach the match on 127.0.0.1:" + port + ": " + failed.getMessage());
				close(CloseReason.CloseCodes.UNEXPECTED_CONDITION, "cannot reach the match on 127.0.0.1:" + port);
			}
			return;
		}
		Thread.ofVirtual().name("kse-monitor-send-" + port).start(this::send);
		CloseReason end = new CloseReason(CloseReason.CloseCodes.NORMAL_CLOSURE, "the match ended");
		try (InputStream in = match.getInputStream()) {
			ByteArrayOutputStream line = new ByteArrayOutputStream(256);
			byte[] buffer = new byte[16 * 1024];
			for (int read; (read = in.read(buffer)) >= 0;) {
				List<String> lines = new ArrayList<>();
				for (int i = 0; i < read; i++) {
					if (buffer[i] == '\n') {
						lines.add(line.toString(StandardCharsets.UTF_8));
						line.reset();
					} else if (line.size() == MAX_MATCH_LINE_BYTES) {
						throw new IOException("a line of the match is longer than " + MAX_MATCH_LINE_BYTES + " bytes");
					} else {
						line.write(buffer[i]);
					}
				}
				if (!lines.isEmpty() && !queue(lines)) {
					return;
				}
			}
		} catch (IOException lost) {
			if (isClosed()) {
				return; // the page went, and closing the match's socket ended the read
			}
			LOG.warn("lost the match on 127.0.0.1:" + port + ": " + lost.getMessage());
			end = new CloseReason(CloseReason.CloseCodes.UNEXPECTED_CONDITION, "lost the match on 127.0.0.1:" + port);
		}
		lock.lock();
		try {
			ending = end;
			changed.signalAll();
		} finally {
			lock.unlock();
		}
	}

	/** Queues lines for the page; false (and the page's connection closed) when the page is too far behind. */
	private boolean queue(List<String> lines) {
		lock.lock();
		try {
			if (closed) {
				return false;
			}
			for (String line : lines) {
				if (!unsent.isEmpty()) {
					unsent.append('\n');
				}
				unsent.append(line);
			}
			if (unsent.length() <= MAX_UNSENT_CHARS) {
				changed.signalAll();
				return true;
			}
		} finally {
			lock.unlock();
		}
		LOG.warn("a monitor page fell more than 8 MiB behind the match on 127.0.0.1:" + port + ": its connection is closed");
		close(CloseReason.CloseCodes.TRY_AGAIN_LATER, "the page fell too far behind the match");
		return false;
	}

	/** Sends what the match wrote, at most one message every BATCH_MILLIS, then closes as the match did. */
	private void send() {
		long last = 0;
		while (true) {
			String batch;
			CloseReason end;
			lock.lock();
			try {
				while (!closed && unsent.isEmpty() && ending == null) {
					changed.await();
				}
				if (closed) {
					return;
				}
				long wait = last + TimeUnit.MILLISECONDS.toNanos(BATCH_MILLIS) - System.nanoTime();
				if (wait > 0 && ending == null) {
					// gather what comes until the next message is due
					changed.awaitNanos(wait);
					continue;
				}
				batch = unsent.isEmpty() ? null : unsent.toString();
				unsent.setLength(0);
				end = ending;
			} catch (InterruptedException interrupted) {
				return;
			} finally {
				lock.unlock();
			}
			if (batch != null) {
				try {
					session.getBasicRemote().sendText(batch);
				} catch (IOException | RuntimeException gone) {
					LOG.debug("a monitor page went: " + gone.getMessage());
					close(CloseReason.CloseCodes.GOING_AWAY, "");
					return;
				}
				last = System.nanoTime();
			} else if (end != null) {
				close(end.getCloseCode(), end.getReasonPhrase());
				return;
			}
		}
	}

	/** A part of a page's message: a whole one must be a subscription of at most MAX_PAGE_MESSAGE_BYTES. */
	private void receive(String part, boolean last) {
		fromPageBytes += part.getBytes(StandardCharsets.UTF_8).length;
		if (fromPageBytes > MAX_PAGE_MESSAGE_BYTES) {
			LOG.warn("a monitor page sent a message over " + MAX_PAGE_MESSAGE_BYTES + " bytes: its connection is closed");
			close(CloseReason.CloseCodes.VIOLATED_POLICY, "a message over " + MAX_PAGE_MESSAGE_BYTES + " bytes");
			return;
		}
		fromPage.append(part);
		if (!last) {
			return;
		}
		String text = fromPage.toString();
		fromPage.setLength(0);
		fromPageBytes = 0;
		List<String> robots = subscribed(text);
		String blackboard = robots == null ? blackboardAskedFor(text) : null;
		if (robots == null && blackboard == null) {
			LOG.warn("a monitor page sent a message that is neither a subscription nor a blackboard request: its connection is closed");
			close(CloseReason.CloseCodes.VIOLATED_POLICY,
					"only {\"type\":\"subscribe\",\"robots\":[…]} and {\"type\":\"blackboard\",\"robot\":…} are accepted");
			return;
		}
		try {
			// written anew by the relay, never passed on as the page wrote it
			writeToMatch(robots != null ? subscription(robots) : blackboardRequest(blackboard));
		} catch (IOException | RuntimeException notYet) {
			// not connected yet, or the match has gone: its end reaches the page through the relay
			LOG.debug("a page's message was not forwarded: " + notYet.getMessage());
		}
	}

	/** The robot of a well-formed blackboard request ({"type":"blackboard","robot":id}), or null. */
	private static String blackboardAskedFor(String text) {
		try {
			if (JsonParser.parseString(text) instanceof JsonObject message && message.size() == 2
					&& new JsonPrimitive("blackboard").equals(message.get("type")) && message.get("robot") instanceof JsonPrimitive robot
					&& robot.isString() && !robot.getAsString().equals("*") && ROBOT.matcher(robot.getAsString()).matches()) {
				return robot.getAsString();
			}
			return null;
		} catch (RuntimeException malformed) {
			return null;
		}
	}

	private static String blackboardRequest(String robot) {
		JsonObject request = new JsonObject();
		request.addProperty("type", "blackboard");
		request.addProperty("robot", robot);
		return request.toString();
	}

	/** The robots of a well-formed subscription, or null. */
	private static List<String> subscribed(String text) {
		try {
			if (!(JsonParser.parseString(text) instanceof JsonObject message) || message.size() != 2
					|| !new JsonPrimitive("subscribe").equals(message.get("type")) || !(message.get("robots") instanceof JsonArray names)
					|| names.size() > MAX_ROBOTS) {
				return null;
			}
			List<String> robots = new ArrayList<>();
			for (JsonElement name : names) {
				if (!(name instanceof JsonPrimitive primitive) || !primitive.isString() || !ROBOT.matcher(primitive.getAsString()).matches()) {
					return null;
				}
				robots.add(primitive.getAsString());
			}
			return robots;
		} catch (RuntimeException malformed) {
			return null;
		}
	}

	private void writeToMatch(String line) throws IOException {
		OutputStream out = toMatch;
		if (out == null) {
			throw new IOException("not connected to the match yet");
		}
		synchronized (out) {
			out.write((line + "\n").getBytes(StandardCharsets.UTF_8));
			out.flush();
		}
	}

	private boolean isClosed() {
		lock.lock();
		try {
			return closed;
		} finally {
			lock.unlock();
		}
	}

	private void refuse(String reason) {
		LOG.warn("refused a monitor connection: " + reason);
		close(CloseReason.CloseCodes.VIOLATED_POLICY, reason);
	}

	/** Closes the page's connection (once) and the match's socket: the match goes on for its other clients. */
	private void close(CloseReason.CloseCode code, String reason) {
		Socket socket;
		lock.lock();
		try {
			if (closed) {
				return;
			}
			closed = true;
			socket = match;
			changed.signalAll();
		} finally {
			lock.unlock();
		}
		if (socket != null) {
			try {
				socket.close();
			} catch (IOException ignored) {
				// it is gone either way
			}
		}
		try {
			if (session.isOpen()) {
				session.close(new CloseReason(code, reason));
			}
		} catch (IOException | RuntimeException gone) {
			LOG.debug("closing a monitor connection: " + gone.getMessage());
		}
	}

	@Override
	public void onClose(Session session, CloseReason reason) {
		close(CloseReason.CloseCodes.NORMAL_CLOSURE, "");
	}

	@Override
	public void onError(Session session, Throwable failure) {
		LOG.debug("a monitor connection failed: " + failure.getMessage());
		close(CloseReason.CloseCodes.UNEXPECTED_CONDITION, "");
	}

	/**
	 * The pages {@code /monitor} accepts: a non-browser client sends no origin; a browser sends its
	 * page's, which must be this server's own ({@code port}: this server's, known once it listens).
	 */
	static Predicate<String> ownPages(IntSupplier port) {
		return origin -> {
			if (origin == null || origin.isEmpty()) {
				return true;
			}
			int own = port.getAsInt();
			boolean accepted = origin.equals("http://127.0.0.1:" + own) || origin.equals("http://localhost:" + own) || origin.equals("http://[::1]:" + own);
			if (!accepted) {
				LOG.warn("refused a monitor connection from a page of another origin");
			}
			return accepted;
		};
	}
}
