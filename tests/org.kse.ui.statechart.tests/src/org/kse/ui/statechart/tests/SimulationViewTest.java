package org.kse.ui.statechart.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableItem;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IViewReference;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.simulation.RuntimePrefix;
import org.kse.simulation.SimulationSession;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;
import org.kse.ui.statechart.simulation.SaveCaseDialog;
import org.kse.ui.statechart.simulation.SimulateHandler;
import org.kse.ui.statechart.simulation.SimulationPreferences;
import org.kse.ui.statechart.simulation.SimulationView;

/**
 * KSE > Simulate on a statechart: the simulator is built against the installed runtime, the
 * Simulation view runs the conformance case TimeoutCheckFalseBeforeFirstTimer through its
 * controls (Start, Finish of the selected activity, Advance) and shows the case's trace and, on
 * the diagram, the active states; the trace saves as a case; after Restart a message published
 * with the form, an activity's message on finish, "finish after 60 ms", Run at 10x and a
 * breakpoint on a state take the statechart to that state and stop there.
 * <p>
 * Building a simulator needs an installed KSE runtime: $KSE_RUNTIME_PREFIX (CI and test.sh set
 * it); without it that test is skipped. The messages for a model with errors and for a runtime
 * that is not there need none, and always run.
 */
@ExtendWith(UnexpectedDialogs.class)
class SimulationViewTest {

	/** The first build compiles the statechart against the runtime: on two cores, a minute or more. */
	private static final long BUILD_TIMEOUT = 480_000;
	private static final long COMMAND_TIMEOUT = 60_000;
	private static final long PAGE_TIMEOUT = 90_000;
	private static final String CASE = "TimeoutCheckFalseBeforeFirstTimer";

	private final List<IProject> projects = new ArrayList<>();

	@AfterEach
	void closeAndClean() throws Exception {
		for (IViewReference view : Ui.page().getViewReferences()) {
			if (SimulationView.ID.equals(view.getId())) {
				Ui.page().hideView(view);
			}
		}
		Ui.page().closeAllEditors(false);
		assertFalse(Ui.page().isPageZoomed(), "closing the Simulation view leaves nothing maximized");
		SimulationPreferences.setRuntimePrefix("");
		for (IProject project : projects) {
			project.delete(true, true, null);
		}
	}

	@Test
	void theViewRunsACaseShowsItsTraceAndStatesSavesItAndStopsAtABreakpoint() throws Exception {
		String prefix = System.getenv(RuntimePrefix.VARIABLE);
		Assumptions.assumeTrue(prefix != null && !prefix.isBlank(), "KSE_RUNTIME_PREFIX is not set: the simulator cannot be built, so this test is"
				+ " skipped (CI and ./test.sh set it to the runtime they install; locally: export KSE_RUNTIME_PREFIX=<cmake --install prefix>)");
		SimulationPreferences.setRuntimePrefix(""); // the environment's, as the preference's default says
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 1000);
		IFile model = model("Simulated", CASE, Files.readString(resource(CASE + ".stct")));
		model.getProject().getFolder("tests").create(true, true, null);

		SimulationView view = simulate(model);
		SimulationSession first = view.session();
		assertEquals(CASE, first.model());
		assertEquals(List.of("Idle", "Timed", "Untimed"), view.activities().getItems().length == 3
				? Arrays.stream(view.activities().getItems()).map(item -> item.getText(0)).sorted().toList() : List.of(), "the model's activities are listed");
		assertTrue(Ui.waitUntil(() -> Boolean.TRUE.equals(view.browser().evaluate("return !!window.kseSimulation && document.body.dataset.kse === 'ready'")),
				PAGE_TIMEOUT), "the diagram page is shown: " + view.browser().getUrl());
		assertEquals(Boolean.TRUE, view.browser().evaluate("return document.body.classList.contains('kse-simulated')"
				+ " && Array.from(document.querySelectorAll('#kse-diagram .tool-palette')).every(palette => getComputedStyle(palette).display === 'none')"),
				"the simulation's diagram is only looked at: no palette");
		Ui.screenshot("50-simulation-ready");

		press(view, "Start");
		idle(view);
		assertEquals("model " + CASE + "\nstart\n  0.1 -> 0.2\n", view.trace().getText());
		diagramShows(view, "0 0.2", "[0]");
		assertTrue(view.clock().getText().startsWith("t = 0 ms · active: 0.2"), view.clock().getText());
		assertEquals("running 0 ms", activity(view, "Idle").getText(1), "Idle runs since the start");
		Ui.screenshot("51-simulation-started");

		// the case's commands, through the view's controls
		finish(view, "Idle");
		finish(view, "Untimed");
		view.stepMs().setSelection(50);
		press(view, "Advance");
		idle(view);
		finish(view, "Idle");
		assertEquals(expectedTrace(CASE), view.trace().getText(), "the view's trace is the conformance case's (its read commands left out)");
		diagramShows(view, "0 0.3", "[1]");
		assertTrue(view.clock().getText().startsWith("t = 50 ms · active: 0.3"), view.clock().getText());
		Ui.screenshot("52-simulation-case-run");

		// one click saves the trace as a case: the project's tests folder and a free name are offered
		String[] offered = new String[2];
		Ui.expectDialog(SaveCaseDialog.TITLE);
		Ui.Answered answered = Ui.whenShown(shell -> SaveCaseDialog.TITLE.equals(shell.getText()), shell -> {
			List<Text> texts = Ui.find(shell, Text.class);
			offered[0] = texts.get(0).getText();
			offered[1] = texts.get(1).getText();
			Ui.screenshotOf(shell, "53-simulation-save-case");
			Ui.press(shell, "Save");
		});
		press(view, "Save as Test Case…");
		answered.check("Save as Test Case");
		assertEquals("/Simulated/tests", offered[0]);
		assertEquals(CASE + "Case1", offered[1]);
		IFile caseFile = model.getProject().getFile("tests/" + CASE + "Case1.case");
		IFile caseModel = model.getProject().getFile("tests/" + CASE + "Case1.stct");
		assertTrue(caseFile.exists() && caseModel.exists(), "the case and its statechart are in the workspace (refreshed)");
		String saved = Files.readString(Path.of(caseFile.getLocationURI()));
		assertEquals("# Recorded in the Simulation view of KSE on /Simulated/" + CASE + ".stct (statechart " + CASE + ");\n"
				+ "# the lines under each command are what it must cause.\n" + expectedTrace(CASE).replace("model " + CASE, "model " + CASE + "Case1"), saved);
		assertTrue(Files.readString(Path.of(caseModel.getLocationURI())).contains("name=\"" + CASE + "Case1\""), "the case's statechart is named as the case");
		assertEquals("Saved the case /Simulated/tests/" + CASE + "Case1.case and its statechart " + CASE + "Case1.stct.", view.message().getText());

		// a fresh run: a breakpoint, a message published before the start, Untimed's message on finish, finish after 60 ms, Run
		press(view, "Restart");
		assertTrue(Ui.waitUntil(() -> view.session() != first && !view.isBusy(), COMMAND_TIMEOUT), "Restart starts the simulator anew");
		assertEquals("model " + CASE + "\n", view.trace().getText(), "a restart starts the trace anew");
		TableItem breakpoint = Arrays.stream(view.breakpoints().getItems()).filter(item -> "0.3".equals(item.getData())).findFirst()
				.orElseThrow(() -> new AssertionError("the state 0.3 is offered as a breakpoint: "
						+ Arrays.stream(view.breakpoints().getItems()).map(TableItem::getText).toList()));
		assertEquals("state 0.3  Timed", breakpoint.getText());
		assertTrue(Arrays.stream(view.breakpoints().getItems()).anyMatch(item -> item.getText().equals("transition 1: 0.2 -> 0.3  [TimeoutCheck(behavior)]")),
				"transitions are offered with their index and expression");
		check(view.breakpoints(), breakpoint);
		assertTrue(Ui.waitUntil(() -> "1 breakpoint set.".equals(view.message().getText()), COMMAND_TIMEOUT), view.message().getText());

		view.topic().setText("behavior");
		view.kind().select(Arrays.asList(view.kind().getItems()).indexOf("State"));
		view.type().select(Arrays.asList(view.type().getItems()).indexOf("HeadToBMessage"));
		view.fields().setText("ball");
		assertEquals(List.of("ballfound : int32"), view.fieldProposals(), "the fields of the chosen type are proposed");
		view.fields().setText("nosuchfield: 1");
		press(view, "Publish");
		idle(view);
		assertTrue(view.message().getText().startsWith("'publish behavior State HeadToBMessage { nosuchfield: 1 }' was refused: "), view.message().getText());
		assertEquals(Ui.display().getSystemColor(SWT.COLOR_RED), view.message().getForeground(), "a refused command is said in red");
		assertEquals("model " + CASE + "\n", view.trace().getText(), "a refused command is not traced");
		view.fields().setText("ballfound: 1");
		press(view, "Publish");
		idle(view);
		select(view, "Untimed");
		press(view, "On Finish of Selected Activity");
		assertEquals("behavior State HeadToBMessage { ballfound: 1 }", activity(view, "Untimed").getText(2));

		press(view, "Start");
		idle(view);
		view.finishAfterMs().setSelection(60);
		view.finishAfter().setSelection(true);
		view.finishAfter().notifyListeners(SWT.Selection, new Event());
		view.speed().select(Arrays.asList(view.speed().getItems()).indexOf("10×"));
		press(view, "Run");
		assertTrue(view.isRunning());
		assertTrue(Ui.waitUntil(() -> !view.isRunning(), COMMAND_TIMEOUT), "the run stops at the breakpoint: " + view.message().getText());
		idle(view);
		assertEquals("Stopped at the breakpoint of state 0.3 (t = 180 ms).", view.message().getText());
		assertEquals("model " + CASE + "\npublish behavior State HeadToBMessage { ballfound: 1 }\nstart\n  0.1 -> 0.2\n"
				+ "advance 60\nfinish Idle\n  0.2 -> 0.4\n"
				+ "advance 60\npublish behavior State HeadToBMessage { ballfound: 1 }\nfinish Untimed\n  0.4 -> 0.2\n"
				+ "advance 60\nfinish Idle\n  0.2 -> 0.3\n", view.trace().getText(),
				"Idle and Untimed finished after 60 ms each, Untimed publishing first; the timer Untimed set (50 ms) had passed when Idle finished again");
		// a step of Run is one press: what it took is marked, here Idle -> Untimed, Untimed -> Idle, Idle -> Timed
		diagramShows(view, "0 0.3", "[1,2,3]");
		Ui.screenshot("54-simulation-breakpoint");
	}

	@Test
	void aModelWithErrorsIsNotSimulatedAndSaysWhy() throws Exception {
		String broken = Files.readString(resource(CASE + ".stct")).replace("name=\"" + CASE + "\"", "name=\"Broken\"")
				.replace("TE=\"[TimeoutCheck(behavior)]\"", "TE=\"[NoSuchTopic.State.NoSuchMessage.x() ==]\"");
		IFile model = model("BrokenSimulation", "Broken", broken);
		String said = refused(model);
		System.out.println("SimulationViewTest: a model with errors: " + said);
		assertTrue(said.matches("(?s)Broken\\.stct has \\d+ errors?, so it cannot be simulated; fix them first \\(the Problems view lists them all\\):\n- .+"), said);
		assertTrue(said.contains("Idle_TO_Timed") || said.contains("0.2 -> 0.3"), "the error names its transition: " + said);
	}

	@Test
	void aRuntimeThatIsNotThereIsNamedInTheMessage() throws Exception {
		assertNotNull(PlatformUI.getWorkbench().getPreferenceManager().find("org.kse.ui.preferences/org.kse.ui.preferences.simulation"),
				"the runtime is named on the preference page KSE > Simulation");
		IFile model = model("NoRuntime", CASE, Files.readString(resource(CASE + ".stct")));
		Path missing = Path.of(System.getProperty("java.io.tmpdir"), "no-kse-runtime-here");
		SimulationPreferences.setRuntimePrefix(missing.toString());
		String said = refused(model);
		assertEquals("The simulation of " + CASE + ".stct cannot start: no KSE runtime at " + missing + ": the folder does not exist", said);
	}

	/** KSE > Simulate on a model that cannot be simulated: what the one message window says (and no view opens). */
	private String refused(IFile model) throws Exception {
		String[] said = new String[1];
		Ui.expectDialog(SimulateHandler.TITLE);
		Ui.Answered answered = Ui.whenShown(shell -> SimulateHandler.TITLE.equals(shell.getText()), shell -> {
			said[0] = String.join("\n", Ui.find(shell, Label.class).stream().map(Label::getText).filter(text -> !text.isBlank()).toList());
			Ui.screenshotOf(shell, "55-simulation-refused-" + model.getProject().getName());
			Ui.press(shell, "OK");
		});
		Ui.select(model);
		Ui.run("org.kse.ui.simulate");
		assertTrue(Ui.waitUntil(() -> answered.done || answered.failure != null, 60_000), "a message says why there is no simulation");
		answered.check(SimulateHandler.TITLE);
		assertTrue(Ui.waitUntil(() -> Job.getJobManager().find(SimulateHandler.FAMILY).length == 0, 10_000));
		Ui.settle(300);
		assertNull(view(), "no Simulation view opens");
		return said[0];
	}

	private SimulationView simulate(IFile model) throws Exception {
		Ui.select(model);
		Ui.run("org.kse.ui.simulate");
		long began = System.currentTimeMillis();
		assertTrue(Ui.waitUntil(() -> view() != null, BUILD_TIMEOUT), "the simulator is built and the Simulation view opens");
		System.out.println("SimulationViewTest: the simulator of " + model.getName() + " was built and started in " + (System.currentTimeMillis() - began) + " ms");
		SimulationView view = view();
		assertNotNull(view.session());
		assertTrue(Ui.page().isPageZoomed(), "the view takes the window");
		return view;
	}

	private static SimulationView view() {
		return Arrays.stream(Ui.page().getViewReferences()).filter(reference -> SimulationView.ID.equals(reference.getId()))
				.map(reference -> (SimulationView) reference.getView(false)).filter(java.util.Objects::nonNull).findFirst().orElse(null);
	}

	private IFile model(String projectName, String name, String content) throws Exception {
		IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject(projectName);
		if (!project.exists()) {
			project.create(null);
		}
		project.open(null);
		projects.add(project);
		IFile file = project.getFile(name + ".stct");
		file.create(new ByteArrayInputStream(content.getBytes(StandardCharsets.UTF_8)), true, null);
		return file;
	}

	private static Path resource(String name) {
		return Path.of(System.getProperty("kse.repository"), "tests/org.kse.ui.statechart.tests/resources/simulation", name);
	}

	/** The case's script and trace without its comments and its read commands (the view has no read). */
	private static String expectedTrace(String name) throws Exception {
		StringBuilder expected = new StringBuilder();
		boolean skipping = false;
		for (String line : Files.readAllLines(resource(name + ".case"))) {
			if (line.startsWith("#") || line.isBlank()) {
				continue;
			}
			if (!line.startsWith(" ")) {
				skipping = line.startsWith("read ");
			}
			if (!skipping) {
				expected.append(line).append('\n');
			}
		}
		return expected.toString();
	}

	private static void press(SimulationView view, String label) {
		Button button = Ui.find(view.control(), Button.class).stream().filter(candidate -> candidate.getText().replace("&", "").equals(label)).findFirst()
				.orElseThrow(() -> new AssertionError("the Simulation view has no button " + label));
		assertTrue(button.isEnabled(), label + " is enabled");
		Ui.press(button);
	}

	/** Waits for the command on its way to be answered. */
	private static void idle(SimulationView view) {
		assertTrue(Ui.waitUntil(() -> !view.isBusy(), COMMAND_TIMEOUT), "the simulator answers: " + view.message().getText());
	}

	private static TableItem activity(SimulationView view, String name) {
		return Arrays.stream(view.activities().getItems()).filter(item -> name.equals(item.getData())).findFirst()
				.orElseThrow(() -> new AssertionError("no activity " + name + " listed"));
	}

	private static void select(SimulationView view, String name) {
		view.activities().setSelection(activity(view, name));
		view.activities().notifyListeners(SWT.Selection, new Event());
	}

	private static void finish(SimulationView view, String name) {
		select(view, name);
		press(view, "Finish");
		idle(view);
	}

	private static void check(Table table, TableItem item) {
		item.setChecked(true);
		Event event = new Event();
		event.detail = SWT.CHECK;
		event.item = item;
		table.notifyListeners(SWT.Selection, event);
	}

	/** The diagram outlines exactly these states (labels) and marks these transitions (model indexes) as just taken. */
	private static void diagramShows(SimulationView view, String activeLabels, String takenIndexes) {
		String drawn = "return window.kseSimulation.drawnActiveLabels().join(' ') + '|' + JSON.stringify(window.kseSimulation.drawnTakenIndexes())";
		String expected = activeLabels + "|" + takenIndexes;
		assertTrue(Ui.waitUntil(() -> expected.equals(view.browser().evaluate(drawn)), PAGE_TIMEOUT),
				"the diagram outlines " + activeLabels + " and marks the transitions " + takenIndexes + "; it shows " + view.browser().evaluate(drawn));
	}
}
