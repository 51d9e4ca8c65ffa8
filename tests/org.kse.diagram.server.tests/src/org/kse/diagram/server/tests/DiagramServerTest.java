package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import org.eclipse.glsp.graph.GGraph;
import org.eclipse.glsp.graph.GNode;
import org.eclipse.glsp.server.actions.Action;
import org.eclipse.glsp.server.actions.ActionMessage;
import org.eclipse.glsp.server.features.core.model.RequestBoundsAction;
import org.eclipse.glsp.server.features.core.model.RequestModelAction;
import org.eclipse.glsp.server.features.core.model.SetModelAction;
import org.eclipse.glsp.server.protocol.GLSPServer;
import org.eclipse.glsp.server.protocol.InitializeClientSessionParameters;
import org.eclipse.glsp.server.protocol.InitializeParameters;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.StatechartDiagramConfiguration;
import org.kse.diagram.server.StatechartServerModule;
import org.kse.diagram.server.StatechartGraph;

import com.google.inject.Guice;

/**
 * The diagram server spoken to as a GLSP client would (in-process, without a socket): a session
 * asks for the Goalie and gets its graph; a path that leaves the served folder is refused and
 * the server keeps serving.
 */
class DiagramServerTest {

	@TempDir
	Path folder;
	private GLSPServer server;
	private final List<ActionMessage> received = new CopyOnWriteArrayList<>();

	@BeforeEach
	void start() throws Exception {
		Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), folder.resolve("Goalie.stct"));
		server = Guice.createInjector(new StatechartServerModule(folder, new org.kse.diagram.server.FileSources())).getInstance(GLSPServer.class);
		server.connect(received::add);
		InitializeParameters parameters = new InitializeParameters();
		parameters.setApplicationId("kse-tests");
		parameters.setProtocolVersion("1.0.0");
		server.initialize(parameters).get(10, TimeUnit.SECONDS);
		server.initializeClientSession(new InitializeClientSessionParameters("session", StatechartDiagramConfiguration.DIAGRAM_TYPE,
				List.of(SetModelAction.KIND, RequestBoundsAction.KIND, "message", "status", "updateModel", "setDirtyState"))).get(10, TimeUnit.SECONDS);
	}

	@AfterEach
	void stop() {
		server.shutdown();
	}

	private <T extends Action> T await(Class<T> type) throws InterruptedException {
		long end = System.currentTimeMillis() + 10_000;
		while (System.currentTimeMillis() < end) {
			for (ActionMessage message : received) {
				if (type.isInstance(message.getAction())) {
					return type.cast(message.getAction());
				}
			}
			Thread.sleep(20);
		}
		return null;
	}

	private String kinds() {
		return received.stream().map(message -> message.getAction() instanceof org.eclipse.glsp.server.actions.MessageAction shown
				? "message(" + shown.getSeverity() + ": " + shown.getMessage() + " " + shown.getDetails().orElse("") + ")"
				: message.getAction().getKind()).toList().toString();
	}

	@Test
	void aSessionAsksForTheGoalieAndGetsItsGraph() throws Exception {
		server.process(new ActionMessage("session", new RequestModelAction(Map.of("sourceUri", "Goalie.stct"))));
		// the server sizes the labels itself: the graph is the model at once, with no client layout first
		SetModelAction model = await(SetModelAction.class);
		assertNotNull(model, () -> "the graph, received: " + kinds());
		assertTrue(received.stream().noneMatch(message -> message.getAction() instanceof RequestBoundsAction), () -> "no client layout asked: " + kinds());
		GGraph graph = assertInstanceOf(GGraph.class, model.getNewRoot());
		GNode root = assertInstanceOf(GNode.class, StatechartGraph.find(graph, "//@nodes.0"));
		assertEquals("state:or", root.getType());
		assertTrue(StatechartGraph.find(graph, "//@transitions.0") != null, "with the transitions");
	}

	@Test
	void aPathOutsideTheServedFolderIsRefusedAndTheServerKeepsServing() throws Exception {
		Files.writeString(folder.getParent().resolve("Outside.stct"), Files.readString(folder.resolve("Goalie.stct")));
		server.process(new ActionMessage("session", new RequestModelAction(Map.of("sourceUri", "../Outside.stct"))));
		Thread.sleep(500);
		assertTrue(received.stream().noneMatch(message -> message.getAction() instanceof SetModelAction), () -> "nothing served: " + kinds());
		server.process(new ActionMessage("session", new RequestModelAction(Map.of("sourceUri", "Goalie.stct"))));
		assertNotNull(await(SetModelAction.class), () -> "still serving: " + kinds());
		assertTrue(kinds().contains("leaves the served folder"), () -> "the client is told why: " + kinds());
	}
}
