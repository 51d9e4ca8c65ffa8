package org.kse.ui.statechart.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Tree;
import org.eclipse.swt.widgets.TreeItem;
import org.eclipse.ui.IViewReference;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.websocket.RunningMatches;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.notation.Notation;
import org.kse.testing.FakeMatch;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;
import org.kse.ui.statechart.monitor.MonitorDialog;
import org.kse.ui.statechart.monitor.MonitorView;

/**
 * KSE > Monitor… against a running match: the dialog lists the match and its robots, Watch opens
 * the Monitor view, where the robot whose behaviour's model is in the workspace is shown live and
 * the one whose model is not says so.
 * <p>
 * The match is a real {@code kse-match --monitor} when $KSE_MATCH names one (e.g. the examples'
 * build/examples/kse-match); otherwise, as in the Maven build, which runs before the C++ runtime
 * is built, a {@link FakeMatch} that announces itself in the same way and plays real transitions
 * of the Goalie's model. Against the fake the test knows every line the match sends, so it also
 * checks that exactly its active states are outlined, its transitions listed, and that the page
 * says the match ended when the result comes.
 */
@ExtendWith(UnexpectedDialogs.class)
class MonitorViewTest {

	private static final long PAGE_TIMEOUT = 90_000;

	@TempDir
	Path runtime;
	private String previousFolder;
	/** The real kse-match, when $KSE_MATCH names one. */
	private Process match;
	/** Otherwise the fake, and what its Goalie (home-1) does. */
	private FakeMatch fake;
	private FakeMatch.Script goalie;
	private long pid;

	@BeforeEach
	void startAMatch() throws Exception {
		// this test's own discovery folder: the match announces itself there, the workbench reads it
		previousFolder = System.getProperty(RunningMatches.FOLDER_PROPERTY);
		Path folder = runtime.resolve("kse/matches");
		System.setProperty(RunningMatches.FOLDER_PROPERTY, folder.toString());
		String binary = System.getenv("KSE_MATCH");
		if (binary != null && !binary.isEmpty()) {
			// named but not there is a mistake of whoever runs the tests, not a reason to test less
			assertTrue(Files.isExecutable(Path.of(binary)), "KSE_MATCH=" + binary + " is no executable kse-match (unset it to play a fake match)");
			ProcessBuilder builder = new ProcessBuilder(binary, "--seed", "2", "--half", "60", "--start-playing", "--home", "Goalie:1,Defender:2", "--away",
					"none", "--monitor", "--monitor-wait", "--speed", "1", "--quiet");
			builder.environment().put("XDG_RUNTIME_DIR", runtime.toString());
			builder.redirectErrorStream(true).redirectOutput(runtime.resolve("match.out").toFile());
			match = builder.start();
			pid = match.pid();
			return;
		}
		FakeMatch.Robot home1 = new FakeMatch.Robot("home-1", "home", 1, "Goalie", example("Goalie"));
		FakeMatch.Robot home2 = new FakeMatch.Robot("home-2", "home", 2, "Defender", example("Defender"));
		fake = new FakeMatch(FakeMatch.newKey(), 2, List.of(home1, home2));
		// joined after its first cycle (as the seeded logs' first frame: the end of 0.2.2 reached), the
		// Goalie loops round 0.2.2, finds the game playing and starts scanning for the ball
		goalie = new FakeMatch.Script(home1, "0", "0.2", "0.2.2", "0.2.2.5")
				.cycle("0.2.2->0.2.2", "0.2.2.1->0.2.2.2", "0.2.2.2->0.2.2.3", "0.2.2.3.1->0.2.2.3.2", "0.2.2.3.2->0.2.2.3.3", "0.2.2.3.3.1->0.2.2.3.3.2")
				.cycle("0.2.2.3.3.2->0.2.2.3.3.2")
				.cycle("0.2.2.3.3.2->0.2.2.3.3.2");
		fake.announce(folder);
		fake.play(goalie);
		pid = fake.pid();
		match = null;
	}

	private static Model example(String behaviour) throws Exception {
		return StatechartResources.load(Path.of(System.getProperty("kse.examples"), behaviour, behaviour + ".stct"));
	}

	@AfterEach
	void stop() throws Exception {
		try {
			for (IViewReference view : Ui.page().getViewReferences()) {
				if (MonitorView.ID.equals(view.getId())) {
					Ui.page().hideView(view);
				}
			}
			Ui.page().closeAllEditors(false);
			// the view opens maximized; closed, it gives the window back to the editors and the other views
			assertFalse(Ui.page().isPageZoomed(), "closing the Monitor view leaves nothing maximized");
		} finally {
			if (match != null) {
				match.destroy();
				match.waitFor();
			}
			if (fake != null) {
				fake.close();
			}
			if (previousFolder == null) {
				System.clearProperty(RunningMatches.FOLDER_PROPERTY);
			} else {
				System.setProperty(RunningMatches.FOLDER_PROPERTY, previousFolder);
			}
		}
	}

	@Test
	void aRobotOfARunningMatchIsWatchedLiveAndOneWithoutItsModelSaysSo() throws Exception {
		Ui.exampleModel("Monitored", null, "Goalie"); // the Goalie's model; no Defender in the workspace
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 900);
		assertTrue(Ui.waitUntil(() -> RunningMatches.list().stream().anyMatch(m -> m.pid() == pid), 30_000),
				"the match announced itself: " + (match != null ? Files.readString(runtime.resolve("match.out")) : fake));
		String key = RunningMatches.list().get(0).key();

		Ui.expectDialog(MonitorDialog.TITLE);
		String[] listed = new String[1];
		Ui.Answered answered = Ui.whenShown(shell -> MonitorDialog.TITLE.equals(shell.getText()), shell -> {
			Tree tree = Ui.find(shell, Tree.class).get(0);
			TreeItem matchItem = Arrays.stream(tree.getItems()).filter(item -> item.getText().startsWith("Match " + pid + " · seed 2 ")).findFirst()
					.orElseThrow(() -> new AssertionError("the dialog lists the match " + pid + ": "
							+ Arrays.stream(tree.getItems()).map(TreeItem::getText).toList()));
			listed[0] = String.join(", ", Arrays.stream(matchItem.getItems()).map(TreeItem::getText).toList());
			Ui.screenshotOf(shell, "40-monitor-dialog");
			Event tick = new Event();
			tick.detail = SWT.CHECK;
			tick.item = matchItem;
			matchItem.setChecked(true);
			tree.notifyListeners(SWT.Selection, tick);
			Ui.press(shell, "Watch");
		});
		Ui.run("org.kse.ui.monitor");
		answered.check("Monitor");
		assertEquals("home-1   Goalie, home-2   Defender", listed[0], "the match's robots with their behaviours");

		MonitorView view = Arrays.stream(Ui.page().getViewReferences()).filter(reference -> MonitorView.ID.equals(reference.getId()))
				.map(reference -> (MonitorView) reference.getView(true)).findFirst().orElseThrow(() -> new AssertionError("Watch opened the Monitor view"));
		List<MonitorView.Tile> tiles = view.tiles();
		assertEquals(List.of("home-1", "home-2"), tiles.stream().map(MonitorView.Tile::robot).toList());
		MonitorView.Tile home1 = tiles.get(0);
		assertNull(home1.problem(), home1.problem());
		assertNotNull(home1.browser());
		assertFalse(home1.browser().getUrl().contains(key), "the page is given the match by pid, never its key: " + home1.browser().getUrl());
		assertTrue(tiles.get(1).problem().startsWith("home-2 runs Defender, and no open project of the workspace has a Defender.stct"), tiles.get(1).problem());

		assertTrue(Ui.waitUntil(() -> "live".equals(home1.browser().evaluate("return document.body.dataset.kseMonitor")), PAGE_TIMEOUT),
				"the page watches home-1 live; it says: " + home1.browser().evaluate("return document.getElementById('kse-status') ? document.getElementById('kse-status').textContent : ''")
						+ (fake != null ? "; the fake match was told " + fake.received() + ", problems " + fake.problems() : ""));
		if (fake != null) {
			followsTheFakeMatchToItsEnd(home1);
			return;
		}
		String state = "return JSON.stringify({taken: window.kse.monitor.taken(), active: document.querySelectorAll('#kse-diagram g.kse-active[data-id]').length,"
				+ " drawn: window.kse.monitor.active().length, clock: (document.querySelector('.kse-monitor-clock') || {}).textContent})";
		boolean following = Ui.waitUntil(() -> String.valueOf(home1.browser().evaluate(state)).matches("\\{\"taken\":[1-9][0-9]*,\"active\":[1-9].*"), 30_000);
		Ui.screenshot("41-monitor-view");
		assertTrue(following, "transitions arrive and the active states are outlined: " + home1.browser().evaluate(state));
		Ui.settle(1500);
		Ui.screenshot("42-monitor-view-later");
	}

	/** What the fake played is what the tile shows: its active states outlined, its transitions listed, then its end. */
	private void followsTheFakeMatchToItsEnd(MonitorView.Tile home1) {
		String outlined = "return Array.from(document.querySelectorAll('#kse-diagram g.kse-active[data-id]')).map(g => g.getAttribute('data-id')).sort().join(' ')";
		String expected = String.join(" ", goalie.lastActiveStates().stream().map(Notation::path).sorted().toList());
		boolean caughtUp = Ui.waitUntil(() -> expected.equals(home1.browser().evaluate(outlined))
				&& Double.valueOf(goalie.taken()).equals(home1.browser().evaluate("return window.kse.monitor.taken()")), 30_000);
		Ui.settle(500); // the last transition's flash fades in the screenshot's place
		Ui.screenshot("41-monitor-view");
		assertTrue(caughtUp, "the tile outlines the Goalie's states " + goalie.lastActive() + " (" + expected + ") after " + goalie.taken()
				+ " transitions; it outlines " + home1.browser().evaluate(outlined) + " after " + home1.browser().evaluate("return window.kse.monitor.taken()"));
		assertEquals(Boolean.TRUE, home1.browser().evaluate("return document.querySelector('.kse-monitor-warning').hidden"),
				"the match's chart has the diagram's states and transitions, so there is no warning: "
						+ home1.browser().evaluate("return document.querySelector('.kse-monitor-warning').textContent"));
		assertEquals(String.valueOf(goalie.taken()), home1.browser().evaluate("return String(document.querySelectorAll('.kse-monitor-list li').length)"),
				"the panel lists every transition taken");
		assertEquals("0.2.2.3.3.2 → 0.2.2.3.3.2", home1.browser().evaluate("return document.querySelector('.kse-monitor-list li .kse-monitor-move').textContent"),
				"the newest transition is listed first: Scan again");
		String guard = String.valueOf(home1.browser().evaluate("return document.querySelector('.kse-monitor-list li .kse-monitor-guard').textContent"));
		assertTrue(guard.startsWith("[TimeoutCheck(behavior)"), "with its guard from the model: " + guard);
		assertEquals("t = 1.3 s", home1.browser().evaluate("return document.querySelector('.kse-monitor-clock').textContent"), "the match's time, from its frames");

		fake.finish();
		boolean ended = Ui.waitUntil(() -> "ended".equals(home1.browser().evaluate("return document.body.dataset.kseMonitor")), 30_000);
		Ui.screenshot("42-monitor-view-ended");
		assertTrue(ended, "after the result the page says the match ended: " + home1.browser().evaluate("return document.body.dataset.kseMonitor"));
		assertEquals("FINISHED", home1.browser().evaluate("return document.querySelector('.kse-monitor-game').textContent"));
		assertEquals("1 : 0", home1.browser().evaluate("return document.querySelector('.kse-monitor-score').textContent"));
		assertEquals(expected, home1.browser().evaluate(outlined), "the last configuration stays outlined");
		assertEquals(List.of(), fake.problems(), "the workbench's relay spoke to the match as docs/monitor.md says");
		assertTrue(fake.received().stream().anyMatch(line -> line.endsWith(": {\"type\":\"subscribe\",\"robots\":[\"home-1\"]}")),
				"the relay subscribed to the robot shown, home-1, only: " + fake.received());
	}
}
