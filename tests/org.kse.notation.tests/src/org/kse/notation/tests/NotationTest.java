package org.kse.notation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.testing.Models;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.notation.Arrange;
import org.kse.notation.Bounds;
import org.kse.notation.LegacyNotation;
import org.kse.notation.Notation;
import org.kse.notation.NotationFiles;

/**
 * Where the diagram draws each state: arranged by ELK with children inside their parents and
 * no overlaps, read from the original tool's .kse diagrams, and kept in a notation file beside
 * the model that survives a reordered model file and reports a broken file instead of failing.
 */
class NotationTest {

	static List<Path> legacyDiagrams() {
		return Models.legacyFiles(".kse");
	}

	/** Every child inside its parent (below the header), siblings apart. */
	private static void assertWellPlaced(Model model, Notation notation) {
		for (Node state : Models.allNodes(model)) {
			Bounds bounds = notation.get(state);
			assertNotNull(bounds, () -> "placed: " + state.getLabel());
			assertTrue(bounds.width() > 0 && bounds.height() > 0, () -> state.getLabel() + " has a size: " + bounds);
			List<Node> children = state.getChildren();
			assertTrue(children.isEmpty() || bounds.width() >= org.kse.notation.Shapes.headerWidth(state) - 0.5,
					() -> state.getLabel() + " is wide enough for its name and label: " + bounds);
			for (int i = 0; i < children.size(); i++) {
				Bounds child = notation.get(children.get(i));
				String label = children.get(i).getLabel();
				assertTrue(child.x() >= 0 && child.y() >= Arrange.HEADER && child.right() <= bounds.width() + 0.5
						&& child.bottom() <= bounds.height() + 0.5, () -> label + " " + child + " inside " + state.getLabel() + " " + bounds);
				for (int j = i + 1; j < children.size(); j++) {
					Bounds other = notation.get(children.get(j));
					String otherLabel = children.get(j).getLabel();
					assertTrue(!child.overlaps(other), () -> label + " and " + otherLabel + " overlap");
				}
			}
		}
	}

	@Test
	void arrangeAllPlacesEveryStateOfTheGoalieInsideItsParentWithoutOverlaps() throws IOException {
		Model goalie = StatechartResources.load(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"));
		Notation notation = Arrange.all(goalie);
		assertEquals(Models.allNodes(goalie).size(), notation.size());
		assertWellPlaced(goalie, notation);
		Notation again = Arrange.all(goalie);
		for (Node state : Models.allNodes(goalie)) {
			assertEquals(notation.get(state), again.get(state), "the same model is arranged the same way");
		}
	}

	@ParameterizedTest
	@MethodSource("legacyDiagrams")
	void theOriginalToolsDiagramGivesItsPositions(Path diagram) throws IOException {
		Path modelFile = diagram.resolveSibling(diagram.getFileName().toString().replace(".kse", ".stct"));
		Model model = StatechartResources.load(modelFile);
		String text = Files.readString(diagram);
		Notation notation = LegacyNotation.read(diagram, model);
		assertTrue(notation.covers(model), "every state has bounds");
		// the first state the diagram places, at the position written in the file
		var reference = java.util.regex.Pattern
				.compile("href=\"[^\"#]*#([^\"]+)\"/>\\s*<layoutConstraint xmi:type=\"notation:Bounds\" xmi:id=\"[^\"]*\" x=\"(\\d+)\" y=\"(\\d+)\"")
				.matcher(text);
		assertTrue(reference.find(), "a placed state in " + diagram);
		Node first = (Node) model.eResource().getEObject(reference.group(1));
		assertEquals(Double.parseDouble(reference.group(2)), notation.get(first).x());
		assertEquals(Double.parseDouble(reference.group(3)), notation.get(first).y());

		Path copy = Files.createTempDirectory("kse-notation").resolve(modelFile.getFileName());
		Files.copy(modelFile, copy);
		Files.copy(diagram, LegacyNotation.beside(copy));
		var opened = NotationFiles.open(copy, StatechartResources.load(copy));
		assertEquals(NotationFiles.Source.LEGACY_DIAGRAM, opened.source(), "a model with a .kse diagram opens with its positions");
	}

	@Test
	void aModelWithoutANotationOpensArrangedAndTheNotationFileRoundTrips(@TempDir Path directory) throws IOException {
		Path modelFile = directory.resolve("Goalie.stct");
		Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), modelFile);
		Model model = StatechartResources.load(modelFile);
		var opened = NotationFiles.open(modelFile, model);
		assertEquals(NotationFiles.Source.ARRANGED, opened.source());
		assertNull(opened.problem());
		assertTrue(opened.notation().covers(model));

		NotationFiles.write(modelFile, model, opened.notation());
		assertTrue(Files.isRegularFile(directory.resolve("Goalie.notation.json")));
		assertEquals(Files.readString(modelFile), Files.readString(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct")),
				"the model file is untouched");
		var reopened = NotationFiles.open(modelFile, StatechartResources.load(modelFile));
		assertEquals(NotationFiles.Source.SIDECAR, reopened.source());
		Model again = StatechartResources.load(modelFile);
		for (Node state : Models.allNodes(again)) {
			Node same = (Node) model.eResource().getEObject(Notation.path(state));
			assertEquals(opened.notation().get(same), reopened.notation().get(state), state.getLabel());
		}
	}

	@Test
	void aStateIsFoundByLabelAndNameWhenTheFileWasReordered() {
		Model model = Models.model("M");
		Node root = Models.root(model, "m", "0", "OR");
		Node start = Models.child(root, "0.1", "0.1", "START");
		Node a = Models.child(root, "A", "0.2", "BASIC");
		Node b = Models.child(root, "B", "0.3", "BASIC");
		Notation notation = Arrange.all(model);
		Bounds placedB = notation.get(b);
		root.getChildren().move(1, b); // B is now where A was in the file
		assertEquals(placedB, notation.get(b), "found by label and name");
		assertNotNull(notation.get(a));
		assertNotNull(notation.get(start));
	}

	@Test
	void aBrokenNotationFileIsReportedAndTheModelOpensArranged(@TempDir Path directory) throws IOException {
		Path modelFile = directory.resolve("Goalie.stct");
		Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), modelFile);
		Files.writeString(NotationFiles.beside(modelFile), "{ \"format\": 1, \"states\": [ { \"element\": ");
		Model model = StatechartResources.load(modelFile);
		var opened = NotationFiles.open(modelFile, model);
		assertEquals(NotationFiles.Source.ARRANGED, opened.source());
		assertTrue(opened.problem() != null && opened.problem().contains("Goalie.notation.json"), () -> "names the file: " + opened.problem());
		assertTrue(opened.notation().covers(model));
	}
}
