package org.kse.formula.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Set;
import java.util.TreeSet;

import org.junit.jupiter.api.Test;
import org.kse.formula.StatechartToFormula;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.testing.Models;

/**
 * The models the Kouretes team edited in the original tool: what their formulas were when they
 * last saved them. The Goalie's chart lost its Init state and gained guards and timers on most
 * transitions; the formulas say the first and list the second, state by state.
 */
class LegacyFormulaTest {

	@Test
	void theLegacyGoalieGivesItsFormulasWithoutInitAndListsEveryGuard() throws IOException {
		Model goalie = StatechartResources.load(Models.legacy("Goalie/Goalie.stct"));
		StatechartToFormula.Result result = StatechartToFormula.recover(goalie);
		print("Goalie", result);

		assertEquals("""
				Goalie
				goalie = (playing | nonPlaying)+
				playing = Scan+ | ApproachBall+ | Kick | followBall
				followBall = Stare+.[SpecialAction]
				nonPlaying = NoPlay.[GoToPosition+]
				""", result.fileText());
		// one problem per state that has a guarded transition, and nothing else
		Set<String> labels = new TreeSet<>();
		result.problems().forEach(problem -> labels.add(problem.label()));
		assertEquals(RoundTrips.guardedSources(goalie), labels, result.problems()::toString);
		assertTrue(result.problems().stream().allMatch(problem -> problem.message().startsWith("its transition to ")), result.problems()::toString);
		StatechartToFormula.Problem timer = result.problems().stream().filter(problem -> problem.label().equals("0.3.2.3.3.1")).findFirst().orElseThrow();
		assertEquals("0.3.2.3.3.1", timer.name());
		assertEquals("its transition to 0.3.2.3.3.2 (Scan) has the expression '/TimeoutAction.behavior.250': a formula has no guards, events,"
				+ " timers or actions, so it keeps the transition without it", timer.message());

		// the formulas are the ones kse transform reads; the team's chart had (playing | nonPlaying)+ one level
		// deeper than the transformation lays out a whole right side, which changes nothing a robot does
		Model again = RoundTrips.transform(result.fileText());
		assertEquals("Goalie", again.getName());
		assertEquals("goalie", again.getNodes().get(0).getName());
		assertEquals(Models.allNodes(goalie).stream().filter(node -> node.getType().equals("BASIC")).map(node -> node.getName()).sorted().toList(),
				Models.allNodes(again).stream().filter(node -> node.getType().equals("BASIC")).map(node -> node.getName()).sorted().toList());
	}

	@Test
	void everyLegacyModelGivesFormulasThatReadBack() throws IOException {
		for (Path file : Models.legacyModels()) {
			Model model = StatechartResources.load(file);
			StatechartToFormula.Result result = StatechartToFormula.recover(model);
			print(file.getFileName().toString(), result);
			assertFalse(result.formulas().isEmpty(), file::toString);
			assertTrue(result.problems().stream().noneMatch(problem -> problem.message().contains("do not read back")), () -> file + "\n" + result.problems());
			RoundTrips.transform(result.fileText());
		}
	}

	/** What the note of issue 20 shows: the formulas recovered and what they leave out. */
	private static void print(String model, StatechartToFormula.Result result) {
		System.out.println("   " + model + ": formulas recovered");
		System.out.print(result.fileText());
		System.out.println("   " + model + ": " + result.problems().size() + " problems");
		result.problems().forEach(problem -> System.out.println("  " + problem));
	}
}
