package org.kse.ui.statechart.simulation;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.OptionalLong;

import org.kse.simulation.SimulationException;
import org.kse.simulation.SimulationSession;
import org.kse.simulation.SimulationSession.Result;

/**
 * What the Simulation view asks of a session, beyond one command: finishing an activity after it
 * publishes its message, advancing time while finishing the activities that have run long enough
 * (the view's "finish after N ms"; the simulator says when each run began). Everything it does
 * is a command of the script language, so the trace (and a case saved from it) shows it.
 * <p>
 * Called on the view's command thread only (the session answers one command at a time); the
 * settings are read from there too and may be changed from the UI thread.
 */
final class SimulationDriver {

	private final SimulationSession session;
	/** An activity's publish command, sent right before it is finished. */
	private final Map<String, String> publishesOnFinish;
	/** Finish every activity once it has run this long (simulated ms); 0: never. */
	private volatile long finishAfter;

	SimulationDriver(SimulationSession session, Map<String, String> publishesOnFinish) {
		this.session = session;
		this.publishesOnFinish = publishesOnFinish;
	}

	SimulationSession session() {
		return session;
	}

	void setFinishAfter(long milliseconds) {
		finishAfter = Math.max(0, milliseconds);
	}

	/** Since when (simulated ms: the wake-up that launched it) an activity runs, if it does. */
	OptionalLong runningSince(String activity) {
		Result last = session.last();
		return last == null ? OptionalLong.empty() : last.since(activity);
	}

	Result execute(String command) throws IOException, SimulationException {
		return session.execute(command);
	}

	/** Breakpoints of the session (states by label, transitions by model index). */
	Result setBreakpoints(Collection<String> states, Collection<Integer> transitions) throws IOException, SimulationException {
		return session.setBreakpoints(states, transitions);
	}

	/**
	 * Ends a running activity: {@code fail} makes it throw; a finish sends its message first when
	 * it has one to publish. Stops at the first command refused.
	 */
	List<Result> end(String activity, boolean fail) throws IOException, SimulationException {
		List<Result> results = new ArrayList<>();
		String publish = publishesOnFinish.get(activity);
		if (!fail && publish != null && !publish.isBlank()) {
			Result published = execute(publish);
			results.add(published);
			if (!published.ok()) {
				return results;
			}
		}
		results.add(execute((fail ? "fail " : "finish ") + activity));
		return results;
	}

	/**
	 * Moves time on by {@code milliseconds}: in one advance, or, when activities are finished after
	 * a time, in advances up to each one's time, finishing it there. Stops at a refused command or
	 * at a breakpoint.
	 */
	List<Result> advance(long milliseconds) throws IOException, SimulationException {
		List<Result> results = new ArrayList<>();
		long remaining = milliseconds;
		for (;;) {
			Result now = session.last();
			long time = now == null ? 0 : now.time();
			long step = remaining;
			if (finishAfter > 0 && now != null) {
				Map<String, Long> due = new HashMap<>();
				long next = Long.MAX_VALUE;
				for (String activity : new LinkedHashSet<>(now.running())) {
					long at = now.since(activity).orElse(time) + finishAfter;
					if (at <= time) {
						due.put(activity, at);
					}
					next = Math.min(next, at);
				}
				if (!due.isEmpty()) {
					for (String activity : due.keySet().stream().sorted().toList()) {
						List<Result> ended = end(activity, false);
						results.addAll(ended);
						Result last = ended.get(ended.size() - 1);
						if (!last.ok() || last.stopped().isPresent()) {
							return results;
						}
					}
					continue;
				}
				if (next != Long.MAX_VALUE) {
					step = Math.min(step, next - time);
				}
			}
			if (remaining <= 0) {
				return results;
			}
			Result advanced = execute("advance " + step);
			results.add(advanced);
			if (!advanced.ok() || advanced.stopped().isPresent()) {
				return results;
			}
			remaining -= step;
		}
	}
}
