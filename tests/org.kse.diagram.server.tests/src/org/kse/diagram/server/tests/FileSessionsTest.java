package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;

import org.eclipse.glsp.graph.GGraph;
import org.eclipse.glsp.graph.GLabel;
import org.eclipse.glsp.server.actions.SetDirtyStateAction;
import org.eclipse.glsp.server.features.undoredo.UndoAction;
import org.eclipse.glsp.server.features.directediting.ApplyLabelEditOperation;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.DiskChanges.DiskChangeAction;
import org.kse.diagram.server.DiskChanges.ResolveAction;
import org.kse.diagram.server.FileSources;

import com.google.gson.Gson;

/**
 * Issue 14: diagram sessions on the files of {@code kse serve}. A session whose file another
 * program changed shows the file read again and tells its page; under unsaved edits the page is
 * asked, and its answer is carried out. A page that asks for its model again keeps the undo
 * history and the unsaved edits that every page of the file shares.
 */
class FileSessionsTest {

	@TempDir
	Path folder;
	private Path goalie;
	private final FileSources sources = new FileSources();

	@BeforeEach
	void copyTheGoalie() throws IOException {
		goalie = Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), folder.resolve("Goalie.stct"));
	}

	private void renameOnDisk(String from, String to) throws IOException {
		Files.writeString(goalie, Files.readString(goalie).replace("name=\"" + from + "\"", "name=\"" + to + "\""));
		Files.setLastModifiedTime(goalie, FileTime.fromMillis(System.currentTimeMillis() + 5_000));
	}

	/** The id of the label that shows this text, or null. */
	private static String labelShowing(GGraph graph, String text) {
		for (var contents = graph.eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof GLabel label && text.equals(label.getText())) {
				return label.getId();
			}
		}
		return null;
	}

	private static boolean shows(GGraph graph, String text) {
		return labelShowing(graph, text) != null;
	}

	@Test
	void aSessionShowsTheFileReadAgainAndTellsItsPage() throws Exception {
		try (GlspSession session = new GlspSession(folder, sources)) {
			session.open("Goalie.stct");
			int graphs = session.graphs().size();
			renameOnDisk("Kick", "KickTheirs");
			sources.checkFiles();
			DiskChangeAction told = session.next(DiskChangeAction.class, 0);
			assertEquals("reloaded", told.getChange());
			assertEquals("Goalie.stct", told.getFile());
			assertTrue(shows(session.nextGraph(graphs), "KickTheirs"), "the page is sent the version on disk");
		}
	}

	@Test
	void underUnsavedEditsThePageIsAskedAndItsChoiceCarriedOut() throws Exception {
		try (GlspSession session = new GlspSession(folder, sources)) {
			GGraph opened = session.open("Goalie.stct");
			session.graphAfter(new ApplyLabelEditOperation(labelShowing(opened, "Scan"), "ScanMine"));
			renameOnDisk("Kick", "KickTheirs");
			sources.checkFiles();
			assertEquals("conflict", session.next(DiskChangeAction.class, 0).getChange());
			int graphs = session.graphs().size();
			// the page's Reload, as it arrives: read from JSON
			session.send(new Gson().fromJson("{\"kind\":\"kseResolveDiskChange\",\"reload\":true}", ResolveAction.class));
			assertEquals("reloaded", session.next(DiskChangeAction.class, 1).getChange());
			GGraph reloaded = session.nextGraph(graphs);
			assertTrue(shows(reloaded, "KickTheirs") && shows(reloaded, "Scan"), "the version on disk, without the dropped edit");
			assertEquals(false, session.all(SetDirtyStateAction.class).get(session.count(SetDirtyStateAction.class) - 1).isDirty());
		}
	}

	@Test
	void aPageThatAsksForItsModelAgainKeepsTheSharedUndoHistoryAndUnsavedEdits() throws Exception {
		try (GlspSession session = new GlspSession(folder, sources)) {
			GGraph opened = session.open("Goalie.stct");
			session.graphAfter(new ApplyLabelEditOperation(labelShowing(opened, "Scan"), "ScanMine"));
			int dirtyStates = session.count(SetDirtyStateAction.class);
			GGraph again = session.open("Goalie.stct");
			assertTrue(shows(again, "ScanMine"));
			assertEquals(true, session.next(SetDirtyStateAction.class, dirtyStates).isDirty(), "the edit is still unsaved");
			assertTrue(shows(session.graphAfter(new UndoAction()), "Scan"), "and undone by undo");
		}
	}
}
