package org.kse.generator.monas;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Set;
import java.util.regex.Pattern;

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
			// names the generated code itself uses
			"NULL", "main", "std", "statechart_engine", "kse");

	/** File names Windows refuses in any case and with any extension ("nul.h" is the null device). */
	private static final Pattern WINDOWS_DEVICE = Pattern.compile("(?i)(CON|PRN|AUX|NUL|COM[0-9]|LPT[0-9])");

	/**
	 * The longest name KSE turns into a file name: a file system allows 255 bytes, and an atomic
	 * write's temporary file adds 46 characters to the name (".", ".cpp", a UUID and ".tmp").
	 */
	public static final int MAX_NAME_LENGTH = 200;

	/** Generated names (transition classes built from two labels) longer than this are shortened. */
	private static final int MAX_GENERATED_LENGTH = 120;

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
		return KEYWORDS.contains(result) || WINDOWS_DEVICE.matcher(result).matches() ? result + "_" : result;
	}

	/**
	 * A generated name kept short enough for a file name: a long one keeps its beginning and gets a
	 * hash of the whole, so it stays unique and the same on every run (deep models have long labels).
	 */
	public static String shortened(String name) {
		if (name.length() <= MAX_GENERATED_LENGTH) {
			return name;
		}
		try {
			byte[] digest = MessageDigest.getInstance("SHA-256").digest(name.getBytes(StandardCharsets.UTF_8));
			return name.substring(0, MAX_GENERATED_LENGTH - 17) + "_" + HexFormat.of().formatHex(digest, 0, 8);
		} catch (NoSuchAlgorithmException e) {
			throw new IllegalStateException("every Java runtime has SHA-256", e);
		}
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
