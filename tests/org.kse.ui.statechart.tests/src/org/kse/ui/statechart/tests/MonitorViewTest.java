package org.kse.ui.statechart.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

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
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;
import org.kse.ui.statechart.monitor.MonitorDialog;
import org.kse.ui.statechart.monitor.MonitorView;

/**
 * KSE > Monitor… against a real {@code kse-match --monitor} (the one $KSE_MATCH names, e.g. the
 * examples' build/examples/kse-match; skipped without it): the dialog lists the running match and
 * its robots, Watch opens the Monitor view, where the robot whose behaviour's model is in the
 * workspace is shown live and the one whose model is not says so.
 */
@ExtendWith(UnexpectedDialogs.class)
class MonitorViewTest {

	private static final long PAGE_TIMEOUT = 90_000;

	@TempDir
	Path runtime;
	private Process match;

	@BeforeEach
	void startAMatch() throws Exception {
		String binary = System.getenv("KSE_MATCH");
		assumeTrue(binary != null && Files.isExecutable(Path.of(binary)),
				"KSE_MATCH names no kse-match built with --monitor (e.g. KSE_MATCH=build/examples/kse-match): the Monitor view is not tested against a running match");
		// this test's own discovery folder: the match announces itself there, the workbench reads it
		System.setProperty(RunningMatches.FOLDER_PROPERTY, runtime.resolve("kse/matches").toString());
		ProcessBuilder builder = new ProcessBuilder(binary, "--seed", "2", "--half", "60", "--start-playing", "--home", "Goalie:1,Defender:2", "--away", "none",
				"--monitor", "--monitor-wait", "--speed", "1", "--quiet");
		builder.environment().put("XDG_RUNTIME_DIR", runtime.toString());
		builder.redirectErrorStream(true).redirectOutput(runtime.resolve("match.out").toFile());
		match = builder.start();
	}

	@AfterEach
	void stop() throws Exception {
		if (match != null) {
			match.destroy();
			match.waitFor();
		}
		System.clearProperty(RunningMatches.FOLDER_PROPERTY);
		for (IViewReference view : Ui.page().getViewReferences()) {
			if (MonitorView.ID.equals(view.getId())) {
				Ui.page().hideView(view);
			}
		}
		Ui.page().closeAllEditors(false);
		// the view opens maximized; closed, it gives the window back to the editors and the other views
		assertFalse(Ui.page().isPageZoomed(), "closing the Monitor view leaves nothing maximized");
	}

	@Test
	void aRobotOfARunningMatchIsWatchedLiveAndOneWithoutItsModelSaysSo() throws Exception {
		Ui.exampleModel("Monitored", null, "Goalie"); // the Goalie's model; no Defender in the workspace
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 900);
		assertTrue(Ui.waitUntil(() -> RunningMatches.list().stream().anyMatch(m -> m.pid() == match.pid()), 30_000),
				"the match announced itself: " + Files.readString(runtime.resolve("match.out")));
		String key = RunningMatches.list().get(0).key();

		Ui.expectDialog(MonitorDialog.TITLE);
		String[] listed = new String[1];
		Ui.Answered answered = Ui.whenShown(shell -> MonitorDialog.TITLE.equals(shell.getText()), shell -> {
			Tree tree = Ui.find(shell, Tree.class).get(0);
			TreeItem matchItem = Arrays.stream(tree.getItems()).filter(item -> item.getText().startsWith("Match " + match.pid() + " ")).findFirst()
					.orElseThrow(() -> new AssertionError("the dialog lists the match " + match.pid()));
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
		MonitorView.Tile goalie = tiles.get(0);
		assertNull(goalie.problem(), goalie.problem());
		assertNotNull(goalie.browser());
		assertFalse(goalie.browser().getUrl().contains(key), "the page is given the match by pid, never its key: " + goalie.browser().getUrl());
		assertTrue(tiles.get(1).problem().startsWith("home-2 runs Defender, and no open project of the workspace has a Defender.stct"), tiles.get(1).problem());

		assertTrue(Ui.waitUntil(() -> "live".equals(goalie.browser().evaluate("return document.body.dataset.kseMonitor")), PAGE_TIMEOUT),
				"the page watches home-1 live; it says: " + goalie.browser().evaluate("return document.getElementById('kse-status') ? document.getElementById('kse-status').textContent : ''"));
		String state = "return JSON.stringify({taken: window.kse.monitor.taken(), active: document.querySelectorAll('#kse-diagram g.kse-active[data-id]').length,"
				+ " drawn: window.kse.monitor.active().length, clock: (document.querySelector('.kse-monitor-clock') || {}).textContent})";
		boolean following = Ui.waitUntil(() -> String.valueOf(goalie.browser().evaluate(state)).matches("\\{\"taken\":[1-9][0-9]*,\"active\":[1-9].*"), 30_000);
		Ui.screenshot("41-monitor-view");
		assertTrue(following, "transitions arrive and the active states are outlined: " + goalie.browser().evaluate(state));
		Ui.settle(1500);
		Ui.screenshot("42-monitor-view-later");
	}
}
