package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.glsp.graph.GGraph;
import org.eclipse.glsp.graph.GModelElement;
import org.eclipse.glsp.graph.GNode;
import org.eclipse.glsp.graph.util.GraphUtil;
import org.eclipse.glsp.server.actions.SaveModelAction;
import org.eclipse.glsp.server.features.clipboard.RequestClipboardDataAction;
import org.eclipse.glsp.server.features.clipboard.SetClipboardDataAction;
import org.eclipse.glsp.server.features.directediting.ApplyLabelEditOperation;
import org.eclipse.glsp.server.features.popup.RequestPopupModelAction;
import org.eclipse.glsp.server.features.popup.SetPopupModelAction;
import org.eclipse.glsp.server.features.undoredo.RedoAction;
import org.eclipse.glsp.server.features.undoredo.UndoAction;
import org.eclipse.glsp.server.features.validation.SetMarkersAction;
import org.eclipse.glsp.server.operations.ChangeBoundsOperation;
import org.eclipse.glsp.server.operations.ChangeContainerOperation;
import org.eclipse.glsp.server.operations.ChangeRoutingPointsOperation;
import org.eclipse.glsp.server.operations.CompoundOperation;
import org.eclipse.glsp.server.operations.CreateEdgeOperation;
import org.eclipse.glsp.server.operations.CreateNodeOperation;
import org.eclipse.glsp.server.operations.DeleteOperation;
import org.eclipse.glsp.server.operations.LayoutOperation;
import org.eclipse.glsp.server.operations.PasteOperation;
import org.eclipse.glsp.server.types.EditorContext;
import org.eclipse.glsp.server.types.ElementAndBounds;
import org.eclipse.glsp.server.types.ElementAndRoutingPoints;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.StatechartGraph;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.notation.Notation;
import org.kse.notation.NotationFiles;

/**
 * Editing the Goalie on the diagram as a user would, through the GLSP protocol: every edit is
 * checked in the graph the client gets and in the files a save writes; the statechart rules
 * refuse edits with a message; undo and redo take edits back whole.
 */
class DiagramEditingTest {

	private static final String ROOT = "//@nodes.0";
	private static final String PLAYING = "//@nodes.0/@Children.1/@Children.1/@Children.2";

	@TempDir
	Path folder;
	private GlspSession session;
	private GGraph graph;

	@BeforeEach
	void open() throws Exception {
		Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), folder.resolve("Goalie.stct"));
		session = new GlspSession(folder);
		graph = session.open("Goalie.stct");
	}

	@AfterEach
	void close() {
		session.close();
	}

	private Model saved() throws Exception {
		// counted by the save's own answer: an edit's dirty state may still be on its way
		int saves = saves();
		session.send(new SaveModelAction());
		long end = System.currentTimeMillis() + 10_000;
		while (saves() == saves && System.currentTimeMillis() < end) {
			Thread.sleep(10);
		}
		assertTrue(saves() > saves, "the save is answered: " + session.kinds());
		return StatechartResources.load(folder.resolve("Goalie.stct"));
	}

	private int saves() {
		return (int) session.all(org.eclipse.glsp.server.actions.SetDirtyStateAction.class).stream()
				.filter(action -> org.eclipse.glsp.server.actions.SetDirtyStateAction.Reason.SAVE.equals(action.getReason().orElse(""))).count();
	}

	private static GNode node(GGraph graph, String id) {
		GModelElement element = StatechartGraph.find(graph, id);
		assertNotNull(element, "the diagram shows " + id);
		return (GNode) element;
	}

	private static CreateNodeOperation create(String type, String container, double x, double y) {
		return new CreateNodeOperation(type, GraphUtil.point(x, y), container);
	}

	private static List<Node> states(Model model) {
		List<Node> states = new ArrayList<>();
		model.eAllContents().forEachRemaining(each -> {
			if (each instanceof Node node) {
				states.add(node);
			}
		});
		return states;
	}

	@Test
	void anOrStateWithAStartABasicAndATransitionIsCreatedAndSaved() throws Exception {
		graph = session.graphAfter(create("state:or", StatechartGraph.ROOT, 900, 40));
		GNode or = node(graph, "//@nodes.1");
		assertEquals("state:or", or.getType());
		assertEquals(900, or.getPosition().getX(), 0.1);
		assertTrue(or.getSize().getWidth() >= 240 && or.getSize().getHeight() >= 160, "a new OR state has room for states: " + or.getSize());
		graph = session.graphAfter(create("state:start", "//@nodes.1", 920, 90));
		graph = session.graphAfter(create("state:basic", "//@nodes.1", 980, 90));
		GNode start = node(graph, "//@nodes.1/@Children.0");
		assertEquals(20, start.getPosition().getX(), 0.1, "placed where dropped, relative to the OR state");
		graph = session.graphAfter(new CreateEdgeOperation("transition", "//@nodes.1/@Children.0", "//@nodes.1/@Children.1"));
		Model model = saved();
		Node created = model.getNodes().get(1);
		assertEquals(List.of("OR", "1"), List.of(created.getType(), created.getLabel()));
		assertEquals(List.of("START", "1.1"), List.of(created.getChildren().get(0).getType(), created.getChildren().get(0).getLabel()));
		assertEquals(List.of("BASIC", "1.2", "NewActivity"),
				List.of(created.getChildren().get(1).getType(), created.getChildren().get(1).getLabel(), created.getChildren().get(1).getName()));
		Transition transition = model.getTransitions().get(model.getTransitions().size() - 1);
		assertEquals(created.getChildren().get(0), transition.getSource());
		assertEquals(created.getChildren().get(1), transition.getTarget());
		Notation notation = NotationFiles.open(folder.resolve("Goalie.stct"), model).notation();
		assertEquals(900, notation.get(created).x(), 0.1, "the positions are saved beside the model");
		assertEquals(80, notation.get(created.getChildren().get(1)).x(), 0.1);
	}

	@Test
	void theStatechartRulesRefuseEditsWithAMessage() throws Exception {
		graph = session.graphAfter(create("state:and", StatechartGraph.ROOT, 900, 40));
		assertTrue(session.refusal(create("state:basic", "//@nodes.1", 920, 90)).contains("an AND state holds only OR regions"));
		graph = session.graphAfter(create("state:or", "//@nodes.1", 920, 90));
		assertEquals("state:or", node(graph, "//@nodes.1/@Children.0").getType(), "an AND state takes OR regions");
		assertTrue(session.refusal(new CreateEdgeOperation("transition", ROOT + "/@Children.1", ROOT + "/@Children.0")).contains("no transition enters a START"));
		assertTrue(session.refusal(create("state:basic", PLAYING + "/@Children.2/@Children.1", 300, 300)).contains("cannot hold other states"),
				"a BASIC state holds nothing");
		assertEquals(2, saved().getNodes().size(), "nothing refused was added");
	}

	@Test
	void aMoveIsUndoneAndRedoneAndItsPositionSaved() throws Exception {
		String id = ROOT + "/@Children.1";
		double x = node(graph, id).getPosition().getX();
		ElementAndBounds moved = new ElementAndBounds();
		moved.setElementId(id);
		moved.setNewPosition(GraphUtil.point(x + 140, 77));
		moved.setNewSize(GraphUtil.dimension(node(graph, id).getSize().getWidth(), node(graph, id).getSize().getHeight()));
		// as a browser sends a move: the bounds with the attached transitions' routes, undone as one
		ElementAndRoutingPoints route = new ElementAndRoutingPoints();
		route.setElementId("//@transitions.0");
		route.setNewRoutingPoints(List.of());
		CompoundOperation move = new CompoundOperation();
		move.setOperationList(List.of(new ChangeBoundsOperation(List.of(moved)), new ChangeRoutingPointsOperation(List.of(route))));
		graph = session.graphAfter(move);
		assertEquals(x + 140, node(graph, id).getPosition().getX(), 0.1);
		graph = session.graphAfter(new UndoAction());
		assertEquals(x, node(graph, id).getPosition().getX(), 0.1, "undone");
		graph = session.graphAfter(new RedoAction());
		assertEquals(x + 140, node(graph, id).getPosition().getX(), 0.1, "redone");
		Model model = saved();
		assertEquals(77, NotationFiles.open(folder.resolve("Goalie.stct"), model).notation().get(model.getNodes().get(0).getChildren().get(1)).y(), 0.1);
	}

	@Test
	void aStateDraggedIntoAnotherCompositeMovesWithItsInsides() throws Exception {
		graph = session.graphAfter(create("state:or", StatechartGraph.ROOT, 900, 40));
		String scanLoop = PLAYING + "/@Children.2";
		int inside = node(graph, scanLoop).getChildren().size();
		graph = session.graphAfter(new ChangeContainerOperation(scanLoop, GraphUtil.point(930, 90), "//@nodes.1"));
		GNode moved = node(graph, "//@nodes.1/@Children.0");
		assertEquals("state:or", moved.getType());
		assertEquals(inside, moved.getChildren().size(), "with its insides");
		assertEquals(30, moved.getPosition().getX(), 0.1);
		assertTrue(session.refusal(new ChangeContainerOperation("//@nodes.1", GraphUtil.point(950, 120), "//@nodes.1/@Children.0"))
				.contains("inside the state itself"), "not into itself");
		Model model = saved();
		assertEquals("Scan_one_or_more_times_", model.getNodes().get(1).getChildren().get(0).getName());
	}

	@Test
	void aStateDroppedOverTheBorderOfItsNewCompositeLandsInsideWithItsTransitionsAndOneUndoTakesItBack() throws Exception {
		graph = session.graphAfter(create("state:or", StatechartGraph.ROOT, 900, 40));
		String scan = PLAYING + "/@Children.2/@Children.1";
		long attached = edgesTouching(graph, scan);
		assertTrue(attached > 0, "Scan has transitions");
		// grabbed in its middle, its corner lies left of and above the composite
		graph = session.graphAfter(new ChangeContainerOperation(scan, GraphUtil.point(880, 20), "//@nodes.1"));
		GNode moved = node(graph, "//@nodes.1/@Children.0");
		assertEquals("Scan", ((org.eclipse.glsp.graph.GLabel) StatechartGraph.find(graph, moved.getId() + "#name")).getText());
		assertEquals(4, moved.getPosition().getX(), 0.1, "inside the composite's left border");
		assertEquals(org.kse.notation.Arrange.HEADER, moved.getPosition().getY(), 0.1, "below the composite's header");
		assertEquals(attached, edgesTouching(graph, moved.getId()), "its transitions come along");
		graph = session.graphAfter(new UndoAction());
		assertEquals("state:basic", node(graph, scan).getType(), "one undo puts it back");
		assertEquals(attached, edgesTouching(graph, scan));
		assertTrue(node(graph, "//@nodes.1").getChildren().stream().noneMatch(GNode.class::isInstance), "and empties the composite");
	}

	@Test
	void aStateIsNotDroppedIntoAStateThatCannotHoldIt() throws Exception {
		String scan = PLAYING + "/@Children.2/@Children.1";
		String kick = PLAYING + "/@Children.4";
		assertTrue(session.refusal(new ChangeContainerOperation(scan, GraphUtil.point(10, 10), kick)).contains("cannot hold other states"));
		graph = session.graphAfter(create("state:and", StatechartGraph.ROOT, 900, 40));
		assertTrue(session.refusal(new ChangeContainerOperation(scan, GraphUtil.point(920, 80), "//@nodes.1")).contains("only OR regions"));
		graph = session.graphAfter(new ChangeContainerOperation(PLAYING + "/@Children.2", GraphUtil.point(920, 80), "//@nodes.1"));
		assertEquals("state:or", node(graph, "//@nodes.1/@Children.0").getType(), "an OR state goes into an AND state");
	}

	private static long edgesTouching(GGraph graph, String stateId) {
		return graph.getChildren().stream().filter(org.eclipse.glsp.graph.GEdge.class::isInstance).map(org.eclipse.glsp.graph.GEdge.class::cast)
				.filter(edge -> stateId.equals(edge.getSourceId()) || stateId.equals(edge.getTargetId())).count();
	}

	@Test
	void deletingAStateDeletesItsInsidesAndEveryTransitionAttached() throws Exception {
		Model before = StatechartResources.load(folder.resolve("Goalie.stct"));
		Node playing = before.getNodes().get(0).getChildren().get(1).getChildren().get(1).getChildren().get(2);
		Set<Node> doomed = new HashSet<>(List.of(playing));
		playing.eAllContents().forEachRemaining(each -> doomed.add((Node) each));
		long attached = before.getTransitions().stream().filter(t -> doomed.contains(t.getSource()) || doomed.contains(t.getTarget())).count();
		graph = session.graphAfter(new DeleteOperation(List.of(PLAYING)));
		Model model = saved();
		assertEquals(states(before).size() - doomed.size(), states(model).size());
		assertEquals(before.getTransitions().size() - attached, model.getTransitions().size());
		assertTrue(model.getTransitions().stream().allMatch(t -> t.getSource() != null && t.getTarget() != null && t.getSource().eResource() != null
				&& t.getTarget().eResource() != null), "no transition dangles");
		graph = session.graphAfter(new UndoAction());
		assertEquals(states(before).size(), states(saved()).size(), "one undo brings everything back");
	}

	@Test
	void namesAndExpressionsAreEditedInPlaceWithTheirChecks() throws Exception {
		String scan = PLAYING + "/@Children.2/@Children.1";
		assertEquals("Scan", ((org.eclipse.glsp.graph.GLabel) StatechartGraph.find(graph, scan + "#name")).getText());
		assertTrue(session.refusal(new ApplyLabelEditOperation(scan + "#name", "9Scan")).contains("C++ class name"));
		graph = session.graphAfter(new ApplyLabelEditOperation(scan + "#name", "ScanField"));
		assertEquals("ScanField", ((org.eclipse.glsp.graph.GLabel) StatechartGraph.find(graph, scan + "#name")).getText(), session.kinds());
		Model model = StatechartResources.load(folder.resolve("Goalie.stct"));
		int guarded = 0;
		while (model.getTransitions().get(guarded).getTE() == null || model.getTransitions().get(guarded).getTE().isBlank()
				|| model.getTransitions().get(guarded).getTE().strip().contains("\n")) {
			guarded++;
		}
		String other = model.getTransitions().get(guarded).getTE().strip();
		String id = "//@transitions." + (guarded == 0 ? 1 : 0);
		String problem = session.refusal(new ApplyLabelEditOperation(id + "#expression", "[player_state(=]"));
		assertTrue(problem.matches("(?s).*\\b1:\\d+: .*"), "an expression error names its line and column: " + problem);
		graph = session.graphAfter(new ApplyLabelEditOperation(id + "#expression", other));
		Model edited = saved();
		assertEquals("ScanField", edited.getNodes().get(0).getChildren().get(1).getChildren().get(1).getChildren().get(2).getChildren().get(2).getChildren().get(1).getName());
		assertEquals(other, edited.getTransitions().get(guarded == 0 ? 1 : 0).getTE().strip());
		// a guard broken over two lines is edited whole, not line by line
		int multiLine = 0;
		while (edited.getTransitions().get(multiLine).getTE() == null || !edited.getTransitions().get(multiLine).getTE().strip().contains("\n")) {
			multiLine++;
		}
		String rejoined = edited.getTransitions().get(multiLine).getTE().strip().replace("\n", " ").replace("==0", "==1");
		session.graphAfter(new ApplyLabelEditOperation("//@transitions." + multiLine + "#expression", rejoined));
		assertEquals(rejoined, saved().getTransitions().get(multiLine).getTE());
	}

	@Test
	void aCopiedCompositeIsPastedRelabelledWithItsTransitions() throws Exception {
		Model before = StatechartResources.load(folder.resolve("Goalie.stct"));
		Node playing = before.getNodes().get(0).getChildren().get(1).getChildren().get(1).getChildren().get(2);
		int[] inside = { 0 };
		playing.eAllContents().forEachRemaining(each -> inside[0]++);
		EditorContext selection = new EditorContext();
		selection.setSelectedElementIds(List.of(PLAYING));
		int copies = session.count(SetClipboardDataAction.class);
		session.send(new RequestClipboardDataAction(selection));
		Map<String, String> clipboard = session.next(SetClipboardDataAction.class, copies).getClipboardData();
		assertTrue(clipboard.get("text/plain").contains("playing"), clipboard.toString());
		PasteOperation paste = new PasteOperation();
		paste.setClipboardData(clipboard);
		EditorContext target = new EditorContext();
		target.setSelectedElementIds(List.of(ROOT));
		paste.setEditorContext(target);
		graph = session.graphAfter(paste);
		Model model = saved();
		Node root = model.getNodes().get(0);
		Node pasted = root.getChildren().get(root.getChildren().size() - 1);
		String label = "0." + root.getChildren().size();
		assertEquals(label, pasted.getLabel(), "the next free label of the root");
		assertEquals("playing", pasted.getName());
		List<String> labels = states(model).stream().map(Node::getLabel).toList();
		assertEquals(labels.size(), new HashSet<>(labels).size(), "labels stay unique: " + labels);
		pasted.eAllContents().forEachRemaining(each -> assertTrue(((Node) each).getLabel().startsWith(label + "."), "relabelled below the pasted state"));
		assertEquals(inside[0] + 1, states(model).size() - states(before).size());
		long inner = model.getTransitions().stream().filter(t -> t.getSource().getLabel().startsWith(label + ".") && t.getTarget().getLabel().startsWith(label + ".")).count();
		assertTrue(inner > 0, "the inner transitions come along");
		assertNotNull(NotationFiles.open(folder.resolve("Goalie.stct"), model).notation().get(pasted), "drawn where it was pasted");
	}

	@Test
	void aCompositeGrowsToHoldWhatIsPastedOrMovedIntoIt() throws Exception {
		graph = session.graphAfter(create("state:or", StatechartGraph.ROOT, 1400, 40));
		GNode box = node(graph, "//@nodes.1");
		double width = box.getSize().getWidth();
		double height = box.getSize().getHeight();
		EditorContext selection = new EditorContext();
		selection.setSelectedElementIds(List.of(PLAYING));
		int copies = session.count(SetClipboardDataAction.class);
		session.send(new RequestClipboardDataAction(selection));
		PasteOperation paste = new PasteOperation();
		paste.setClipboardData(session.next(SetClipboardDataAction.class, copies).getClipboardData());
		EditorContext target = new EditorContext();
		target.setSelectedElementIds(List.of("//@nodes.1"));
		paste.setEditorContext(target);
		graph = session.graphAfter(paste);
		GNode pasted = node(graph, "//@nodes.1/@Children.0");
		GNode grown = node(graph, "//@nodes.1");
		assertTrue(pasted.getSize().getWidth() > width, "the pasted state is larger than the new box: the test means something");
		assertTrue(grown.getSize().getWidth() >= pasted.getPosition().getX() + pasted.getSize().getWidth()
				&& grown.getSize().getHeight() >= pasted.getPosition().getY() + pasted.getSize().getHeight(),
				"the box grew to hold the pasted state: " + grown.getSize() + " holds " + pasted.getPosition() + " " + pasted.getSize());
		assertEquals(box.getPosition().getX(), grown.getPosition().getX(), 0.1, "it grows to the right and down only");
		graph = session.graphAfter(new UndoAction());
		assertEquals(width, node(graph, "//@nodes.1").getSize().getWidth(), 0.1, "one undo takes the paste and the growth back");
		assertEquals(height, node(graph, "//@nodes.1").getSize().getHeight(), 0.1);

		String inner = ROOT + "/@Children.1";
		double rootWidth = node(graph, ROOT).getSize().getWidth();
		ElementAndBounds moved = new ElementAndBounds();
		moved.setElementId(inner);
		moved.setNewPosition(GraphUtil.point(rootWidth + 50, 60));
		graph = session.graphAfter(new ChangeBoundsOperation(List.of(moved)));
		assertTrue(node(graph, ROOT).getSize().getWidth() >= rootWidth + 50 + node(graph, inner).getSize().getWidth(),
				"a state dragged past its composite's border widens it");
	}

	@Test
	void arrangeAllPlacesTheStatesAnewAsOneUndoableStep() throws Exception {
		String id = ROOT + "/@Children.1";
		ElementAndBounds moved = new ElementAndBounds();
		moved.setElementId(id);
		moved.setNewPosition(GraphUtil.point(700, 500));
		graph = session.graphAfter(new ChangeBoundsOperation(List.of(moved)));
		graph = session.graphAfter(new LayoutOperation(List.of()));
		assertNotEquals(700, node(graph, id).getPosition().getX(), 0.1);
		graph = session.graphAfter(new UndoAction());
		assertEquals(700, node(graph, id).getPosition().getX(), 0.1);
	}

	@Test
	void problemsAreMarkedOnTheirStatesAndTheWholeExpressionShowsOnHover() throws Exception {
		int markers = session.count(SetMarkersAction.class);
		graph = session.graphAfter(create("state:or", StatechartGraph.ROOT, 900, 40));
		SetMarkersAction marked = session.next(SetMarkersAction.class, markers);
		assertTrue(marked.getMarkers().stream().anyMatch(marker -> marker.getElementId().equals("//@nodes.1") && marker.getType().equals("error")),
				() -> "the empty OR state is marked: " + marked.getMarkers().stream().map(m -> m.getElementId() + " " + m.getDescription()).toList());
		Model model = StatechartResources.load(folder.resolve("Goalie.stct"));
		int longest = 0;
		for (int i = 0; i < model.getTransitions().size(); i++) {
			String te = model.getTransitions().get(i).getTE();
			if (te != null && te.length() > (model.getTransitions().get(longest).getTE() == null ? 0 : model.getTransitions().get(longest).getTE().length())) {
				longest = i;
			}
		}
		int popups = session.count(SetPopupModelAction.class);
		session.send(new RequestPopupModelAction("//@transitions." + longest, GraphUtil.bounds(0, 0, 10, 10)));
		String popup = ((org.eclipse.glsp.graph.GPreRenderedElement) session.next(SetPopupModelAction.class, popups).getNewRoot().getChildren().get(0)).getCode();
		String expected = model.getTransitions().get(longest).getTE().strip().lines().reduce((a, b) -> b).orElseThrow().strip();
		assertTrue(popup.contains(expected.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;")),
				() -> "the whole expression, even its last line '" + expected + "': " + popup);
	}
}
