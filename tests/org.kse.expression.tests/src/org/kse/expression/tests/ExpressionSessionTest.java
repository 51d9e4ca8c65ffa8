package org.kse.expression.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.kse.expression.ExpressionParser;
import org.kse.expression.transitionExpression.MessageAccess;
import org.kse.testing.Issues;
import org.kse.testing.ParserFuzz;
import org.kse.testing.ParserFuzz.Outcome;

/**
 * A parse session, which a validation and a generation share so that each expression of a model
 * is parsed once per run: the same issues as parsing each text on its own, every text parsed
 * once, and what it parsed still readable after the texts that came later.
 */
class ExpressionSessionTest {

	/** Clean, warned, broken and misspelt expressions, and the whole legacy Goalie. */
	private static List<String> texts() {
		List<String> texts = new ArrayList<>(List.of( //
				"[worldstate.State.GameStateMessage==NULL || worldstate.State.GameStateMessage.player_state()!=PLAYER_PLAYING]", //
				"[a==1 && TimeoutCheck(behavior)]", // a warning
				"[a==1", // a syntax error at the end
				"[a==1 ||\n  worldstate.Stat.M==NULL]", // an error on the second line
				"[TimeoutCheck(behavior.State.M)]/TimeoutAction.behavior.10", //
				"/publish.behavior.State.FallMessage.set_fall()", //
				"/TimeoutAction.behavior.0", //
				"Ev[a==1]/process_messages", //
				"[a==1 &&\r\n b<>1]"));
		texts.addAll(Legacy.goalieTransitionExpressions());
		return texts;
	}

	@Test
	void aSessionReportsWhatParsingEachTextAloneReports() {
		ExpressionParser.Session session = ExpressionParser.session();
		for (String text : texts()) {
			ExpressionParser.Result alone = ExpressionParser.parse(text);
			ExpressionParser.Result shared = session.parse(text);
			assertEquals(describeAll(alone.issues()), describeAll(shared.issues()), text);
			assertEquals(alone.expression() == null, shared.expression() == null, text);
		}
	}

	@Test
	void eachTextIsParsedOnceAndItsResultHandedOutAgain() {
		ExpressionParser.Session session = ExpressionParser.session();
		List<String> texts = texts();
		List<ExpressionParser.Result> first = texts.stream().map(session::parse).toList();
		int distinct = (int) texts.stream().distinct().count();
		assertEquals(distinct, session.parsed());
		for (int i = 0; i < texts.size(); i++) {
			assertSame(first.get(i), session.parse(texts.get(i)), texts.get(i));
			// an equal text that is another String object is the same expression too
			assertSame(first.get(i), session.parse(new String(texts.get(i).toCharArray())), texts.get(i));
		}
		assertEquals(distinct, session.parsed());
	}

	@Test
	void blankTextsAreNotParsed() {
		ExpressionParser.Session session = ExpressionParser.session();
		for (String blank : new String[] { null, "", "  \n\t" }) {
			assertNull(session.parse(blank).expression());
			assertEquals(List.of(), session.parse(blank).issues());
		}
		assertEquals(0, session.parsed());
	}

	/**
	 * A session keeps one resource set for all its texts; each text's resource leaves it once
	 * parsed, so the set does not grow, and what was parsed stays whole: its node model (which
	 * gives the checks their positions) still reads the text it came from.
	 */
	@Test
	void earlierResultsStayReadableAndTheResourceSetDoesNotGrow() {
		ExpressionParser.Session session = ExpressionParser.session();
		String text = "[worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING]";
		ExpressionParser.Result early = session.parse(text);
		for (String later : texts()) {
			session.parse(later);
		}
		assertNotNull(early.expression().eResource(), "the parsed expression keeps its resource");
		assertNull(early.expression().eResource().getResourceSet(), "the resource left the session's resource set");
		MessageAccess access = firstMessageAccess(early.expression());
		assertEquals("GameStateMessage", access.getMessage());
		ICompositeNode node = NodeModelUtils.findActualNodeFor(access);
		assertNotNull(node, "the node model is still attached");
		assertEquals("worldstate.State.GameStateMessage.player_state()", node.getText().strip());
		assertEquals(1, node.getOffset());
	}

	/** A parse that overflows the stack is an error, and the session parses normally afterwards. */
	@Test
	void aSessionSurvivesTooDeepNesting() throws InterruptedException {
		ExpressionParser.Session session = ExpressionParser.session();
		String deep = "[" + "(".repeat(5000) + "a" + ")".repeat(5000) + "]";
		String normal = "[TimeoutCheck(behavior) && a.State.M==NULL]/publish_all";
		List<Outcome> outcomes = ParserFuzz.parseOnSmallStack(text -> {
			ExpressionParser.Result result = session.parse(text);
			return new Outcome(result.hasErrors(), result.expression() != null, result.issues(), false);
		}, List.of(deep, normal));
		assertTrue(outcomes.get(0).hasErrors(), "no error for nesting 5000 deep");
		assertEquals(List.of(), outcomes.get(1).issues());
		assertNotNull(session.parse(normal).expression());
	}

	private static String describeAll(List<Issue> issues) {
		return Issues.describe(issues) + issues.stream().map(issue -> " @" + issue.getOffset() + "+" + issue.getLength()).toList();
	}

	private static MessageAccess firstMessageAccess(EObject root) {
		for (var it = root.eAllContents(); it.hasNext();) {
			if (it.next() instanceof MessageAccess access) {
				return access;
			}
		}
		throw new AssertionError("no message access in " + root);
	}
}
