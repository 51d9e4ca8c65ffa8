package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.Supplier;

import org.eclipse.emf.common.notify.Notification;
import org.eclipse.emf.ecore.util.EContentAdapter;
import org.eclipse.emf.edit.command.SetCommand;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.eclipse.glsp.graph.GGraph;
import org.eclipse.glsp.graph.GLabel;
import org.eclipse.glsp.graph.GNode;
import org.eclipse.glsp.graph.util.GraphUtil;
import org.eclipse.glsp.server.operations.ChangeBoundsOperation;
import org.eclipse.glsp.server.types.ElementAndBounds;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.StatechartGraph;
import org.kse.diagram.server.StatechartSources;
import org.kse.model.StatechartResources;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartPackage;
import org.kse.notation.NotationFiles;

/**
 * A diagram session on a model that an editor holds, as in the workbench: the session edits the
 * editor's model on its command stack, on the editor's thread; a change made elsewhere reaches the
 * diagram; the editor's own save writes the diagram's notation too.
 */
class SharedModelTest {

	private static final String SEARCH = "//@nodes.0/@Children.1";

	@TempDir
	Path folder;
	private final ExecutorService editorThread = Executors.newSingleThreadExecutor(run -> new Thread(run, "editor"));
	private EditingDomain domain;
	private Model model;
	private StatechartSources.NotationWriter editorSaveParticipant;
	private boolean closed;
	private GlspSession session;
	private GGraph graph;
	private final Set<String> changingThreads = ConcurrentHashMap.newKeySet();

	/** What a workbench editor hands out: its model and domain, with every access on its own thread. */
	private final StatechartSources editorSources = file -> new StatechartSources.Source() {
		@Override
		public Model model() {
			return model;
		}

		@Override
		public EditingDomain domain() {
			return domain;
		}

		@Override
		public <T> T access(Supplier<T> access) {
			try {
				return editorThread.submit(access::get).get();
			} catch (Exception e) {
				throw new IllegalStateException(e);
			}
		}

		@Override
		public void save(StatechartSources.NotationWriter notation) throws IOException {
			StatechartResources.save(model, file);
			notation.write();
		}

		@Override
		public void onSave(StatechartSources.NotationWriter notation) {
			editorSaveParticipant = notation;
		}

		@Override
		public void close() {
			closed = true;
		}
	};

	@BeforeEach
	void open() throws Exception {
		Path file = folder.resolve("Goalie.stct");
		Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), file);
		domain = StatechartEdits.newDomain();
		model = StatechartResources.load(domain.getResourceSet(), file);
		model.eAdapters().add(new EContentAdapter() {
			@Override
			public void notifyChanged(Notification notification) {
				super.notifyChanged(notification);
				if (!notification.isTouch()) {
					changingThreads.add(Thread.currentThread().getName());
				}
			}
		});
		session = new GlspSession(folder, editorSources);
		graph = session.open("Goalie.stct");
	}

	@AfterEach
	void close() {
		session.close();
		editorThread.shutdownNow();
	}

	private static String name(GGraph graph, String id) {
		GLabel label = (GLabel) StatechartGraph.find(graph, id + "#name");
		assertNotNull(label, "the diagram shows " + id);
		return label.getText();
	}

	@Test
	void aRenameMadeElsewhereIsShownOnTheDiagram() throws Exception {
		Node search = (Node) model.eResource().getEObject(SEARCH);
		assertEquals(org.kse.notation.Captions.of(search), name(graph, SEARCH));
		int graphs = session.graphs().size();
		// as the Properties view does: a command on the editor's stack, on the editor's thread
		editorThread.submit(() -> domain.getCommandStack().execute(SetCommand.create(domain, search, StatechartPackage.Literals.NODE__NAME, "LookAround"))).get();
		GGraph changed = session.nextGraph(graphs);
		assertEquals("LookAround", name(changed, SEARCH));
		assertTrue(session.next(org.eclipse.glsp.server.actions.SetDirtyStateAction.class, 0).isDirty(), "the page shows unsaved changes");

		int after = session.graphs().size();
		editorThread.submit(() -> domain.getCommandStack().undo()).get();
		changed = session.nextGraph(after);
		assertEquals(org.kse.notation.Captions.of(search), name(changed, SEARCH), "the workbench's undo is shown too");
	}

	@Test
	void aDiagramEditGoesOnTheEditorsStackOnTheEditorsThread() throws Exception {
		Node search = (Node) model.eResource().getEObject(SEARCH);
		graph = session.graphAfter(new org.eclipse.glsp.server.features.directediting.ApplyLabelEditOperation(SEARCH + "#name", "Survey"));
		assertEquals("Survey", search.getName(), "the editor's model object changed");
		assertEquals("Survey", name(graph, SEARCH));
		assertTrue(domain.getCommandStack().canUndo(), "the edit is on the editor's stack");
		assertEquals(Set.of("editor"), changingThreads, "the model changed on the editor's thread only");
		editorThread.submit(() -> domain.getCommandStack().undo()).get();
		assertFalse(search.getName().equals("Survey"), "undone from the editor");
	}

	@Test
	void theEditorsSaveWritesTheDiagramsNotation() throws Exception {
		GNode node = (GNode) StatechartGraph.find(graph, SEARCH);
		ElementAndBounds moved = new ElementAndBounds();
		moved.setElementId(SEARCH);
		moved.setNewPosition(GraphUtil.point(node.getPosition().getX() + 60, 91));
		moved.setNewSize(GraphUtil.dimension(node.getSize().getWidth(), node.getSize().getHeight()));
		graph = session.graphAfter(new ChangeBoundsOperation(List.of(moved)));
		assertNotNull(editorSaveParticipant, "the session asked to be part of the editor's saves");
		// the editor's Save (the tree's, or the menu's): the model, then its participants
		StatechartResources.save(model, folder.resolve("Goalie.stct"));
		editorSaveParticipant.write();
		Model saved = StatechartResources.load(folder.resolve("Goalie.stct"));
		assertEquals(91, NotationFiles.open(folder.resolve("Goalie.stct"), saved).notation().get((Node) saved.eResource().getEObject(SEARCH)).y(), 0.1);
		session.close();
		long end = System.currentTimeMillis() + 5000;
		while (!closed && System.currentTimeMillis() < end) {
			Thread.sleep(10);
		}
		assertTrue(closed, "the session let go of the editor's model when it ended");
		assertSame(model, editorSources.open(folder.resolve("Goalie.stct")).model());
	}
}
