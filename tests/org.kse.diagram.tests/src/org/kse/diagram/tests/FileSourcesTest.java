package org.kse.diagram.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.edit.command.SetCommand;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.diagram.server.FileSources;
import org.kse.diagram.server.StatechartSources.Source;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartPackage;

/**
 * Issue 14: the pages of one file (two tabs, or a page and the one that replaced it after its
 * connection dropped) share one model, one command stack and one layout; unsaved edits outlive
 * the last page; a save never overwrites a change made on disk since the model was read.
 */
class FileSourcesTest {

	@TempDir
	Path folder;
	private Path goalie;
	private final FileSources sources = new FileSources();

	@BeforeEach
	void copyTheGoalie() throws IOException {
		goalie = Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), folder.resolve("Goalie.stct"));
	}

	private static void rename(Source source, String name) {
		Node root = source.model().getNodes().get(0);
		source.domain().getCommandStack().execute(SetCommand.create(source.domain(), root, StatechartPackage.Literals.NODE__NAME, name));
	}

	@Test
	void twoPagesOfOneFileEditOneModelOnOneCommandStack() throws IOException {
		Source first = sources.open(goalie);
		Source second = sources.open(goalie);
		assertSame(first.model(), second.model());
		assertSame(first.domain().getCommandStack(), second.domain().getCommandStack());
		assertSame(first.shared(StringBuilder.class, StringBuilder::new), second.shared(StringBuilder.class, StringBuilder::new), "one layout");
		rename(first, "keeper");
		assertEquals("keeper", second.model().getNodes().get(0).getName());
		second.domain().getCommandStack().undo();
		assertEquals("goalie", first.model().getNodes().get(0).getName(), "one undo history");
		assertEquals(2, sources.pages(goalie));
	}

	@Test
	void aSaveInOnePageTellsTheOthersAndWritesTheFile() throws IOException {
		Source first = sources.open(goalie);
		Source second = sources.open(goalie);
		List<String> told = new ArrayList<>();
		first.onSave(() -> told.add("first"));
		second.onSave(() -> told.add("second"));
		rename(second, "keeper");
		second.save(() -> told.add("second saved"));
		assertEquals(List.of("second saved", "first"), told);
		assertEquals("keeper", StatechartResources.load(goalie).getNodes().get(0).getName());
	}

	@Test
	void unsavedEditsOutliveTheLastPageAndACleanModelIsReadAgain() throws IOException {
		Source page = sources.open(goalie);
		rename(page, "keeper");
		page.close();
		assertEquals(0, sources.pages(goalie));
		Source reconnected = sources.open(goalie);
		assertEquals("keeper", reconnected.model().getNodes().get(0).getName(), "the edit is still there");
		reconnected.domain().getCommandStack().undo();
		reconnected.close();
		Source fresh = sources.open(goalie);
		assertNotSame(page.model(), fresh.model(), "a model without unsaved edits is let go and read again");
	}

	@Test
	void aSaveNeverOverwritesAChangeMadeOnDiskSinceTheModelWasRead() throws IOException {
		Source page = sources.open(goalie);
		rename(page, "keeper");
		String theirs = Files.readString(goalie).replace("name=\"goalie\"", "name=\"theirs\"");
		Files.writeString(goalie, theirs);
		Files.setLastModifiedTime(goalie, FileTime.fromMillis(System.currentTimeMillis() + 5_000));
		IOException refused = assertThrows(IOException.class, () -> page.save(() -> {
		}));
		assertTrue(refused.getMessage().startsWith("Goalie.stct was changed on disk by another program"), refused.getMessage());
		assertEquals(theirs, Files.readString(goalie), "their version is kept");
	}
}
