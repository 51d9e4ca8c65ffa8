package org.kse.model.tests;

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

	@Test
	void anEmptyExpressionIsFine() {
		assertEquals(List.of(), ExpressionChecks.check("", StandardMessages.catalog()));
		assertEquals(List.of(), ExpressionChecks.check(null, StandardMessages.catalog()));
	}
}
