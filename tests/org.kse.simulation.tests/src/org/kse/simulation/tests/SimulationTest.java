package org.kse.simulation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kse.generator.monas.MonasGenerator;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.simulation.RuntimePrefix;
import org.kse.simulation.Script;
import org.kse.simulation.SimulationException;
import org.kse.simulation.SimulationSession;
import org.kse.simulation.SimulatorBuilder;
import org.kse.simulation.Trace;

/**
 * The simulation as the tool runs it: conformance cases of the suite driven through a session on
 * the real simulator (built with CMake against the runtime installed in KSE_RUNTIME_PREFIX), a
 * recorded trace saved as a case that the simulator then passes, and the messages a user gets
 * when something is missing or wrong.
 */
class SimulationTest {

	private static final Path CASES = Path.of(System.getProperty("kse.repository", "../.."), "tests", "conformance", "cases");

	@TempDir
	Path temp;

	/** Simulators by case: a build takes seconds, and one simulator serves many sessions. */
	@TempDir
	static Path simulators;
	private static final java.util.Map<String, SimulatorBuilder.Simulator> BUILT = new java.util.HashMap<>();

	private static Path runtime() {
		String prefix = System.getenv(RuntimePrefix.VARIABLE);
		assumeTrue(prefix != null && !prefix.isBlank(), "KSE_RUNTIME_PREFIX names no installed runtime: the simulator cannot be built here (test.sh sets it)");
		return Path.of(prefix);
	}

	private static List<Script.Step> steps(Path caseFile) throws IOException {
		try (var reader = Files.newBufferedReader(caseFile, StandardCharsets.UTF_8)) {
			return Script.read(reader);
		}
	}

	private static SimulationSession session(String caseName) throws Exception {
		SimulatorBuilder.Simulator simulator = BUILT.get(caseName);
		if (simulator == null) {
			Model model = StatechartResources.load(CASES.resolve(caseName + ".stct"));
			simulator = SimulatorBuilder.build(model, RuntimePrefix.resolve(runtime().toString()), simulators.resolve(caseName), SimulatorBuilder.Progress.NONE);
			BUILT.put(caseName, simulator);
		}
		return SimulationSession.start(simulator);
	}

	@ParameterizedTest
	@ValueSource(strings = { "ActivityRunsOnce", "TimeoutWakesAtItsTime", "SelfLoopRerunsActivity" })
	void aConformanceCaseDrivenThroughASessionGivesItsTrace(String caseName) throws Exception {
		runtime();
		try (SimulationSession session = session(caseName)) {
			assertEquals(caseName, session.model());
			for (Script.Step step : steps(CASES.resolve(caseName + ".case"))) {
				SimulationSession.Result result = session.execute(step.command());
				assertTrue(result.ok(), () -> step.command() + ": " + result.error());
				assertEquals(step.expected(), result.lines(), step.command());
			}
		}
	}

	@Test
	void aRecordedTraceSavesAsACaseWithItsStatechartRenamed() throws Exception {
		runtime();
		Model model = StatechartResources.load(CASES.resolve("SelfLoopRerunsActivity.stct"));
		try (SimulationSession session = session("SelfLoopRerunsActivity")) {
			session.execute("start");
			session.execute("advance 20");
			assertEquals(java.util.OptionalLong.of(0), session.execute("advance 30").since("Work"), "Work runs since the start");
			assertFalse(session.execute("finish Nobody").ok(), "finishing an activity that is not running");
			assertEquals(java.util.OptionalLong.of(50), session.execute("finish Work").since("Work"), "the self-loop ran Work again at 50 ms");
			session.execute("active");
			Path saved = session.trace().saveCase(temp.resolve("cases"), "MyLoopCase", model, List.of("recorded by a test"));
			assertEquals("""
					# recorded by a test
					model MyLoopCase
					start
					  0.1 -> 0.2
					advance 50
					finish Work
					  0.2 -> 0.2
					active
					  active: 0.2
					""", Files.readString(saved));
			assertEquals("MyLoopCase", StatechartResources.load(temp.resolve("cases/MyLoopCase.stct")).getName());
		}
		// that the simulator passes the saved pair as a case is tests/conformance/run.sh's check (a
		// simulator of its own for the saved statechart)
	}

	@Test
	void anAdvanceStopsAtABreakpointAndTheTraceSaysHowFarItWent() throws Exception {
		runtime();
		try (SimulationSession session = session("TimeoutWakesAtItsTime")) {
			session.execute("start");
			assertTrue(session.setBreakpoints(List.of("0.3"), List.of()).ok());
			SimulationSession.Result result = session.execute("advance 60000");
			assertEquals(Optional.of("state 0.3"), result.stopped());
			assertEquals("advance 100", result.command());
			assertEquals(100, result.time());
			assertEquals(List.of("0.2 -> 0.3"), result.lines());
			assertEquals(List.of(new SimulationSession.Taken(1, "0.2", "0.3")), result.taken());
			assertTrue(result.active().contains("0.3"), result.active().toString());
			assertEquals("advance 100", session.trace().entries().get(1).command());
		}
	}

	@Test
	void aRefusedCommandSaysWhyAndIsNotTraced() throws Exception {
		runtime();
		try (SimulationSession session = session("ActivityRunsOnce")) {
			session.execute("start");
			for (String wrong : List.of("publish t State NoSuchType", "advance soon", "finish Work Rest", "teleport 0.3")) {
				SimulationSession.Result result = session.execute(wrong);
				assertFalse(result.ok(), wrong);
				assertTrue(result.error().isPresent() && !result.error().get().isBlank(), wrong);
				assertEquals(List.of("Work"), result.running(), wrong + " changed nothing");
			}
			assertEquals(1, session.trace().entries().size());
			assertThrows(IllegalArgumentException.class, () -> session.execute("start\nfinish Work"));
		}
	}

	@Test
	void aModelWithErrorsIsNotBuilt() throws Exception {
		Model model = StatechartResources.load(CASES.resolve("ActivityRunsOnce.stct"));
		model.getTransitions().get(0).setTE("not a guard ((");
		MonasGenerator.ModelHasErrorsException refused = assertThrows(MonasGenerator.ModelHasErrorsException.class,
				() -> SimulatorBuilder.build(model, temp, temp.resolve("build"), SimulatorBuilder.Progress.NONE));
		assertFalse(refused.errors().isEmpty());
		assertFalse(Files.exists(temp.resolve("build/build")), "nothing was configured");
	}

	@Test
	void aMissingRuntimeIsExplained() throws Exception {
		SimulationException none = assertThrows(SimulationException.class, () -> RuntimePrefix.resolve(temp.resolve("nowhere").toString()));
		assertTrue(none.getMessage().contains("does not exist"), none.getMessage());
		SimulationException empty = assertThrows(SimulationException.class, () -> RuntimePrefix.resolve(temp.toString()));
		assertTrue(empty.getMessage().contains("kse_runtimeConfig.cmake"), empty.getMessage());
	}

	@Test
	void aBuildThatFailsEndsWithTheEndOfItsLog() throws Exception {
		assumeTrue(SimulatorBuilder.onPath("cmake"), "cmake is not installed");
		Path broken = temp.resolve("broken-prefix/lib/cmake/kse_runtime");
		Files.createDirectories(broken);
		Files.writeString(broken.resolve("kse_runtimeConfig.cmake"), "message(FATAL_ERROR \"this runtime is broken on purpose\")\n");
		Model model = StatechartResources.load(CASES.resolve("ActivityRunsOnce.stct"));
		SimulationException failed = assertThrows(SimulationException.class, () -> SimulatorBuilder.build(model,
				RuntimePrefix.resolve(temp.resolve("broken-prefix").toString()), temp.resolve("build"), SimulatorBuilder.Progress.NONE));
		assertTrue(failed.getMessage().contains("this runtime is broken on purpose"), failed.getMessage());
		assertTrue(failed.getMessage().contains(temp.resolve("build/configure.log").toString()), failed.getMessage());
	}

	@Test
	void aRunOfSmallStepsReadsAsTheAdvanceItAmountsTo() {
		Trace trace = new Trace("M");
		trace.add(result("start", List.of("0.1 -> 0.2")));
		trace.add(result("advance 100", List.of()));
		trace.add(result("advance 100", List.of()));
		trace.add(result("advance 100", List.of("0.2 -> 0.3")));
		trace.add(result("advance 100", List.of()));
		trace.add(result("active", List.of("active: 0.3")));
		trace.add(result("advance 5", List.of()));
		assertEquals("""
				model Case
				start
				  0.1 -> 0.2
				advance 300
				  0.2 -> 0.3
				advance 100
				active
				  active: 0.3
				advance 5
				""", trace.caseText("Case", List.of()));
		assertThrows(IllegalArgumentException.class, () -> trace.saveCase(temp, "not a name", null, List.of()));
	}

	private static SimulationSession.Result result(String command, List<String> lines) {
		return new SimulationSession.Result(true, command, lines, List.of(), Optional.empty(), Optional.empty(), List.of(), List.of(), List.of(), 0, true);
	}
}
