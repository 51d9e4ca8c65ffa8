package org.kse.ui.formula;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Where the formulas of a text define their names. One formula a line, so a line's left side is
 * found without parsing, which keeps it right while the text is being typed and has errors.
 */
public final class Definitions {

	/** A formula: the name it defines, where that name is, and its right side as written. */
	public record Definition(String name, int offset, int line, String expression) {
	}

	private static final Pattern FORMULA = Pattern.compile("(?m)^[ \\t]*([A-Za-z_][A-Za-z0-9_]*)[ \\t]*=[ \\t]*([^\\r\\n]*)");

	private Definitions() {
	}

	public static List<Definition> of(String text) {
		List<Definition> definitions = new ArrayList<>();
		Matcher matcher = FORMULA.matcher(text);
		int line = 1;
		int counted = 0;
		while (matcher.find()) {
			String expression = matcher.group(2);
			int comment = expression.indexOf("//");
			expression = (comment >= 0 ? expression.substring(0, comment) : expression).trim();
			for (; counted < matcher.start(1); counted++) {
				if (text.charAt(counted) == '\n') {
					line++;
				}
			}
			definitions.add(new Definition(matcher.group(1), matcher.start(1), line, expression));
		}
		return definitions;
	}

	/** The name around {@code offset} (start and end offsets), or null when there is none. */
	public static int[] wordAt(String text, int offset) {
		int start = offset;
		while (start > 0 && FormulaScanner.isNamePart(text.charAt(start - 1))) {
			start--;
		}
		int end = offset;
		while (end < text.length() && FormulaScanner.isNamePart(text.charAt(end))) {
			end++;
		}
		return start == end ? null : new int[] { start, end };
	}

	/** The definition of {@code name}, or null. */
	public static Definition find(String text, String name) {
		return of(text).stream().filter(definition -> definition.name().equals(name)).findFirst().orElse(null);
	}
}
