package org.kse.notation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;

import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.w3c.dom.Element;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;

/**
 * The positions and sizes of the original tool's GMF diagram ({@code .kse}): each notation node
 * refers to its state as {@code Model.stct#//@nodes.0/@Children.1} and holds its bounds relative
 * to the compartment of its parent. Sizes the original left to GMF (no width or height) are taken
 * from {@link Shapes}, or for a composite, from the extent of its children.
 */
public final class LegacyNotation {

	private LegacyNotation() {
	}

	public static Notation read(Path kseFile, Model model) throws IOException {
		Map<String, double[]> bounds = new HashMap<>();
		try {
			DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
			factory.setNamespaceAware(false);
			factory.setExpandEntityReferences(false);
			factory.setFeature(StatechartResources.DISALLOW_DOCTYPE, true);
			// as deep as a model may be (the JDK's default of 100 is less than a deep model's diagram)
			factory.setAttribute("jdk.xml.maxElementDepth", String.valueOf(StatechartResources.MAX_ELEMENT_DEPTH));
			var builder = factory.newDocumentBuilder();
			// The default handler prints "[Fatal Error] …" on the terminal besides throwing.
			builder.setErrorHandler(new org.xml.sax.helpers.DefaultHandler() {
				@Override
				public void fatalError(SAXParseException e) throws SAXException {
					throw e;
				}
			});
			var document = builder.parse(kseFile.toFile());
			var references = document.getElementsByTagName("element");
			for (int i = 0; i < references.getLength(); i++) {
				Element reference = (Element) references.item(i);
				String href = reference.getAttribute("href");
				int hash = href.indexOf('#');
				if (hash < 0 || !(reference.getParentNode() instanceof Element view)) {
					continue;
				}
				Element constraint = child(view, "layoutConstraint");
				if (constraint != null && !constraint.getAttribute("xmi:type").endsWith("Bounds")) {
					constraint = null;
				}
				bounds.put(href.substring(hash + 1), constraint == null ? new double[] { 0, 0, -1, -1 }
						: new double[] { number(kseFile, constraint, "x", 0), number(kseFile, constraint, "y", 0),
								number(kseFile, constraint, "width", -1), number(kseFile, constraint, "height", -1) });
			}
		} catch (SAXParseException e) {
			throw new IOException(StatechartResources.where(kseFile, e) + ": not a diagram of the original KSE: " + StatechartResources.xmlMessage(e), e);
		} catch (SAXException e) {
			throw new IOException(kseFile + ": not a diagram of the original KSE: " + StatechartResources.xmlMessage(e), e);
		} catch (ParserConfigurationException e) {
			throw new IOException(kseFile + ": cannot be read: " + e.getMessage(), e);
		}
		Notation notation = new Notation();
		for (Node root : model.getNodes()) {
			place(root, bounds, notation);
		}
		return notation;
	}

	/** Places a state and its children; returns its bounds. */
	private static Bounds place(Node node, Map<String, double[]> read, Notation notation) {
		double[] found = read.getOrDefault(Notation.path(node), new double[] { 0, 0, -1, -1 });
		double width = found[2];
		double height = found[3];
		double childrenRight = 0;
		double childrenBottom = 0;
		for (Node child : node.getChildren()) {
			Bounds placed = place(child, read, notation);
			childrenRight = Math.max(childrenRight, placed.right());
			childrenBottom = Math.max(childrenBottom, placed.bottom());
		}
		Bounds fallback = Shapes.size(node);
		if (width < 0) {
			width = node.getChildren().isEmpty() ? fallback.width() : Math.max(fallback.width(), childrenRight + 14);
		}
		if (height < 0) {
			height = node.getChildren().isEmpty() ? fallback.height() : childrenBottom + Arrange.HEADER + 14;
		}
		Bounds bounds = new Bounds(found[0], found[1], width, height);
		notation.put(node, bounds);
		return bounds;
	}

	private static Element child(Element parent, String name) {
		for (var node = parent.getFirstChild(); node != null; node = node.getNextSibling()) {
			if (node instanceof Element element && element.getTagName().equals(name)) {
				return element;
			}
		}
		return null;
	}

	/** The largest coordinate or size taken from a diagram: far beyond any screen, small enough to lay out. */
	private static final double MAX_COORDINATE = 1_000_000;

	private static double number(Path kseFile, Element element, String attribute, double otherwise) throws IOException {
		String value = element.getAttribute(attribute);
		if (value.isEmpty()) {
			return otherwise;
		}
		double number;
		try {
			number = Double.parseDouble(value);
		} catch (NumberFormatException e) {
			number = Double.NaN;
		}
		if (!(Math.abs(number) <= MAX_COORDINATE)) {
			String shown = value.length() > 40 ? value.substring(0, 40) + "…" : value;
			throw new IOException(kseFile + ": not a diagram of the original KSE: the " + attribute + " of a <" + element.getTagName() + "> is '"
					+ shown.replaceAll("\\p{Cntrl}", "?") + "', not a number from -" + (long) MAX_COORDINATE + " to " + (long) MAX_COORDINATE);
		}
		return number;
	}

	/** The original's diagram next to a model: {@code Goalie.kse} for {@code Goalie.stct}. */
	public static Path beside(Path modelFile) {
		String name = modelFile.getFileName().toString();
		return modelFile.resolveSibling(name.replaceFirst("\\.stct$", "") + ".kse");
	}

	static boolean exists(Path modelFile) {
		return Files.isRegularFile(beside(modelFile));
	}
}
