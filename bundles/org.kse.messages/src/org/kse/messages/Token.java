package org.kse.messages;

/**
 * A lexical token. For strings, {@code text} is the decoded value; otherwise it is the source
 * text. {@code endLine}/{@code endColumn} is the position just after the token.
 */
record Token(Kind kind, String text, int line, int column, int endLine, int endColumn) {

	enum Kind {
		IDENT, INT, FLOAT, STRING, SYMBOL, EOF
	}

	boolean is(Kind k) {
		return kind == k;
	}

	boolean isSymbol(char c) {
		return kind == Kind.SYMBOL && text.charAt(0) == c;
	}

	boolean isKeyword(String word) {
		return kind == Kind.IDENT && text.equals(word);
	}

	/** How the token is named in a problem message. */
	String describe() {
		return switch (kind) {
		case EOF -> "end of file";
		case STRING -> "string \"" + abbreviate(text) + "\"";
		default -> "'" + abbreviate(text) + "'";
		};
	}

	private static String abbreviate(String s) {
		return s.length() <= 40 ? s : s.substring(0, 37) + "...";
	}
}
