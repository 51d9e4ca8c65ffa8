package org.kse.benchmarks;

import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.eclipse.emf.common.util.URI;
import org.kse.diagram.server.websocket.DiagramSocketServer;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.notation.NotationFiles;
import org.kse.transform.FormulaTransformation;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The diagram server as the browser uses it, over its WebSocket on loopback: opening a statechart
 * of about 1,000 states that has no notation (load, arrange with ELK, build the graph, send it;
 * goal under 2 s), and the round trip of moving a state of a 500-state model, from sending the
 * move to receiving the updated model after the client's measuring step (goal p95 under 50 ms).
 * Baselines measured in the same run: loading the model alone, and a request that changes nothing.
 * Run with {@code bench/diagram.sh}.
 */
public final class DiagramBenchmark {

	private static final int OPENS = 7;
	private static final int MOVES = 200;

	/** A WebSocket client that queues whole text messages. */
	private static final class Client implements WebSocket.Listener {
		final BlockingQueue<JsonObject> messages = new LinkedBlockingQueue<>();
		private final StringBuilder partial = new StringBuilder();
		WebSocket socket;

		@Override
		public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
			partial.append(data);
			if (last) {
				messages.add(JsonParser.parseString(partial.toString()).getAsJsonObject());
				partial.setLength(0);
			}
			webSocket.request(1);
			return null;
		}

		void send(String json) {
			socket.sendText(json, true).join();
		}

		void process(String client, String action) {
			send("{\"jsonrpc\":\"2.0\",\"method\":\"process\",\"params\":{\"clientId\":\"" + client + "\",\"action\":" + action + "}}");
		}

		/** The next action of this kind sent to the client; other messages are skipped. */
		JsonObject await(String kind) throws InterruptedException {
			long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
			while (System.nanoTime() < end) {
				JsonObject message = messages.poll(100, TimeUnit.MILLISECONDS);
				if (message != null && message.has("params") && message.getAsJsonObject("params").has("action")) {
					JsonObject action = message.getAsJsonObject("params").getAsJsonObject("action");
					if (kind.equals(action.get("kind").getAsString())) {
						return action;
					}
				} else if (message != null && message.has("id") && kind.equals("result")) {
					return message;
				}
			}
			throw new IllegalStateException("the diagram server sent no " + kind);
		}

		void session(String client) throws InterruptedException {
			send("{\"jsonrpc\":\"2.0\",\"id\":\"" + client + "\",\"method\":\"initializeClientSession\",\"params\":{\"clientSessionId\":\"" + client
					+ "\",\"diagramType\":\"kse-statechart\",\"clientActionKinds\":[\"requestBounds\",\"setModel\",\"updateModel\",\"setDirtyState\","
					+ "\"setMarkers\",\"setTypeHints\",\"message\",\"status\"]}}");
			await("result");
		}
	}

	public static void main(String[] args) throws Exception {
		Path folder = Files.createTempDirectory("kse-diagram-bench");
		int large = write(folder, "Large", 10, 24);
		int medium = write(folder, "Medium", 5, 24);
		try (DiagramSocketServer server = DiagramSocketServer.start(folder, 0)) {
			Client client = new Client();
			client.socket = HttpClient.newHttpClient().newWebSocketBuilder().buildAsync(server.uri(), client).get(10, TimeUnit.SECONDS);
			client.send("{\"jsonrpc\":\"2.0\",\"id\":\"init\",\"method\":\"initialize\",\"params\":{\"applicationId\":\"kse-bench\",\"protocolVersion\":\"1.0.0\"}}");
			client.await("result");
			System.out.printf(Locale.ROOT, "KSE diagram benchmark over the WebSocket on loopback: open %d states (no notation yet), move in %d states%n", large, medium);

			double load = Timing.median(2, OPENS, () -> StatechartResources.load(folder.resolve("Large.stct")));
			int[] sessions = { 0 };
			double open = Timing.median(2, OPENS, () -> {
				Files.deleteIfExists(NotationFiles.beside(folder.resolve("Large.stct")));
				String session = "open" + sessions[0]++;
				client.session(session);
				client.process(session, "{\"kind\":\"requestModel\",\"options\":{\"sourceUri\":\"Large.stct\"}}");
				return client.await("setModel"); // the server sizes the labels: no client layout in between
			});
			Timing.report("load the model (baseline)", load, 0);
			Timing.report("open it on the diagram (load, ELK, graph)", open, load);

			client.session("move");
			client.process("move", "{\"kind\":\"requestModel\",\"options\":{\"sourceUri\":\"Medium.stct\"}}");
			client.await("setModel");
			double[] nothing = Timing.sample(20, MOVES, () -> {
				client.process("move", "{\"kind\":\"requestTypeHints\",\"requestId\":\"hints\"}");
				return client.await("setTypeHints");
			});
			int[] step = { 0 };
			double[] moves = Timing.sample(20, MOVES, () -> {
				int x = 40 + step[0]++ % 50;
				client.process("move", "{\"kind\":\"changeBounds\",\"isOperation\":true,\"newBounds\":[{\"elementId\":\"//@nodes.0/@Children.1\","
						+ "\"newPosition\":{\"x\":" + x + ",\"y\":60}}]}");
				return client.await("updateModel");
			});
			Timing.report("a request that changes nothing (baseline)", Timing.percentile(nothing, 50), 0);
			Timing.report("move a state: median round trip", Timing.percentile(moves, 50), Timing.percentile(nothing, 50));
			Timing.report("move a state: p95 round trip", Timing.percentile(moves, 95), Timing.percentile(nothing, 95));
			System.out.printf(Locale.ROOT, "goals: open under 2 s %s; move p95 under 50 ms %s%n", open < 2000 ? "met" : "NOT met",
					Timing.percentile(moves, 95) < 50 ? "met" : "NOT met");
			client.socket.sendClose(java.net.http.WebSocket.NORMAL_CLOSURE, "done").get(10, TimeUnit.SECONDS);
		} finally {
			try (var files = Files.list(folder)) {
				for (Path file : files.toList()) {
					Files.delete(file);
				}
			}
			Files.delete(folder);
		}
	}

	private static int write(Path folder, String name, int capabilities, int activities) throws Exception {
		Model model = FormulaTransformation.run(NotationBenchmark.formulas(capabilities, activities), URI.createURI(name + ".liveness"), name).model();
		StatechartResources.save(model, folder.resolve(name + ".stct"));
		int[] states = new int[1];
		model.eAllContents().forEachRemaining(each -> states[0] += each instanceof org.kse.model.statechart.Node ? 1 : 0);
		return states[0];
	}
}
