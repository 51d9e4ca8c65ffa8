package org.kse.cli.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kse.testing.Models;
import org.kse.cli.Kse;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Transition;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.xml.sax.InputSource;

/**
 * {@code kse diagram}: the statechart as an SVG picture in the thesis' notation, with the
 * positions of the notation file, of the original's .kse diagram, or arranged by ELK.
 */
class DiagramCommandTest {

	@TempDir
	Path directory;

	private static Document parse(Path svg) throws Exception {
		DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
		return factory.newDocumentBuilder().parse(new InputSource(new StringReader(Files.readString(svg))));
	}

	private static List<Element> groups(Document svg, String cssClass) {
		List<Element> found = new ArrayList<>();
		var groups = svg.getElementsByTagName("g");
		for (int i = 0; i < groups.getLength(); i++) {
			Element group = (Element) groups.item(i);
			if ((" " + group.getAttribute("class") + " ").contains(" " + cssClass + " ")) {
				found.add(group);
			}
		}
		return found;
	}

	private static long count(Model model, String type) {
		return Models.allNodes(model).stream().filter(node -> type.equals(node.getType())).count();
	}

	@Test
	void theGoalieIsDrawnInTheThesisNotation() throws Exception {
		Path model = directory.resolve("Goalie.stct");
		Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), model);
		var run = CommandLineTest.kse("diagram", model.toString());
		assertEquals(Kse.OK, run.code(), run.all());
		Path svg = directory.resolve("Goalie.svg");
		assertTrue(run.out().contains("drew " + svg) && run.out().contains("arranged with ELK"), run.all());
		assertTrue(!Files.exists(directory.resolve("Goalie.notation.json")), "no notation file unless asked");

		Model goalie = StatechartResources.load(model);
		Document picture = parse(svg);
		assertEquals(Models.allNodes(goalie).size(), groups(picture, "state").size(), "a shape per state");
		for (String type : List.of("BASIC", "OR", "START", "END", "CONDITION")) {
			assertEquals(count(goalie, type), groups(picture, type.toLowerCase()).size(), type);
		}
		for (Element start : groups(picture, "start")) {
			Element disc = (Element) start.getElementsByTagName("circle").item(0);
			assertEquals("#000000", disc.getAttribute("fill"), "START is a black disc");
		}
		for (Element end : groups(picture, "end")) {
			assertEquals(2, end.getElementsByTagName("circle").getLength(), "END is a disc with a black centre");
		}
		for (Element condition : groups(picture, "condition")) {
			assertEquals("C", condition.getElementsByTagName("text").item(0).getTextContent());
		}
		for (Element basic : groups(picture, "basic")) {
			assertEquals("#b9e4a4", ((Element) basic.getElementsByTagName("rect").item(0)).getAttribute("fill"), "BASIC is green");
		}

		List<Element> arrows = groups(picture, "transition");
		assertEquals(goalie.getTransitions().size(), arrows.size(), "an arrow per transition");
		Transition multiLine = goalie.getTransitions().stream().filter(t -> t.getTE() != null && t.getTE().strip().contains("\n")).findFirst()
				.orElseThrow();
		Element arrow = arrows.get(goalie.getTransitions().indexOf(multiLine));
		String shown = arrow.getElementsByTagName("text").item(0).getTextContent();
		String title = arrow.getElementsByTagName("title").item(0).getTextContent();
		String firstLine = multiLine.getTE().strip().lines().findFirst().orElseThrow().strip();
		assertTrue(shown.endsWith(" …") && firstLine.startsWith(shown.substring(0, shown.length() - 2)), "the start of the first line on the arrow: " + shown);
		assertTrue(shown.length() <= org.kse.notation.TransitionLayout.LABEL_MAX_CHARACTERS + 2, "a long line is cut: " + shown);
		assertTrue(title.contains(multiLine.getTE().strip()), "the whole expression on hover");
	}

	@Test
	void theOriginalDiagramGivesThePositionsAndSaveNotationKeepsThem() throws Exception {
		Path model = directory.resolve("Goalie.stct");
		Files.copy(Models.LEGACY.resolve("Goalie/Goalie.stct"), model);
		Files.copy(Models.LEGACY.resolve("Goalie/Goalie.kse"), directory.resolve("Goalie.kse"));
		var run = CommandLineTest.kse("diagram", model.toString(), "-o", directory.resolve("legacy.svg").toString(), "--save-notation");
		assertEquals(Kse.OK, run.code(), run.all());
		assertTrue(run.out().contains("from the original diagram Goalie.kse"), run.all());
		assertTrue(Files.isRegularFile(directory.resolve("Goalie.notation.json")));
		Files.delete(directory.resolve("Goalie.kse"));
		var again = CommandLineTest.kse("diagram", model.toString(), "-o", directory.resolve("again.svg").toString());
		assertTrue(again.out().contains("from Goalie.notation.json"), again.all());
		assertEquals(Files.readString(directory.resolve("legacy.svg")), Files.readString(directory.resolve("again.svg")),
				"the notation file keeps the original's positions");
	}

	@Test
	void aBrokenNotationFileIsAWarningAndTheDiagramIsStillDrawn() throws IOException {
		Path model = directory.resolve("Goalie.stct");
		Files.copy(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"), model);
		Files.writeString(directory.resolve("Goalie.notation.json"), "not json at all {");
		var run = CommandLineTest.kse("diagram", model.toString());
		assertEquals(Kse.OK, run.code(), run.all());
		assertTrue(run.err().contains("warning") && run.err().contains("Goalie.notation.json"), run.all());
		assertTrue(Files.isRegularFile(directory.resolve("Goalie.svg")));
		var missing = CommandLineTest.kse("diagram", directory.resolve("Nothing.stct").toString());
		assertEquals(Kse.FAILED, missing.code(), missing.all());
	}
}
