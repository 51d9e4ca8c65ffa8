package org.kse.liveness.tests;

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

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.kse.liveness.FormulaLoader;
import org.kse.liveness.Formulas;
import org.kse.liveness.liveness.Expression;
import org.kse.liveness.liveness.Formula;
import org.kse.liveness.liveness.FormulaFile;
import org.kse.liveness.liveness.Group;
import org.kse.liveness.liveness.Operator;
import org.kse.liveness.liveness.Option;
import org.kse.liveness.liveness.Reference;
import org.kse.liveness.liveness.Repetition;
import org.kse.liveness.liveness.RepetitionKind;
import org.kse.liveness.liveness.Replication;
import org.kse.liveness.validation.LivenessValidator;
import org.kse.testing.Issues;
import org.kse.testing.Models;

/** The liveness formula language (docs/original-kse.md §2): what parses, and where every error is reported. */
class LivenessGrammarTest {

	/** The original Goalie.txt, byte for byte: the model name alone on line 1. */
	static final String GOALIE = """
			Goalie
			goalie = Init.(playing | nonPlaying)+
			nonPlaying = NoPlay .[GoToPosition+]
			playing = Scan+ | ApproachBall+ | Kick | followBall
			followBall = Stare+.[SpecialAction]
			""";

	static FormulaLoader.Result load(String text) {
		return FormulaLoader.load(text, URI.createURI("test.liveness"));
	}

	private static FormulaLoader.Result loadClean(String text) {
		FormulaLoader.Result result = load(text);
		assertNoIssues(text, result.issues());
		assertFalse(result.hasErrors());
		assertNotNull(result.file());
		return result;
	}

	private static Formula formula(FormulaFile file, String name) {
		Formula formula = Formulas.capabilities(file).get(name);
		assertNotNull(formula, () -> "no formula '" + name + "'");
		return formula;
	}

	// ---------------------------------------------------------------- valid formulas

	@ParameterizedTest
	@ValueSource(strings = { //
			"a = B.C", "a = B . C . D", "a = B|C", "a = B | C | D", "a = B||C", "a = B || C || D", //
			"a = B*", "a = B+", "a = B~", "a = [B]", "a = (B)", "a = |B~|3 . C", "a = D || |(B.C)~|12", //
			"a = (B.[C|D]*)||(E+ . |F~|2)", "a = ((((B))))", "a = [[B]]", "a = (B|C)+ . [D*] . E~", //
			"a = Xyz_1.Abc_2", "a = B . (C | D) . (E || F)", //
			"a = B+~", "a = |B~|2+", "a = [B]+~", "a = B*+", "a = (B.C)+~", "a = B~~", "a = |(B|C)~|2*", "a = |[B]~|2 . C+*~" })
	void everyOperatorParsesWithoutIssues(String text) {
		FormulaLoader.Result result = loadClean(text);
		assertEquals(1, result.file().getFormulas().size());
		Formula formula = result.file().getFormulas().get(0);
		assertEquals("a", formula.getName());
		// the parse keeps every operator: printing it back gives the right side without blanks
		assertEquals(text.substring("a = ".length()).replace(" ", ""), Formulas.text(formula.getExpression()));
	}

	@Test
	void sequenceChoiceAndParallelAreTheirOperators() {
		assertEquals(List.of(Operator.SEQUENCE, Operator.SEQUENCE), operators("a = B.C.D"));
		assertEquals(List.of(Operator.CHOICE), operators("a = B|C"));
		assertEquals(List.of(Operator.PARALLEL, Operator.PARALLEL), operators("a = B||C||D"));
	}

	private static List<Operator> operators(String text) {
		return loadClean(text).file().getFormulas().get(0).getExpression().getOperators();
	}

	@Test
	void repetitionsOptionGroupAndReplicationBuildTheirTerms() {
		Expression expression = loadClean("a = B* . C+ . D~ . [E] . (F) . |G~|4").file().getFormulas().get(0).getExpression();
		assertEquals(6, expression.getTerms().size());
		assertEquals(RepetitionKind.ZERO_OR_MORE, assertInstanceOf(Repetition.class, expression.getTerms().get(0)).getKind());
		assertEquals(RepetitionKind.ONE_OR_MORE, assertInstanceOf(Repetition.class, expression.getTerms().get(1)).getKind());
		assertEquals(RepetitionKind.FOREVER, assertInstanceOf(Repetition.class, expression.getTerms().get(2)).getKind());
		assertEquals("E", Formulas.text(assertInstanceOf(Option.class, expression.getTerms().get(3)).getExpression()));
		assertEquals("F", Formulas.text(assertInstanceOf(Group.class, expression.getTerms().get(4)).getExpression()));
		Replication replication = assertInstanceOf(Replication.class, expression.getTerms().get(5));
		assertEquals(4, replication.getCount());
		assertEquals("G", assertInstanceOf(Reference.class, replication.getOperand()).getName());
	}

	@Test
	void eachSuffixAppliesToTheTermBuiltBeforeIt() {
		Expression expression = loadClean("a = B+~ . |C~|2+ . [D]*+~").file().getFormulas().get(0).getExpression();
		Repetition forever = assertInstanceOf(Repetition.class, expression.getTerms().get(0));
		assertEquals(RepetitionKind.FOREVER, forever.getKind());
		Repetition oneOrMore = assertInstanceOf(Repetition.class, forever.getOperand());
		assertEquals(RepetitionKind.ONE_OR_MORE, oneOrMore.getKind());
		assertEquals("B", assertInstanceOf(Reference.class, oneOrMore.getOperand()).getName());

		Repetition repeatedCopies = assertInstanceOf(Repetition.class, expression.getTerms().get(1));
		assertEquals(RepetitionKind.ONE_OR_MORE, repeatedCopies.getKind());
		assertEquals(2, assertInstanceOf(Replication.class, repeatedCopies.getOperand()).getCount());

		Repetition outer = assertInstanceOf(Repetition.class, expression.getTerms().get(2));
		Repetition middle = assertInstanceOf(Repetition.class, outer.getOperand());
		Repetition inner = assertInstanceOf(Repetition.class, middle.getOperand());
		assertEquals(List.of(RepetitionKind.FOREVER, RepetitionKind.ONE_OR_MORE, RepetitionKind.ZERO_OR_MORE),
				List.of(outer.getKind(), middle.getKind(), inner.getKind()));
		assertInstanceOf(Option.class, inner.getOperand());
	}

	@Test
	void aSuffixInsideReplicationNeedsBrackets() {
		FormulaLoader.Result result = load("a = |B+~|2");
		Issue error = assertOnlyError(result.issues(), Issues.SYNTAX, 1, 7);
		assertTrue(error.getMessage().contains("|(B+)~|3"), error.getMessage());
		loadClean("a = |(B+)~|2 . C");
	}

	@Test
	void capabilitiesExpandAcrossLines() {
		FormulaFile file = loadClean("a = b . c\nb = X | Y\nc = (Z)+\n").file();
		assertEquals(List.of("a", "b", "c"), file.getFormulas().stream().map(Formula::getName).toList());
		assertEquals("a", Formulas.root(file).getName());
		assertNull(file.getTitle());
	}

	@Test
	void tabsAndSpacesAreBlanks() {
		FormulaFile file = loadClean("\ta\t=  B \t.\tb2\t \n  b2\t= \t[ D |\tE ]  ").file();
		assertEquals("B.b2", Formulas.text(formula(file, "a").getExpression()));
		assertEquals("[D|E]", Formulas.text(formula(file, "b2").getExpression()));
	}

	@Test
	void commentsAndBlankLinesAreIgnored() {
		String text = "// the root\n\na = b // trailing comment\n\n\n   \n// another // one\nb = C.D\n\n";
		FormulaFile file = loadClean(text).file();
		assertEquals(2, file.getFormulas().size());
		assertEquals("C.D", Formulas.text(formula(file, "b").getExpression()));
	}

	@Test
	void windowsLineEndingsAreLineEnds() {
		FormulaFile file = loadClean("a = b\r\nb = C | D\r\n\r\n// c\r\n").file();
		assertEquals(2, file.getFormulas().size());
		assertEquals("C|D", Formulas.text(formula(file, "b").getExpression()));
	}

	@Test
	void windowsLineEndingsKeepErrorLinesAndColumns() {
		FormulaLoader.Result result = load("a = b\r\nb = C.D | E\r\n");
		assertOnlyError(result.issues(), LivenessValidator.MIXED_OPERATORS, 2, 9);
	}

	@Test
	void originalTxtFormHasTheModelNameOnItsFirstLine() {
		FormulaLoader.Result result = FormulaLoader.load(GOALIE, URI.createURI("Goalie.txt"));
		assertNoIssues(GOALIE, result.issues());
		FormulaFile file = result.file();
		assertEquals("Goalie", file.getTitle());
		assertEquals(List.of("goalie", "nonPlaying", "playing", "followBall"), file.getFormulas().stream().map(Formula::getName).toList());
		assertEquals("goalie", Formulas.root(file).getName());
		assertEquals("Init.(playing|nonPlaying)+", Formulas.text(formula(file, "goalie").getExpression()));
		assertEquals("NoPlay.[GoToPosition+]", Formulas.text(formula(file, "nonPlaying").getExpression()));
		assertEquals("Scan+|ApproachBall+|Kick|followBall", Formulas.text(formula(file, "playing").getExpression()));
		assertEquals("Stare+.[SpecialAction]", Formulas.text(formula(file, "followBall").getExpression()));
	}

	@Test
	void theLegacyGoalieFileLoadsWithoutIssues() throws IOException {
		Path path = Models.legacy("Goalie/Goalie.txt");
		String text = Files.readString(path, StandardCharsets.UTF_8);
		FormulaLoader.Result result = FormulaLoader.load(text, URI.createFileURI(path.toAbsolutePath().toString()));
		assertNoIssues(text, result.issues());
		assertEquals("Goalie", result.file().getTitle());
		assertEquals(4, result.file().getFormulas().size());
	}

	@Test
	void titleWithWindowsLineEnding() {
		FormulaFile file = loadClean("Goalie\r\ngoalie = A\r\n").file();
		assertEquals("Goalie", file.getTitle());
		assertEquals(List.of("goalie"), file.getFormulas().stream().map(Formula::getName).toList());
	}

	// ---------------------------------------------------------------- state names

	@Test
	void stateNamesSpellOperatorsOutAsTheOriginalDid() {
		FormulaFile file = loadClean(GOALIE).file();
		Expression goalie = formula(file, "goalie").getExpression();
		assertEquals("_open_group_playing_or_nonPlaying_close_group__one_or_more_times_", Formulas.stateName(goalie.getTerms().get(1)));
		Expression nonPlaying = formula(file, "nonPlaying").getExpression();
		assertEquals("_open_option_GoToPosition_one_or_more_times__close_option_", Formulas.stateName(nonPlaying.getTerms().get(1)));
		Expression playing = formula(file, "playing").getExpression();
		assertEquals("Scan_one_or_more_times_", Formulas.stateName(playing.getTerms().get(0)));
		assertEquals("Kick", Formulas.stateName(playing.getTerms().get(2)));
		Expression followBall = formula(file, "followBall").getExpression();
		assertEquals("Stare_one_or_more_times__sequence__open_option_SpecialAction_close_option_", Formulas.stateName(followBall));
	}

	@ParameterizedTest
	@CsvSource(delimiter = ';', value = { //
			"B*;B_zero_or_more_times_", "B~;B_forever_", "B||C;B_parallel_C", "B.C;B_sequence_C", "(B|C);_open_group_B_or_C_close_group_",
			"|B~|3 . C;_or_B_forever__or_3_sequence_C", "B+~;B_one_or_more_times__forever_",
			"|B~|2+;_or_B_forever__or_2_one_or_more_times_", "[B]+~;_open_option_B_close_option__one_or_more_times__forever_",
			"(B.C)+~;_open_group_B_sequence_C_close_group__one_or_more_times__forever_" })
	void stateNameOfEveryOperator(String expression, String stateName) {
		FormulaFile file = loadClean("a = " + expression).file();
		assertEquals(stateName, Formulas.stateName(file.getFormulas().get(0).getExpression()));
	}

	// ---------------------------------------------------------------- undefined and unused capabilities

	@Test
	void nameDifferingOnlyInCaseFromACapabilityIsAnError() {
		FormulaLoader.Result result = load("a = B\nb = C");
		Issue issue = assertIssue(result.issues(), Severity.ERROR, LivenessValidator.UNDEFINED_CAPABILITY, 1, 5);
		assertTrue(issue.getMessage().contains("'b'"), issue.getMessage());
		assertTrue(result.hasErrors());
	}

	@Test
	void undefinedLowercaseNameIsAWarning() {
		FormulaLoader.Result result = load("a = X . xyz");
		assertIssue(result.issues(), Severity.WARNING, LivenessValidator.UNDEFINED_CAPABILITY, 1, 9);
		assertNoErrors("a = X . xyz", result.issues());
		assertEquals(1, result.issues().size(), () -> describe(result.issues()));
	}

	@Test
	void undefinedCapitalisedNameIsAnActivity() {
		loadClean("a = Xyz");
	}

	@Test
	void unusedCapabilityIsAWarning() {
		FormulaLoader.Result result = load("a = B\nc = D");
		assertIssue(result.issues(), Severity.WARNING, LivenessValidator.UNUSED_CAPABILITY, 2, 1);
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
	}

	@Test
	void capabilityUsedOnlyByAnUnusedOneIsUnusedToo() {
		FormulaLoader.Result result = load("a = B\nc = d\nd = E");
		List<Issue> unused = result.issues().stream().filter(issue -> LivenessValidator.UNUSED_CAPABILITY.equals(issue.getCode())).toList();
		assertEquals(List.of("2:1", "3:1"), unused.stream().map(issue -> issue.getLineNumber() + ":" + issue.getColumn()).toList(),
				() -> describe(result.issues()));
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
	}

	// ---------------------------------------------------------------- definitions given twice

	@Test
	void aNameDefinedAgainIsReplacedWithAWarningAtTheReplacedDefinition() {
		FormulaLoader.Result result = load("a = b\nb = C\nb = D");
		Issue issue = assertIssue(result.issues(), Severity.WARNING, LivenessValidator.REPLACED_DEFINITION, 2, 1);
		assertEquals("this definition of 'b' is replaced by the one on line 3", issue.getMessage());
		assertEquals(1, result.issues().size(), () -> describe(result.issues()));
		assertEquals("D", Formulas.text(formula(result.file(), "b").getExpression()));
	}

	@Test
	void everyReplacedDefinitionNamesTheLastOne() {
		FormulaLoader.Result result = load("a = b\nb = C\n\nb = D\nb = E");
		List<Issue> replaced = result.issues().stream().filter(issue -> LivenessValidator.REPLACED_DEFINITION.equals(issue.getCode())).toList();
		assertEquals(List.of("2:1 line 5", "4:1 line 5"),
				replaced.stream().map(issue -> issue.getLineNumber() + ":" + issue.getColumn() + " line "
						+ issue.getMessage().replaceAll(".*line ", "")).toList(),
				() -> describe(result.issues()));
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
		assertEquals("E", Formulas.text(formula(result.file(), "b").getExpression()));
	}

	@Test
	void theRootDefinedAgainKeepsItsNameAndTakesTheLastExpression() {
		FormulaLoader.Result result = load("// root\na = B\n\na = C");
		Issue issue = assertIssue(result.issues(), Severity.WARNING, LivenessValidator.REPLACED_DEFINITION, 2, 1);
		assertTrue(issue.getMessage().endsWith("line 4"), issue.getMessage());
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
		assertEquals("a", Formulas.root(result.file()).getName());
		assertEquals("C", Formulas.text(Formulas.rootDefinition(result.file()).getExpression()));
	}

	@Test
	void onlyTheDefinitionInForceCountsForRecursionAndUse() {
		// the replaced 'b' used itself and 'c'; the one in force uses neither
		FormulaLoader.Result result = load("a = b\nb = b.c\nb = D\nc = E");
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
		assertIssue(result.issues(), Severity.WARNING, LivenessValidator.REPLACED_DEFINITION, 2, 1);
		assertIssue(result.issues(), Severity.WARNING, LivenessValidator.UNUSED_CAPABILITY, 4, 1);
	}

	@Test
	void aCapabilityUsedOnlyByAReplacedRootIsUnused() {
		FormulaLoader.Result result = load("a = b\nb = C\na = D");
		assertIssue(result.issues(), Severity.WARNING, LivenessValidator.UNUSED_CAPABILITY, 2, 1);
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
	}

	@Test
	void leftSidesDifferingOnlyInCaseAreAWarning() {
		FormulaLoader.Result result = load("a = B\nA = C");
		assertIssue(result.issues(), Severity.WARNING, LivenessValidator.DUPLICATE_DEFINITION, 2, 1);
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
	}

	// ---------------------------------------------------------------- recursion

	@Test
	void directRecursionIsAnError() {
		FormulaLoader.Result result = load("a = a.B");
		assertOnlyError(result.issues(), LivenessValidator.RECURSIVE_DEFINITION, 1, 5);
	}

	@Test
	void indirectRecursionIsAnErrorAtTheReferenceClosingTheCycle() {
		FormulaLoader.Result result = load("a = b\nb = C.a");
		Issue issue = assertOnlyError(result.issues(), LivenessValidator.RECURSIVE_DEFINITION, 2, 7);
		assertTrue(issue.getMessage().contains("a \u2192 b \u2192 a"), issue.getMessage());
	}

	@Test
	void recursionInsideNestedTermsIsFound() {
		FormulaLoader.Result result = load("a = X . [(C | b)+]\nb = D || (E . a*)");
		assertOnlyError(result.issues(), LivenessValidator.RECURSIVE_DEFINITION, 2, 15);
	}

	/**
	 * 5000 capabilities, each using the next, the last using the first. Run on a thread with
	 * a small stack so that a recursive walk would overflow whatever -Xss the build uses.
	 */
	@Test
	void longChainEndingInACycleIsAnErrorNotAStackOverflow() throws InterruptedException {
		int n = 5000;
		StringBuilder text = new StringBuilder();
		for (int i = 0; i < n - 1; i++) {
			text.append('c').append(i).append(" = c").append(i + 1).append(".X\n");
		}
		text.append('c').append(n - 1).append(" = c0.Y\n");
		AtomicReference<Object> outcome = new AtomicReference<>();
		Thread thread = new Thread(null, () -> {
			try {
				outcome.set(load(text.toString()));
			} catch (Throwable t) {
				outcome.set(t);
			}
		}, "long-chain", 512 * 1024);
		thread.start();
		thread.join(60_000);
		assertFalse(thread.isAlive(), "validation of 5000 capabilities did not finish within 60 s");
		Object value = outcome.get();
		if (value instanceof Throwable t) {
			throw new AssertionError("loading threw " + t, t);
		}
		FormulaLoader.Result result = (FormulaLoader.Result) value;
		assertNotNull(result.file(), () -> describe(result.issues()));
		assertEquals(n, result.file().getFormulas().size());
		Issue issue = assertOnlyError(result.issues(), LivenessValidator.RECURSIVE_DEFINITION, n, 9);
		assertTrue(issue.getMessage().startsWith("recursive definition: c0 \u2192 c1 \u2192 c2"), issue.getMessage());
		assertTrue(issue.getMessage().endsWith("c4999 \u2192 c0"), issue.getMessage());
		assertEquals(1, result.issues().size(), () -> "only the cycle is wrong:" + describe(result.issues()));
	}

	// ---------------------------------------------------------------- mixed operators

	@ParameterizedTest
	@CsvSource(delimiter = ';', value = { //
			"a = B . C | D;1;11", //
			"a = B | C || D;1;11", //
			"a = B || C . D;1;12", //
			"a = B.C.D|E;1;10", //
			"a = (B | C . D)+;1;12", //
			"a = [B||C|D];1;10", //
			"a = b\\nb = (C . D . E | F);2;16", //
			"a = b\\n\\n   b = [X] || Y | Z;3;17" })
	void mixedOperatorsAreAnErrorAtTheSecondOperator(String text, int line, int column) {
		FormulaLoader.Result result = load(text.replace("\\n", "\n"));
		assertOnlyError(result.issues(), LivenessValidator.MIXED_OPERATORS, line, column);
	}

	@Test
	void parenthesesResolveMixedOperators() {
		loadClean("a = (B . C) | D");
		loadClean("a = B . (C | D) . (E || F)");
	}

	// ---------------------------------------------------------------- empty parts

	@Test
	void emptyFormulaIsAnError() {
		FormulaLoader.Result result = load("a =");
		assertOnlyError(result.issues(), LivenessValidator.EMPTY_FORMULA, 1, 1);
	}

	@Test
	void emptyFormulaOnALaterLineIsAnError() {
		FormulaLoader.Result result = load("a = b\n  b =   // nothing yet");
		assertOnlyError(result.issues(), LivenessValidator.EMPTY_FORMULA, 2, 3);
	}

	@ParameterizedTest
	@CsvSource(delimiter = ';', value = { "a = ();5", "a = B.();7", "a = [];5", "a = B | [ ];9", "a = (B.( ))*;8" })
	void emptyGroupOrOptionIsAnError(String text, int column) {
		FormulaLoader.Result result = load(text);
		assertOnlyError(result.issues(), LivenessValidator.EMPTY_GROUP, 1, column);
	}

	// ---------------------------------------------------------------- a root that is only |x~|n

	@ParameterizedTest
	@CsvSource(delimiter = ';', value = { "team = |Player~|3;1;8", "team = (|Player~|3);1;9", "// copies\\nteam = ((|Player~|3));2;10",
			"team = X\\nteam = |Player~|3;2;8" })
	void aRootThatIsOnlyReplicationIsWarnedAboutAtTheReplication(String text, int line, int column) {
		FormulaLoader.Result result = load(text.replace("\\n", "\n"));
		Issue issue = assertIssue(result.issues(), Severity.WARNING, LivenessValidator.AND_ROOT, line, column);
		assertTrue(issue.getMessage().contains("AND state") && issue.getMessage().contains("'team = teamCopies'")
				&& issue.getMessage().contains("'teamCopies = |Player~|3'"), issue.getMessage());
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
	}

	@ParameterizedTest
	@ValueSource(strings = { "team = teamCopies\\nteamCopies = |Player~|3", "team = |Player~|3 . Rest", "team = |Player~|3+",
			"team = (|Player~|3)~" })
	void aRootThatIsMoreThanReplicationIsNotWarnedAbout(String text) {
		loadClean(text.replace("\\n", "\n"));
	}

	@Test
	void aReplacedRootDefinitionIsNotWarnedAbout() {
		FormulaLoader.Result result = load("team = |Player~|3\nteam = Rest");
		assertTrue(result.issues().stream().noneMatch(issue -> LivenessValidator.AND_ROOT.equals(issue.getCode())), () -> describe(result.issues()));
	}

	@Test
	void replicationOfZeroCopiesIsAnError() {
		FormulaLoader.Result result = load("a = |B~|0");
		assertOnlyError(result.issues(), LivenessValidator.BAD_COUNT, 1, 9);
	}

	/** Issue 13: explicit limits, far above real models, instead of running out of memory. */
	@Test
	void replicationOfMoreThanTenThousandCopiesIsAnError() {
		FormulaLoader.Result result = load("a = x\nx = |B~|10001");
		assertOnlyError(result.issues(), LivenessValidator.BAD_COUNT, 2, 9);
		assertTrue(Issues.errors(result.issues()).get(0).getMessage().contains("at most 10,000 copies"), () -> describe(result.issues()));
		assertFalse(load("a = x\nx = |B~|10000").hasErrors());
	}

	@Test
	void aFormulaThatBecomesMoreThanTheStateLimitIsRefusedAtTheCapability() {
		FormulaLoader.Result result = load("team = players\nplayers = |player~|1000\nplayer = |B~|1000");
		assertOnlyError(result.issues(), LivenessValidator.TOO_LARGE, 2, 1);
		assertTrue(Issues.errors(result.issues()).get(0).getMessage().startsWith("'players' becomes more than 100,000 states (KSE's limit)"),
				() -> describe(result.issues()));
		assertFalse(load("team = players\nplayers = |player~|100\nplayer = |B~|100").hasErrors());
	}

	@Test
	void aChainOfTenThousandDefinitionsIsRefusedForItsDepth() {
		StringBuilder text = new StringBuilder();
		for (int i = 0; i < 10_000; i++) {
			text.append("d").append(i).append(" = d").append(i + 1).append(" . A\n");
		}
		text.append("d10000 = B\n");
		FormulaLoader.Result result = load(text.toString());
		List<Issue> errors = Issues.errors(result.issues());
		assertEquals(1, errors.size(), () -> describe(result.issues()));
		assertTrue(errors.get(0).getMessage().contains("nests states more than 1,000 levels deep (KSE's limit)"), () -> describe(result.issues()));
	}

	@Test
	void replicationCountTooLargeForAnIntIsAnErrorAtTheCount() {
		FormulaLoader.Result result = load("a = |B~|99999999999");
		assertTrue(result.hasErrors());
		for (Issue error : Issues.errors(result.issues())) {
			assertEquals("1:9", error.getLineNumber() + ":" + error.getColumn(), () -> describe(result.issues()));
		}
	}

	@Test
	void sameAlternativeTwiceInAChoiceIsAWarning() {
		FormulaLoader.Result result = load("a = B | C | B");
		assertIssue(result.issues(), Severity.WARNING, LivenessValidator.DUPLICATE_CHOICE, 1, 13);
		assertFalse(result.hasErrors(), () -> describe(result.issues()));
	}

	@Test
	void aFormulaCannotContinueOnTheNextLine() {
		FormulaLoader.Result result = load("a = B . C\n  . D");
		assertTrue(result.hasErrors());
		Issue first = Issues.errors(result.issues()).get(0);
		assertEquals("2:3", first.getLineNumber() + ":" + first.getColumn(), () -> describe(result.issues()));
	}

	@Test
	void emptyFileIsAnError() {
		FormulaLoader.Result result = load("");
		assertOnlyError(result.issues(), LivenessValidator.NO_FORMULA, 1, 1);
	}

	@Test
	void titleWithoutFormulasIsAnError() {
		FormulaLoader.Result result = load("Goalie\n\n// nothing\n");
		assertOnlyError(result.issues(), LivenessValidator.NO_FORMULA, 1, 1);
	}

	// ---------------------------------------------------------------- syntax errors

	@ParameterizedTest
	@CsvSource(delimiter = ';', value = { //
			"a = B ..C;1;8", // the second '.'
			"a = B $ C;1;7", // a character outside the language
			"a = b\\nb = C . . D;2;9", //
			"a = B\\n  = C;2;3" })
	void syntaxErrorsAreReportedAtTheOffendingCharacter(String text, int line, int column) {
		FormulaLoader.Result result = load(text.replace("\\n", "\n"));
		assertTrue(result.hasErrors());
		Issue first = Issues.errors(result.issues()).get(0);
		assertEquals(Issues.SYNTAX, first.getCode(), () -> describe(result.issues()));
		assertEquals(line + ":" + column, first.getLineNumber() + ":" + first.getColumn(), () -> describe(result.issues()));
	}

	@Test
	void unclosedGroupIsAnError() {
		FormulaLoader.Result result = load("a = (B . C");
		assertTrue(result.hasErrors(), () -> describe(result.issues()));
		assertTrue(result.issues().stream().anyMatch(issue -> issue.getMessage().contains("')'")), () -> describe(result.issues()));
	}
}
