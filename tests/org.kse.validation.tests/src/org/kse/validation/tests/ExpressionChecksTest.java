package org.kse.validation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.kse.messages.StandardMessages;
import org.kse.validation.ExpressionChecks;

/** One expression checked on its own, as the expression editor does while it is typed. */
class ExpressionChecksTest {

	@Test
	void aCorrectGuardHasNoProblem() {
		assertEquals(List.of(), ExpressionChecks.check(
				"[worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING && behavior.State.HeadToBMessage.ballfound()>0]/TimeoutAction.behavior.250",
				StandardMessages.catalog()));
	}

	@Test
	void anUnknownFieldIsReportedWhereItIs() {
		String guard = "[worldstate.State.GameStateMessage.no_such_field()==1]";
		List<ExpressionChecks.Problem> problems = ExpressionChecks.check(guard, StandardMessages.catalog());
		assertEquals(1, problems.size(), problems::toString);
		ExpressionChecks.Problem problem = problems.get(0);
		assertTrue(problem.error());
		assertEquals(1, problem.line());
		assertTrue(problem.message().contains("no_such_field"), problem.message());
		assertEquals(guard.indexOf("no_such_field"), problem.offset(), problem::toString);
	}

	@Test
	void aSyntaxErrorOnTheSecondLineHasItsLineAndColumn() {
		List<ExpressionChecks.Problem> problems = ExpressionChecks.check("[a==1 &&\n && b==2]", StandardMessages.catalog());
		assertTrue(!problems.isEmpty());
		ExpressionChecks.Problem problem = problems.get(0);
		assertEquals(2, problem.line(), problem::toString);
		assertEquals(2, problem.column(), problem::toString);
		assertEquals("[a==1 &&\n ".length(), problem.offset());
	}

	/** The Properties view and the diagram check an expression through here: an event is refused where it is. */
	@Test
	void anEventIsAnErrorAtItsPositionInEveryForm() {
		for (String expression : List.of("Ev[behavior.State.FallMessage.fall()!=0]", "Ev/TimeoutAction.behavior.100", "Ev", "[behavior.State.FallMessage==NULL]\n",
				"  \n\tEv [behavior.State.FallMessage==NULL]")) {
			List<ExpressionChecks.Problem> problems = ExpressionChecks.check(expression, StandardMessages.catalog());
			if (!expression.contains("Ev")) {
				assertEquals(List.of(), problems, expression);
				continue;
			}
			assertEquals(1, problems.size(), () -> expression + ": " + problems);
			ExpressionChecks.Problem problem = problems.get(0);
			assertTrue(problem.error(), problem::toString);
			assertEquals(ExpressionChecks.Kind.UNSUPPORTED, problem.kind());
			assertEquals(expression.indexOf("Ev"), problem.offset(), problem::toString);
			assertEquals(expression.startsWith(" ") ? 2 : 1, problem.line(), problem::toString);
			assertEquals(expression.startsWith(" ") ? 2 : 1, problem.column(), problem::toString);
			assertTrue(problem.message().startsWith("events are not supported: the engine never raises 'Ev', so this transition would never fire"),
					problem.message());
			assertTrue(problem.message().contains("say in the condition what to wait for instead"), problem.message());
		}
	}

	@Test
	void misspeltNamesGetTheNearestKnownOne() {
		assertEquals("1:2: unknown topic 'wordstate'; did you mean 'worldstate'?",
				ExpressionChecks.check("[wordstate.State.GameStateMessage==NULL]", StandardMessages.catalog()).get(0).toString());
		assertEquals("1:17: unknown message type 'FallMesage'; did you mean 'FallMessage'?",
				ExpressionChecks.check("[behavior.State.FallMesage==NULL]", StandardMessages.catalog()).get(0).toString());
		assertEquals("1:36: 'GameStateMessage' has no field 'player_sate'; did you mean 'player_state'?",
				ExpressionChecks.check("[worldstate.State.GameStateMessage.player_sate()==1]", StandardMessages.catalog()).get(0).toString());
		String far = ExpressionChecks.check("[teamplay.State.GameStateMessage==NULL]", StandardMessages.catalog()).get(0).message();
		assertTrue(far.startsWith("unknown topic 'teamplay'; known topics: behavior, worldstate"), "no guess when nothing is close: " + far);
	}

	@Test
	void anEmptyExpressionIsFine() {
		assertEquals(List.of(), ExpressionChecks.check("", StandardMessages.catalog()));
		assertEquals(List.of(), ExpressionChecks.check(null, StandardMessages.catalog()));
	}
}
