package org.kse.generator.monas;

import java.util.Set;

/**
 * Turns model names into C++ identifiers, predictably: every character that cannot
 * appear in an identifier becomes '_', a leading digit gets a '_' in front, and a C++
 * keyword (or a reserved name) gets a '_' appended. The same name always gives the
 * same identifier, so regenerating never renames files.
 */
public final class CppNames {

	private static final Set<String> KEYWORDS = Set.of("alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor",
			"bool", "break", "case", "catch", "char", "char8_t", "char16_t", "char32_t", "class", "compl", "concept", "const",
			"consteval", "constexpr", "constinit", "const_cast", "continue", "co_await", "co_return", "co_yield", "decltype",
			"default", "delete", "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float",
			"for", "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not", "not_eq",
			"nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register", "reinterpret_cast", "requires",
			"return", "short", "signed", "sizeof", "static", "static_assert", "static_cast", "struct", "switch", "template",
			"this", "thread_local", "throw", "true", "try", "typedef", "typeid", "typename", "union", "unsigned", "using",
			"virtual", "void", "volatile", "wchar_t", "while", "xor", "xor_eq",
			// names the generated code itself uses, and file names Windows refuses
			"NULL", "main", "std", "statechart_engine", "kse", "CON", "PRN", "AUX", "NUL");

	private CppNames() {
	}

	public static String identifier(String name) {
		if (name == null || name.isEmpty()) {
			return "_";
		}
		StringBuilder out = new StringBuilder(name.length() + 1);
		for (int i = 0; i < name.length(); i++) {
			char c = name.charAt(i);
			boolean ok = c < 128 && (Character.isLetterOrDigit(c) || c == '_');
			out.append(ok ? c : '_');
		}
		if (Character.isDigit(out.charAt(0))) {
			out.insert(0, '_');
		}
		String result = out.toString();
		return KEYWORDS.contains(result) ? result + "_" : result;
	}

	/**
	 * A label such as 0.3.2 as it appears inside identifiers and file names: 0_3_2. Every
	 * character that cannot be part of an identifier becomes '_', so a label is never code.
	 */
	public static String label(String label) {
		if (label == null || label.isEmpty()) {
			return "unlabeled";
		}
		StringBuilder out = new StringBuilder(label.length());
		for (int i = 0; i < label.length(); i++) {
			char c = label.charAt(i);
			out.append(c < 128 && (Character.isLetterOrDigit(c) || c == '_') ? c : '_');
		}
		return out.toString();
	}

	/** A C++ string literal with the text escaped. */
	public static String string(String text) {
		StringBuilder out = new StringBuilder("\"");
		for (char c : text.toCharArray()) {
			switch (c) {
				case '"' -> out.append("\\\"");
				case '\\' -> out.append("\\\\");
				case '\n' -> out.append("\\n");
				case '\r' -> out.append("\\r");
				case '\t' -> out.append("\\t");
				default -> out.append(c < 32 || c > 126 ? '?' : c);
			}
		}
		return out.append('"').toString();
	}

	/**
	 * Text safe inside a C++ comment, block or line: no end of a block comment, no line break,
	 * and no backslash (one at the end of a line comment would continue it onto the next line).
	 */
	public static String comment(String text) {
		return text == null ? "" : text.replace("*/", "* /").replace('\\', '/').replace("\r", "").replace("\n", " ");
	}
}
