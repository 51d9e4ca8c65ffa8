package org.kse.formula.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.kse.formula.StatechartToFormula;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.testing.Models;

/**
 * Charts edited by hand after the transformation: the closest formulas, and one problem per
 * state for what they cannot say, naming the state by its label and name.
 */
class HandEditedFormulaTest {

	@Test
	void aTransitionBackAndAGuardGiveTheSequenceAndNameBothStates() {
		Model model = RoundTrips.transform("a = B.C.D");
		transition(model, "0.2", "0.3").setTE("[ballSeen(behavior)]");
		Models.transition(model, Models.byLabel(model, "0.4"), Models.byLabel(model, "0.2"));

		StatechartToFormula.Result result = StatechartToFormula.recover(model);

		assertEquals("a = B.C.D\n", result.fileText());
		assertEquals(List.of(
				"0 (a): its states form none of a formula's shapes (a sequence, a choice, an option, a repetition, a parallel) with its transitions"
						+ " 0.1->0.2 0.2->0.3 0.3->0.4 0.4->0.5 0.4->0.2: written as the sequence B.C.D in the order they are reached from START",
				"0.2 (B): its transition to 0.3 (C) has the expression '[ballSeen(behavior)]': a formula has no guards, events, timers or actions,"
						+ " so it keeps the transition without it"),
				result.problems().stream().map(Object::toString).toList());
	}

	@Test
	void aChoiceKeepsItsBranchesInPriorityOrderAndListsEachGuard() {
		Model model = RoundTrips.transform("a = B | C | D");
		// the user moved D's branch first: the CONDITION tries its transitions in the model's order
		Transition toD = transition(model, "0.2", "0.5");
		model.getTransitions().move(0, toD);
		toD.setTE("[x]");
		transition(model, "0.2", "0.3").setTE("[y]");

		StatechartToFormula.Result result = StatechartToFormula.recover(model);

		assertEquals("a = D | B | C\n", result.fileText());
		assertEquals(List.of("0.2", "0.2"), result.problems().stream().map(StatechartToFormula.Problem::label).toList());
		assertEquals(2, result.problems().stream().map(StatechartToFormula.Problem::message).distinct().count(), "one problem per guard");
	}

	@Test
	void aRenamedStateIsACapabilityOfItsNameAndANameAFormulaCannotHoldIsMadeOne() {
		Model model = RoundTrips.transform("a = X.(B | C).[D.E]");
		Models.byLabel(model, "0.3").setName("searchBall");
		Models.byLabel(model, "0.4").setName("kick it");

		StatechartToFormula.Result result = StatechartToFormula.recover(model);

		assertEquals("a = X.searchBall.kick_it\nsearchBall = B | C\nkick_it = [D.E]\n", result.fileText());
		assertEquals(List.of("0.4 (kick it): 'kick it' is not a formula name: written as the capability kick_it"),
				result.problems().stream().map(Object::toString).toList());
		// a renamed state without other edits round-trips exactly: the transformation names it after its capability
		Model again = RoundTrips.transform(result.fileText());
		assertEquals("searchBall", Models.byLabel(again, "0.3").getName());
		assertEquals(Models.allNodes(model).size(), Models.allNodes(again).size());
	}

	@Test
	void twoStatesOfOneNameWithDifferentContentGetTwoCapabilities() {
		Model model = RoundTrips.transform("a = b.c\nb = X.Y\nc = E | F");
		Models.byLabel(model, "0.3").setName("b");

		StatechartToFormula.Result result = StatechartToFormula.recover(model);

		assertEquals("a = b.b_2\nb = X.Y\nb_2 = E | F\n", result.fileText());
		assertEquals(List.of("0.3 (b): the state 0.2 (b) has the same name and stands for another formula: written as the capability b_2"),
				result.problems().stream().map(Object::toString).toList());
	}

	@Test
	void aTransitionBetweenLevelsAndAStateOfNoShapeAreNamedNotThrown() {
		Model model = Models.model("Keeper");
		Node root = Models.root(model, "keeper", "0", "OR");
		Node start = Models.child(root, "0.1", "0.1", "START");
		Node watch = Models.child(root, "watch", "0.2", "OR");
		Node stare = Models.child(watch, "Stare", "0.2.1", "BASIC");
		Models.child(watch, "Dive", "0.2.2", "BASIC");
		Node end = Models.child(root, "0.3", "0.3", "END");
		Models.transition(model, start, watch);
		Models.transition(model, watch, end);
		Models.transition(model, stare, end, "[ballClose(behavior)]");
		Models.child(root, "", "0.4", "AND");

		StatechartToFormula.Result result = StatechartToFormula.recover(model);

		assertEquals("Keeper\nkeeper = watch.state_0_4\nwatch = Stare.Dive\n", result.fileText());
		String shapes = "its states form none of a formula's shapes (a sequence, a choice, an option, a repetition, a parallel) with ";
		assertEquals(List.of(
				"0 (keeper): " + shapes + "its transitions 0.1->0.2 0.2->0.3: written as the sequence watch.state_0_4 in the order they are reached from START",
				"0.2 (watch): " + shapes + "no transitions between them: written as the sequence Stare.Dive in the order they are reached from START",
				"0.2.1 (Stare): its transition to 0.3 (0.3) has the expression '[ballClose(behavior)]': a formula has no guards, events, timers"
						+ " or actions, so it keeps the transition without it",
				"0.2.1 (Stare): its transition to 0.3 (0.3) goes to another level of the hierarchy: a formula only orders states inside one"
						+ " composite state, so it is left out",
				"0.4 (): '' is not a formula name: written as the activity state_0_4",
				"0.4 (): an AND state that holds no activity or composite state: written as the activity state_0_4"),
				result.problems().stream().map(Object::toString).toList());
	}

	private static Transition transition(Model model, String from, String to) {
		return model.getTransitions().stream().filter(t -> t.getSource().getLabel().equals(from) && t.getTarget().getLabel().equals(to)).findFirst()
				.orElseThrow();
	}
}
