package org.kse.simulation;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;

/**
 * A running simulation: the simulator program (see {@link SimulatorBuilder}) talked to over its
 * standard input and output, one command and one JSON line back at a time (docs/simulation.md).
 * Nothing listens on a port: the pipes are this process's own. Every command that ran goes into
 * the {@link #trace()}, which saves as a conformance case.
 */
public final class SimulationSession implements AutoCloseable {

	/** A transition segment taken: the model's {@code //@transitions.index} and its states' labels. */
	public record Taken(int transition, String from, String to) {
	}

	/**
	 * What a command did: the command as it ran (an advance a breakpoint cut short says how far it
	 * went), the trace lines it caused, the segments taken, the breakpoint that stopped it, and the
	 * statechart afterwards: its active states, the running activities (one per run, by name) and
	 * when each of those runs began ({@code runningSince}, simulated ms, in the same order). {@code ok}
	 * false: refused with {@code error}, nothing changed.
	 */
	public record Result(boolean ok, String command, List<String> lines, List<Taken> taken, Optional<String> stopped, Optional<String> error,
			List<String> active, List<String> running, List<Long> runningSince, long time, boolean started) {

		/** When the earliest run of {@code activity} going on began (simulated ms), if one is. */
		public OptionalLong since(String activity) {
			OptionalLong earliest = OptionalLong.empty();
			for (int i = 0; i < running.size() && i < runningSince.size(); i++) {
				if (running.get(i).equals(activity) && (earliest.isEmpty() || runningSince.get(i) < earliest.getAsLong())) {
					earliest = OptionalLong.of(runningSince.get(i));
				}
			}
			return earliest;
		}
	}

	/** The longest wait for one answer: an advance of an hour through a busy chart takes seconds. */
	public static final Duration ANSWER_LIMIT = Duration.ofSeconds(60);
	/** Commands are lines; the simulator refuses longer ones too. */
	public static final int LONGEST_COMMAND = 64 * 1024;

	private static final JsonObject END = new JsonObject();

	private final Process process;
	private final Writer input;
	private final BlockingQueue<JsonObject> answers;
	private final Path errorLog;
	private final String model;
	private final List<String> states;
	private final int transitionCount;
	private final List<String> activities;
	private final Trace trace;
	private Result last;

	private SimulationSession(Process process, BlockingQueue<JsonObject> answers, Path errorLog, JsonObject ready) {
		this.process = process;
		this.answers = answers;
		this.input = new OutputStreamWriter(process.getOutputStream(), StandardCharsets.UTF_8);
		this.errorLog = errorLog;
		this.model = ready.get("model").getAsString();
		this.states = strings(ready.getAsJsonArray("states"));
		this.transitionCount = ready.get("transitions").getAsInt();
		this.activities = strings(ready.getAsJsonArray("activities"));
		this.trace = new Trace(model);
	}

	/** Starts the simulator and waits for it to be ready. */
	public static SimulationSession start(SimulatorBuilder.Simulator simulator) throws IOException, SimulationException {
		Path errorLog = simulator.folder().resolve("session.log");
		List<String> command = List.of(simulator.program().toString(), "--activities", String.join(",", simulator.activities()), "--serve",
				simulator.model());
		Process process = new ProcessBuilder(command).redirectError(errorLog.toFile()).start();
		BlockingQueue<JsonObject> answers = new LinkedBlockingQueue<>();
		Thread reader = new Thread(() -> read(process, answers), "KSE simulation " + simulator.model());
		reader.setDaemon(true);
		reader.start();
		JsonObject ready = take(answers, process, errorLog);
		if (!"ready".equals(text(ready, "type"))) {
			process.destroyForcibly();
			throw new SimulationException("the simulator did not start: " + text(ready, "error"));
		}
		return new SimulationSession(process, answers, errorLog, ready);
	}

	private static void read(Process process, BlockingQueue<JsonObject> answers) {
		try (BufferedReader output = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
			for (String line; (line = output.readLine()) != null;) {
				try {
					JsonElement element = JsonParser.parseString(line);
					if (element.isJsonObject()) {
						answers.add(element.getAsJsonObject());
					}
				} catch (JsonParseException e) {
					// not an answer (a line the statechart's code printed): the protocol's lines are JSON
				}
			}
		} catch (IOException e) {
			// the simulator ended; END below says so
		}
		answers.add(END);
	}

	public String model() {
		return model;
	}

	/** Labels of the statechart's states, in the model's order (the root first). */
	public List<String> states() {
		return states;
	}

	public int transitionCount() {
		return transitionCount;
	}

	public List<String> activities() {
		return activities;
	}

	public Trace trace() {
		return trace;
	}

	/** The last answer (the statechart now), or null before the first command. */
	public synchronized Result last() {
		return last;
	}

	/**
	 * Runs one command of the script language (start, publish, finish, fail, advance, active,
	 * running, read). A refused command comes back with {@code ok} false and is not traced.
	 */
	public synchronized Result execute(String command) throws IOException, SimulationException {
		if (command.indexOf('\n') >= 0 || command.indexOf('\r') >= 0) {
			throw new IllegalArgumentException("a command is one line");
		}
		if (command.length() > LONGEST_COMMAND) {
			return refused(command, "a command longer than 64 KiB");
		}
		Result result = send(command);
		if (result.ok()) {
			trace.add(result);
		}
		return result;
	}

	/** Breakpoints: states (labels) that become active, transitions (model indexes) taken. Replaces the last set. */
	public synchronized Result setBreakpoints(Collection<String> stateLabels, Collection<Integer> transitions) throws IOException, SimulationException {
		StringBuilder command = new StringBuilder("breakpoints");
		for (String label : stateLabels) {
			if (label.isBlank() || label.chars().anyMatch(Character::isWhitespace)) {
				throw new IllegalArgumentException("a state's label has no spaces: '" + label + "'");
			}
			command.append(" state:").append(label);
		}
		for (int transition : transitions) {
			command.append(" transition:").append(transition);
		}
		return send(command.toString());
	}

	private Result send(String command) throws IOException, SimulationException {
		if (!process.isAlive()) {
			throw new SimulationException("the simulator has ended" + errorTail());
		}
		input.write(command);
		input.write('\n');
		input.flush();
		JsonObject answer = take(answers, process, errorLog);
		if ("error".equals(text(answer, "type"))) {
			close();
			throw new SimulationException("the simulation stopped: " + text(answer, "error") + errorTail());
		}
		last = result(answer);
		return last;
	}

	private static JsonObject take(BlockingQueue<JsonObject> answers, Process process, Path errorLog) throws SimulationException {
		JsonObject answer;
		try {
			answer = answers.poll(ANSWER_LIMIT.toMillis(), TimeUnit.MILLISECONDS);
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new SimulationException("interrupted while the simulator answered");
		}
		if (answer == null) {
			process.destroyForcibly();
			throw new SimulationException("the simulator did not answer within " + ANSWER_LIMIT.toSeconds() + " s; it was stopped");
		}
		if (answer == END) {
			answers.add(END);
			throw new SimulationException("the simulator ended" + tail(errorLog));
		}
		return answer;
	}

	private Result refused(String command, String why) {
		Result now = last;
		return new Result(false, command, List.of(), List.of(), Optional.empty(), Optional.of(why), now == null ? List.of() : now.active(),
				now == null ? List.of() : now.running(), now == null ? List.of() : now.runningSince(), now == null ? 0 : now.time(), now != null && now.started());
	}

	private static Result result(JsonObject answer) {
		List<Taken> taken = new ArrayList<>();
		if (answer.has("taken")) {
			for (JsonElement element : answer.getAsJsonArray("taken")) {
				JsonObject segment = element.getAsJsonObject();
				taken.add(new Taken(segment.get("tr").getAsInt(), text(segment, "from"), text(segment, "to")));
			}
		}
		return new Result(answer.get("ok").getAsBoolean(), text(answer, "command"),
				answer.has("lines") ? strings(answer.getAsJsonArray("lines")) : List.of(), List.copyOf(taken),
				Optional.ofNullable(answer.has("stopped") ? text(answer, "stopped") : null),
				Optional.ofNullable(answer.has("error") ? text(answer, "error") : null), strings(answer.getAsJsonArray("active")),
				strings(answer.getAsJsonArray("running")), numbers(answer.getAsJsonArray("since")), answer.get("time").getAsLong(),
				answer.get("started").getAsBoolean());
	}

	private static String text(JsonObject object, String member) {
		JsonElement element = object.get(member);
		return element == null || element.isJsonNull() ? "" : element.getAsString();
	}

	private static List<Long> numbers(JsonArray array) {
		List<Long> items = new ArrayList<>();
		if (array != null) {
			array.forEach(element -> items.add(element.getAsLong()));
		}
		return List.copyOf(items);
	}

	private static List<String> strings(JsonArray array) {
		List<String> items = new ArrayList<>();
		if (array != null) {
			array.forEach(element -> items.add(element.getAsString()));
		}
		return List.copyOf(items);
	}

	private String errorTail() {
		return tail(errorLog);
	}

	private static String tail(Path errorLog) {
		try {
			List<String> lines = Files.readAllLines(errorLog, StandardCharsets.UTF_8);
			return lines.isEmpty() ? "" : ": " + String.join("\n", lines.subList(Math.max(0, lines.size() - 10), lines.size()));
		} catch (IOException e) {
			return "";
		}
	}

	public boolean isAlive() {
		return process.isAlive();
	}

	/** Ends the simulator (its running activities return). */
	@Override
	public void close() {
		try {
			if (process.isAlive()) {
				input.write("quit\n");
				input.flush();
				input.close();
			}
		} catch (IOException e) {
			// it ended already
		}
		try {
			if (!process.waitFor(5, TimeUnit.SECONDS)) {
				process.destroyForcibly();
			}
		} catch (InterruptedException e) {
			process.destroyForcibly();
			Thread.currentThread().interrupt();
		}
	}
}
