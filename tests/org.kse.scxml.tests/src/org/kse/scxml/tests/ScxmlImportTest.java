package org.kse.scxml.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.common.util.Diagnostic;
import org.junit.jupiter.api.Test;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.scxml.ScxmlImport;
import org.kse.scxml.ScxmlProblem;
import org.kse.validation.ModelValidation;

/**
 * Charts written by other tools, imported: each of SCXML's constructs as the KSE state it becomes
 * (shown by the statechart's outline), and what KSE cannot run named by element and position.
 */
class ScxmlImportTest {

	static final Path DATA = Path.of(System.getProperty("kse.repository", "../.."), "tests", "org.kse.scxml.tests", "data", "import");

	/**
	 * A model as text a person reads: each state indented under its parent as
	 * {@code label TYPE name [activity]} (the name left out when it is the label), then each
	 * transition in the model's order as {@code source -> target expression (name)}.
	 */
	static String outline(Model model) {
		StringBuilder text = new StringBuilder("model ").append(model.getName()).append('\n');
		for (Node root : model.getNodes()) {
			outline(root, 0, text);
		}
		for (Transition transition : model.getTransitions()) {
			text.append(shown(transition.getSource())).append(" -> ").append(shown(transition.getTarget()));
			if (transition.getTE() != null) {
				text.append(' ').append(transition.getTE().isEmpty() ? "\"\"" : transition.getTE());
			}
			text.append(" (").append(transition.getName()).append(")\n");
		}
		return text.toString();
	}

	private static void outline(Node node, int depth, StringBuilder text) {
		text.append("  ".repeat(depth)).append(node.getLabel()).append(' ').append(node.getType());
		if (node.getName() == null || !node.getName().equals(node.getLabel())) {
			text.append(' ').append(node.getName());
		}
		if (node.getActivity() != null) {
			text.append(" activity=").append(node.getActivity());
		}
		text.append('\n');
		for (Node child : node.getChildren()) {
			outline(child, depth + 1, text);
		}
	}

	private static String shown(Node node) {
		return node == null ? "?" : node.getLabel();
	}

	static String problems(ScxmlImport.Result result) {
		return result.problems().stream().map(ScxmlProblem::toString).collect(Collectors.joining("\n"));
	}

	private static ScxmlImport.Result imported(String fixture) throws IOException {
		return ScxmlImport.read(DATA.resolve(fixture));
	}

	/** A model that the validator passes: no error. */
	private static void assertValid(Model model) {
		List<String> errors = ModelValidation.validate(model).getChildren().stream().filter(d -> d.getSeverity() == Diagnostic.ERROR)
				.map(Diagnostic::getMessage).toList();
		assertEquals(List.of(), errors, "validation errors");
	}

	@Test
	void aParallelTrafficLightBecomesAnAndStateWhoseRegionsAreOrStatesAndItsAtomicBeaconGetsARegionOfItsOwn() throws IOException {
		ScxmlImport.Result result = imported("TrafficLight.scxml");

		assertNotNull(result.model(), () -> problems(result));
		assertTrue(result.complete(), () -> problems(result));
		assertEquals("""
				model TrafficLight
				0 OR trafficLight
				  0.1 START
				  0.2 AND Crossing
				    0.2.1 OR Cars
				      0.2.1.1 START
				      0.2.1.2 BASIC CarsRed
				      0.2.1.3 BASIC CarsGreen
				      0.2.1.4 BASIC CarsYellow
				    0.2.2 OR Walkers
				      0.2.2.1 START
				      0.2.2.2 BASIC DontWalk
				      0.2.2.3 BASIC Walk
				    0.2.3 OR
				      0.2.3.1 START
				      0.2.3.2 BASIC Beacon
				  0.3 END
				0.1 -> 0.2 (0.1_TO_Crossing)
				0.2.1.1 -> 0.2.1.2 (0.2.1.1_TO_CarsRed)
				0.2.2.1 -> 0.2.2.2 (0.2.2.1_TO_DontWalk)
				0.2.3.1 -> 0.2.3.2 (0.2.3.1_TO_Beacon)
				0.2.1.2 -> 0.2.1.3 [TimeoutCheck(behavior)] (CarsRed_TO_CarsGreen)
				0.2.1.3 -> 0.2.1.4 [TimeoutCheck(behavior)] (CarsGreen_TO_CarsYellow)
				0.2.1.4 -> 0.2.1.2 [TimeoutCheck(behavior)] (CarsYellow_TO_CarsRed)
				0.2.2.2 -> 0.2.2.3 [behavior.State.HeadToBMessage.ballfound()==1] (DontWalk_TO_Walk)
				0.2.2.3 -> 0.2.2.2 [behavior.State.HeadToBMessage.ballfound()==0] (Walk_TO_DontWalk)
				0.2 -> 0.3 [worldstate.State.GameStateMessage.player_state()==PLAYER_FINISHED] (Crossing_TO_0.3)
				""", outline(result.model()), "the wrapping region is named by its label");
		assertValid(result.model());
	}

	@Test
	void aStartEntersTheChildTheInitialAttributeOrTheInitialElementNamesElseTheFirstChild() throws IOException {
		ScxmlImport.Result result = imported("Initials.scxml");

		assertNotNull(result.model(), () -> problems(result));
		assertTrue(result.complete(), () -> problems(result));
		assertEquals("""
				model Initials
				0 OR initials
				  0.1 START
				  0.2 OR ByAttribute
				    0.2.1 START
				    0.2.3 BASIC First
				    0.2.2 BASIC Second
				  0.3 OR ByElement
				    0.3.1 START
				    0.3.3 BASIC Left
				    0.3.2 BASIC Right
				  0.4 OR ByOrder
				    0.4.1 START
				    0.4.2 BASIC Front
				    0.4.3 BASIC Back
				0.1 -> 0.2 (0.1_TO_ByAttribute)
				0.2.1 -> 0.2.2 (0.2.1_TO_Second)
				0.3.1 -> 0.3.2 (0.3.1_TO_Right)
				0.4.1 -> 0.4.2 (0.4.1_TO_Front)
				0.2.2 -> 0.2.3 [TimeoutCheck(behavior)] (Second_TO_First)
				0.2 -> 0.3 [worldstate.State.GameStateMessage.player_state()==PLAYER_READY] (ByAttribute_TO_ByElement)
				0.3.2 -> 0.3.3 [TimeoutCheck(behavior)] (Right_TO_Left)
				0.3 -> 0.4 [worldstate.State.GameStateMessage.player_state()==PLAYER_SET] (ByElement_TO_ByOrder)
				""", outline(result.model()), "the states keep the document's order; the labels follow the START (kse label)");
		assertValid(result.model());
	}

	@Test
	void finalStatesBecomeOneEndAndDoneStateIsTheCompositesOwnTransitionAndConditionsKeepScxmlsPriority() throws IOException {
		ScxmlImport.Result result = imported("FinalAndDone.scxml");

		assertNotNull(result.model(), () -> problems(result));
		assertTrue(result.complete(), () -> problems(result));
		assertEquals(List.of(), result.problems(), "nothing to say");
		assertEquals("""
				model FinalAndDone
				0 OR finalAndDone
				  0.1 START
				  0.2 OR Approach
				    0.2.1 START
				    0.2.2 BASIC Search
				    0.2.3 END
				  0.3 BASIC Kick
				  0.4 END
				0.1 -> 0.2 (0.1_TO_Approach)
				0.2.1 -> 0.2.2 (0.2.1_TO_Search)
				0.2.2 -> 0.2.3 [TimeoutCheck(behavior)] (Search_TO_0.2.3)
				0.2.2 -> 0.2.3 [behavior.State.HeadToBMessage.ballfound()==1] (Search_TO_0.2.3)
				0.2 -> 0.3 (Approach_TO_Kick)
				0.3 -> 0.4 [TimeoutCheck(behavior)] (Kick_TO_0.4)
				""", outline(result.model()));
		assertValid(result.model());
	}

	@Test
	void compoundStatesNestAsOrStatesAndATransitionMayLeaveFromTheInnermost() throws IOException {
		ScxmlImport.Result result = imported("Nested.scxml");

		assertNotNull(result.model(), () -> problems(result));
		String outline = outline(result.model());
		assertTrue(outline.contains("""
				  0.2 OR Playing
				    0.2.1 START
				    0.2.2 OR Attack
				      0.2.2.1 START
				      0.2.2.2 OR Dribble
				        0.2.2.2.1 START
				        0.2.2.2.2 BASIC Approach
				        0.2.2.2.3 BASIC Push
				    0.2.3 BASIC Defend
				"""), outline);
		assertTrue(outline.contains("0.2.2.2.3 -> 0.2.3 [behavior.State.HeadToBMessage.ballfound()==0] (Push_TO_Defend)"), outline);
		assertEquals(List.of("WARNING <transition target=\"Defend\"> at 11:102: transition 0.2.2.2.3->0.2.3 (Push_TO_Defend): source and target should be in the same composite state"),
				result.problems().stream().map(ScxmlProblem::toString).toList(), "the validator's warning, at the element of the document");
		assertValid(result.model());
	}

	@Test
	void anEventDrivenChartIsRefusedWithAnErrorPerElementNamedByItsIdAndPosition() throws IOException {
		ScxmlImport.Result result = imported("EventDriven.scxml");

		assertNull(result.model(), "no model");
		String all = problems(result);
		List<String> expected = List.of(
				"WARNING <datamodel> at 5:16: left out",
				"ERROR <transition event=\"start\" target=\"Running\"> at 9:53: the event 'start': KSE's engine raises no events (docs/semantics.md, rule 12)",
				"ERROR <state id=\"Running\"> at 11:40: the initial state 'Deep' is not a child but a deeper descendant",
				"ERROR <transition event=\"pause\" target=\"Resume\"> at 16:52: its target 'Resume' is a history state",
				"ERROR <transition target=\"Idle\"> at 17:56: the condition 'count > 3' is not a KSE condition (it reads the data model's 'count'",
				"ERROR <transition event=\"tick\"> at 18:34: a transition without a target",
				"ERROR <transition target=\"Idle Running\"> at 21:44: the transition enters 2 states at once",
				"WARNING <invoke> at 22:71: left out");
		assertEquals(expected.size(), result.problems().size(), all);
		for (int i = 0; i < expected.size(); i++) {
			assertTrue(result.problems().get(i).toString().startsWith(expected.get(i)), "problem " + (i + 1) + " of\n" + all);
		}
	}

	@Test
	void sideEffectsAreLeftOutWithAWarningEachAndTheModelIsStillMade() throws IOException {
		ScxmlImport.Result result = imported("SideEffects.scxml");

		assertNotNull(result.model(), () -> problems(result));
		assertTrue(!result.complete());
		assertEquals(List.of("<datamodel> at 5:16", "<onentry> at 9:18", "<invoke> at 12:71", "<transition target=\"Kick\"> at 13:87", "<onexit> at 18:17"),
				result.leftOut().stream().map(ScxmlProblem::element).toList(), () -> problems(result));
		assertTrue(result.leftOut().get(3).message().startsWith("its <log> left out"), () -> problems(result));
		assertEquals(result.leftOut(), result.problems(), "the validator has nothing to add");
		String outline = outline(result.model());
		assertTrue(outline.contains("0.2 -> 0.3 [behavior.State.HeadToBMessage.ballfound()==1] (Wait_TO_Kick)"), outline);
		assertValid(result.model());
	}

	@Test
	void eachProblemIsPrintedWithTheFileLineAndColumnFirst() {
		assertEquals("chart.scxml:8:50: error: <transition event=\"start\">: the event 'start'",
				ScxmlImport.format("chart.scxml", ScxmlProblem.error("<transition event=\"start\"> at 8:50", "the event 'start'")));
		assertEquals("chart.scxml:3:1: error: not well-formed XML", ScxmlImport.format("chart.scxml", ScxmlProblem.error("the document at 3:1", "not well-formed XML")));
		assertEquals("chart.scxml: state 0.2 (Kick): warning: a warning",
				ScxmlImport.format("chart.scxml", ScxmlProblem.warning("state 0.2 (Kick)", "a warning")));
	}

	@Test
	void aDocumentWhoseRootIsNotScxmlIsRefused() throws IOException {
		ScxmlImport.Result result = ScxmlImport.read(new java.io.ByteArrayInputStream("<?xml version=\"1.0\"?>\n<statechart/>".getBytes()), "Other");

		assertNull(result.model());
		assertEquals("ERROR <statechart> at 2:14: not an SCXML document: its root element is <statechart>, not <scxml> of http://www.w3.org/2005/07/scxml",
				problems(result));
	}

	@Test
	void theKindsOfStateAreKsesKinds() throws IOException {
		Model model = imported("TrafficLight.scxml").model();
		for (var it = model.eAllContents(); it.hasNext();) {
			if (it.next() instanceof Node node) {
				assertNotNull(NodeKind.of(node), node.getName());
			}
		}
	}
}
