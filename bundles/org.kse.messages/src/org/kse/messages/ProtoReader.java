package org.kse.messages;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.AbstractRule;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.TerminalRule;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Issue;
import org.kse.proto.ProtoStandaloneSetup;
import org.kse.proto.proto.EditionDecl;
import org.kse.proto.proto.EmptyDecl;
import org.kse.proto.proto.ExtendDecl;
import org.kse.proto.proto.EnumDecl;
import org.kse.proto.proto.EnumValueDecl;
import org.kse.proto.proto.FieldDecl;
import org.kse.proto.proto.GroupDecl;
import org.kse.proto.proto.ImportDecl;
import org.kse.proto.proto.MapFieldDecl;
import org.kse.proto.proto.MessageDecl;
import org.kse.proto.proto.MessageElement;
import org.kse.proto.proto.OneofDecl;
import org.kse.proto.proto.OptionDecl;
import org.kse.proto.proto.PackageDecl;
import org.kse.proto.proto.ProtoDocument;
import org.kse.proto.proto.ProtoPackage.Literals;
import org.kse.proto.proto.Statement;
import org.kse.proto.proto.StrayBrace;
import org.kse.proto.proto.SyntaxDecl;
import org.kse.proto.proto.UnexpectedElement;
import org.kse.proto.proto.UnexpectedEnumElement;
import org.kse.proto.proto.UnexpectedStatement;
import org.kse.proto.ProtoTokens;
import org.kse.proto.validation.ProtoSyntaxErrorMessageProvider;
import org.kse.xtext.support.TextParsing;

import com.google.inject.Injector;

/**
 * Reads one {@code .proto} file (proto2 or proto3) with the Xtext grammar {@code org.kse.proto.Proto}
 * and builds its messages, fields and enums. The grammar says what is well formed; this class adds
 * what protoc checks on top, in one place (ADR 0019): the lexical rules for numbers, strings and
 * comments, the syntax statement first, labels per syntax, field number ranges, duplicate names and
 * numbers, map keys, enum values. Field types that name messages or enums stay unresolved until the
 * file is linked into a {@link MessageCatalog} ({@link TypeResolver}).
 *
 * <p>
 * It never throws on bad input: every problem is recorded with its line and column, and whatever
 * was understood is kept. Parsing reads only the text given: no import is opened, nothing is run.
 */
public final class ProtoReader {

	/** Blocks nested deeper are skipped before parsing, so crafted input cannot overflow the parser's stack. */
	static final int MAX_NESTING = 64;

	private static final int MAX_FIELD_NUMBER = 536_870_911;
	private static final int RESERVED_FIRST = 19_000;
	private static final int RESERVED_LAST = 19_999;

	private static final URI SYNTHETIC_URI = URI.createURI("inmemory:/file.proto");

	private static final Pattern DECIMAL = Pattern.compile("0|[1-9][0-9]*");
	private static final Pattern OCTAL = Pattern.compile("0[0-7]+");
	private static final Pattern HEX = Pattern.compile("0[xX][0-9a-fA-F]+");
	private static final Pattern FLOAT = Pattern.compile("([0-9]+\\.[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?|[0-9]+[eE][+-]?[0-9]+");

	private static final class Holder {
		static final Injector INJECTOR = new ProtoStandaloneSetup().createInjectorAndDoEMFRegistration();
	}

	private final Path file;
	private final String text;
	private final Problems problems;
	private final int[] lineStarts;
	/** Offsets of lexical problems: a syntax error at the same token says less, and is dropped. */
	private final Set<Integer> lexicalOffsets = new HashSet<>();
	/** Offsets of syntax errors: the parser's recovery may keep the same token as an unexpected statement. */
	private final Set<Integer> syntaxErrorOffsets = new HashSet<>();

	private String syntax;
	private String packageName;
	private boolean seenDeclaration;
	private final List<ProtoImport> imports = new ArrayList<>();
	private final List<MessageType> messages = new ArrayList<>();
	private final List<EnumType> enums = new ArrayList<>();
	private final List<MessageType> allMessages = new ArrayList<>();
	private final List<EnumType> allEnums = new ArrayList<>();

	private ProtoReader(Path file, String text) {
		this.file = file;
		this.text = text == null ? "" : text;
		this.problems = new Problems(file);
		this.lineStarts = LineStarts.of(this.text);
	}

	/** Reads one file; {@code file} only names it in the model and in problems, it is not opened. */
	public static ProtoFile read(Path file, String text) {
		return new ProtoReader(file, text).read();
	}

	private ProtoFile read() {
		String limited = limitNesting(text);
		TextParsing.Parsed parsed = TextParsing.parse(Holder.INJECTOR, SYNTHETIC_URI, limited,
				"blocks nested too deeply to be read");
		ProtoDocument document = parsed.root() instanceof ProtoDocument d ? d : null;
		if (document != null && NodeModelUtils.getNode(document) != null) {
			checkTokens(NodeModelUtils.getNode(document).getRootNode());
		}
		for (Issue issue : parsed.issues()) {
			reportIssue(issue);
		}
		if (document != null) {
			EObject previous = null;
			for (Statement statement : document.getStatements()) {
				if (statement instanceof UnexpectedStatement unexpected) {
					unexpected(unexpected, written(unexpected, Literals.UNEXPECTED_STATEMENT__TOKEN), previous,
							"expected 'message', 'enum', 'import', 'package', 'option' or 'service'");
				}
				statement(statement);
				previous = statement;
			}
		}
		String pkg = packageName == null ? "" : packageName;
		if (!pkg.isEmpty()) {
			allMessages.forEach(m -> m.qualify(pkg));
			allEnums.forEach(e -> e.qualify(pkg));
		}
		problems.list().sort(java.util.Comparator.comparingInt(ProtoProblem::line).thenComparingInt(ProtoProblem::column));
		return new ProtoFile(file, syntax == null ? "proto2" : syntax, pkg, imports, messages, enums, problems.list());
	}

	// ---- statements

	private void statement(Statement statement) {
		if (!(statement instanceof SyntaxDecl)) {
			seenDeclaration = true; // even an empty statement: protoc wants syntax first of all
		}
		switch (statement) {
		case SyntaxDecl s -> syntax(s);
		case EditionDecl e -> report(start(e), "editions are not supported; use syntax = \"proto2\" or \"proto3\"");
		case PackageDecl p -> {
			String name = written(p, Literals.PACKAGE_DECL__NAME);
			if (name != null) {
				if (packageName != null) {
					report(start(p), "multiple package statements");
				} else {
					packageName = name;
				}
			}
		}
		case ImportDecl i -> importStatement(i);
		case StrayBrace brace -> report(start(brace), "unmatched '}'");
		case ExtendDecl extend -> {
			EObject previous = null;
			for (MessageElement element : extend.getElements()) {
				if (element instanceof UnexpectedElement unexpected) {
					unexpected(unexpected, written(unexpected, Literals.UNEXPECTED_ELEMENT__TOKEN), previous, "expected a field in the extension");
				}
				previous = element;
			}
		}
		case MessageDecl m -> {
			MessageType message = message(m, null, 1);
			if (message != null) {
				messages.add(message);
			}
		}
		case EnumDecl e -> {
			EnumType enumType = enumType(e, null);
			if (enumType != null) {
				enums.add(enumType);
			}
		}
		default -> {
			// options, services and extend blocks carry nothing a statechart reads
		}
		}
	}

	private void syntax(SyntaxDecl statement) {
		if (seenDeclaration || syntax != null) {
			report(start(statement), "the syntax statement must be the first statement of the file");
		}
		String value = strings(statement, Literals.SYNTAX_DECL__VALUE);
		if (value == null) {
			return; // a syntax error says what is missing
		}
		if (value.equals("proto2") || value.equals("proto3")) {
			if (syntax == null) {
				syntax = value;
			}
		} else {
			report(start(statement, Literals.SYNTAX_DECL__VALUE),
					"unknown syntax \"" + value + "\"; expected \"proto2\" or \"proto3\"");
		}
	}

	private void importStatement(ImportDecl statement) {
		String path = strings(statement, Literals.IMPORT_DECL__PATH);
		if (path == null) {
			return;
		}
		ProtoImport.Modifier modifier = switch (statement.getModifier() == null ? "" : statement.getModifier()) {
		case "public" -> ProtoImport.Modifier.PUBLIC;
		case "weak" -> ProtoImport.Modifier.WEAK;
		default -> ProtoImport.Modifier.NONE;
		};
		int at = start(statement, Literals.IMPORT_DECL__PATH);
		if (imports.stream().anyMatch(i -> i.path().equals(path))) {
			report(at, "the file \"" + path + "\" is imported twice");
		} else {
			imports.add(new ProtoImport(path, modifier, line(at), column(at)));
		}
	}

	// ---- messages

	/** @param depth 1 for a top-level message */
	private MessageType message(MessageDecl declaration, MessageType parent, int depth) {
		String name = written(declaration, Literals.MESSAGE_DECL__NAME);
		if (name == null || depth > MAX_NESTING) {
			return null; // a syntax error, or blocks skipped by limitNesting (reported there)
		}
		int at = start(declaration, Literals.MESSAGE_DECL__NAME);
		String relativeName = parent == null ? name : parent.fullName() + "." + name;
		MessageType message = new MessageType(name, relativeName, file, line(at), column(at), parent);
		allMessages.add(message);
		FieldNames seen = new FieldNames(message.name());
		EObject previous = null;
		for (MessageElement element : declaration.getElements()) {
			switch (element) {
			case UnexpectedElement u -> unexpected(u, written(u, Literals.UNEXPECTED_ELEMENT__TOKEN), previous,
					"expected a field, 'message', 'enum' or 'oneof' in message " + name);
			case FieldDecl f -> field(f, message, "", seen);
			case MapFieldDecl f -> mapField(f, message, "", seen);
			case GroupDecl g -> group(g);
			case OneofDecl o -> oneof(o, message, seen);
			case MessageDecl m -> {
				MessageType nested = message(m, message, depth + 1);
				if (nested != null) {
					message.addMessage(nested);
				}
			}
			case EnumDecl e -> {
				EnumType nested = enumType(e, message);
				if (nested != null) {
					message.addEnum(nested);
				}
			}
			default -> {
				// options, reserved ranges, extensions and extend blocks carry no data of the message
			}
			}
			previous = element;
		}
		return message;
	}

	private void oneof(OneofDecl oneof, MessageType message, FieldNames seen) {
		String name = written(oneof, Literals.ONEOF_DECL__NAME);
		if (name == null) {
			return;
		}
		EObject previous = null;
		for (MessageElement element : oneof.getElements()) {
			switch (element) {
			case UnexpectedElement u -> unexpected(u, written(u, Literals.UNEXPECTED_ELEMENT__TOKEN), previous, "expected a field in oneof " + name);
			case FieldDecl f -> field(f, message, name, seen);
			case MapFieldDecl f -> {
				report(start(f), "map fields are not allowed in oneof " + name);
				mapField(f, message, name, seen);
			}
			case GroupDecl g -> group(g);
			case OptionDecl o -> {
				// options of the oneof itself
			}
			case EmptyDecl e -> {
				// a lone ';'
			}
			default -> report(start(element), "only fields are allowed inside oneof " + name);
			}
			previous = element;
		}
	}

	private void group(GroupDecl group) {
		report(keyword(group, "group"), "groups are not supported; use a nested message");
	}

	private void field(FieldDecl declaration, MessageType message, String oneof, FieldNames seen) {
		String type = written(declaration, Literals.FIELD_DECL__TYPE);
		String name = written(declaration, Literals.FIELD_DECL__NAME);
		if (type == null || name == null) {
			return; // a syntax error says what is missing
		}
		int typeAt = start(declaration, Literals.FIELD_DECL__TYPE);
		Field.Label label = label(declaration.getLabel());
		checkLabel(label, declaration, typeAt, oneof);
		int number = fieldNumber(declaration, Literals.FIELD_DECL__NUMBER);
		int nameAt = start(declaration, Literals.FIELD_DECL__NAME);
		seen.check(name, nameAt, number);
		message.addField(new Field(name, number, label == null ? Field.Label.OPTIONAL : label, type, null, oneof,
				line(nameAt), column(nameAt), line(typeAt), column(typeAt)));
	}

	private void mapField(MapFieldDecl declaration, MessageType message, String oneof, FieldNames seen) {
		if (declaration.getLabel() != null) {
			report(start(declaration, Literals.MAP_FIELD_DECL__LABEL), "map fields cannot have a label");
		}
		String keyType = written(declaration, Literals.MAP_FIELD_DECL__KEY_TYPE);
		String valueType = written(declaration, Literals.MAP_FIELD_DECL__VALUE_TYPE);
		String name = written(declaration, Literals.MAP_FIELD_DECL__NAME);
		if (keyType == null || valueType == null || name == null) {
			return;
		}
		if (!ScalarKind.fromProtoName(keyType).map(ScalarKind::isValidMapKey).orElse(false)) {
			report(start(declaration, Literals.MAP_FIELD_DECL__KEY_TYPE),
					"invalid map key type '" + keyType + "'; use an integral type, bool or string");
		}
		int typeAt = start(declaration, Literals.MAP_FIELD_DECL__VALUE_TYPE);
		int number = fieldNumber(declaration, Literals.MAP_FIELD_DECL__NUMBER);
		int nameAt = start(declaration, Literals.MAP_FIELD_DECL__NAME);
		seen.check(name, nameAt, number);
		message.addField(new Field(name, number, Field.Label.MAP, valueType, keyType, oneof, line(nameAt), column(nameAt),
				line(typeAt), column(typeAt)));
	}

	private static Field.Label label(String keyword) {
		return switch (keyword == null ? "" : keyword) {
		case "optional" -> Field.Label.OPTIONAL;
		case "required" -> Field.Label.REQUIRED;
		case "repeated" -> Field.Label.REPEATED;
		default -> null;
		};
	}

	private void checkLabel(Field.Label label, FieldDecl declaration, int typeAt, String oneof) {
		int labelAt = label == null ? typeAt : start(declaration, Literals.FIELD_DECL__LABEL);
		if (!oneof.isEmpty()) {
			if (label != null) {
				report(labelAt, "fields in a oneof cannot have a label");
			}
		} else if (label == null && !"proto3".equals(syntax)) {
			report(typeAt, "missing label: proto2 fields need 'optional', 'required' or 'repeated'");
		} else if (label == Field.Label.REQUIRED && "proto3".equals(syntax)) {
			report(labelAt, "'required' is not allowed in proto3");
		}
	}

	/** @return the number, or 0 when it is missing (a syntax error) or invalid (reported here) */
	private int fieldNumber(EObject declaration, EStructuralFeature feature) {
		String written = written(declaration, feature);
		if (written == null) {
			return 0;
		}
		int at = start(declaration, feature);
		boolean negative = written.startsWith("-");
		String digits = negative ? written.substring(1) : written;
		Long value = integer(digits);
		if (value == null) {
			if (isWellFormedNumber(digits)) {
				report(numberToken(declaration, feature), "expected a field number, found '" + digits + "'");
			}
			return 0;
		}
		if (negative || value < 1 || value > MAX_FIELD_NUMBER) {
			report(at, "field number " + written + " is out of range 1 to " + MAX_FIELD_NUMBER);
			return 0;
		}
		if (value >= RESERVED_FIRST && value <= RESERVED_LAST) {
			report(at, "field numbers " + RESERVED_FIRST + " to " + RESERVED_LAST
					+ " are reserved for the protocol buffer implementation");
		}
		return (int) (long) value;
	}

	// ---- enums

	private EnumType enumType(EnumDecl declaration, MessageType parent) {
		String name = written(declaration, Literals.ENUM_DECL__NAME);
		if (name == null) {
			return null;
		}
		int at = start(declaration, Literals.ENUM_DECL__NAME);
		String relativeName = parent == null ? name : parent.fullName() + "." + name;
		EnumType enumType = new EnumType(name, relativeName, file, line(at), column(at), parent);
		allEnums.add(enumType);
		EObject previous = null;
		for (EObject element : declaration.getElements()) {
			if (element instanceof EnumValueDecl value) {
				enumValue(value, enumType);
			} else if (element instanceof UnexpectedEnumElement u) {
				unexpected(u, written(u, Literals.UNEXPECTED_ENUM_ELEMENT__TOKEN), previous, "expected an enum value in enum " + name);
			}
			previous = element;
		}
		if (enumType.values().isEmpty()) {
			report(at, "enum " + name + " has no values");
		}
		return enumType;
	}

	private void enumValue(EnumValueDecl declaration, EnumType enumType) {
		String name = written(declaration, Literals.ENUM_VALUE_DECL__NAME);
		String written = written(declaration, Literals.ENUM_VALUE_DECL__NUMBER);
		if (name == null || written == null) {
			return;
		}
		int at = start(declaration, Literals.ENUM_VALUE_DECL__NUMBER);
		boolean negative = written.startsWith("-");
		String digits = negative ? written.substring(1) : written;
		Long parsed = integer(digits);
		if (parsed == null) {
			if (isWellFormedNumber(digits)) {
				report(numberToken(declaration, Literals.ENUM_VALUE_DECL__NUMBER),
						"expected the number of enum value " + name + ", found '" + digits + "'");
			}
			return;
		}
		long value = negative ? -parsed : parsed;
		if (value < Integer.MIN_VALUE || value > Integer.MAX_VALUE) {
			report(at, "enum value " + name + " is outside the 32-bit range");
			value = 0;
		}
		if (enumType.values().isEmpty() && value != 0 && "proto3".equals(syntax)) {
			report(at, "the first value of a proto3 enum must be zero");
		}
		if (!enumType.addValue(name, (int) value)) {
			report(start(declaration, Literals.ENUM_VALUE_DECL__NAME), "duplicate value " + name + " in enum " + enumType.name());
		}
	}

	/** The first of a run of tokens that cannot start a statement where they stand. */
	private void unexpected(EObject element, String token, EObject previous, String expected) {
		boolean inRun = previous instanceof UnexpectedStatement || previous instanceof UnexpectedElement
				|| previous instanceof UnexpectedEnumElement;
		if (!inRun && token != null && !syntaxErrorOffsets.contains(start(element))) {
			report(start(element), expected + ", found " + ProtoTokens.describe(token));
		}
	}

	/** How a token is named in a problem message. */
	// ---- numbers and strings

	/** An integer literal's value ({@code Long.MAX_VALUE} when too large), or null for anything else. */
	private static Long integer(String digits) {
		try {
			if (HEX.matcher(digits).matches()) {
				return Long.parseLong(digits.substring(2), 16);
			}
			if (OCTAL.matcher(digits).matches()) {
				return Long.parseLong(digits, 8);
			}
			if (DECIMAL.matcher(digits).matches()) {
				return Long.parseLong(digits);
			}
		} catch (NumberFormatException e) {
			return Long.MAX_VALUE; // too many digits: outside every valid range
		}
		return null;
	}

	/** A number protoc's tokenizer accepts (a float, say), as opposed to one {@link #checkTokens} reports. */
	private static boolean isWellFormedNumber(String digits) {
		return numberProblem(digits) == null;
	}

	/** What is wrong with a number as written, or null. */
	private static String numberProblem(String number) {
		if (HEX.matcher(number).matches() || DECIMAL.matcher(number).matches() || OCTAL.matcher(number).matches()
				|| FLOAT.matcher(number).matches()) {
			return null;
		}
		if (number.equals("0x") || number.equals("0X")) {
			return "hexadecimal number without digits";
		}
		if (number.chars().allMatch(c -> c >= '0' && c <= '9')) {
			return "invalid octal number '" + number + "'";
		}
		if (number.matches("([0-9]+\\.?[0-9]*|\\.[0-9]+)[eE][+-]?")) {
			return "number with an empty exponent";
		}
		return "invalid number '" + number + "'";
	}

	/** Adjacent string literals of a feature, decoded and joined; null when the feature is missing. */
	private String strings(EObject object, EStructuralFeature feature) {
		if (object.eGet(feature) == null) {
			return null;
		}
		StringBuilder value = new StringBuilder();
		for (INode node : NodeModelUtils.findNodesForFeature(object, feature)) {
			for (ILeafNode leaf : node.getLeafNodes()) {
				if (!leaf.isHidden() && ProtoTokens.isString(leaf.getText())) {
					value.append(decode(leaf.getText(), leaf.getOffset(), false));
				}
			}
		}
		return value.toString();
	}


	/**
	 * The value of a string literal as written (quotes included). With {@code check}, reports what
	 * protoc's tokenizer refuses: a missing closing quote, an unknown escape, an escape without digits.
	 */
	private String decode(String literal, int offset, boolean check) {
		char quote = literal.charAt(0);
		boolean closed = literal.length() >= 2 && literal.charAt(literal.length() - 1) == quote
				&& !escapedAt(literal, literal.length() - 1);
		if (check && !closed) {
			report(offset, "unterminated string literal");
		}
		int end = closed ? literal.length() - 1 : literal.length();
		StringBuilder value = new StringBuilder();
		int i = 1;
		while (i < end) {
			char c = literal.charAt(i);
			if (c != '\\' || i + 1 >= end) {
				value.append(c == '\\' ? "" : String.valueOf(c));
				i++;
				continue;
			}
			int escape = i;
			char e = literal.charAt(i + 1);
			i += 2;
			switch (e) {
			case 'a' -> value.append('\u0007');
			case 'b' -> value.append('\b');
			case 'f' -> value.append('\f');
			case 'n' -> value.append('\n');
			case 'r' -> value.append('\r');
			case 't' -> value.append('\t');
			case 'v' -> value.append('\u000B');
			case '\\', '\'', '"', '?' -> value.append(e);
			case 'x', 'X', 'u', 'U' -> {
				int max = e == 'u' ? 4 : e == 'U' ? 8 : 2;
				int digitsEnd = digits(literal, i, end, max, 16);
				code(value, literal.substring(i, digitsEnd), 16, offset + escape, check);
				i = digitsEnd;
			}
			default -> {
				if (e >= '0' && e <= '7') {
					int digitsEnd = digits(literal, i - 1, end, 3, 8);
					code(value, literal.substring(i - 1, digitsEnd), 8, offset + escape, check);
					i = digitsEnd;
				} else {
					if (check) {
						report(offset + escape, "invalid escape sequence '\\" + e + "'");
					}
					value.append(e);
				}
			}
			}
		}
		return value.toString();
	}

	/** Whether the character at {@code index} is escaped by an odd run of backslashes before it. */
	private static boolean escapedAt(String literal, int index) {
		int backslashes = 0;
		for (int i = index - 1; i > 0 && literal.charAt(i) == '\\'; i--) {
			backslashes++;
		}
		return backslashes % 2 == 1;
	}

	private static int digits(String s, int from, int end, int max, int radix) {
		int i = from;
		while (i < end && i - from < max && s.charAt(i) < 128 && Character.digit(s.charAt(i), radix) >= 0) {
			i++;
		}
		return i;
	}

	private void code(StringBuilder value, String digits, int radix, int at, boolean check) {
		if (digits.isEmpty()) {
			if (check) {
				report(at, "escape sequence without digits");
			}
			return;
		}
		long code = Long.parseLong(digits, radix);
		if (code > Character.MAX_CODE_POINT) {
			if (check) {
				report(at, "escape sequence beyond Unicode");
			}
			return;
		}
		value.appendCodePoint((int) code);
	}

	// ---- lexical checks, over every token the lexer made (hidden ones included)

	private void checkTokens(ICompositeNode root) {
		int garbageStart = -1;
		int garbageEnd = -1;
		for (ILeafNode leaf : root.getLeafNodes()) {
			String token = leaf.getText();
			int offset = leaf.getOffset();
			if (token.isEmpty() || offset >= text.length()) {
				continue;
			}
			boolean garbage = isGarbage(leaf);
			if (garbageStart >= 0 && (!garbage || offset != garbageEnd)) {
				reportGarbage(garbageStart, garbageEnd);
				garbageStart = -1;
			}
			if (garbage) {
				if (garbageStart < 0) {
					garbageStart = offset;
				}
				garbageEnd = offset + token.length();
				continue;
			}
			char first = token.charAt(0);
			if (token.startsWith("/*")) {
				if (token.length() < 4 || !token.endsWith("*/")) {
					lexical(offset, "unterminated comment: '/*' without '*/'");
				}
			} else if (first == '"' || first == '\'') {
				int before = problems.list().size();
				decode(token, offset, true);
				if (problems.list().size() > before) {
					lexicalOffsets.add(offset);
				}
			} else if (first >= '0' && first <= '9' || first == '.' && token.length() > 1) {
				String problem = numberProblem(token);
				if (problem != null) {
					lexical(offset, problem);
				}
			}
		}
		if (garbageStart >= 0) {
			reportGarbage(garbageStart, garbageEnd);
		}
	}

	/** A character the lexer made an ANY_OTHER token of: one that starts no token of the language. */
	private static boolean isGarbage(ILeafNode leaf) {
		EObject element = leaf.getGrammarElement();
		AbstractRule rule = element instanceof RuleCall call ? call.getRule() : element instanceof AbstractRule r ? r : null;
		return rule instanceof TerminalRule && "ANY_OTHER".equals(rule.getName());
	}

	/** A run of unexpected characters is reported once, not once per character. */
	private void reportGarbage(int start, int end) {
		String garbage = text.substring(start, Math.min(end, text.length()));
		String shown = garbage.codePoints().limit(10)
				.mapToObj(cp -> Character.isISOControl(cp) ? String.format("\\u%04X", cp) : Character.toString(cp))
				.reduce("", String::concat);
		lexical(start, "unexpected character" + (garbage.codePointCount(0, garbage.length()) > 1 ? "s" : "") + " '" + shown
				+ (garbage.codePointCount(0, garbage.length()) > 10 ? "..." : "") + "'");
	}

	private void lexical(int offset, String message) {
		lexicalOffsets.add(offset);
		report(offset, message);
	}

	private void reportIssue(Issue issue) {
		String[] data = issue.getData();
		int offset;
		if (data != null && data.length == 1 && ProtoSyntaxErrorMessageProvider.AT_END.equals(data[0])) {
			offset = text.length();
		} else if (data != null && data.length == 1 && data[0].matches("-?[0-9]+")) {
			offset = Integer.parseInt(data[0]);
		} else {
			offset = issue.getOffset() == null ? 0 : issue.getOffset();
		}
		if (!lexicalOffsets.contains(offset)) {
			syntaxErrorOffsets.add(offset);
			report(offset, issue.getMessage());
		}
	}

	// ---- nesting

	/**
	 * The text with the inside of every block nested more than {@link #MAX_NESTING} deep blanked out
	 * (line breaks kept, so positions stay): an LL parser recurses once per level, and a crafted file
	 * must not overflow its stack. Comments and strings are skipped as the lexer does.
	 */
	private String limitNesting(String source) {
		char[] chars = null;
		int depth = 0;
		int blankFrom = -1;
		int i = 0;
		int n = source.length();
		while (i < n) {
			char c = source.charAt(i);
			if (c == '/' && i + 1 < n && source.charAt(i + 1) == '/') {
				while (i < n && source.charAt(i) != '\n' && source.charAt(i) != '\r') {
					i++;
				}
				continue;
			}
			if (c == '/' && i + 1 < n && source.charAt(i + 1) == '*') {
				int close = source.indexOf("*/", i + 2);
				i = close < 0 ? n : close + 2;
				continue;
			}
			if (c == '"' || c == '\'') {
				i++;
				while (i < n && source.charAt(i) != c && source.charAt(i) != '\n' && source.charAt(i) != '\r') {
					i += source.charAt(i) == '\\' && i + 1 < n && source.charAt(i + 1) != '\n' && source.charAt(i + 1) != '\r' ? 2 : 1;
				}
				i = Math.min(n, i + 1);
				continue;
			}
			if (c == '{' || c == '<') {
				depth++;
				if (depth == MAX_NESTING + 1 && blankFrom < 0) {
					report(i, "blocks nested more than " + MAX_NESTING + " deep; their content is skipped");
					blankFrom = i + 1;
				}
			} else if ((c == '}' || c == '>') && depth > 0) {
				depth--;
				if (depth == MAX_NESTING && blankFrom >= 0) {
					chars = blank(chars, source, blankFrom, i);
					blankFrom = -1;
				}
			}
			i++;
		}
		if (blankFrom >= 0) {
			chars = blank(chars, source, blankFrom, n);
		}
		return chars == null ? source : new String(chars);
	}

	private static char[] blank(char[] chars, String source, int from, int to) {
		char[] result = chars == null ? source.toCharArray() : chars;
		for (int i = from; i < to; i++) {
			if (result[i] != '\n' && result[i] != '\r') {
				result[i] = ' ';
			}
		}
		return result;
	}

	/**
	 * A feature as written, its tokens joined without what lies between them (a data-type rule's
	 * value keeps comments and blanks: {@code - 1} would not read as a number); null when absent.
	 */
	private static String written(EObject object, EStructuralFeature feature) {
		if (object.eGet(feature) == null) {
			return null;
		}
		StringBuilder text = new StringBuilder();
		for (INode node : NodeModelUtils.findNodesForFeature(object, feature)) {
			for (ILeafNode leaf : node.getLeafNodes()) {
				if (!leaf.isHidden()) {
					text.append(leaf.getText());
				}
			}
		}
		return text.isEmpty() ? null : text.toString();
	}

	// ---- positions

	/** Offset of an object's first token. */
	private static int start(EObject object) {
		INode node = NodeModelUtils.getNode(object);
		return node == null ? 0 : node.getOffset();
	}

	/** Offset of a feature's first token; the object's when the feature has no node. */
	private static int start(EObject object, EStructuralFeature feature) {
		List<INode> nodes = NodeModelUtils.findNodesForFeature(object, feature);
		return nodes.isEmpty() ? start(object) : nodes.get(0).getOffset();
	}

	/** Offset of the number token of a feature written {@code -N}: after the sign. */
	private static int numberToken(EObject object, EStructuralFeature feature) {
		for (INode node : NodeModelUtils.findNodesForFeature(object, feature)) {
			for (ILeafNode leaf : node.getLeafNodes()) {
				if (!leaf.isHidden() && !leaf.getText().equals("-")) {
					return leaf.getOffset();
				}
			}
		}
		return start(object, feature);
	}

	/** Offset of a keyword inside an object's text. */
	private static int keyword(EObject object, String keyword) {
		INode node = NodeModelUtils.getNode(object);
		if (node != null) {
			for (ILeafNode leaf : node.getLeafNodes()) {
				if (!leaf.isHidden() && leaf.getText().equals(keyword)) {
					return leaf.getOffset();
				}
			}
		}
		return start(object);
	}

	private int lineIndex(int offset) {
		return LineStarts.lineIndex(lineStarts, Math.max(0, Math.min(offset, text.length())));
	}

	private int line(int offset) {
		return lineIndex(offset) + 1;
	}

	private int column(int offset) {
		int o = Math.max(0, Math.min(offset, text.length()));
		return o - lineStarts[lineIndex(o)] + 1;
	}

	private void report(int offset, String message) {
		problems.report(line(offset), column(offset), message);
	}

	/** Duplicate names and numbers inside one message, oneof fields included. */
	private final class FieldNames {
		private final String messageName;
		private final Set<String> names = new HashSet<>();
		private final Map<Integer, String> numbers = new HashMap<>();

		FieldNames(String messageName) {
			this.messageName = messageName;
		}

		void check(String name, int at, int number) {
			if (!names.add(name)) {
				report(at, "duplicate field name " + name + " in message " + messageName);
			}
			if (number > 0) {
				String other = numbers.putIfAbsent(number, name);
				if (other != null) {
					report(at, "field number " + number + " of " + name + " is already used by " + other);
				}
			}
		}
	}
}
