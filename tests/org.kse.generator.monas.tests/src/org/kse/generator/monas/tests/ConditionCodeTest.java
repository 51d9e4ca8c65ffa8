package org.kse.generator.monas.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.expression.ExpressionParser;
import org.kse.generator.monas.ConditionCode;

/**
 * Guards as C++: a term that reads a message is false while the message is missing, also
 * under '!' (its null checks stand outside the negation), while NULL tests keep their meaning.
 */
class ConditionCodeTest {

	private static final String HEAD = "behavior.State.HeadToBMessage";
	private static final String GAME = "worldstate.State.GameStateMessage";

	static Stream<Arguments> conditions() {
		return Stream.of(
				Arguments.of("!" + HEAD + ".ballfound()", "(msg0 != nullptr && !msg0->ballfound())"),
				Arguments.of("!(" + HEAD + ".ballfound()==1)", "(msg0 != nullptr && !(msg0->ballfound() == 1))"),
				Arguments.of("!" + HEAD + ".ballfound()==1", "(msg0 != nullptr && !msg0->ballfound() == 1)"),
				Arguments.of("!ballAway(worldstate.Data.WorldInfo)", "(msg0 != nullptr && !ballAway((*msg0)))"),
				Arguments.of("!robotInPosition(worldstate.Data.WorldInfo, behavior.State.PositionMessage)",
						"(msg0 != nullptr && msg1 != nullptr && !robotInPosition((*msg0), (*msg1)))"),
				Arguments.of("!(" + HEAD + ".ballfound()==1 && " + GAME + ".player_state()==2)",
						"(msg0 != nullptr && msg1 != nullptr && !((msg0->ballfound() == 1) && (msg1->player_state() == 2)))"),
				Arguments.of("!!" + HEAD + ".ballfound()", "(msg0 != nullptr && !!msg0->ballfound())"),
				Arguments.of("!!(" + HEAD + ".ballfound()>0 || " + GAME + "==NULL)",
						"(msg0 != nullptr && !!((msg0->ballfound() > 0) || (msg1 == nullptr)))"),
				Arguments.of(HEAD + "==NULL", "(msg0 == nullptr)"),
				Arguments.of(HEAD + "!=NULL", "(msg0 != nullptr)"),
				Arguments.of("NULL==" + HEAD, "(msg0 == nullptr)"),
				Arguments.of("!(" + HEAD + "==NULL)", "!(msg0 == nullptr)"),
				Arguments.of("!(" + HEAD + "!=NULL)", "!(msg0 != nullptr)"),
				Arguments.of("!!(" + HEAD + "==NULL)", "!!(msg0 == nullptr)"),
				Arguments.of("!" + HEAD, "!(msg0 != nullptr)"),
				Arguments.of("!(" + HEAD + "==NULL || " + HEAD + ".ballfound()==0)",
						"(msg0 != nullptr && !((msg0 == nullptr) || (msg0->ballfound() == 0)))"),
				Arguments.of(HEAD + "==NULL || !" + HEAD + ".ballfound()",
						"((msg0 == nullptr) || (msg0 != nullptr && !msg0->ballfound()))"),
				Arguments.of(HEAD + ".ballfound()>0 && !ballAway(worldstate.Data.WorldInfo)",
						"((msg0 != nullptr && msg0->ballfound() > 0) && (msg1 != nullptr && !ballAway((*msg1))))"),
				Arguments.of("!" + GAME + ".player_state()==PLAYER_PLAYING", "(msg0 != nullptr && !msg0->player_state() == PLAYER_PLAYING)"),
				Arguments.of("!(" + GAME + ".player_state()==PLAYER_PLAYING)", "(msg0 != nullptr && !(msg0->player_state() == PLAYER_PLAYING))"),
				Arguments.of("!true", "!(true)"),
				Arguments.of("!TimeoutCheck(behavior)", "!statechart_engine::TimeoutCheck(*_blk, timeout0)"),
				Arguments.of("TimeoutCheck(behavior) && !" + HEAD + ".ballfound()",
						"(statechart_engine::TimeoutCheck(*_blk, timeout0) && (msg0 != nullptr && !msg0->ballfound()))"));
	}

	@ParameterizedTest(name = "[{0}]")
	@MethodSource("conditions")
	void generates(String condition, String cpp) {
		assertEquals(cpp, translate(new ConditionCode(), condition));
	}

	@Test
	void eachMessageIsReadOnceInOrderOfFirstUseAndTimeoutChecksReadTheirTopicsTimeoutMsg() {
		ConditionCode code = new ConditionCode();
		translate(code, "TimeoutCheck(behavior) && !(" + HEAD + ".ballfound()==1 && " + GAME + ".player_state()==2) && " + HEAD + "!=NULL");
		assertEquals(List.of("timeout0 State TimeoutMsg behavior", "msg0 State HeadToBMessage behavior", "msg1 State GameStateMessage worldstate"),
				code.reads().stream().map(read -> read.variable + " " + read.kind + " " + read.type + " " + read.topic).toList());
		assertEquals(List.of("behavior", "worldstate"), code.topics());
		assertTrue(code.checksTimeouts());
	}

	@Test
	void aGuardWithoutTimeoutCheckDoesNotProcessMessages() {
		ConditionCode code = new ConditionCode();
		translate(code, "!" + HEAD + ".ballfound()");
		assertFalse(code.checksTimeouts());
	}

	private static String translate(ConditionCode code, String condition) {
		ExpressionParser.Result parsed = ExpressionParser.parse("[" + condition + "]");
		assertFalse(parsed.hasErrors(), () -> condition + ": " + parsed.issues());
		return code.translate(parsed.expression().getCondition());
	}
}
