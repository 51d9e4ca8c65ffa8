package org.kse.scxml;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParser;
import javax.xml.parsers.SAXParserFactory;

import org.kse.model.StatechartResources;
import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * Reads an SCXML file into a small tree of elements that remember their line and column. The
 * parser is locked down: a DOCTYPE is refused where it begins, so no entity is expanded and no
 * DTD or external entity is fetched or read (a file from elsewhere must not make KSE read other
 * files or reach the network); elements nest at most {@value #MAX_DEPTH} deep.
 */
final class ScxmlImportReader {

	static final String SCXML_NAMESPACE = "http://www.w3.org/2005/07/scxml";
	static final String KSE_NAMESPACE = "http://kse/scxml/1.0";

	/** Deeper than KSE's statecharts may nest (the validator's limit is 1,000 states), with room for executable content. */
	static final int MAX_DEPTH = 1_100;

	private static final String DISALLOW_DOCTYPE = StatechartResources.DISALLOW_DOCTYPE;

	/** One XML element: its namespace and local name, its attributes, where its start tag ends, its child elements. */
	static final class Element {
		final String namespace;
		final String name;
		/** Attributes without a namespace, by local name. */
		final Map<String, String> attributes;
		/** Attributes in KSE's namespace, by local name. */
		final Map<String, String> kse;
		final int line;
		final int column;
		final Element parent;
		final List<Element> children = new ArrayList<>();

		Element(String namespace, String name, Map<String, String> attributes, Map<String, String> kse, int line, int column, Element parent) {
			this.namespace = namespace;
			this.name = name;
			this.attributes = attributes;
			this.kse = kse;
			this.line = line;
			this.column = column;
			this.parent = parent;
		}

		/** An element of SCXML's namespace (or of none, as hand-written files sometimes have) with this name. */
		boolean is(String scxmlName) {
			return isScxml() && name.equals(scxmlName);
		}

		boolean isScxml() {
			return SCXML_NAMESPACE.equals(namespace) || namespace.isEmpty();
		}

		boolean isKse(String kseName) {
			return KSE_NAMESPACE.equals(namespace) && name.equals(kseName);
		}

		String attribute(String attributeName) {
			return attributes.get(attributeName);
		}

		/** How messages name the element: its tag with its id (or, for a transition, its event and target), and where it is. */
		String describe() {
			StringBuilder text = new StringBuilder("<").append(isScxml() || !KSE_NAMESPACE.equals(namespace) ? name : "kse:" + name);
			for (String shown : List.of("id", "event", "target")) {
				if (attributes.containsKey(shown)) {
					text.append(' ').append(shown).append("=\"").append(shorten(attributes.get(shown))).append('"');
				}
			}
			if (kse.containsKey("label") && !attributes.containsKey("id")) {
				text.append(" kse:label=\"").append(shorten(kse.get("label"))).append('"');
			}
			return text.append("> at ").append(line).append(':').append(column).toString();
		}

		private static String shorten(String value) {
			String shown = value.length() > 40 ? value.substring(0, 40) + "…" : value;
			return shown.codePoints().map(c -> Character.isISOControl(c) ? '?' : c)
					.collect(StringBuilder::new, StringBuilder::appendCodePoint, StringBuilder::append).toString();
		}
	}

	/** The file is not XML a parser reads, with where and why. */
	static final class Unreadable extends Exception {
		private static final long serialVersionUID = 1L;
		final int line;
		final int column;

		Unreadable(int line, int column, String message) {
			super(message);
			this.line = line;
			this.column = column;
		}
	}

	private ScxmlImportReader() {
	}

	static Element read(InputStream input) throws Unreadable, IOException {
		SAXParser parser;
		try {
			SAXParserFactory factory = SAXParserFactory.newInstance();
			factory.setNamespaceAware(true);
			factory.setValidating(false);
			factory.setXIncludeAware(false);
			factory.setFeature(DISALLOW_DOCTYPE, true);
			factory.setFeature("http://xml.org/sax/features/external-general-entities", false);
			factory.setFeature("http://xml.org/sax/features/external-parameter-entities", false);
			factory.setFeature("http://apache.org/xml/features/nonvalidating/load-external-dtd", false);
			factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
			parser = factory.newSAXParser();
			parser.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
			parser.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
			parser.setProperty("jdk.xml.maxElementDepth", String.valueOf(MAX_DEPTH));
			// without a DOCTYPE only the five predefined entities exist, which cost nothing: a
			// large chart full of &amp;&amp; in its conditions must not reach the JDK's entity limits
			parser.setProperty("jdk.xml.maxGeneralEntitySizeLimit", "0");
			parser.setProperty("jdk.xml.totalEntitySizeLimit", "0");
		} catch (ParserConfigurationException | SAXException e) {
			throw new IOException("the XML parser cannot be set up safely: " + e.getMessage(), e);
		}
		Builder builder = new Builder();
		try {
			parser.parse(new InputSource(input), builder);
		} catch (SAXParseException e) {
			throw new Unreadable(Math.max(e.getLineNumber(), 1), Math.max(e.getColumnNumber(), 1), message(e));
		} catch (SAXException e) {
			throw new Unreadable(1, 1, "not XML: " + e.getMessage());
		}
		if (builder.root == null) {
			throw new Unreadable(1, 1, "the file holds no XML element");
		}
		return builder.root;
	}

	/** A parser's message in a user's terms: without the JDK's message codes and property names. */
	private static String message(SAXParseException e) {
		String message = String.valueOf(e.getMessage());
		if (message.contains(DISALLOW_DOCTYPE) || message.contains("DOCTYPE")) {
			return "the file declares a DOCTYPE, which KSE does not read: no entity or DTD of it is expanded, fetched or read (SCXML needs none)";
		}
		if (message.startsWith("Content is not allowed in prolog")) {
			return "the file is not XML (an SCXML file begins with <?xml or <scxml)";
		}
		if (message.contains("maxElementDepth")) {
			return "the XML nests elements deeper than " + MAX_DEPTH + ", which KSE does not read";
		}
		return "not well-formed XML: " + message.replaceFirst("^JAXP\\d+: ", "").replaceAll("\\s*set by \"jdk\\.xml\\.\\w+\"\\.?", "");
	}

	private static final class Builder extends DefaultHandler {
		private Locator locator;
		private Element root;
		private Element current;

		@Override
		public void setDocumentLocator(Locator locator) {
			this.locator = locator;
		}

		@Override
		public void startElement(String uri, String localName, String qName, Attributes attributes) {
			Map<String, String> plain = new LinkedHashMap<>();
			Map<String, String> kse = new LinkedHashMap<>();
			for (int i = 0; i < attributes.getLength(); i++) {
				String namespace = attributes.getURI(i);
				if (namespace == null || namespace.isEmpty()) {
					plain.put(attributes.getLocalName(i), attributes.getValue(i));
				} else if (KSE_NAMESPACE.equals(namespace)) {
					kse.put(attributes.getLocalName(i), attributes.getValue(i));
				}
			}
			Element element = new Element(uri == null ? "" : uri, localName, plain, kse, locator == null ? 0 : locator.getLineNumber(),
					locator == null ? 0 : locator.getColumnNumber(), current);
			if (current == null) {
				root = element;
			} else {
				current.children.add(element);
			}
			current = element;
		}

		@Override
		public void endElement(String uri, String localName, String qName) {
			current = current.parent;
		}

		@Override
		public InputSource resolveEntity(String publicId, String systemId) {
			// never reached with DOCTYPEs refused; should it be, nothing is read
			return new InputSource(new java.io.StringReader(""));
		}
	}
}
