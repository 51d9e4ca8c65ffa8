package org.kse.messages;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.kse.messages.Token.Kind;

/**
 * Recursive-descent parser for the part of the proto2/proto3 language that describes data:
 * messages, fields, enums, imports. Options, services, extensions and reserved ranges are
 * recognised and skipped. It never throws on bad input: every problem is recorded with its
 * position and parsing resumes at the next statement, so whatever was understood is kept.
 */
public final class ProtoParser {

	/** Deeper nesting is skipped rather than recursed into, so crafted input cannot overflow the stack. */
	static final int MAX_NESTING = 64;

	private static final int MAX_FIELD_NUMBER = 536_870_911;
	private static final int RESERVED_FIRST = 19_000;
	private static final int RESERVED_LAST = 19_999;

	private final Path file;
	private final Problems problems;
	private final List<Token> tokens;
	private int pos;

	private String syntax;
	private String packageName;
	private boolean seenDeclaration;
	private final List<ProtoImport> imports = new ArrayList<>();
	private final List<MessageType> messages = new ArrayList<>();
	private final List<EnumType> enums = new ArrayList<>();
	private final List<MessageType> allMessages = new ArrayList<>();
	private final List<EnumType> allEnums = new ArrayList<>();

	private ProtoParser(Path file, String text) {
		this.file = file;
		this.problems = new Problems(file);
		this.tokens = Tokenizer.tokenize(text == null ? "" : text, problems);
	}

	/** Parses one file; field types naming messages or enums stay unresolved (see {@link MessageCatalog}). */
	public static ProtoFile parse(Path file, String text) {
		return new ProtoParser(file, text).parseFile();
	}

	private ProtoFile parseFile() {
		while (!peek().is(Kind.EOF)) {
			int before = pos;
			parseTopLevelStatement();
			ensureProgress(before);
		}
		String pkg = packageName == null ? "" : packageName;
		if (!pkg.isEmpty()) {
			allMessages.forEach(m -> m.qualify(pkg));
			allEnums.forEach(e -> e.qualify(pkg));
		}
		problems.list().sort(java.util.Comparator.comparingInt(ProtoProblem::line)
				.thenComparingInt(ProtoProblem::column));
		return new ProtoFile(file, syntax == null ? "proto2" : syntax, pkg, imports, messages, enums,
				problems.list());
	}

	private void parseTopLevelStatement() {
		Token t = peek();
		String keyword = t.is(Kind.IDENT) ? t.text() : "";
		if (!keyword.equals("syntax")) {
			seenDeclaration = true; // even an empty statement: protoc wants syntax first of all
		}
		if (t.isSymbol(';')) {
			next();
			return;
		}
		if (t.isSymbol('}')) {
			report(t, "unmatched '}'");
			next();
			return;
		}
		switch (keyword) {
		case "syntax" -> parseSyntax();
		case "edition" -> {
			report(t, "editions are not supported; use syntax = \"proto2\" or \"proto3\"");
			skipStatement();
		}
		case "package" -> parsePackage();
		case "import" -> parseImport();
		case "option", "service", "extend" -> skipStatement();
		case "message" -> {
			MessageType m = parseMessage(null, 1);
			if (m != null) {
				messages.add(m);
			}
		}
		case "enum" -> {
			EnumType e = parseEnum(null);
			if (e != null) {
				enums.add(e);
			}
		}
		default -> {
			report(t, "expected 'message', 'enum', 'import', 'package', 'option' or 'service', found "
					+ t.describe());
			skipStatement();
		}
		}
	}

	private void parseSyntax() {
		Token keyword = next();
		if (seenDeclaration || syntax != null) {
			report(keyword, "the syntax statement must be the first statement of the file");
		}
		if (!expectSymbol('=', "after 'syntax'")) {
			skipStatement();
			return;
		}
		Token valueToken = peek();
		String value = parseString();
		if (value == null) {
			report(valueToken, "expected \"proto2\" or \"proto3\", found " + valueToken.describe());
			skipStatement();
			return;
		}
		if (value.equals("proto2") || value.equals("proto3")) {
			if (syntax == null) {
				syntax = value;
			}
		} else {
			report(valueToken, "unknown syntax \"" + value + "\"; expected \"proto2\" or \"proto3\"");
		}
		expectSemicolon("after the syntax statement");
	}

	private void parsePackage() {
		Token keyword = next();
		Token nameToken = peek();
		String name = parseFullIdent(false);
		if (name == null) {
			report(nameToken, "expected a package name, found " + nameToken.describe());
			skipStatement();
			return;
		}
		if (packageName != null) {
			report(keyword, "multiple package statements");
		} else {
			packageName = name;
		}
		expectSemicolon("after the package name");
	}

	private void parseImport() {
		next();
		ProtoImport.Modifier modifier = ProtoImport.Modifier.NONE;
		if (peek().isKeyword("public")) {
			next();
			modifier = ProtoImport.Modifier.PUBLIC;
		} else if (peek().isKeyword("weak")) {
			next();
			modifier = ProtoImport.Modifier.WEAK;
		}
		Token pathToken = peek();
		String path = parseString();
		if (path == null) {
			report(pathToken, "expected the imported file name as a string, found " + pathToken.describe());
			skipStatement();
			return;
		}
		if (imports.stream().anyMatch(i -> i.path().equals(path))) {
			report(pathToken, "the file \"" + path + "\" is imported twice");
		} else {
			imports.add(new ProtoImport(path, modifier, pathToken.line(), pathToken.column()));
		}
		expectSemicolon("after the import");
	}

	// ---- messages

	/** @param depth 1 for a top-level message */
	private MessageType parseMessage(MessageType parent, int depth) {
		Token keyword = next();
		if (depth > MAX_NESTING) {
			report(keyword, "messages nested more than " + MAX_NESTING + " deep; skipped");
			skipStatement();
			return null;
		}
		Token nameToken = expectIdent("a message name");
		if (nameToken == null || !expectSymbol('{', "after the message name")) {
			skipStatement();
			return null;
		}
		String relativeName = parent == null ? nameToken.text() : parent.fullName() + "." + nameToken.text();
		MessageType message = new MessageType(nameToken.text(), relativeName, file, nameToken.line(),
				nameToken.column(), parent);
		allMessages.add(message);
		parseMessageBody(message, keyword, depth);
		return message;
	}

	private void parseMessageBody(MessageType message, Token opening, int depth) {
		FieldNames seen = new FieldNames();
		while (true) {
			Token t = peek();
			if (t.is(Kind.EOF)) {
				reportUnclosed(t, "message " + message.name(), opening);
				return;
			}
			if (t.isSymbol('}')) {
				next();
				return;
			}
			int before = pos;
			String keyword = t.is(Kind.IDENT) ? t.text() : "";
			switch (keyword) {
			case "message" -> {
				MessageType nested = parseMessage(message, depth + 1);
				if (nested != null) {
					message.addMessage(nested);
				}
			}
			case "enum" -> {
				EnumType nested = parseEnum(message);
				if (nested != null) {
					message.addEnum(nested);
				}
			}
			case "oneof" -> parseOneof(message, seen);
			case "option", "reserved", "extensions", "extend" -> skipStatement();
			default -> {
				if (t.isSymbol(';')) {
					next();
				} else if (t.is(Kind.IDENT) || t.isSymbol('.')) {
					parseField(message, "", seen);
				} else {
					report(t, "expected a field, 'message', 'enum' or 'oneof' in message " + message.name()
							+ ", found " + t.describe());
					skipStatement();
				}
			}
			}
			ensureProgress(before);
		}
	}

	private void parseOneof(MessageType message, FieldNames seen) {
		Token keyword = next();
		Token nameToken = expectIdent("a oneof name");
		if (nameToken == null || !expectSymbol('{', "after the oneof name")) {
			skipStatement();
			return;
		}
		while (true) {
			Token t = peek();
			if (t.is(Kind.EOF)) {
				reportUnclosed(t, "oneof " + nameToken.text(), keyword);
				return;
			}
			if (t.isSymbol('}')) {
				next();
				return;
			}
			int before = pos;
			if (t.isSymbol(';')) {
				next();
			} else if (t.isKeyword("option")) {
				skipStatement();
			} else if (t.isKeyword("message") || t.isKeyword("enum") || t.isKeyword("oneof")) {
				report(t, "only fields are allowed inside oneof " + nameToken.text());
				skipStatement();
			} else if (t.is(Kind.IDENT) || t.isSymbol('.')) {
				parseField(message, nameToken.text(), seen);
			} else {
				report(t, "expected a field in oneof " + nameToken.text() + ", found " + t.describe());
				skipStatement();
			}
			ensureProgress(before);
		}
	}

	private void parseField(MessageType message, String oneof, FieldNames seen) {
		Token labelToken = peek();
		Field.Label label = switch (labelToken.is(Kind.IDENT) ? labelToken.text() : "") {
		case "optional" -> Field.Label.OPTIONAL;
		case "required" -> Field.Label.REQUIRED;
		case "repeated" -> Field.Label.REPEATED;
		default -> null;
		};
		if (label != null) {
			next();
		}
		if (peek().isKeyword("group") && peek(1).is(Kind.IDENT)) {
			report(peek(), "groups are not supported; use a nested message");
			skipStatement();
			return;
		}
		Token typeToken = peek();
		String keyType = null;
		String typeName;
		if (typeToken.isKeyword("map") && peek(1).isSymbol('<')) {
			next();
			next();
			Token keyToken = peek();
			keyType = parseFullIdent(true);
			if (keyType == null) {
				report(keyToken, "expected the map key type, found " + keyToken.describe());
				skipStatement();
				return;
			}
			if (!ScalarKind.fromProtoName(keyType).map(ScalarKind::isValidMapKey).orElse(false)) {
				report(keyToken, "invalid map key type '" + keyType + "'; use an integral type, bool or string");
			}
			if (!expectSymbol(',', "after the map key type")) {
				skipStatement();
				return;
			}
			typeToken = peek();
			typeName = parseFullIdent(true);
			if (typeName == null) {
				report(typeToken, "expected the map value type, found " + typeToken.describe());
				skipStatement();
				return;
			}
			if (!expectSymbol('>', "after the map value type")) {
				skipStatement();
				return;
			}
			if (label != null) {
				report(labelToken, "map fields cannot have a label");
			}
			label = Field.Label.MAP;
		} else {
			typeName = parseFullIdent(true);
			if (typeName == null) {
				report(typeToken, "expected a field type, found " + typeToken.describe());
				skipStatement();
				return;
			}
			checkLabel(label, labelToken, typeToken, oneof);
			if (label == null) {
				label = Field.Label.OPTIONAL;
			}
		}
		Token nameToken = expectIdent("a field name");
		if (nameToken == null) {
			skipStatement();
			return;
		}
		int number = 0;
		boolean complete = expectSymbol('=', "after field name " + nameToken.text());
		if (complete) {
			number = parseFieldNumber();
			if (peek().isSymbol('[')) {
				skipBracketedOptions();
			}
			expectSemicolon("after field " + nameToken.text());
		} else {
			skipStatement();
		}
		seen.check(nameToken, number, message.name());
		message.addField(new Field(nameToken.text(), number, label, typeName, keyType, oneof, nameToken.line(),
				nameToken.column(), typeToken.line(), typeToken.column()));
	}

	private void checkLabel(Field.Label label, Token labelToken, Token typeToken, String oneof) {
		if (!oneof.isEmpty()) {
			if (label != null) {
				report(labelToken, "fields in a oneof cannot have a label");
			}
		} else if (label == null && !"proto3".equals(syntax)) {
			report(typeToken, "missing label: proto2 fields need 'optional', 'required' or 'repeated'");
		} else if (label == Field.Label.REQUIRED && "proto3".equals(syntax)) {
			report(labelToken, "'required' is not allowed in proto3");
		}
	}

	/** @return the number, or 0 after reporting a missing or invalid one */
	private int parseFieldNumber() {
		Token start = peek();
		boolean negative = false;
		if (start.isSymbol('-')) {
			negative = true;
			next();
		}
		Token t = peek();
		if (!t.is(Kind.INT)) {
			report(t, "expected a field number, found " + t.describe());
			if (t.is(Kind.IDENT) || t.is(Kind.FLOAT) || t.is(Kind.STRING)) {
				next();
			}
			return 0;
		}
		next();
		Long parsed = parseInteger(t);
		if (parsed == null) {
			return 0;
		}
		long value = parsed;
		if (negative || value < 1 || value > MAX_FIELD_NUMBER) {
			report(start, "field number " + (negative ? "-" : "") + t.text() + " is out of range 1 to "
					+ MAX_FIELD_NUMBER);
			return 0;
		}
		if (value >= RESERVED_FIRST && value <= RESERVED_LAST) {
			report(start, "field numbers " + RESERVED_FIRST + " to " + RESERVED_LAST
					+ " are reserved for the protocol buffer implementation");
		}
		return (int) value;
	}

	// ---- enums

	private EnumType parseEnum(MessageType parent) {
		Token keyword = next();
		Token nameToken = expectIdent("an enum name");
		if (nameToken == null || !expectSymbol('{', "after the enum name")) {
			skipStatement();
			return null;
		}
		String relativeName = parent == null ? nameToken.text() : parent.fullName() + "." + nameToken.text();
		EnumType enumType = new EnumType(nameToken.text(), relativeName, file, nameToken.line(), nameToken.column(),
				parent);
		allEnums.add(enumType);
		while (true) {
			Token t = peek();
			if (t.is(Kind.EOF)) {
				reportUnclosed(t, "enum " + enumType.name(), keyword);
				break;
			}
			if (t.isSymbol('}')) {
				next();
				break;
			}
			int before = pos;
			if (t.isSymbol(';')) {
				next();
			} else if (t.isKeyword("option") || t.isKeyword("reserved")) {
				skipStatement();
			} else if (t.is(Kind.IDENT)) {
				parseEnumValue(enumType);
			} else {
				report(t, "expected an enum value in enum " + enumType.name() + ", found " + t.describe());
				skipStatement();
			}
			ensureProgress(before);
		}
		if (enumType.values().isEmpty()) {
			report(nameToken, "enum " + enumType.name() + " has no values");
		}
		return enumType;
	}

	private void parseEnumValue(EnumType enumType) {
		Token nameToken = next();
		if (!expectSymbol('=', "after enum value " + nameToken.text())) {
			skipStatement();
			return;
		}
		Token start = peek();
		boolean negative = start.isSymbol('-');
		if (negative) {
			next();
		}
		Token numberToken = peek();
		if (!numberToken.is(Kind.INT)) {
			report(numberToken, "expected the number of enum value " + nameToken.text() + ", found "
					+ numberToken.describe());
			skipStatement();
			return;
		}
		next();
		Long parsed = parseInteger(numberToken);
		if (parsed == null) {
			skipStatement();
			return;
		}
		long value = negative ? -parsed : parsed;
		if (value < Integer.MIN_VALUE || value > Integer.MAX_VALUE) {
			report(start, "enum value " + nameToken.text() + " is outside the 32-bit range");
			value = 0;
		}
		if (enumType.values().isEmpty() && value != 0 && "proto3".equals(syntax)) {
			report(start, "the first value of a proto3 enum must be zero");
		}
		if (!enumType.addValue(nameToken.text(), (int) value)) {
			report(nameToken, "duplicate value " + nameToken.text() + " in enum " + enumType.name());
		}
		if (peek().isSymbol('[')) {
			skipBracketedOptions();
		}
		expectSemicolon("after enum value " + nameToken.text());
	}

	// ---- small grammar pieces

	/** One or more adjacent string literals, concatenated as in C; null when there is none. */
	private String parseString() {
		if (!peek().is(Kind.STRING)) {
			return null;
		}
		StringBuilder value = new StringBuilder();
		while (peek().is(Kind.STRING)) {
			value.append(next().text());
		}
		return value.toString();
	}

	/** {@code a.b.c}, with a leading dot when {@code allowLeadingDot}; null when no name starts here. */
	private String parseFullIdent(boolean allowLeadingDot) {
		StringBuilder name = new StringBuilder();
		if (allowLeadingDot && peek().isSymbol('.') && peek(1).is(Kind.IDENT)) {
			name.append(next().text());
		}
		if (!peek().is(Kind.IDENT)) {
			return null;
		}
		name.append(next().text());
		while (peek().isSymbol('.')) {
			Token dot = next();
			Token part = peek();
			if (!part.is(Kind.IDENT)) {
				report(part, "expected a name after '.', found " + part.describe());
				return name.toString();
			}
			name.append(dot.text()).append(next().text());
		}
		return name.toString();
	}

	/** @return the value, {@code Long.MAX_VALUE} when too large, null (reported) for a bad octal number */
	private Long parseInteger(Token t) {
		String text = t.text();
		boolean hex = text.startsWith("0x") || text.startsWith("0X");
		boolean octal = !hex && text.length() > 1 && text.startsWith("0");
		if (octal && !text.chars().allMatch(c -> c >= '0' && c <= '7')) {
			report(t, "invalid octal number '" + text + "'");
			return null;
		}
		try {
			if (hex) {
				return text.length() > 2 ? Long.parseLong(text.substring(2), 16) : 0L;
			}
			return Long.parseLong(text, octal ? 8 : 10);
		} catch (NumberFormatException e) {
			return Long.MAX_VALUE; // too many digits: outside every valid range
		}
	}

	/** Skips {@code [ ... ]} with nesting; stops before a ';' or '}' that shows the ']' is missing. */
	private void skipBracketedOptions() {
		Token open = next();
		int depth = 1;
		while (depth > 0) {
			Token t = peek();
			if (t.is(Kind.EOF) || t.isSymbol(';') || t.isSymbol('}')) {
				report(t, "missing ']' to close the options opened at " + open.line() + ":" + open.column());
				return;
			}
			next();
			if (t.isSymbol('[')) {
				depth++;
			} else if (t.isSymbol(']')) {
				depth--;
			}
		}
	}

	/**
	 * Error recovery and skipping of uninteresting statements: consumes up to and including the next
	 * ';' or the block that ends the statement, but not a '}' that closes an enclosing block.
	 */
	private void skipStatement() {
		int depth = 0;
		while (true) {
			Token t = peek();
			if (t.is(Kind.EOF)) {
				return;
			}
			if (t.isSymbol('}')) {
				if (depth == 0) {
					return;
				}
				next();
				if (--depth == 0) {
					return;
				}
				continue;
			}
			next();
			if (t.isSymbol('{')) {
				depth++;
			} else if (t.isSymbol(';') && depth == 0) {
				return;
			}
		}
	}

	/** Reports a missing ';' right after the previous token. */
	private void expectSemicolon(String context) {
		if (peek().isSymbol(';')) {
			next();
			return;
		}
		Token previous = tokens.get(Math.max(0, pos - 1));
		Token t = peek();
		problems.report(previous.endLine(), previous.endColumn(), "expected ';' " + context + ", found " + t.describe());
		// A statement on a later line most likely just lacks its ';': keep it instead of skipping it.
		if (t.line() == previous.endLine() && !t.isSymbol('}') && !t.is(Kind.EOF)) {
			skipStatement();
		}
	}

	private boolean expectSymbol(char symbol, String context) {
		if (peek().isSymbol(symbol)) {
			next();
			return true;
		}
		report(peek(), "expected '" + symbol + "' " + context + ", found " + peek().describe());
		return false;
	}

	private Token expectIdent(String what) {
		if (peek().is(Kind.IDENT)) {
			return next();
		}
		report(peek(), "expected " + what + ", found " + peek().describe());
		return null;
	}

	private void reportUnclosed(Token eof, String what, Token opening) {
		report(eof, "missing '}' to close " + what + " opened at " + opening.line() + ":" + opening.column());
	}

	/** Guarantees termination even if a branch forgot to consume: every loop turn eats a token. */
	private void ensureProgress(int before) {
		if (pos == before && !peek().is(Kind.EOF)) {
			next();
		}
	}

	private void report(Token at, String message) {
		problems.report(at.line(), at.column(), message);
	}

	private Token peek() {
		return tokens.get(pos);
	}

	private Token peek(int ahead) {
		return tokens.get(Math.min(pos + ahead, tokens.size() - 1));
	}

	/** The EOF token is never consumed, so {@code pos} always indexes a token. */
	private Token next() {
		Token t = tokens.get(pos);
		if (!t.is(Kind.EOF)) {
			pos++;
		}
		return t;
	}

	/** Duplicate names and numbers inside one message, oneof fields included. */
	private final class FieldNames {
		private final Map<String, Token> names = new HashMap<>();
		private final Map<Integer, String> numbers = new HashMap<>();

		void check(Token name, int number, String messageName) {
			if (names.putIfAbsent(name.text(), name) != null) {
				report(name, "duplicate field name " + name.text() + " in message " + messageName);
			}
			if (number > 0) {
				String other = numbers.putIfAbsent(number, name.text());
				if (other != null) {
					report(name, "field number " + number + " of " + name.text() + " is already used by " + other);
				}
			}
		}
	}
}
