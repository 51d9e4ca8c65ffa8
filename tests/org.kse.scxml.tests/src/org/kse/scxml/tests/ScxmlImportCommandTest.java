package org.kse.scxml.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.cli.Kse;
import org.kse.model.StatechartResources;
import org.kse.testing.CommandRun;

/** {@code kse import-scxml}, run in-process as the other command-line tests run kse. */
class ScxmlImportCommandTest {

	@TempDir
	Path directory;

	static CommandRun kse(String... args) {
		return CommandRun.capture((out, err) -> new Kse(out, err).run(args));
	}

	private Path copy(String fixture) throws IOException {
		return Files.copy(ScxmlImportTest.DATA.resolve(fixture), directory.resolve(fixture));
	}

	@Test
	void aChartThatMapsWhollyIsWrittenWhereOptionOSaysAndValidates() throws IOException {
		Path chart = copy("TrafficLight.scxml");
		Path model = directory.resolve("out/Crossing.stct");

		CommandRun run = kse("import-scxml", chart.toString(), "-o", model.toString());

		assertEquals(Kse.OK, run.code(), run.all());
		assertEquals("wrote " + model + " (16 states, 10 transitions)\n", run.out(), run.all());
		assertEquals(Kse.OK, kse("validate", model.toString()).code(), kse("validate", model.toString()).all());
		assertEquals("TrafficLight", StatechartResources.load(model).getName());
	}

	@Test
	void withoutOptionOTheModelGoesBesideTheChart() throws IOException {
		Path chart = copy("Initials.scxml");

		CommandRun run = kse("import-scxml", chart.toString());

		assertEquals(Kse.OK, run.code(), run.all());
		assertTrue(Files.isRegularFile(directory.resolve("Initials.stct")), run.all());
	}

	@Test
	void anEventDrivenChartPrintsAnErrorPerElementWithFileLineAndColumnAndWritesNothing() throws IOException {
		Path chart = copy("EventDriven.scxml");
		Path model = directory.resolve("Player.stct");

		CommandRun run = kse("import-scxml", chart.toString(), "-o", model.toString());

		assertEquals(Kse.INVALID, run.code(), run.all());
		assertEquals("", run.out(), run.all());
		assertTrue(run.err().contains(chart + ":9:53: error: <transition event=\"start\" target=\"Running\">: the event 'start': KSE's engine raises no events"),
				run.all());
		assertTrue(run.err().lines().anyMatch(line -> line.startsWith(chart + ":5:16: warning: <datamodel>: left out")), run.all());
		assertTrue(run.err().lines().reduce((a, b) -> b).orElse("").matches("kse: .*EventDriven.scxml: \\d+ errors, no model written"), run.all());
		assertFalse(Files.exists(model), "no model written");
	}

	@Test
	void whatIsLeftOutIsAWarningEachTheModelIsWrittenAndTheExitCodeIsOne() throws IOException {
		Path chart = copy("SideEffects.scxml");

		CommandRun run = kse("import-scxml", chart.toString());

		assertEquals(Kse.INVALID, run.code(), run.all());
		assertTrue(run.out().startsWith("wrote " + directory.resolve("SideEffects.stct")), run.all());
		assertEquals(5, run.err().lines().filter(line -> line.contains(": warning: <")).count(), run.all());
		assertTrue(run.err().contains(chart + ": 5 parts of the document left out of the model"), run.all());
	}

	@Test
	void aMalformedFileIsNamedByLineAndColumn() throws IOException {
		Path chart = copy("Malformed.scxml");

		CommandRun run = kse("import-scxml", chart.toString());

		assertEquals(Kse.INVALID, run.code(), run.all());
		assertTrue(run.err().startsWith(chart + ":6:3: error: not well-formed XML: "), run.all());
	}

	@Test
	void helpUsageAndAMissingFile() {
		CommandRun help = kse("import-scxml", "--help");
		assertEquals(Kse.OK, help.code());
		assertTrue(help.out().startsWith("usage: kse import-scxml <chart.scxml> [-o model.stct]"), help.all());
		assertEquals(help.out(), kse("help", "import-scxml").out());
		assertTrue(kse("--help").out().contains("import-scxml <chart.scxml>") || kse("help").out().contains("import-scxml <chart.scxml>"));

		CommandRun none = kse("import-scxml");
		assertEquals(Kse.FAILED, none.code());
		assertTrue(none.err().startsWith("kse: missing SCXML file"), none.all());

		CommandRun missing = kse("import-scxml", directory.resolve("nothing.scxml").toString());
		assertEquals(Kse.FAILED, missing.code());
		assertTrue(missing.err().contains("nothing.scxml: no such file"), missing.all());
	}
}
