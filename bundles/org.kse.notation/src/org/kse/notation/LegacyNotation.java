package org.kse.notation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;

import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.w3c.dom.Element;
import org.xml.sax.SAXException;

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
			factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
			var document = factory.newDocumentBuilder().parse(kseFile.toFile());
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
						: new double[] { number(constraint, "x", 0), number(constraint, "y", 0), number(constraint, "width", -1),
								number(constraint, "height", -1) });
			}
		} catch (ParserConfigurationException | SAXException | NumberFormatException e) {
			throw new IOException(kseFile + ": not a diagram of the original KSE: " + e.getMessage(), e);
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

	private static double number(Element element, String attribute, double otherwise) {
		String value = element.getAttribute(attribute);
		return value.isEmpty() ? otherwise : Double.parseDouble(value);
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
