package org.kse.scxml.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.scxml.ScxmlImport;
import org.kse.scxml.ScxmlProblem;
import org.kse.testing.NetworkTrap;

/**
 * Files that are not what they should be: malformed XML named by line and column, a DOCTYPE with
 * external entities that must be neither fetched nor read, a huge chart and a deep one that must
 * not hang or crash the import.
 */
class ScxmlImportHostileInputTest {

	@TempDir
	Path directory;

	@Test
	void malformedXmlIsAnErrorAtItsLineAndColumn() throws IOException {
		ScxmlImport.Result result = ScxmlImport.read(ScxmlImportTest.DATA.resolve("Malformed.scxml"));

		assertNull(result.model());
		assertEquals(1, result.problems().size(), () -> ScxmlImportTest.problems(result));
		ScxmlProblem problem = result.problems().get(0);
		assertTrue(problem.isError());
		assertEquals("the document at 6:3", problem.element(), "where the unclosed <state id=\"Open\"> is found out");
		assertTrue(problem.message().startsWith("not well-formed XML: ") && problem.message().contains("state"), problem.message());
		assertEquals("Malformed.scxml:6:3: error: " + problem.message(), ScxmlImport.format("Malformed.scxml", problem));
	}

	@Test
	void aDoctypeIsRefusedAndItsExternalEntitiesAreNeitherReadNorFetched() throws IOException {
		Path secret = Files.writeString(directory.resolve("secret.txt"), "TOP-SECRET-TEXT");
		try (NetworkTrap trap = new NetworkTrap()) {
			Path file = Files.writeString(directory.resolve("Hostile.scxml"), """
					<?xml version="1.0" encoding="UTF-8"?>
					<!DOCTYPE scxml [
					  <!ENTITY secret SYSTEM "%s">
					  <!ENTITY remote SYSTEM "%s/entity">
					  <!ENTITY %% remoteDtd SYSTEM "%s/dtd">
					  %%remoteDtd;
					]>
					<scxml xmlns="http://www.w3.org/2005/07/scxml" version="1.0" name="Hostile">
					  <state id="Leak"><transition cond="&secret;&remote;" target="Leak"/></state>
					</scxml>
					""".formatted(secret.toUri(), trap.remote(), trap.remote()));

			ScxmlImport.Result result = ScxmlImport.read(file);

			assertNull(result.model());
			assertEquals(1, result.problems().size(), () -> ScxmlImportTest.problems(result));
			assertEquals("the document at 2:10", result.problems().get(0).element());
			assertTrue(result.problems().get(0).message().contains("DOCTYPE"), result.problems().get(0).message());
			assertFalse(ScxmlImportTest.problems(result).contains("TOP-SECRET-TEXT"), "the file was not read");
			assertNull(trap.take(), "nothing was fetched");
		}
	}

	@Test
	void theCommittedFixtureWithAnExternalEntityIsRefusedAtItsDoctype() throws IOException {
		ScxmlImport.Result result = ScxmlImport.read(ScxmlImportTest.DATA.resolve("ExternalEntity.scxml"));

		assertNull(result.model());
		assertEquals("ERROR the document at 2:10: the file declares a DOCTYPE, which KSE does not read: no entity or DTD of it is expanded, fetched or read (SCXML needs none)",
				ScxmlImportTest.problems(result));
	}

	@Test
	void aChartOfTenThousandStatesIsImportedAndValidatedWithoutHanging() throws IOException {
		int states = 10_000;
		StringBuilder text = new StringBuilder("<scxml xmlns=\"http://www.w3.org/2005/07/scxml\" version=\"1.0\" name=\"Huge\">\n");
		for (int i = 0; i < states; i++) {
			text.append("<state id=\"s").append(i).append("\"><transition cond=\"TimeoutCheck(behavior)\" target=\"s").append((i + 1) % states)
					.append("\"/></state>\n");
		}
		Path file = Files.writeString(directory.resolve("Huge.scxml"), text.append("</scxml>\n"));

		// a bound far above the time it takes, so that only a hang fails
		ScxmlImport.Result result = assertTimeoutPreemptively(Duration.ofMinutes(2), () -> ScxmlImport.read(file));

		assertNotNull(result.model(), () -> ScxmlImportTest.problems(result).lines().limit(5).toList().toString());
		assertEquals(states + 1, result.model().getNodes().get(0).getChildren().size(), "the states and the START");
		assertEquals(states + 1, result.model().getTransitions().size());
	}

	@Test
	void aChartNestedDeeperThanKseReadsIsAnErrorNotACrash() throws IOException {
		int depth = 5_000;
		StringBuilder text = new StringBuilder("<scxml xmlns=\"http://www.w3.org/2005/07/scxml\" version=\"1.0\" name=\"Deep\">");
		for (int i = 0; i < depth; i++) {
			text.append("<state id=\"s").append(i).append("\">");
		}
		text.append("</state>".repeat(depth)).append("</scxml>");
		Path file = Files.writeString(directory.resolve("Deep.scxml"), text);

		ScxmlImport.Result result = assertTimeoutPreemptively(Duration.ofMinutes(1), () -> ScxmlImport.read(file));

		assertNull(result.model());
		assertTrue(ScxmlImportTest.problems(result).contains("nests elements deeper than"), ScxmlImportTest.problems(result));
	}

	@Test
	void anEmptyFileAndAFolderSayWhatTheyAre() throws IOException {
		Path empty = Files.writeString(directory.resolve("Empty.scxml"), "");
		ScxmlImport.Result result = ScxmlImport.read(empty);
		assertNull(result.model());
		assertTrue(result.problems().get(0).isError(), () -> ScxmlImportTest.problems(result));

		IOException folder = org.junit.jupiter.api.Assertions.assertThrows(IOException.class, () -> ScxmlImport.read(directory));
		assertTrue(folder.getMessage().contains("is a folder"), folder.getMessage());
	}
}
