package org.kse.scxml.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.scxml.ScxmlExport;
import org.kse.scxml.ScxmlImport;
import org.kse.scxml.ScxmlProblem;

/**
 * Our own export read back: every conformance case and example statechart, exported to SCXML and
 * imported again, is the model it was: the same file, byte for byte, as KSE saves it (states,
 * labels, names, types, activities, connectors, transitions with their expressions, in the
 * model's order).
 */
class ScxmlImportRoundTripTest {

	private static final Path REPOSITORY = Path.of(System.getProperty("kse.repository", "../.."));

	static Stream<Path> models() throws IOException {
		List<Path> models = new ArrayList<>();
		try (Stream<Path> cases = Files.list(REPOSITORY.resolve("tests/conformance/cases"))) {
			cases.filter(file -> file.toString().endsWith(".stct")).sorted().forEach(models::add);
		}
		try (Stream<Path> examples = Files.walk(REPOSITORY.resolve("examples"), 2)) {
			examples.filter(file -> file.toString().endsWith(".stct")).sorted().forEach(models::add);
		}
		return models.stream();
	}

	private static ScxmlImport.Result imported(String scxml) throws IOException {
		return ScxmlImport.read(new ByteArrayInputStream(scxml.getBytes(StandardCharsets.UTF_8)), "Unnamed");
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("models")
	void anExportedStatechartImportsAsTheSameModel(Path file) throws IOException {
		Model original = StatechartResources.load(file);
		ScxmlExport.Result exported = ScxmlExport.export(original);
		// what the export refuses (and says why) is the export's tests' business
		Assumptions.assumeFalse(exported.refused(), () -> "the export refuses it: " + exported.problems());

		ScxmlImport.Result result = imported(exported.scxml());

		assertNotNull(result.model(), () -> ScxmlImportTest.problems(result));
		assertTrue(result.complete(), () -> ScxmlImportTest.problems(result));
		assertTrue(result.problems().stream().noneMatch(ScxmlProblem::isError), () -> ScxmlImportTest.problems(result));
		assertEquals(new String(StatechartResources.toBytes(original), StandardCharsets.US_ASCII),
				new String(StatechartResources.toBytes(result.model()), StandardCharsets.US_ASCII));
	}

	@Test
	void theExamplesAndNearlyEveryCaseGoRoundTrip() throws IOException {
		List<String> refused = new ArrayList<>();
		List<Path> all = models().toList();
		for (Path file : all) {
			if (ScxmlExport.export(StatechartResources.load(file)).refused()) {
				refused.add(file.getFileName().toString());
			}
		}
		assertTrue(refused.stream().noneMatch(name -> List.of("Goalie.stct", "Defender.stct", "Attacker.stct").contains(name)), refused::toString);
		assertTrue(all.size() - refused.size() >= 50, () -> "round trips: " + (all.size() - refused.size()) + " of " + all.size() + "; refused " + refused);
	}

	@Test
	void anExportedDocumentWhoseAnnotationsPointNowhereIsRefusedPerElement() throws IOException {
		Model goalie = StatechartResources.load(REPOSITORY.resolve("examples/Goalie/Goalie.stct"));
		String scxml = ScxmlExport.export(goalie).scxml();
		assertTrue(scxml.contains("kse:chain=\""), "the Goalie passes connectors");
		String broken = scxml.replaceFirst("kse:chain=\"[^\"]*\"", "kse:chain=\"9.9\"");

		ScxmlImport.Result result = imported(broken);

		assertNull(result.model());
		String problems = ScxmlImportTest.problems(result);
		assertTrue(problems.startsWith("ERROR <transition ") && problems.contains(": its target '9.9' is the label of no state or connector"), problems);
		assertTrue(problems.matches("(?s)ERROR <transition [^>]*> at \\d+:\\d+: .*"), problems);
	}

	@Test
	void anExportedDocumentKeepsItsModelNameAndTheRootsOwnName() throws IOException {
		Model goalie = StatechartResources.load(REPOSITORY.resolve("examples/Goalie/Goalie.stct"));

		Model back = imported(ScxmlExport.export(goalie).scxml()).model();

		assertEquals("Goalie", back.getName());
		assertEquals("goalie", back.getNodes().get(0).getName());
		assertFalse(back.getTransitions().isEmpty());
	}
}
