package org.kse.diagram.server.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
 * the last page; a save never overwrites a change made on disk since the model was read. A file
 * changed on disk by another program is read again when nobody has unsaved edits, and otherwise
 * the pages are asked once, and the choice (reload, keep the edits) is every page's.
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

	/** Another program's version of the file: the root state renamed, with a time of its own. */
	private void changeOnDisk(String rootName) throws IOException {
		Files.writeString(goalie, Files.readString(goalie).replaceFirst("name=\"[^\"]*\" label=\"0\"", "name=\"" + rootName + "\" label=\"0\""));
		Files.setLastModifiedTime(goalie, FileTime.fromMillis(System.currentTimeMillis() + 5_000));
	}

	private static String rootName(Source source) {
		return source.access(() -> source.model().getNodes().get(0).getName());
	}

	private static List<String> listen(Source source) {
		List<String> told = new ArrayList<>();
		source.onDiskChange((change, detail) -> told.add(change + (detail == null ? "" : ": " + detail)));
		return told;
	}

	@Test
	void aFileChangedOnDiskWithoutUnsavedEditsIsReadAgainForEveryPage() throws IOException {
		Source first = sources.open(goalie);
		Source second = sources.open(goalie);
		List<String> firstTold = listen(first);
		List<String> secondTold = listen(second);
		sources.checkFiles();
		assertEquals(List.of(), firstTold, "nothing changed yet");
		changeOnDisk("theirs");
		sources.checkFiles();
		assertEquals(List.of("RELOADED"), firstTold);
		assertEquals(List.of("RELOADED"), secondTold);
		assertEquals("theirs", rootName(first));
		assertSame(first.model(), second.model(), "still one model");
		assertFalse(first.domain().getCommandStack().canUndo(), "a model read again starts a new history");
		sources.checkFiles();
		assertEquals(List.of("RELOADED"), firstTold, "told once");
	}

	@Test
	void underUnsavedEditsThePagesAreAskedAndKeepingTheEditsLetsTheSaveOverwrite() throws IOException {
		Source first = sources.open(goalie);
		Source second = sources.open(goalie);
		List<String> firstTold = listen(first);
		List<String> secondTold = listen(second);
		rename(first, "keeper");
		changeOnDisk("theirs");
		sources.checkFiles();
		sources.checkFiles();
		assertEquals(List.of("CONFLICT"), firstTold, "asked once per change");
		assertEquals(List.of("CONFLICT"), secondTold);
		assertEquals("keeper", rootName(first), "nothing is thrown away unasked");
		assertThrows(IOException.class, () -> second.save(() -> {
		}), "no save before the choice");
		second.keepEdits();
		assertEquals(List.of("CONFLICT", "KEPT"), firstTold, "the choice is every page's");
		first.save(() -> {
		});
		assertEquals("keeper", StatechartResources.load(goalie).getNodes().get(0).getName(), "the save overwrote their version, as chosen");
	}

	@Test
	void reloadingDropsTheUnsavedEditsOfEveryPage() throws IOException {
		Source first = sources.open(goalie);
		Source second = sources.open(goalie);
		List<String> secondTold = listen(second);
		rename(first, "keeper");
		changeOnDisk("theirs");
		sources.checkFiles();
		first.reload();
		assertEquals(List.of("CONFLICT", "RELOADED"), secondTold);
		assertEquals("theirs", rootName(second));
		assertFalse(second.domain().getCommandStack().canUndo());
	}

	@Test
	void aPageThatComesBackIsAskedAboutAChangeStillUndecided() throws IOException {
		Source page = sources.open(goalie);
		rename(page, "keeper");
		page.close();
		changeOnDisk("theirs");
		sources.checkFiles();
		Source reconnected = sources.open(goalie);
		assertEquals(List.of("CONFLICT"), listen(reconnected));
		assertEquals("keeper", rootName(reconnected));
	}

	@Test
	void aFileThatCannotBeReadIsReportedAndTheModelKept() throws IOException {
		Source page = sources.open(goalie);
		List<String> told = listen(page);
		Files.writeString(goalie, "<not a statechart");
		Files.setLastModifiedTime(goalie, FileTime.fromMillis(System.currentTimeMillis() + 5_000));
		sources.checkFiles();
		assertEquals(1, told.size());
		assertTrue(told.get(0).startsWith("UNREADABLE: "), told.get(0));
		assertEquals("goalie", rootName(page), "the model is kept");
	}
}
