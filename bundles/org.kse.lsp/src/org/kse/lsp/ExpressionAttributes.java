package org.kse.lsp;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The transition expressions of a {@code .stct} file's text: the {@code TE} attribute of each
 * {@code <transitions>} element, as an XML parser reads its value (entities decoded, line breaks
 * written as such turned into spaces), with where each character of that value stands in the file.
 * Read from the text as it is, so that a file being typed, not well-formed yet, still has its
 * expressions checked and completed.
 */
final class ExpressionAttributes {

	/**
	 * One {@code TE} attribute: its transition's {@code name} (empty when it has none), the
	 * element's extent in the file, the value as parsed and, for each of its characters and for its
	 * end, the offset in the file where it is written.
	 */
	record Attribute(String transition, int elementStart, int elementEnd, String value, int[] offsets) {

		/** The file offset of an offset in the value (the value's end maps to the closing quote). */
		int fileOffset(int valueOffset) {
			return offsets[Math.max(0, Math.min(valueOffset, value.length()))];
		}

		/** The value offset of a file offset inside the quotes, or -1 when the offset is outside them. */
		int valueOffset(int fileOffset) {
			if (fileOffset < offsets[0] || fileOffset > offsets[value.length()]) {
				return -1;
			}
			int index = 0;
			while (index < value.length() && offsets[index + 1] <= fileOffset) {
				index++;
			}
			return index;
		}
	}

	private static final Pattern ELEMENT = Pattern.compile("<(?:[\\w.-]+:)?transitions(?=[\\s/>])");
	private static final Pattern ATTRIBUTE = Pattern.compile("\\s*([\\w:.-]+)\\s*=\\s*([\"'])");

	private ExpressionAttributes() {
	}

	static List<Attribute> of(String text) {
		List<Attribute> attributes = new ArrayList<>();
		Matcher element = ELEMENT.matcher(text);
		int from = 0;
		while (from < text.length() && element.find(from)) {
			int position = element.end();
			String transition = "";
			List<int[]> expressions = new ArrayList<>();
			Matcher attribute = ATTRIBUTE.matcher(text);
			while (attribute.region(position, text.length()).lookingAt()) {
				char quote = attribute.group(2).charAt(0);
				int valueStart = attribute.end();
				int valueEnd = text.indexOf(quote, valueStart);
				if (valueEnd < 0) {
					valueEnd = text.length();
				}
				if (attribute.group(1).equals("name")) {
					transition = decode(text, valueStart, valueEnd).value();
				} else if (attribute.group(1).equals("TE")) {
					expressions.add(new int[] { valueStart, valueEnd });
				}
				position = Math.min(text.length(), valueEnd + 1);
			}
			int end = text.indexOf('>', position);
			end = end < 0 ? text.length() : end + 1;
			for (int[] range : expressions) {
				Attribute decoded = decode(text, range[0], range[1]);
				attributes.add(new Attribute(transition, element.start(), end, decoded.value(), decoded.offsets()));
			}
			from = end;
		}
		return attributes;
	}

	/** An attribute value between two offsets of the file, decoded as an XML parser does. */
	private static Attribute decode(String text, int start, int end) {
		StringBuilder value = new StringBuilder();
		List<Integer> offsets = new ArrayList<>();
		int i = start;
		while (i < end) {
			char c = text.charAt(i);
			offsets.add(i);
			if (c == '&') {
				int semicolon = text.indexOf(';', i);
				String character = semicolon > i && semicolon < end && semicolon - i <= 10 ? entity(text.substring(i + 1, semicolon)) : null;
				if (character != null) {
					value.append(character);
					// a character outside the BMP takes two chars in the value: both start at the entity
					for (int extra = 1; extra < character.length(); extra++) {
						offsets.add(i);
					}
					i = semicolon + 1;
					continue;
				}
				value.append(c);
			} else if (c == '\r' || c == '\n' || c == '\t') {
				// attribute-value normalization: a line break or tab written as such reads as a space
				value.append(' ');
				if (c == '\r' && i + 1 < end && text.charAt(i + 1) == '\n') {
					i++;
				}
			} else {
				value.append(c);
			}
			i++;
		}
		offsets.add(end);
		return new Attribute("", start, end, value.toString(), offsets.stream().mapToInt(Integer::intValue).toArray());
	}

	private static String entity(String name) {
		switch (name) {
			case "amp": return "&";
			case "lt": return "<";
			case "gt": return ">";
			case "quot": return "\"";
			case "apos": return "'";
			default:
		}
		try {
			int code = name.startsWith("#x") || name.startsWith("#X") ? Integer.parseInt(name.substring(2), 16)
					: name.startsWith("#") ? Integer.parseInt(name.substring(1)) : -1;
			return Character.isValidCodePoint(code) ? Character.toString(code) : null;
		} catch (NumberFormatException e) {
			return null;
		}
	}

	/** A text as it must be written inside a double-quoted attribute value. */
	static String escape(String text) {
		return text.replace("&", "&amp;").replace("<", "&lt;").replace("\"", "&quot;");
	}
}
