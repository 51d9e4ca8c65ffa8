package org.kse.formula.tests;

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
import org.kse.testing.Models;

/** {@code kse formula}, run in-process as the other command-line tests run kse. */
class FormulaCommandTest {

	@TempDir
	Path directory;

	static CommandRun kse(String... args) {
		return CommandRun.capture((out, err) -> new Kse(out, err).run(args));
	}

	@Test
	void aTransformedFormulaComesBackIntoTheFileOfOptionOAndExitsWithZero() throws IOException {
		Path formula = directory.resolve("Keeper.liveness");
		Files.writeString(formula, "keeper = Init.(watch | Dive)+\nwatch = Stare+.[Guard]\n");
		assertEquals(Kse.OK, kse("transform", formula.toString(), "-q").code());
		Path model = directory.resolve("Keeper.stct");
		Path back = directory.resolve("back/Keeper.liveness");

		CommandRun run = kse("formula", model.toString(), "-o", back.toString());

		assertEquals(Kse.OK, run.code(), run.all());
		assertEquals("wrote " + back + " (2 formulas)\n", run.out(), run.all());
		assertEquals("", run.err(), run.all());
		assertEquals("keeper = Init.(watch | Dive)+\nwatch = Stare+.[Guard]\n", Files.readString(back));
	}

	@Test
	void theLegacyGoalieGoesToStandardOutputWithAWarningPerGuardAndExitsWithOne() throws IOException {
		Path model = directory.resolve("Goalie.stct");
		Files.copy(Models.legacy("Goalie/Goalie.stct"), model);

		CommandRun run = kse("formula", model.toString());

		assertEquals(Kse.INVALID, run.code(), run.all());
		assertTrue(run.out().startsWith("Goalie\ngoalie = (playing | nonPlaying)+\n"), run.all());
		assertTrue(run.err().contains(model + ": 0.3.2.3.3.1 (0.3.2.3.3.1): warning: its transition to 0.3.2.3.3.2 (Scan) has the expression"
				+ " '/TimeoutAction.behavior.250'"), run.all());
		long guarded = StatechartResources.load(model).getTransitions().stream().filter(t -> t.getTE() != null && !t.getTE().isBlank()).count();
		assertEquals(32, guarded, "the team's guards and timers");
		assertEquals(guarded, run.err().lines().filter(line -> line.contains(": warning: ")).count(), run.all());
		assertTrue(run.err().contains(model + ": " + guarded + " parts of the statechart not expressed by the formulas"), run.all());
	}

	@Test
	void severalModelsGoIntoTheFolderOfOptionOOneFileEach() throws IOException {
		for (String name : new String[] { "A", "B" }) {
			Path formula = directory.resolve(name + ".liveness");
			Files.writeString(formula, name.toLowerCase() + " = X" + name + " || Y" + name + "\n");
			assertEquals(Kse.OK, kse("transform", formula.toString(), "-q").code());
		}
		Path folder = directory.resolve("formulas");

		CommandRun run = kse("formula", directory.resolve("A.stct").toString(), directory.resolve("B.stct").toString(), "-o", folder.toString());

		assertEquals(Kse.OK, run.code(), run.all());
		assertEquals("a = XA || YA\n", Files.readString(folder.resolve("A.liveness")));
		assertEquals("b = XB || YB\n", Files.readString(folder.resolve("B.liveness")));
	}

	@Test
	void aMissingOrBrokenModelExitsWithTwoAndNamesIt() throws IOException {
		Path missing = directory.resolve("nowhere.stct");
		CommandRun run = kse("formula", missing.toString());
		assertEquals(Kse.FAILED, run.code(), run.all());
		assertTrue(run.err().contains(missing.toString()), run.all());

		Path text = directory.resolve("text.stct");
		Files.writeString(text, "goalie = Init\n");
		run = kse("formula", text.toString());
		assertEquals(Kse.FAILED, run.code(), run.all());
		assertTrue(run.err().contains(text + ":1:1: not a statechart model"), run.all());

		run = kse("formula");
		assertEquals(Kse.FAILED, run.code(), run.all());
		assertTrue(run.err().contains("missing model file"), run.all());
	}

	@Test
	void helpSaysWhatItDoes() {
		for (String[] args : new String[][] { { "formula", "--help" }, { "help", "formula" } }) {
			CommandRun run = kse(args);
			assertEquals(Kse.OK, run.code(), run.all());
			assertTrue(run.out().startsWith("usage: kse formula <model.stct>... [-o out.liveness|folder]"), run.all());
		}
		assertTrue(kse("--help").out().contains("  formula <model.stct>..."));
		assertFalse(kse("formula", "--frobnicate", "x.stct").code() == Kse.OK);
	}
}
