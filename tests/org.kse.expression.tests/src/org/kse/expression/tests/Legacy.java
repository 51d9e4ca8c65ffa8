package org.kse.expression.tests;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.kse.testing.Models;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * Transition expressions taken from the original KSE's Goalie model, kept in the repository
 * under tests/data/legacy-kse ({@link Models#LEGACY}).
 */
final class Legacy {

	private Legacy() {
	}

	static Path goalieStatechart() {
		return Models.legacy("Goalie/Goalie.stct");
	}

	/** The TE attribute of every transition of the legacy Goalie.stct, XML-unescaped, in file order. */
	static List<String> goalieTransitionExpressions() {
		try {
			var factory = DocumentBuilderFactory.newInstance();
			factory.setNamespaceAware(true);
			var document = factory.newDocumentBuilder().parse(goalieStatechart().toFile());
			NodeList transitions = document.getElementsByTagNameNS("*", "transitions");
			List<String> result = new ArrayList<>();
			for (int i = 0; i < transitions.getLength(); i++) {
				Element transition = (Element) transitions.item(i);
				if (transition.hasAttribute("TE")) {
					result.add(transition.getAttribute("TE"));
				}
			}
			return result;
		} catch (Exception e) {
			throw new AssertionError("cannot read " + goalieStatechart() + ": " + e, e);
		}
	}
}
