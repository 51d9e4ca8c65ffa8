package org.kse.diagram.server.tests;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import org.eclipse.glsp.graph.GGraph;
import org.eclipse.glsp.graph.GModelRoot;
import org.eclipse.glsp.server.actions.Action;
import org.eclipse.glsp.server.actions.ActionMessage;
import org.eclipse.glsp.server.actions.MessageAction;
import org.eclipse.glsp.server.features.core.model.SetModelAction;
import org.eclipse.glsp.server.features.core.model.UpdateModelAction;
import org.eclipse.glsp.server.features.core.model.RequestModelAction;
import org.eclipse.glsp.server.protocol.GLSPServer;
import org.eclipse.glsp.server.protocol.InitializeClientSessionParameters;
import org.eclipse.glsp.server.protocol.InitializeParameters;
import org.kse.diagram.server.StatechartDiagramConfiguration;
import org.kse.diagram.server.StatechartServerModule;

import com.google.inject.Guice;

/**
 * A GLSP client session with the diagram server, in-process: sends actions as the browser client
 * would and waits for what the server sends back. Each edit is answered with the new graph.
 */
final class GlspSession implements AutoCloseable {

	static final String ID = "session";

	private final GLSPServer server;
	final List<ActionMessage> received = new CopyOnWriteArrayList<>();

	GlspSession(Path folder) throws Exception {
		this(folder, new org.kse.diagram.server.FileSources());
	}

	GlspSession(Path folder, org.kse.diagram.server.StatechartSources sources) throws Exception {
		server = Guice.createInjector(new StatechartServerModule(folder, sources)).getInstance(GLSPServer.class);
		server.connect(received::add);
		InitializeParameters parameters = new InitializeParameters();
		parameters.setApplicationId("kse-tests");
		parameters.setProtocolVersion("1.0.0");
		server.initialize(parameters).get(10, TimeUnit.SECONDS);
		server.initializeClientSession(new InitializeClientSessionParameters(ID, StatechartDiagramConfiguration.DIAGRAM_TYPE,
				List.of("setModel", "requestBounds", "updateModel", "message", "status", "setDirtyState", "setMarkers", "setClipboardData",
						"setPopupModel", "setEditValidationResult", org.kse.diagram.server.DiskChanges.DiskChangeAction.KIND))).get(10, TimeUnit.SECONDS);
	}

	void send(Action action) {
		server.process(new ActionMessage(ID, action));
	}

	/** Opens a model of the served folder and returns its graph. */
	GGraph open(String model) throws InterruptedException {
		return graphAfter(new RequestModelAction(Map.of("sourceUri", model)));
	}

	/** Sends the action and returns the graph the server sends next (an edit's result). */
	GGraph graphAfter(Action action) throws InterruptedException {
		int before = graphs().size();
		send(action);
		long end = System.currentTimeMillis() + 15_000;
		while (System.currentTimeMillis() < end) {
			List<GModelRoot> graphs = graphs();
			if (graphs.size() > before) {
				return (GGraph) graphs.get(graphs.size() - 1);
			}
			Thread.sleep(10);
		}
		throw new AssertionError("no new graph after " + action.getKind() + "; received " + kinds());
	}

	/** Sends an edit the server should refuse and returns the message the client is shown. */
	String refusal(Action action) throws InterruptedException {
		int before = all(MessageAction.class).size();
		int graphs = graphs().size();
		send(action);
		long end = System.currentTimeMillis() + 10_000;
		while (System.currentTimeMillis() < end) {
			List<MessageAction> messages = all(MessageAction.class);
			if (messages.size() > before) {
				Thread.sleep(100);
				if (graphs().size() != graphs) {
					throw new AssertionError("the refused edit changed the diagram");
				}
				MessageAction message = messages.get(messages.size() - 1);
				return message.getSeverity() + ": " + message.getMessage() + " " + message.getDetails().orElse("");
			}
			Thread.sleep(10);
		}
		throw new AssertionError("no message after " + action.getKind() + "; received " + kinds());
	}

	/** The latest action of the type that arrives within 10 s after {@code after} of them had arrived. */
	<T extends Action> T next(Class<T> type, int after) throws InterruptedException {
		long end = System.currentTimeMillis() + 10_000;
		while (System.currentTimeMillis() < end) {
			List<T> all = all(type);
			if (all.size() > after) {
				return all.get(all.size() - 1);
			}
			Thread.sleep(10);
		}
		throw new AssertionError("no " + type.getSimpleName() + "; received " + kinds());
	}

	/**
	 * The graphs the server sent, in order: a new model ({@code setModel}) or an edit's result
	 * ({@code updateModel}). The server sizes every label itself, so no client measures them first.
	 */
	List<GModelRoot> graphs() {
		return received.stream().map(ActionMessage::getAction)
				.map(action -> action instanceof SetModelAction set ? set.getNewRoot() : action instanceof UpdateModelAction update ? update.getNewRoot() : null)
				.filter(java.util.Objects::nonNull).toList();
	}

	/** The latest graph that arrives within 10 s after {@code after} graphs had arrived. */
	GGraph nextGraph(int after) throws InterruptedException {
		long end = System.currentTimeMillis() + 10_000;
		while (System.currentTimeMillis() < end) {
			List<GModelRoot> graphs = graphs();
			if (graphs.size() > after) {
				return (GGraph) graphs.get(graphs.size() - 1);
			}
			Thread.sleep(10);
		}
		throw new AssertionError("no new graph; received " + kinds());
	}

	int count(Class<? extends Action> type) {
		return all(type).size();
	}

	<T extends Action> List<T> all(Class<T> type) {
		return received.stream().map(ActionMessage::getAction).filter(type::isInstance).map(type::cast).toList();
	}

	String kinds() {
		return received.stream().map(message -> message.getAction() instanceof MessageAction shown
				? "message(" + shown.getSeverity() + ": " + shown.getMessage() + " " + shown.getDetails().orElse("") + ")"
				: message.getAction().getKind()).toList().toString();
	}

	@Override
	public void close() {
		server.shutdown();
	}
}
