package org.kse.expression.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.kse.testing.Issues.assertIssue;
import static org.kse.testing.Issues.assertNoErrors;
import static org.kse.testing.Issues.assertNoIssues;
import static org.kse.testing.Issues.assertOnlyError;
import static org.kse.testing.Issues.describe;

import java.util.List;
import java.util.stream.Stream;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.kse.expression.ExpressionParser;
import org.kse.expression.transitionExpression.Binary;
import org.kse.expression.transitionExpression.Call;
import org.kse.expression.transitionExpression.Constant;
import org.kse.expression.transitionExpression.MessageAccess;
import org.kse.expression.transitionExpression.Not;
import org.kse.expression.transitionExpression.NumberLiteral;
import org.kse.expression.transitionExpression.ProcessMessages;
import org.kse.expression.transitionExpression.Publish;
import org.kse.expression.transitionExpression.PublishAll;
import org.kse.expression.transitionExpression.StringLiteral;
import org.kse.expression.transitionExpression.TimeoutAction;
import org.kse.expression.transitionExpression.TransitionExpression;
import org.kse.expression.validation.TransitionExpressionValidator;
import org.kse.testing.Issues;

/** Transition expressions {@code event[condition]/actions} (docs/original-kse.md §6). */
class ExpressionGrammarTest {

	private static TransitionExpression parseClean(String text) {
		ExpressionParser.Result result = ExpressionParser.parse(text);
		assertNoIssues(text, result.issues());
		assertNotNull(result.expression());
		return result.expression();
	}

	// ---------------------------------------------------------------- the legacy Goalie

	static Stream<String> legacyExpressions() {
		return Legacy.goalieTransitionExpressions().stream();
	}

	@Test
	void theLegacyGoalieHasItsTransitionExpressions() {
		List<String> expressions = Legacy.goalieTransitionExpressions();
		assertEquals(32, expressions.size());
		// XML escapes are undone: '&amp;&amp;' is '&&' and '&#xA;' a line break
		assertTrue(expressions.stream().anyMatch(text -> text.contains("&&\n")), () -> String.join("\n", expressions));
		assertTrue(expressions.stream().noneMatch(text -> text.contains("&amp;")));
	}

	@ParameterizedTest
	@MethodSource("legacyExpressions")
	void everyLegacyExpressionParsesWithoutError(String text) {
		ExpressionParser.Result result = ExpressionParser.parse(text);
		assertNoErrors(text, result.issues());
		assertFalse(result.hasErrors());
		assertNotNull(result.expression(), text);
		// every legacy expression has a condition or an action, and the parser kept it
		TransitionExpression expression = result.expression();
		assertTrue(expression.getCondition() != null || !expression.getActions().isEmpty(), text);
		assertEquals(text.contains("["), expression.getCondition() != null, text);
		assertEquals(text.contains("/"), !expression.getActions().isEmpty(), text);
	}

	@Test
	void theReferenceExampleParsesIntoItsParts() {
		TransitionExpression expression = parseClean("[TimeoutCheck(behavior) && worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING"
				+ " && (behavior.State.HeadToBMessage==NULL || behavior.State.HeadToBMessage.ballfound()==0)]/TimeoutAction.behavior.250");
		assertNull(expression.getEvent());
		// && is left-associative: ((TimeoutCheck && ==) && (...))
		Binary and = assertInstanceOf(Binary.class, expression.getCondition());
		assertEquals("&&", and.getOperator());
		Binary leftAnd = assertInstanceOf(Binary.class, and.getLeft());
		Call check = assertInstanceOf(Call.class, leftAnd.getLeft());
		assertEquals("TimeoutCheck", check.getFunction());
		assertEquals("behavior", assertInstanceOf(Constant.class, check.getArguments().get(0)).getName());
		Binary playing = assertInstanceOf(Binary.class, leftAnd.getRight());
		assertEquals("==", playing.getOperator());
		MessageAccess state = assertInstanceOf(MessageAccess.class, playing.getLeft());
		assertEquals(List.of("worldstate", "State", "GameStateMessage"), List.of(state.getTopic(), state.getKind(), state.getMessage()));
		assertEquals("player_state", state.getMembers().get(0).getName());
		assertEquals("PLAYER_PLAYING", assertInstanceOf(Constant.class, playing.getRight()).getName());
		Binary or = assertInstanceOf(Binary.class, and.getRight());
		assertEquals("||", or.getOperator());
		TimeoutAction timeout = assertInstanceOf(TimeoutAction.class, expression.getActions().get(0));
		assertEquals("behavior", timeout.getTopic());
		assertEquals(250, timeout.getMilliseconds());
	}

	// ---------------------------------------------------------------- the parts

	@ParameterizedTest
	@ValueSource(strings = { "", " ", "\t\n  " })
	void emptyExpressionIsAlwaysTrue(String text) {
		ExpressionParser.Result result = ExpressionParser.parse(text);
		assertNull(result.expression());
		assertTrue(result.issues().isEmpty(), () -> describe(result.issues()));
		assertFalse(result.hasErrors());
	}

	@Test
	void nullExpressionIsAlwaysTrue() {
		ExpressionParser.Result result = ExpressionParser.parse(null);
		assertNull(result.expression());
		assertTrue(result.issues().isEmpty());
	}

	@Test
	void eventOnly() {
		TransitionExpression expression = parseClean("ballSeen");
		assertEquals("ballSeen", expression.getEvent().getName());
		assertNull(expression.getCondition());
		assertTrue(expression.getActions().isEmpty());
	}

	@Test
	void conditionOnly() {
		TransitionExpression expression = parseClean("[worldstate.State.GameStateMessage==NULL]");
		assertNull(expression.getEvent());
		Binary equals = assertInstanceOf(Binary.class, expression.getCondition());
		assertEquals("==", equals.getOperator());
		assertTrue(expression.getActions().isEmpty());
	}

	@Test
	void emptyConditionIsAllowed() {
		TransitionExpression expression = parseClean("[]");
		assertNull(expression.getCondition());
	}

	@Test
	void actionsOnly() {
		TransitionExpression expression = parseClean("/process_messages");
		assertNull(expression.getEvent());
		assertNull(expression.getCondition());
		assertEquals(1, expression.getActions().size());
		assertInstanceOf(ProcessMessages.class, expression.getActions().get(0));
	}

	@Test
	void eventConditionAndActions() {
		TransitionExpression expression = parseClean("fall [ behavior.State.FallMessage.fall() != 0 ] / publish_all ; process_messages");
		assertEquals("fall", expression.getEvent().getName());
		assertEquals("!=", assertInstanceOf(Binary.class, expression.getCondition()).getOperator());
		assertEquals(2, expression.getActions().size());
		assertInstanceOf(PublishAll.class, expression.getActions().get(0));
		assertInstanceOf(ProcessMessages.class, expression.getActions().get(1));
	}

	@Test
	void publishSetsAMember() {
		TransitionExpression expression = parseClean("/publish.behavior.State.FallMessage.set_fall(1)");
		Publish publish = assertInstanceOf(Publish.class, expression.getActions().get(0));
		assertEquals(List.of("behavior", "State", "FallMessage"), List.of(publish.getTopic(), publish.getKind(), publish.getMessage()));
		assertEquals(1, publish.getMembers().size());
		assertEquals("set_fall", publish.getMembers().get(0).getName());
		assertEquals("1", assertInstanceOf(NumberLiteral.class, publish.getMembers().get(0).getArgument()).getValue());
	}

	@Test
	void publishTakesStringsAndNegativeNumbers() {
		Publish text = assertInstanceOf(Publish.class, parseClean("/publish.a.Signal.M.set_text(\"hi \\\" there\")").getActions().get(0));
		assertInstanceOf(StringLiteral.class, text.getMembers().get(0).getArgument());
		Publish number = assertInstanceOf(Publish.class, parseClean("/publish.a.Data.M.set_x(-1.5)").getActions().get(0));
		assertEquals("-1.5", assertInstanceOf(NumberLiteral.class, number.getMembers().get(0).getArgument()).getValue());
	}

	@Test
	void severalActionsSeparatedBySemicolons() {
		TransitionExpression expression = parseClean("/process_messages;publish_all");
		assertEquals(2, expression.getActions().size());
		assertInstanceOf(ProcessMessages.class, expression.getActions().get(0));
		assertInstanceOf(PublishAll.class, expression.getActions().get(1));
		assertEquals(2, parseClean("/process_messages;publish_all;").getActions().size(), "a trailing ';' is allowed");
	}

	@Test
	void timeoutAction() {
		TimeoutAction timeout = assertInstanceOf(TimeoutAction.class, parseClean("/TimeoutAction.behavior.250").getActions().get(0));
		assertEquals("behavior", timeout.getTopic());
		assertEquals(250, timeout.getMilliseconds());
	}

	@Test
	void andBindsTighterThanOr() {
		Binary or = assertInstanceOf(Binary.class, parseClean("[a==1 || b==2 && c==3]").getCondition());
		assertEquals("||", or.getOperator());
		assertEquals("==", assertInstanceOf(Binary.class, or.getLeft()).getOperator());
		assertEquals("&&", assertInstanceOf(Binary.class, or.getRight()).getOperator());
	}

	@Test
	void parenthesesOverridePrecedence() {
		Binary and = assertInstanceOf(Binary.class, parseClean("[(a==1 || b==2) && c==3]").getCondition());
		assertEquals("&&", and.getOperator());
		assertEquals("||", assertInstanceOf(Binary.class, and.getLeft()).getOperator());
	}

	@Test
	void negationAppliesToItsOperand() {
		Binary and = assertInstanceOf(Binary.class, parseClean("[!ballAway(worldstate.Data.WorldInfo) && !!x]").getCondition());
		Not not = assertInstanceOf(Not.class, and.getLeft());
		assertEquals("ballAway", assertInstanceOf(Call.class, not.getOperand()).getFunction());
		assertInstanceOf(Not.class, assertInstanceOf(Not.class, and.getRight()).getOperand());
	}

	@ParameterizedTest
	@ValueSource(strings = { "<", "<=", ">", ">=", "==", "!=" })
	void everyComparisonOperator(String operator) {
		Binary comparison = assertInstanceOf(Binary.class, parseClean("[a.State.M.v() " + operator + " -2]").getCondition());
		assertEquals(operator, comparison.getOperator());
	}

	@Test
	void callsTakeSeveralArguments() {
		Call call = assertInstanceOf(Call.class,
				parseClean("[robotInPosition(worldstate.Data.WorldInfo, behavior.State.PositionMessage)]").getCondition());
		assertEquals("robotInPosition", call.getFunction());
		assertEquals(2, call.getArguments().size());
	}

	// ---------------------------------------------------------------- errors at their position

	@Test
	void unknownMessageKindIsAnErrorAtTheKind() {
		ExpressionParser.Result result = ExpressionParser.parse("[worldstate.Stat.GameStateMessage==NULL]");
		Issue issue = assertOnlyError(result.issues(), TransitionExpressionValidator.BAD_KIND, 1, 13);
		assertEquals(4, issue.getLength());
		assertTrue(result.hasErrors());
	}

	@Test
	void unknownMessageKindInPublishIsAnError() {
		ExpressionParser.Result result = ExpressionParser.parse("/publish.behavior.state.FallMessage.set_fall(1)");
		assertOnlyError(result.issues(), TransitionExpressionValidator.BAD_KIND, 1, 19);
	}

	@Test
	void unbalancedBracketIsAnError() {
		ExpressionParser.Result result = ExpressionParser.parse("[a==1");
		assertTrue(result.hasErrors());
		Issue issue = Issues.errors(result.issues()).get(0);
		assertEquals(Issues.SYNTAX, issue.getCode());
		assertTrue(issue.getMessage().contains("']'"), issue.getMessage());
		assertEquals(1, issue.getLineNumber());
		// reported just past the end of the text, where ']' is missing
		assertEquals(6, issue.getColumn(), () -> describe(result.issues()));
		assertEquals(5, issue.getOffset());
	}

	@ParameterizedTest
	@CsvSource(delimiter = '#', value = { //
			"[a==1]]#7", // one ']' too many
			"[(a==1]#7", // ')' missing before ']'
			"a==1]#2", // '[' missing
			"ev ev2#4", // two events
			"/foo#2", // unknown action
			"[a==1]/publish_all;;#20" })
	void syntaxErrorsAreReportedAtTheirColumn(String text, int column) {
		ExpressionParser.Result result = ExpressionParser.parse(text);
		List<Issue> errors = Issues.errors(result.issues());
		assertFalse(errors.isEmpty(), text);
		assertEquals(Issues.SYNTAX, errors.get(0).getCode());
		assertEquals("1:" + column, errors.get(0).getLineNumber() + ":" + errors.get(0).getColumn(), () -> describe(result.issues()));
	}

	@ParameterizedTest
	@CsvSource(delimiter = '#', value = { //
			"[a<>1]#4", "[a===1]#5", //
			"[worldstate.State.GameStateMessage=NULL]#35", // '=' for '=='
			"[f(x) = 1]#7", "[1 = a]#4", //
			"[a==1 & b==2]#7", "[a==1 and b==2]#7", "[a ==1 | b==2]#8" })
	void badOperatorIsAnErrorAtTheOperator(String text, int column) {
		ExpressionParser.Result result = ExpressionParser.parse(text);
		List<Issue> errors = Issues.errors(result.issues());
		assertFalse(errors.isEmpty(), text);
		assertEquals(Issues.SYNTAX, errors.get(0).getCode());
		assertEquals("1:" + column, errors.get(0).getLineNumber() + ":" + errors.get(0).getColumn(), () -> describe(result.issues()));
	}

	@Test
	void timeoutCheckNeedsATopic() {
		ExpressionParser.Result result = ExpressionParser.parse("[TimeoutCheck()]");
		assertOnlyError(result.issues(), TransitionExpressionValidator.BAD_TIMEOUT_CHECK, 1, 2);
	}

	@Test
	void timeoutCheckTakesATopicNameNotAMessage() {
		ExpressionParser.Result result = ExpressionParser.parse("[TimeoutCheck(behavior.State.M)]/TimeoutAction.behavior.10");
		assertOnlyError(result.issues(), TransitionExpressionValidator.BAD_TIMEOUT_CHECK, 1, 2);
	}

	@Test
	void timeoutCheckNotFirstIsAWarning() {
		ExpressionParser.Result result = ExpressionParser.parse("[a==1 && TimeoutCheck(behavior)]");
		assertIssue(result.issues(), Severity.WARNING, TransitionExpressionValidator.TIMEOUT_CHECK_NOT_FIRST, 1, 10);
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
	}

	@Test
	void timeoutCheckFirstIsFine() {
		parseClean("[TimeoutCheck(behavior) && a==1]");
	}

	@Test
	void publishWithoutSetterValueIsAnError() {
		ExpressionParser.Result result = ExpressionParser.parse("/publish.b.Signal.M.set_x()");
		assertOnlyError(result.issues(), TransitionExpressionValidator.MISSING_SETTER_VALUE, 1, 21);
	}

	@Test
	void zeroTimeoutIsAnError() {
		ExpressionParser.Result result = ExpressionParser.parse("/TimeoutAction.behavior.0");
		assertOnlyError(result.issues(), TransitionExpressionValidator.BAD_TIMEOUT, 1, 25);
	}

	@Test
	void errorOnTheSecondLineReportsLineTwoAndItsColumn() {
		ExpressionParser.Result result = ExpressionParser.parse("[a==1 ||\n  worldstate.Stat.M==NULL]");
		Issue issue = assertOnlyError(result.issues(), TransitionExpressionValidator.BAD_KIND, 2, 14);
		assertEquals("[a==1 ||\n  ".length() + "worldstate.".length(), issue.getOffset());
	}

	@Test
	void syntaxErrorOnTheSecondLineReportsLineTwoAndItsColumn() {
		for (String newline : List.of("\n", "\r\n")) {
			ExpressionParser.Result result = ExpressionParser.parse("[a==1 &&" + newline + " b<>1]");
			List<Issue> errors = Issues.errors(result.issues());
			assertFalse(errors.isEmpty());
			assertEquals("2:4", errors.get(0).getLineNumber() + ":" + errors.get(0).getColumn(), () -> describe(result.issues()));
		}
	}

	@Test
	void legacyStyleMultiLineConditionWithAnErrorOnLineTwo() {
		String text = "[TimeoutCheck(behavior) && \n worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING && behavior.Sate.HeadToBMessage.ballfound()>0]";
		ExpressionParser.Result result = ExpressionParser.parse(text);
		assertOnlyError(result.issues(), TransitionExpressionValidator.BAD_KIND, 2, 79);
	}
}
