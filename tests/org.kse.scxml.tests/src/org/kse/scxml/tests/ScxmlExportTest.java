package org.kse.scxml.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import javax.xml.XMLConstants;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.cli.Kse;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.scxml.ScxmlExport;
import org.kse.scxml.ScxmlProblem;
import org.kse.testing.CommandRun;
import org.kse.testing.Models;
import org.xml.sax.SAXException;

/** {@code ScxmlExport}: what it writes is W3C SCXML, what it cannot write faithfully it names, and the command. */
class ScxmlExportTest {

	static final Path REPOSITORY = Path.of(System.getProperty("kse.repository", "../.."));
	static final Path CASES = REPOSITORY.resolve("tests/conformance/cases");
	static final Path SCHEMA = REPOSITORY.resolve("tests/data/scxml-schema/scxml.xsd");

	@TempDir
	Path directory;

	static Schema schema() throws SAXException {
		SchemaFactory factory = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI);
		factory.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
		factory.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "file");
		return factory.newSchema(SCHEMA.toFile());
	}

	static void assertValid(String scxml) throws SAXException, IOException {
		schema().newValidator().validate(new StreamSource(new StringReader(scxml)));
	}

	static Stream<Path> charts() throws IOException {
		List<Path> cases;
		try (Stream<Path> files = Files.list(CASES)) {
			cases = files.filter(f -> f.toString().endsWith(".stct")).sorted().toList();
		}
		List<Path> examples;
		try (Stream<Path> files = Files.walk(REPOSITORY.resolve("examples"), 2)) {
			examples = files.filter(f -> f.toString().endsWith(".stct")).sorted().toList();
		}
		return Stream.concat(cases.stream(), examples.stream());
	}

	@ParameterizedTest
	@MethodSource("charts")
	void everyChartExportsAsValidScxmlOrNamesTheElementsThatHaveNoFaithfulForm(Path file) throws Exception {
		ScxmlExport.Result result = ScxmlExport.export(StatechartResources.load(file));

		String name = file.getFileName().toString().replace(".stct", "");
		if (file.startsWith(CASES)) {
			assertNotNull(result.scxml(), () -> name + ": " + result.problems());
		}
		if (result.scxml() != null) {
			assertValid(result.scxml());
			assertTrue(result.scxml().contains("kse:export=\"1\""));
		} else {
			assertFalse(result.problems().isEmpty());
			for (ScxmlProblem problem : result.problems()) {
				assertTrue(problem.element().matches(".+ '.*'"), problem.toString());
			}
		}
	}

	@Test
	void theMappingWritesRegionsAsParallelStartAsInitialEndAsFinalAndKeepsKseFacts() throws Exception {
		String scxml = ScxmlExport.export(StatechartResources.load(CASES.resolve("OtherRegionRunsOn.stct"))).scxml();

		assertValid(scxml);
		assertTrue(scxml.contains("<parallel id=\"Both\" kse:type=\"AND\" kse:label=\"0.2\" kse:name=\"Both\">"), scxml);
		assertTrue(scxml.contains("<state id=\"s_0.2.1\" initial=\"s_0.2.1.1\" kse:type=\"OR\" kse:label=\"0.2.1\""), scxml);
		assertTrue(scxml.contains("<final id=\"s_0.3\" kse:type=\"END\" kse:label=\"0.3\""), scxml);
		// the AND state's exit waits for both regions and for the root region
		assertTrue(scxml.contains("cond=\"kse.idle([&apos;0.2.1&apos;,&apos;0.2.2&apos;,&apos;0&apos;])\"")
				|| scxml.contains("cond=\"kse.idle(['0.2.1','0.2.2','0'])\""), scxml);
		assertTrue(scxml.contains("kse.enterBasic('0.2.1', 'Slow', '0.2.1.2');"), scxml);
	}

	@Test
	void guardedTransitionsComeFirstLastCreatedFirstThenUnguardedInCreationOrder() throws Exception {
		String scxml = ScxmlExport.export(StatechartResources.load(CASES.resolve("GuardedBeforeUnguarded.stct"))).scxml();
		Model model = StatechartResources.load(CASES.resolve("GuardedBeforeUnguarded.stct"));
		int firstUnguarded = -1;
		int lastGuarded = -1;
		for (var t : model.getTransitions()) {
			int at = scxml.indexOf("kse:name=\"" + t.getName() + "\"");
			assertTrue(at > 0, t.getName());
			if (t.getTE() != null && t.getTE().contains("[")) {
				lastGuarded = Math.max(lastGuarded, at);
			} else if (t.getSource() == model.getTransitions().stream().filter(x -> x.getTE() != null && x.getTE().contains("["))
					.findFirst().get().getSource()) {
				firstUnguarded = firstUnguarded < 0 ? at : Math.min(firstUnguarded, at);
			}
		}
		assertTrue(firstUnguarded < 0 || lastGuarded < firstUnguarded, scxml);
	}

	@Test
	void aConnectorChainIsOneTransitionPerCompletePathAndTheConnectorIsKept() throws Exception {
		String scxml = ScxmlExport.export(StatechartResources.load(CASES.resolve("ConnectorChainIsOneStep.stct"))).scxml();

		assertValid(scxml);
		assertTrue(scxml.contains("kse:chain=\"0.2 0.3\""), scxml);
		assertTrue(scxml.contains("kse:chain=\"0.2\""), scxml);
		assertTrue(scxml.contains("<kse:connector kse:label=\"0.3\" kse:name=\"0.3\">"), scxml);
		assertTrue(scxml.contains("expr=\"'0.1 -&gt; 0.2 -&gt; 0.3 -&gt; 0.4'\""), scxml);
	}

	@Test
	void anEventIsRefusedNamingTheTransition() {
		Model model = Models.model("Evented");
		Node root = Models.root(model, "root", "0", "OR");
		Node start = Models.child(root, "0.1", "0.1", "START");
		Node work = Models.child(root, "Work", "0.2", "BASIC");
		Models.transition(model, start, work, "Go[worldstate.State.GameStateMessage!=NULL]");

		ScxmlExport.Result result = ScxmlExport.export(model);

		assertNull(result.scxml());
		assertEquals(1, result.problems().size(), result.problems().toString());
		assertEquals("0.1->0.2 '0.1_TO_Work'", result.problems().get(0).element());
		assertTrue(result.problems().get(0).message().contains("event 'Go'"), result.problems().toString());
	}

	@Test
	void aTimeoutCheckLeavingAnAndStateIsRefusedPerElement() {
		Model model = Models.model("Polling");
		Node root = Models.root(model, "root", "0", "OR");
		Node start = Models.child(root, "0.1", "0.1", "START");
		Node both = Models.child(root, "Both", "0.2", "AND");
		for (int r = 1; r <= 2; r++) {
			Node region = Models.child(both, "0.2." + r, "0.2." + r, "OR");
			Node inner = Models.child(region, "0.2." + r + ".1", "0.2." + r + ".1", "START");
			Node work = Models.child(region, "W" + r, "0.2." + r + ".2", "BASIC");
			Models.transition(model, inner, work);
		}
		Models.transition(model, start, both, "/TimeoutAction.behavior.100");
		Models.transition(model, both, both, "[TimeoutCheck(behavior)]/TimeoutAction.behavior.100");
		Models.transition(model, both, both, "[behavior.Signal.FallMessage.fall()==1]").setName("Both_TO_Both_2");

		ScxmlExport.Result result = ScxmlExport.export(model);

		assertNull(result.scxml());
		assertEquals(List.of("0.2->0.2 'Both_TO_Both_2'", "0.2->0.2 'Both_TO_Both'"),
				result.problems().stream().map(ScxmlProblem::element).toList());
		assertTrue(result.problems().get(0).message().contains("AND state"), result.problems().toString());
	}

	@Test
	void anUnknownConstantAndAHasCallAreRefusedNamingTheirTransitions() {
		Model model = Models.model("Unknown");
		Node root = Models.root(model, "root", "0", "OR");
		Node start = Models.child(root, "0.1", "0.1", "START");
		Node a = Models.child(root, "A", "0.2", "BASIC");
		Node b = Models.child(root, "B", "0.3", "BASIC");
		Models.transition(model, start, a, "[worldstate.State.GameStateMessage.player_state()==NO_SUCH_STATE]");
		Models.transition(model, a, b, "[worldstate.Data.WorldInfo.has_myposition()]");

		ScxmlExport.Result result = ScxmlExport.export(model);

		assertNull(result.scxml());
		assertEquals(List.of("0.1->0.2 '0.1_TO_A'", "0.2->0.3 'A_TO_B'"), result.problems().stream().map(ScxmlProblem::element).toList());
		assertTrue(result.problems().get(0).message().contains("NO_SUCH_STATE"));
		assertTrue(result.problems().get(1).message().contains("has_myposition"));
	}

	/**
	 * An AND state: region 0.2.1 sets a timer with {@code timerAction} as it leaves its START;
	 * region 0.2.2 checks {@code TimeoutCheck(behavior)} from its START, or from Watch after
	 * waiting there ({@code checkAfterWatch}).
	 */
	static Model timerBesideTimeoutCheck(String timerAction, boolean checkAfterWatch) {
		Model model = Models.model("TimerBesideCheck");
		Node root = Models.root(model, "root", "0", "OR");
		Node start = Models.child(root, "0.1", "0.1", "START");
		Node both = Models.child(root, "Both", "0.2", "AND");
		Models.transition(model, start, both);
		Node first = Models.child(both, "0.2.1", "0.2.1", "OR");
		Node firstStart = Models.child(first, "0.2.1.1", "0.2.1.1", "START");
		Node timer = Models.child(first, "Timer", "0.2.1.2", "BASIC");
		Models.transition(model, firstStart, timer, timerAction);
		Node second = Models.child(both, "0.2.2", "0.2.2", "OR");
		Node secondStart = Models.child(second, "0.2.2.1", "0.2.2.1", "START");
		Node watch = Models.child(second, "Watch", "0.2.2.2", "BASIC");
		Node end = Models.child(second, "0.2.2.3", "0.2.2.3", "END");
		if (checkAfterWatch) {
			Models.transition(model, secondStart, watch);
			Models.transition(model, watch, end, "[TimeoutCheck(behavior)]");
		} else {
			Models.transition(model, secondStart, end, "[TimeoutCheck(behavior)]");
		}
		return model;
	}

	@Test
	void aTimeoutCheckInTheStepWhereAnEarlierRegionSetsItsTopicsTimerIsRefused() {
		ScxmlExport.Result result = ScxmlExport.export(timerBesideTimeoutCheck("/TimeoutAction.behavior.100", false));

		// in the first step the engine sets the timer before the check reads and refreshes; SCXML after
		assertNull(result.scxml());
		assertEquals(List.of("0.2.2.1->0.2.2.3 '0.2.2.1_TO_0.2.2.3'"), result.problems().stream().map(ScxmlProblem::element).toList());
		assertTrue(result.problems().get(0).message().contains("0.2.1.1->0.2.1.2 '0.2.1.1_TO_Timer'"), result.problems().toString());
	}

	@Test
	void anEarlierRegionsTimerIsAcceptedWhenTheCheckCannotRunInItsStepOrItsBlackboardNeverReadsTheTopic() throws Exception {
		// the timer is set only in the first step, when Watch is not yet active (conformance TimeoutSharedByTopic)
		ScxmlExport.Result later = ScxmlExport.export(timerBesideTimeoutCheck("/TimeoutAction.behavior.100", true));
		// the same step, but 0.2.2's blackboard reads only behavior: the motion timer never reaches it
		ScxmlExport.Result otherTopic = ScxmlExport.export(timerBesideTimeoutCheck("/TimeoutAction.motion.100", false));

		assertNotNull(later.scxml(), later.problems().toString());
		assertValid(later.scxml());
		assertTrue(later.scxml().contains("kse.setTimeout('0.2.1','behavior',100);"), later.scxml());
		assertNotNull(otherTopic.scxml(), otherTopic.problems().toString());
		assertValid(otherTopic.scxml());
	}

	@Test
	void anEarlierRegionsPublishAfterItsFirstStepStillRefusesTheLaterCheck() {
		Model model = timerBesideTimeoutCheck(null, true);
		Node first = Models.byLabel(model, "0.2.1");
		Node timer = Models.byLabel(model, "0.2.1.2");
		Node again = Models.child(first, "Again", "0.2.1.3", "BASIC");
		Models.transition(model, timer, again, "/TimeoutAction.behavior.100");

		ScxmlExport.Result result = ScxmlExport.export(model);

		// Timer's activity may end while Watch waits: the timer and the check then share a step
		assertNull(result.scxml());
		assertEquals(List.of("0.2.2.2->0.2.2.3 'Watch_TO_0.2.2.3'"), result.problems().stream().map(ScxmlProblem::element).toList());
		assertTrue(result.problems().get(0).message().contains("0.2.1.2->0.2.1.3 'Timer_TO_Again'"), result.problems().toString());
	}

	// ------------------------------------------------------------ the command

	static CommandRun kse(String... args) {
		return CommandRun.capture((out, err) -> new Kse(out, err).run(args));
	}

	@Test
	void theCommandWritesAValidDocumentWhereOptionOSays() throws Exception {
		Path model = Files.copy(CASES.resolve("RedecideFromTheTop.stct"), directory.resolve("RedecideFromTheTop.stct"));
		Path chart = directory.resolve("out/chart.scxml");

		CommandRun run = kse("export-scxml", model.toString(), "-o", chart.toString());

		assertEquals(Kse.OK, run.code(), run.all());
		assertEquals("wrote " + chart + "\n", run.out(), run.all());
		assertValid(Files.readString(chart));
		try (Stream<Path> left = Files.list(chart.getParent())) {
			assertEquals(List.of(chart), left.toList(), "no temporary file is left behind");
		}
	}

	@Test
	void theCommandRefusesPerElementWithExitCode1AndWritesNothing() throws Exception {
		Model model = Models.model("Evented");
		Node root = Models.root(model, "root", "0", "OR");
		Node start = Models.child(root, "0.1", "0.1", "START");
		Node work = Models.child(root, "Work", "0.2", "BASIC");
		Models.transition(model, start, work, "Go");
		Path file = directory.resolve("Evented.stct");
		StatechartResources.save(model, file);

		CommandRun run = kse("export-scxml", file.toString());

		assertEquals(Kse.INVALID, run.code(), run.all());
		assertTrue(run.err().contains(file + ": ERROR 0.1->0.2 '0.1_TO_Work': the event 'Go'"), run.all());
		assertFalse(Files.exists(directory.resolve("Evented.scxml")));
	}

	@Test
	void severalModelsInOneCallAreWrittenIntoTheFolderAndARefusedOneIsNamed() throws Exception {
		Path folder = directory.resolve("charts");
		Path evented = directory.resolve("Evented.stct");
		Model model = Models.model("Evented");
		Node root = Models.root(model, "root", "0", "OR");
		Models.transition(model, Models.child(root, "0.1", "0.1", "START"), Models.child(root, "Work", "0.2", "BASIC"), "Go");
		StatechartResources.save(model, evented);

		CommandRun run = kse("export-scxml", CASES.resolve("InnerFirst.stct").toString(), evented.toString(),
				CASES.resolve("OrEntersStart.stct").toString(), "-o", folder.toString());

		assertEquals(Kse.INVALID, run.code(), run.all());
		assertValid(Files.readString(folder.resolve("InnerFirst.scxml")));
		assertValid(Files.readString(folder.resolve("OrEntersStart.scxml")));
		assertFalse(Files.exists(folder.resolve("Evented.scxml")));
		assertTrue(run.err().contains(evented + ": ERROR 0.1->0.2 '0.1_TO_Work'"), run.all());
	}

	@Test
	void aMissingModelIsExitCode2() {
		CommandRun run = kse("export-scxml", directory.resolve("none.stct").toString());

		assertEquals(Kse.FAILED, run.code(), run.all());
	}
}
