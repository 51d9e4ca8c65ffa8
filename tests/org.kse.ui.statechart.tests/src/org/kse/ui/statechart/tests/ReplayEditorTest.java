package org.kse.ui.statechart.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IFolder;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.swt.browser.Browser;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.notation.Notation;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;
import org.kse.ui.statechart.diagram.WorkspaceDiagramServer;
import org.kse.ui.statechart.editor.StatechartEditor;
import org.kse.ui.statechart.replay.ReplayEditor;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * A match log opened in the workbench: the Match Replay editor shows the replay page of the
 * workspace's diagram server, with the field and the timeline of the log, and a selected robot's
 * statechart (its model found in the workspace and lent read-only, no editor opened) outlining
 * the states the log says were active at t. A robot whose model is not in the workspace, a log
 * cut short and a file that is not a log open with the page's messages; a log outside the
 * workspace folder (a linked project) with the editor's own.
 * <p>
 * The log (resources/replay/seed1-half20.jsonl, see its README) is a real one of the examples'
 * kse-match; read here, apart from the page, it is the reference.
 */
@ExtendWith(UnexpectedDialogs.class)
class ReplayEditorTest {

	private static final long PAGE_TIMEOUT = 90_000;
	private static final String PROJECT = "Replays";

	@TempDir
	Path elsewhere;
	/** The projects other tests left open, closed for this one: their models (a Goalie.stct, an Attacker.stct) would be found first. */
	private final List<IProject> closed = new ArrayList<>();

	@BeforeEach
	void onlyThisTestsProjectsAreOpen() throws Exception {
		for (IProject project : ResourcesPlugin.getWorkspace().getRoot().getProjects()) {
			if (project.isOpen()) {
				project.close(null);
				closed.add(project);
			}
		}
	}

	@AfterEach
	void closeEverything() throws Exception {
		IWorkbenchPage page = Ui.page();
		if (page.isPageZoomed()) {
			page.setPartState(page.getActivePartReference(), IWorkbenchPage.STATE_RESTORED);
		}
		page.closeAllEditors(false);
		for (String project : new String[] { PROJECT, "Elsewhere" }) {
			IProject holder = ResourcesPlugin.getWorkspace().getRoot().getProject(project);
			if (holder.exists()) {
				// the linked project's files are the test's temporary folder's: only the project goes
				holder.delete(!project.equals("Elsewhere"), true, null);
			}
		}
		for (IProject project : closed) {
			project.open(null);
		}
	}

	private static Path resource(String name) {
		return Path.of(System.getProperty("kse.repository"), "tests/org.kse.ui.statechart.tests/resources/replay", name);
	}

	private static IFile put(IProject project, String path, byte[] content) throws Exception {
		IFile file = project.getFile(path);
		if (file.getParent() instanceof IFolder folder && !folder.exists()) {
			folder.create(true, true, null);
		}
		if (file.exists()) {
			file.setContents(new ByteArrayInputStream(content), IResource.FORCE, null);
		} else {
			file.create(new ByteArrayInputStream(content), true, null);
		}
		return file;
	}

	/** Opens the file as a double click does (its default editor) and maximizes it, as a user replaying a match would. */
	private static ReplayEditor open(IFile file) throws Exception {
		IEditorPart editor = IDE.openEditor(Ui.page(), file);
		assertTrue(editor instanceof ReplayEditor, file.getName() + " opens in the Match Replay editor, not " + editor);
		if (!Ui.page().isPageZoomed()) {
			Ui.page().setPartState(Ui.page().getReference(editor), IWorkbenchPage.STATE_MAXIMIZED);
		}
		return (ReplayEditor) editor;
	}

	/** Waits until the page has read the log (ready) or refused it (error), and returns which. */
	private static String loaded(Browser browser) {
		String state = "return document.body && document.body.dataset.kseReplay ? document.body.dataset.kseReplay : ''";
		Ui.waitUntil(() -> Set.of("ready", "error").contains(String.valueOf(browser.evaluate(state))), PAGE_TIMEOUT);
		return String.valueOf(browser.evaluate(state));
	}

	private static String text(Browser browser, String script) {
		return String.valueOf(browser.evaluate(script));
	}

	private static List<JsonObject> records(Path log) throws Exception {
		List<JsonObject> records = new ArrayList<>();
		for (String line : Files.readAllLines(log, StandardCharsets.UTF_8)) {
			if (!line.isEmpty()) {
				records.add(JsonParser.parseString(line).getAsJsonObject());
			}
		}
		return records;
	}

	/** The robot's record in a frame. */
	private static JsonObject robot(JsonObject frame, String id) {
		for (JsonElement robot : frame.getAsJsonArray("robots")) {
			if (robot.getAsJsonObject().get("id").getAsString().equals(id)) {
				return robot.getAsJsonObject();
			}
		}
		throw new AssertionError(id + " is in the frame at " + frame.get("t"));
	}

	/** The diagram's id of each state (its path in the model) by the engine's name (GenerationPlan.stateName's rule). */
	private static Map<String, String> statesByEngineName(Path model) throws Exception {
		Model loaded = StatechartResources.load(model);
		Map<String, String> ids = new HashMap<>();
		loaded.eAllContents().forEachRemaining(each -> {
			if (each instanceof Node node) {
				String name = node.getName();
				String label = node.getLabel() == null ? "" : node.getLabel();
				String engine = name == null || name.isEmpty() || name.equals(label) ? (label.isEmpty() ? "unlabeled" : label.replaceAll("[^A-Za-z0-9_]", "_")) : name;
				ids.put("Node_" + engine, Notation.path(node));
			}
		});
		return ids;
	}

	private static final String OUTLINED = "var chart = document.querySelector('iframe.kse-replay-chart');"
			+ " if (!chart || chart.hidden || !chart.contentDocument) return '';"
			+ " return Array.from(chart.contentDocument.querySelectorAll('#kse-diagram g.kse-active[data-id]')).map(g => g.getAttribute('data-id')).sort().join(' ')";

	@Test
	void aMatchLogReplaysInTheWorkbenchWithTheRobotsStatechart() throws Exception {
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 900);
		assertEquals(ReplayEditor.ID, PlatformUI.getWorkbench().getEditorRegistry().getDefaultEditor("match.jsonl").getId(),
				"a .jsonl opens in the Match Replay editor by double click");
		Path source = resource("seed1-half20.jsonl");
		List<JsonObject> log = records(source);
		List<JsonObject> frames = log.stream().filter(record -> record.get("type").getAsString().equals("frame")).toList();
		List<JsonObject> events = log.stream().filter(record -> record.get("type").getAsString().equals("event")).toList();

		// only the Goalie's model in the workspace: the Attacker (away-1) has none
		IFile goalie = Ui.exampleModel(PROJECT, null, "Goalie");
		IProject project = goalie.getProject();
		IFile logFile = put(project, "logs/seed1-half20.jsonl", Files.readAllBytes(source));
		ReplayEditor editor = open(logFile);
		assertNull(editor.problem(), editor.problem());
		assertEquals(Set.of("Goalie"), editor.models().keySet(), "the model of the log's behaviour found in the workspace is named to the page: " + editor.models());
		assertTrue(editor.models().get("Goalie").matches("editor-[0-9a-f]{32}/Goalie\\.stct"), editor.models().toString());
		Browser browser = editor.browser();
		assertNotNull(browser);
		assertEquals("ready", loaded(browser), "the replay page read the log; it says: " + text(browser, "return window.kse && window.kse.replay ? window.kse.replay.message() : document.body.innerText"));
		assertEquals(1, Ui.page().getEditorReferences().length, "the model is lent to the page without opening its editor");
		browser.execute("window.kse.replay.seek(45); window.kse.replay.select('away-1')");
		boolean said = Ui.waitUntil(() -> text(browser, "return document.querySelector('.kse-replay-chart-message').hidden ? '' : document.querySelector('.kse-replay-chart-message').textContent")
				.startsWith("There is no Attacker.stct in the workspace's open projects: away-1's statechart cannot be shown"), 30_000);
		Ui.screenshot("61-replay-no-model");
		assertTrue(said, "away-1 plays the Attacker, whose model is not in the workspace; the page says: "
				+ text(browser, "return document.querySelector('.kse-replay-chart-message').textContent"));
		Ui.page().closeAllEditors(false);

		// with the Attacker's model as well
		Ui.exampleModel(PROJECT, null, "Attacker");
		editor = open(logFile);
		assertEquals(Set.of("Goalie", "Attacker"), editor.models().keySet(), editor.models().toString());
		Browser replay = editor.browser();
		assertEquals("ready", loaded(replay));
		assertEquals("", text(replay, "return window.kse.replay.message()"), "a whole log opens without a notice");
		// the field and the timeline, as the log has them
		assertEquals((double) frames.size(), replay.evaluate("return window.kse.replay.frameCount()"), "every frame of the log is read");
		assertEquals(String.valueOf(frames.size() - 1), text(replay, "return document.querySelector('.kse-replay-scrub').max"), "the timeline spans the frames");
		// this log's events are all state changes, each marked on the timeline
		assertEquals((double) events.size(), replay.evaluate("return document.querySelectorAll('.kse-replay-markers .kse-replay-event').length"),
				"the timeline marks the log's events");
		assertEquals("home-1 away-1", text(replay, "return window.kse.replay.robots().join(' ')"));
		assertEquals(2.0, replay.evaluate("return document.querySelectorAll('svg.kse-replay-field .kse-replay-marker').length"), "both robots are drawn on the field");
		Ui.screenshot("60-replay-opened");

		// home-1, the Goalie, at t = 50 s (PLAYING): its statechart outlines the states the log says
		double t = 50;
		JsonObject at = frames.stream().filter(frame -> frame.get("t").getAsDouble() <= t + 1e-6).reduce((first, second) -> second).orElseThrow();
		Map<String, String> ids = statesByEngineName(Path.of(project.getFile("Goalie.stct").getLocationURI()));
		List<String> wanted = new ArrayList<>();
		JsonArray active = robot(at, "home-1").getAsJsonArray("active");
		for (JsonElement state : active) {
			assertTrue(ids.containsKey(state.getAsString()), "the log's active state " + state + " is a state of Goalie.stct");
			wanted.add(ids.get(state.getAsString()));
		}
		String expected = String.join(" ", wanted.stream().sorted().toList());
		replay.execute("window.kse.replay.seek(" + t + "); window.kse.replay.select('home-1')");
		boolean outlined = Ui.waitUntil(() -> expected.equals(text(replay, OUTLINED)), PAGE_TIMEOUT);
		Ui.settle(500);
		Ui.screenshot("62-replay-goalie-at-50s");
		assertTrue(outlined, "home-1's chart outlines its active states at t = " + at.get("t") + ", " + active + " (" + expected + "); it outlines '"
				+ text(replay, OUTLINED) + "'; the page says: " + text(replay, "return document.querySelector('.kse-replay-robot').innerText"));
		assertEquals(at.get("t").getAsDouble(), replay.evaluate("return window.kse.replay.time()"), "the frame drawn is the last at or before t");
		assertEquals(String.join(",", active.asList().stream().map(JsonElement::getAsString).toList()), text(replay, "return window.kse.replay.activeNames().join(',')"));
		JsonObject pose = robot(at, "home-1");
		String drawn = text(replay, "var r = window.kse.replay.drawnRobots().find(r => r.id === 'home-1'); return r.x.toFixed(3) + ' ' + r.y.toFixed(3)");
		assertEquals(String.format(java.util.Locale.ROOT, "%.3f %.3f", pose.getAsJsonArray("pose").get(0).getAsDouble(), pose.getAsJsonArray("pose").get(1).getAsDouble()), drawn,
				"home-1 is drawn where the log has it");
		assertEquals(1, Ui.page().getEditorReferences().length, "still no statechart editor opened");

		// a step forward: the chart follows the next frame
		JsonObject next = frames.get(frames.indexOf(at) + 1);
		List<String> nextWanted = new ArrayList<>();
		robot(next, "home-1").getAsJsonArray("active").forEach(state -> nextWanted.add(ids.get(state.getAsString())));
		String nextExpected = String.join(" ", nextWanted.stream().sorted().toList());
		replay.execute("document.querySelector('[data-action=\"replay-forward\"]').click()");
		assertTrue(Ui.waitUntil(() -> nextExpected.equals(text(replay, OUTLINED)) && Double.valueOf(next.get("t").getAsDouble()).equals(replay.evaluate("return window.kse.replay.time()")), 30_000),
				"one frame forward, t = " + next.get("t") + ": " + nextExpected + "; outlined '" + text(replay, OUTLINED) + "'");

		// the Goalie's model opened in its editor and closed again: the replay still shows its chart
		String lentAs = editor.models().get("Goalie");
		assertEquals(lentAs, WorkspaceDiagramServer.name(Path.of(goalie.getLocationURI())), "the replay lends the Goalie's model");
		IEditorPart statechart = IDE.openEditor(Ui.page(), goalie, StatechartEditor.ID, false);
		Ui.settle(300);
		Ui.page().closeEditor(statechart, false);
		assertEquals(lentAs, WorkspaceDiagramServer.name(Path.of(goalie.getLocationURI())), "the replay's model keeps its name when its editor closes");
		// away-1 first, so that the chart's frame holds another page before home-1's is loaded anew
		Map<String, String> attackerIds = statesByEngineName(Path.of(project.getFile("Attacker.stct").getLocationURI()));
		String attacker = String.join(" ", robot(next, "away-1").getAsJsonArray("active").asList().stream().map(state -> attackerIds.get(state.getAsString())).sorted().toList());
		String chartUrl = "var chart = document.querySelector('iframe.kse-replay-chart'); return chart && chart.contentWindow ? chart.contentWindow.location.href : ''";
		replay.execute("window.kse.replay.select('away-1')");
		assertTrue(Ui.waitUntil(() -> text(replay, chartUrl).contains("Attacker.stct") && attacker.equals(text(replay, OUTLINED)), PAGE_TIMEOUT),
				"away-1's chart, the Attacker's, outlines " + attacker + "; it outlines '" + text(replay, OUTLINED) + "'; the page says: "
						+ text(replay, "return document.querySelector('.kse-replay-robot').innerText"));
		replay.execute("window.kse.replay.select('home-1')");
		assertTrue(Ui.waitUntil(() -> text(replay, chartUrl).contains("Goalie.stct") && nextExpected.equals(text(replay, OUTLINED)), PAGE_TIMEOUT),
				"home-1's chart is shown again after its editor was closed: outlined '" + text(replay, OUTLINED) + "'; the page says: "
						+ text(replay, "return document.querySelector('.kse-replay-robot').innerText"));
	}

	@Test
	void aLogCutShortOrNotALogOpensWithThePagesMessage() throws Exception {
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 900);
		IProject project = Ui.exampleModel(PROJECT, null, "Goalie").getProject();
		List<String> lines = Files.readAllLines(resource("seed1-half20.jsonl"), StandardCharsets.UTF_8);
		// cut in the middle of a frame's line, as a writer killed mid-line would leave it
		List<String> kept = lines.subList(0, lines.size() * 6 / 10);
		JsonObject lastFrame = kept.stream().map(line -> JsonParser.parseString(line).getAsJsonObject()).filter(record -> record.get("type").getAsString().equals("frame"))
				.reduce((first, second) -> second).orElseThrow();
		String cut = String.join("\n", kept) + "\n" + lines.get(kept.size()).substring(0, 200);
		ReplayEditor truncated = open(put(project, "logs/cut.jsonl", cut.getBytes(StandardCharsets.UTF_8)));
		assertEquals("ready", loaded(truncated.browser()), "a log cut short is replayed up to where it ends");
		assertEquals(String.format(java.util.Locale.ROOT, "The log ends at t = %.1f s: truncated (its last line is cut short).", lastFrame.get("t").getAsDouble()),
				text(truncated.browser(), "return document.querySelector('.kse-replay-notice').textContent"));
		Ui.screenshot("63-replay-truncated");
		Ui.page().closeAllEditors(false);

		ReplayEditor newer = open(put(project, "logs/v2.jsonl", String.join("\n", lines).replace("\"version\":1", "\"version\":2").getBytes(StandardCharsets.UTF_8)));
		assertEquals("error", loaded(newer.browser()));
		String v2 = text(newer.browser(), "return document.querySelector('.kse-replay-notice').textContent");
		assertTrue(v2.startsWith("Replays/logs/v2.jsonl: This match log has version 2; this page replays version 1"), v2);
		Ui.page().closeAllEditors(false);

		ReplayEditor notALog = open(put(project, "logs/transcript.jsonl", "kse-match: this is a console transcript, not a log\n".getBytes(StandardCharsets.UTF_8)));
		assertEquals(Map.of(), notALog.models(), "no behaviours in a file that is not a log");
		assertEquals("error", loaded(notALog.browser()));
		String message = text(notALog.browser(), "return document.querySelector('.kse-replay-notice').textContent");
		Ui.screenshot("64-replay-not-a-log");
		assertTrue(message.startsWith("Replays/logs/transcript.jsonl: This is not a match log: its first line is not JSON"), message);
		Ui.page().closeAllEditors(false);

		// a linked project outside the workspace folder: the server sends no file there, the editor says so
		Files.copy(resource("seed1-half20.jsonl"), elsewhere.resolve("away.jsonl"));
		var description = ResourcesPlugin.getWorkspace().newProjectDescription("Elsewhere");
		description.setLocationURI(elsewhere.toUri());
		IProject linked = ResourcesPlugin.getWorkspace().getRoot().getProject("Elsewhere");
		linked.create(description, null);
		linked.open(null);
		ReplayEditor outside = open(linked.getFile("away.jsonl"));
		Ui.settle(300);
		Ui.screenshot("65-replay-outside-the-workspace");
		assertNull(outside.browser(), "no page for a log the server cannot send");
		assertTrue(outside.problem().startsWith(elsewhere.resolve("away.jsonl").toRealPath() + " lies outside the workspace folder")
				|| outside.problem().startsWith(elsewhere.resolve("away.jsonl") + " lies outside the workspace folder"), outside.problem());
		assertTrue(outside.problem().contains("kse serve"), "the message says how to replay it: " + outside.problem());
	}
}
