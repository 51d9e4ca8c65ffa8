package org.kse.ui.preferences;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.eclipse.core.runtime.preferences.InstanceScope;

/**
 * "Configure KSE", as the original tool had it: which editor opens an activity's C++ and which
 * generator writes the code. Commands are templates with {file}, {model} and {folder}.
 */
public final class KsePreferences {

	public static final String NODE = "org.kse.ui";
	public static final String ACTIVITY_EDITOR = "activityEditor";
	public static final String ACTIVITY_EDITOR_COMMAND = "activityEditorCommand";
	public static final String GENERATOR = "generator";
	public static final String GENERATOR_COMMAND = "generatorCommand";
	public static final String INTERNAL = "internal";
	public static final String EXTERNAL = "external";

	private KsePreferences() {
	}

	public static IEclipsePreferences node() {
		return InstanceScope.INSTANCE.getNode(NODE);
	}

	public static boolean externalActivityEditor() {
		return EXTERNAL.equals(node().get(ACTIVITY_EDITOR, INTERNAL)) && !node().get(ACTIVITY_EDITOR_COMMAND, "").isBlank();
	}

	public static boolean externalGenerator() {
		return EXTERNAL.equals(node().get(GENERATOR, INTERNAL)) && !node().get(GENERATOR_COMMAND, "").isBlank();
	}

	/**
	 * The words of a command template with its placeholders filled in: words are separated by
	 * blanks, double quotes keep blanks in a word, and a placeholder stays one word whatever its value holds.
	 */
	public static List<String> command(String template, Map<String, String> values) {
		List<String> words = new ArrayList<>();
		StringBuilder word = new StringBuilder();
		boolean quoted = false;
		boolean inWord = false;
		for (int i = 0; i < template.length(); i++) {
			char c = template.charAt(i);
			if (c == '"') {
				quoted = !quoted;
				inWord = true;
			} else if (Character.isWhitespace(c) && !quoted) {
				if (inWord) {
					words.add(word.toString());
					word.setLength(0);
					inWord = false;
				}
			} else {
				word.append(c);
				inWord = true;
			}
		}
		if (inWord) {
			words.add(word.toString());
		}
		List<String> filled = new ArrayList<>();
		for (String each : words) {
			String value = each;
			for (Map.Entry<String, String> entry : values.entrySet()) {
				value = value.replace("{" + entry.getKey() + "}", entry.getValue());
			}
			filled.add(value);
		}
		return filled;
	}
}
