package org.kse.messages;

import java.util.ArrayList;
import java.util.List;

import org.kse.messages.Token.Kind;

/**
 * Splits {@code .proto} text into tokens. Comments and whitespace are dropped; lexical errors are
 * reported and skipped, so the result always ends with exactly one EOF token.
 */
final class Tokenizer {

	private static final String SYMBOLS = "{}[]()<>;,=.-+:";

	private final String text;
	private final Problems problems;
	private final List<Token> tokens = new ArrayList<>();
	private int pos;
	private int line = 1;
	private int column = 1;

	private Tokenizer(String text, Problems problems) {
		this.text = text;
		this.problems = problems;
	}

	static List<Token> tokenize(String text, Problems problems) {
		Tokenizer tokenizer = new Tokenizer(text, problems);
		tokenizer.run();
		return tokenizer.tokens;
	}

	private void run() {
		while (true) {
			skipWhitespaceAndComments();
			if (pos >= text.length()) {
				tokens.add(new Token(Kind.EOF, "", line, column, line, column));
				return;
			}
			int startLine = line;
			int startColumn = column;
			char c = text.charAt(pos);
			if (isIdentStart(c)) {
				add(Kind.IDENT, readWhile(Tokenizer::isIdentPart), startLine, startColumn);
			} else if (isDigit(c) || (c == '.' && isDigit(peek(1)))) {
				readNumber(startLine, startColumn);
			} else if (c == '"' || c == '\'') {
				readString(c, startLine, startColumn);
			} else if (SYMBOLS.indexOf(c) >= 0) {
				advance();
				add(Kind.SYMBOL, String.valueOf(c), startLine, startColumn);
			} else {
				skipGarbage(startLine, startColumn);
			}
		}
	}

	private void add(Kind kind, String value, int startLine, int startColumn) {
		tokens.add(new Token(kind, value, startLine, startColumn, line, column));
	}

	private void skipWhitespaceAndComments() {
		while (pos < text.length()) {
			char c = text.charAt(pos);
			if (Character.isWhitespace(c)) {
				advance();
			} else if (c == '/' && peek(1) == '/') {
				while (pos < text.length() && !isLineBreak(text.charAt(pos))) {
					advance();
				}
			} else if (c == '/' && peek(1) == '*') {
				skipBlockComment();
			} else {
				return;
			}
		}
	}

	private void skipBlockComment() {
		int startLine = line;
		int startColumn = column;
		advance();
		advance();
		while (pos < text.length()) {
			if (text.charAt(pos) == '*' && peek(1) == '/') {
				advance();
				advance();
				return;
			}
			advance();
		}
		problems.report(startLine, startColumn, "unterminated comment: '/*' without '*/'");
	}

	private void readNumber(int startLine, int startColumn) {
		int start = pos;
		Kind kind = Kind.INT;
		if (text.charAt(pos) == '0' && (peek(1) == 'x' || peek(1) == 'X')) {
			advance();
			advance();
			if (readWhile(Tokenizer::isHexDigit).isEmpty()) {
				problems.report(startLine, startColumn, "hexadecimal number without digits");
			}
		} else {
			readWhile(Tokenizer::isDigit);
			if (peekChar() == '.') {
				kind = Kind.FLOAT;
				advance();
				readWhile(Tokenizer::isDigit);
			}
			if (peekChar() == 'e' || peekChar() == 'E') {
				kind = Kind.FLOAT;
				advance();
				if (peekChar() == '+' || peekChar() == '-') {
					advance();
				}
				if (readWhile(Tokenizer::isDigit).isEmpty()) {
					problems.report(startLine, startColumn, "number with an empty exponent");
				}
			}
		}
		// "12abc" is one bad token rather than a number followed by a name.
		if (isIdentPart(peekChar())) {
			readWhile(Tokenizer::isIdentPart);
			problems.report(startLine, startColumn, "invalid number '" + text.substring(start, pos) + "'");
		}
		add(kind, text.substring(start, pos), startLine, startColumn);
	}

	private void readString(char quote, int startLine, int startColumn) {
		StringBuilder value = new StringBuilder();
		advance();
		while (true) {
			if (pos >= text.length() || isLineBreak(text.charAt(pos))) {
				problems.report(startLine, startColumn, "unterminated string literal");
				break;
			}
			char c = text.charAt(pos);
			if (c == quote) {
				advance();
				break;
			}
			if (c == '\\') {
				readEscape(value);
			} else {
				value.append(c);
				advance();
			}
		}
		add(Kind.STRING, value.toString(), startLine, startColumn);
	}

	private void readEscape(StringBuilder value) {
		int escLine = line;
		int escColumn = column;
		advance();
		if (pos >= text.length() || isLineBreak(text.charAt(pos))) {
			return; // the caller reports the unterminated string
		}
		char c = text.charAt(pos);
		advance();
		switch (c) {
		case 'a' -> value.append('\u0007');
		case 'b' -> value.append('\b');
		case 'f' -> value.append('\f');
		case 'n' -> value.append('\n');
		case 'r' -> value.append('\r');
		case 't' -> value.append('\t');
		case 'v' -> value.append('\u000B');
		case '\\', '\'', '"', '?' -> value.append(c);
		case 'x', 'X' -> appendCode(value, readDigits(2, 16), 16, escLine, escColumn);
		case 'u' -> appendCode(value, readDigits(4, 16), 16, escLine, escColumn);
		case 'U' -> appendCode(value, readDigits(8, 16), 16, escLine, escColumn);
		default -> {
			if (c >= '0' && c <= '7') {
				pos--; // the octal escape's first digit was consumed above
				column--;
				appendCode(value, readDigits(3, 8), 8, escLine, escColumn);
			} else {
				problems.report(escLine, escColumn, "invalid escape sequence '\\" + c + "'");
				value.append(c);
			}
		}
		}
	}

	private String readDigits(int max, int radix) {
		int start = pos;
		while (pos - start < max && pos < text.length() && Character.digit(text.charAt(pos), radix) >= 0
				&& text.charAt(pos) < 128) {
			advance();
		}
		return text.substring(start, pos);
	}

	private void appendCode(StringBuilder value, String digits, int radix, int escLine, int escColumn) {
		if (digits.isEmpty()) {
			problems.report(escLine, escColumn, "escape sequence without digits");
			return;
		}
		long code = Long.parseLong(digits, radix);
		if (code > Character.MAX_CODE_POINT) {
			problems.report(escLine, escColumn, "escape sequence beyond Unicode");
			return;
		}
		value.appendCodePoint((int) code);
	}

	/** Reports a run of unexpected characters once instead of once per character. */
	private void skipGarbage(int startLine, int startColumn) {
		int start = pos;
		do {
			advance();
		} while (pos < text.length() && !startsToken(text.charAt(pos)));
		String garbage = text.substring(start, pos);
		String shown = garbage.codePoints().limit(10)
				.mapToObj(cp -> Character.isISOControl(cp) ? String.format("\\u%04X", cp) : Character.toString(cp))
				.reduce("", String::concat);
		problems.report(startLine, startColumn, "unexpected character" + (garbage.length() > 1 ? "s" : "") + " '"
				+ shown + (garbage.codePointCount(0, garbage.length()) > 10 ? "..." : "") + "'");
	}

	private boolean startsToken(char c) {
		return Character.isWhitespace(c) || isIdentStart(c) || isDigit(c) || c == '"' || c == '\'' || c == '/'
				|| SYMBOLS.indexOf(c) >= 0;
	}

	private String readWhile(java.util.function.IntPredicate accept) {
		int start = pos;
		while (pos < text.length() && accept.test(text.charAt(pos))) {
			advance();
		}
		return text.substring(start, pos);
	}

	/** Moves one char on, counting "\r\n", "\n" and a lone "\r" as one line break each. */
	private void advance() {
		char c = text.charAt(pos++);
		if (c == '\n' || (c == '\r' && peekChar() != '\n')) {
			line++;
			column = 1;
		} else {
			column++;
		}
	}

	private char peekChar() {
		return peek(0);
	}

	private char peek(int ahead) {
		int i = pos + ahead;
		return i < text.length() ? text.charAt(i) : '\0';
	}

	private static boolean isLineBreak(char c) {
		return c == '\n' || c == '\r';
	}

	private static boolean isIdentStart(int c) {
		return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
	}

	private static boolean isIdentPart(int c) {
		return isIdentStart(c) || isDigit(c);
	}

	private static boolean isDigit(int c) {
		return c >= '0' && c <= '9';
	}

	private static boolean isHexDigit(int c) {
		return isDigit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
	}
}
