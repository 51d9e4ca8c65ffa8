package org.kse.notation.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.kse.model.NodeKind;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.notation.Arrange;
import org.kse.notation.NotationStyle;
import org.kse.notation.Shapes;
import org.kse.notation.SvgDiagram;
import org.kse.notation.TransitionLayout;
import org.kse.testing.Models;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;
import org.xml.sax.InputSource;

/**
 * The notation's one style (notation-style.json, which the diagram page bundles too): every kind
 * has one, {@code kse diagram}'s SVG draws each state and transition with it, and a broken style
 * says where it is broken.
 */
class NotationStyleTest {

	private static final NotationStyle STYLE = NotationStyle.get();

	private static String bundledStyle() throws IOException {
		try (InputStream in = NotationStyle.class.getResourceAsStream(NotationStyle.RESOURCE)) {
			assertNotNull(in, "the bundle holds " + NotationStyle.RESOURCE);
			return new String(in.readAllBytes(), StandardCharsets.UTF_8);
		}
	}

	private static List<Element> children(Element parent, String tag) {
		List<Element> found = new ArrayList<>();
		for (org.w3c.dom.Node child = parent.getFirstChild(); child != null; child = child.getNextSibling()) {
			if (child instanceof Element element && element.getTagName().equals(tag)) {
				found.add(element);
			}
		}
		return found;
	}

	private static Element childWithClass(Element parent, String cssClass) {
		for (org.w3c.dom.Node child = parent.getFirstChild(); child != null; child = child.getNextSibling()) {
			if (child instanceof Element element && element.getAttribute("class").equals(cssClass)) {
				return element;
			}
		}
		return null;
	}

	private static double number(Element element, String attribute) {
		return Double.parseDouble(element.getAttribute(attribute));
	}

	@Test
	void everyKindOfTheModelAndUnknownHaveAStyle() {
		for (NodeKind kind : NodeKind.values()) {
			assertNotNull(STYLE.of(kind), kind.name());
		}
		assertNotNull(STYLE.of(null), "a type the model does not know");
		assertEquals(NotationStyle.kindNames(), List.copyOf(STYLE.states().keySet()));
		// the thesis' shapes
		assertEquals(NotationStyle.Shape.DISC, STYLE.of(NodeKind.START).shape());
		assertEquals(NotationStyle.Shape.RINGED_DISC, STYLE.of(NodeKind.END).shape());
		assertEquals(NotationStyle.Shape.CIRCLED_LETTER, STYLE.of(NodeKind.CONDITION).shape());
		assertEquals("C", STYLE.of(NodeKind.CONDITION).letter());
		assertEquals(NotationStyle.Shape.ROUNDED_BOX, STYLE.of(NodeKind.BASIC).shape());
		assertEquals(NotationStyle.Shape.COMPOSITE_BOX, STYLE.of(NodeKind.OR).shape());
		assertEquals(NotationStyle.Shape.COMPOSITE_BOX, STYLE.of(NodeKind.AND).shape());
	}

	@Test
	void theDefaultSizesAndTheLabelFontComeFromTheStyle() {
		Model model = Models.model("M");
		Node root = Models.root(model, "m", "0", "OR");
		for (NodeKind kind : List.of(NodeKind.START, NodeKind.END, NodeKind.CONDITION)) {
			Node state = Models.child(root, kind.name().toLowerCase(Locale.ROOT), "0." + kind.ordinal(), kind.name());
			NotationStyle.Size size = STYLE.of(kind).size();
			assertEquals(size.width(), Shapes.size(state).width(), kind.name());
			assertEquals(size.height(), Shapes.size(state).height(), kind.name());
		}
		assertEquals(STYLE.transitionLabel().size(), TransitionLayout.LABEL_FONT_SIZE);
	}

	/** Each state of the Goalie drawn by kse diagram's SVG has its kind's shape, colours, stroke and fonts. */
	@Test
	void theSvgDrawsEveryStateAndTransitionOfTheGoalieInTheStyle() throws Exception {
		Model goalie = StatechartResources.load(Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.stct"));
		String svg = SvgDiagram.render(goalie, Arrange.all(goalie));
		Document picture = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(new InputSource(new StringReader(svg)));
		assertEquals(STYLE.fontFamily(), picture.getDocumentElement().getAttribute("font-family"));
		NodeList groups = picture.getElementsByTagName("g");
		int states = 0;
		int transitions = 0;
		for (int i = 0; i < groups.getLength(); i++) {
			Element group = (Element) groups.item(i);
			String[] classes = group.getAttribute("class").split(" ");
			if (classes[0].equals("state")) {
				states++;
				String label = group.getAttribute("data-label");
				Node state = Models.byLabel(goalie, label);
				NodeKind kind = NodeKind.of(state);
				assertEquals(kind.name().toLowerCase(Locale.ROOT), classes[1], label);
				NotationStyle.StateStyle style = STYLE.of(kind);
				Element shape = childWithClass(group, "shape");
				assertNotNull(shape, label + " has a shape");
				assertEquals(style.isCircle() ? "circle" : "rect", shape.getTagName(), label);
				assertEquals(style.fill(), shape.getAttribute("fill"), label + " fill");
				assertEquals(style.stroke(), shape.getAttribute("stroke"), label + " stroke");
				assertEquals(style.strokeWidth(), number(shape, "stroke-width"), label + " stroke width");
				if (!style.isCircle()) {
					assertEquals(style.cornerRadius(), number(shape, "rx"), label + " corner radius");
				}
				if (style.shape() == NotationStyle.Shape.RINGED_DISC) {
					Element centre = childWithClass(group, "centre");
					assertEquals(style.innerDiscFill(), centre.getAttribute("fill"), label + " centre");
					double outer = Math.min(Shapes.size(state).width(), Shapes.size(state).height()) / 2;
					assertEquals(outer * style.innerDiscRatio(), number(centre, "r"), 0.06, label + " centre's radius");
				}
				Element caption = childWithClass(group, "caption");
				if (kind == NodeKind.START || kind == NodeKind.END) {
					assertEquals(null, caption, label + " has no caption");
				} else {
					NotationStyle.TextStyle font = kind == NodeKind.CONDITION ? STYLE.letterCaption()
							: kind.isComposite() ? STYLE.headerCaption() : STYLE.centredCaption();
					assertEquals(kind == NodeKind.CONDITION ? "C" : org.kse.notation.Captions.of(state), caption.getTextContent(), label);
					assertEquals(font.size(), number(caption, "font-size"), label + " caption size");
					assertEquals(font.weight(), caption.getAttribute("font-weight"), label + " caption weight");
					assertEquals(font.colour(), caption.getAttribute("fill"), label + " caption colour");
				}
				Element hierarchical = childWithClass(group, "label");
				if (style.shape() == NotationStyle.Shape.COMPOSITE_BOX) {
					assertEquals(label, hierarchical.getTextContent());
					assertEquals(STYLE.label().colour(), hierarchical.getAttribute("fill"));
					assertEquals(STYLE.label().size(), number(hierarchical, "font-size"));
				} else {
					assertEquals(null, hierarchical, label + " shows its label only on hover");
				}
			} else if (classes[0].equals("transition")) {
				transitions++;
				Element line = childWithClass(group, "line");
				assertEquals(STYLE.line().colour(), line.getAttribute("stroke"));
				assertEquals(STYLE.line().width(), number(line, "stroke-width"));
				Element expression = childWithClass(group, "expression");
				if (expression != null) {
					assertEquals(STYLE.transitionLabel().colour(), expression.getAttribute("fill"));
					assertEquals(STYLE.transitionLabel().size(), number(expression, "font-size"));
				}
			}
		}
		assertEquals(Models.allNodes(goalie).size(), states);
		assertEquals(goalie.getTransitions().size(), transitions);
		Element arrow = children((Element) picture.getElementsByTagName("marker").item(0), "path").get(0);
		assertEquals(STYLE.arrow().fill(), arrow.getAttribute("fill"), "the arrow head");
		assertEquals("userSpaceOnUse", ((Element) arrow.getParentNode()).getAttribute("markerUnits"), "not scaled by the line's width");
	}

	@Test
	void theBundledStyleReadsAsTheOneInUse() throws IOException {
		NotationStyle again = NotationStyle.read(new StringReader(bundledStyle()), NotationStyle.RESOURCE);
		assertEquals(STYLE.states(), again.states());
		assertEquals(STYLE.line(), again.line());
		assertEquals(STYLE.arrow(), again.arrow());
	}

	@Test
	void aStyleWithoutAValueSaysWhichAndWhere() throws IOException {
		String broken = bundledStyle().replaceFirst("\"fill\": \"#b9e4a4\", ", "");
		var missing = assertThrows(IllegalArgumentException.class, () -> NotationStyle.read(new StringReader(broken), "style.json"));
		assertEquals("style.json: $.states.basic.fill: missing", missing.getMessage());

		String noKind = bundledStyle().replaceFirst("\"and\": \\{", "\"und\": {");
		var kindless = assertThrows(IllegalArgumentException.class, () -> NotationStyle.read(new StringReader(noKind), "style.json"));
		assertEquals("style.json: $.states.and: missing", kindless.getMessage());

		String named = bundledStyle().replace("#fff5c2", "yellow");
		var colour = assertThrows(IllegalArgumentException.class, () -> NotationStyle.read(new StringReader(named), "style.json"));
		assertEquals("style.json: $.states.or.fill: \"yellow\" is not a colour #rrggbb (lower case)", colour.getMessage());

		var syntax = assertThrows(IllegalArgumentException.class, () -> NotationStyle.read(new StringReader("{\n  \"states\": {\n    \"start\": [}\n"), "style.json"));
		assertTrue(syntax.getMessage().startsWith("style.json: ") && syntax.getMessage().contains("line 3"), syntax.getMessage());
	}
}
