package org.kse.proto.validation;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.antlr.runtime.CommonToken;
import org.antlr.runtime.MismatchedTokenException;
import org.antlr.runtime.RecognitionException;
import org.antlr.runtime.Token;
import org.antlr.runtime.TokenStream;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.AbstractRule;
import org.eclipse.xtext.Action;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.RuleCall;
import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.parser.antlr.SyntaxErrorMessageProvider;
import org.eclipse.xtext.util.LineAndColumn;
import org.kse.proto.parser.antlr.internal.InternalProtoParser;
import org.kse.proto.ProtoTokens;

/**
 * Syntax errors in the words a protobuf writer uses ("expected ';' after field x", "missing '}' to
 * close message A opened at 2:1"), never the parser's token names. The message is worked out from
 * the rule being parsed, the token before the error and the token the parser wanted.
 *
 * <p>
 * Each message carries, as its only issue datum, the offset where it belongs: the offending token's,
 * or for a missing ';' the end of the token before it (where the ';' should go), or {@link #AT_END}
 * at the end of the file. Xtext places syntax errors on nodes, which is not always that point.
 */
public class ProtoSyntaxErrorMessageProvider extends SyntaxErrorMessageProvider {

	/** The issue datum for "at the end of the text". */
	public static final String AT_END = "end";

	private static final Set<String> BLOCKS = Set.of("MessageDecl", "EnumDecl", "OneofDecl", "ServiceDecl", "ExtendDecl",
			"GroupDecl", "RpcDecl");

	@Override
	public SyntaxErrorMessage getSyntaxErrorMessage(IParserErrorContext context) {
		RecognitionException exception = context.getRecognitionException();
		if (exception == null || exception.token == null || !(exception.input instanceof TokenStream tokens)) {
			return new SyntaxErrorMessage("this cannot be read as part of a .proto file", Diagnostic.SYNTAX_DIAGNOSTIC);
		}
		Error error = new Error(exception, tokens, context.getCurrentNode(), context.getTokenNames());
		String message = error.message();
		String at = error.atEnd ? AT_END : String.valueOf(error.offset);
		return new SyntaxErrorMessage(message, Diagnostic.SYNTAX_DIAGNOSTIC, new String[] { at });
	}

	/** One syntax error and what is known around it. */
	private static final class Error {
		final Token offending;
		final Token previous;
		final int expecting;
		final String[] tokenNames;
		/** Rule invocations, innermost first. */
		final List<ICompositeNode> rules = new ArrayList<>();
		int offset;
		boolean atEnd;

		Error(RecognitionException exception, TokenStream tokens, INode node, String[] tokenNames) {
			this.offending = exception.token;
			this.tokenNames = tokenNames;
			this.expecting = exception instanceof MismatchedTokenException mismatch ? mismatch.expecting : Integer.MIN_VALUE;
			this.previous = previousSignificant(tokens, offending);
			for (INode n = node; n != null; n = n.getParent()) {
				if (n instanceof ICompositeNode composite && ruleName(composite) != null) {
					rules.add(composite);
				}
			}
			this.atEnd = offending.getType() == Token.EOF;
			this.offset = start(offending);
		}

		String message() {
			String inner = rules.isEmpty() ? "" : ruleName(rules.get(0));
			String found = describe(offending);
			String prev = previous == null ? "" : previous.getText();

			if (expecting == t(";")) {
				if (previous != null) {
					atEnd = false;
					offset = stop(previous) + 1;
				}
				return "expected ';' " + after() + ", found " + found;
			}
			if (atEnd) {
				ICompositeNode block = innermostBlock();
				if (block != null && (BLOCKS.contains(inner) || expecting == t("}"))) {
					return "missing '}' to close " + what(block) + " opened at " + position(block);
				}
			}
			if (expecting == t("=")) {
				return "expected '=' " + switch (enclosing()) {
				case "FieldDecl", "MapFieldDecl", "GroupDecl" -> "after field name " + name(enclosingNode());
				case "EnumValueDecl" -> "after enum value " + name(enclosingNode());
				case "SyntaxDecl" -> "after 'syntax'";
				case "EditionDecl" -> "after 'edition'";
				default -> "after the option name";
				} + ", found " + found;
			}
			if (expecting == t("]")) {
				ICompositeNode options = find("FieldOptions");
				return options != null ? "missing ']' to close the options opened at " + position(options) + ", found " + found
						: "expected ']', found " + found;
			}
			if (expecting == t("}") || expecting == Token.EOF) {
				if (expecting == t("}") && inner.equals("Aggregate")) {
					return "expected a field of the option value or '}', found " + found;
				}
				return unexpectedInBlock(found);
			}
			if (prev.equals("=")) {
				return switch (enclosing()) {
				case "FieldDecl", "MapFieldDecl", "GroupDecl" -> "expected a field number, found " + found;
				case "EnumValueDecl" -> "expected the number of enum value " + name(enclosingNode()) + ", found " + found;
				case "SyntaxDecl" -> "expected \"proto2\" or \"proto3\", found " + found;
				case "EditionDecl" -> "expected the edition as a string, found " + found;
				default -> "expected an option value, found " + found;
				};
			}
			if ((prev.equals("optional") || prev.equals("required") || prev.equals("repeated"))
					&& (inner.equals("MessageElement") || enclosing().equals("FieldDecl"))) {
				return "expected a field type after '" + prev + "', found " + found;
			}
			if (prev.equals(".")) {
				return "expected a name after '.', found " + found;
			}
			switch (prev) {
			case "message", "enum", "oneof", "service", "rpc", "group" -> {
				if (enclosing().equals(declaration(prev))) {
					return "expected " + (prev.equals("enum") ? "an " : "a ") + prev + " name, found " + found;
				}
			}
			case "package" -> {
				return "expected a package name, found " + found;
			}
			case "import", "public", "weak" -> {
				if (enclosing().equals("ImportDecl")) {
					return "expected the imported file name as a string, found " + found;
				}
			}
			case "option" -> {
				return "expected an option name, found " + found;
			}
			case "extend" -> {
				return "expected the name of the message to extend, found " + found;
			}
			case "reserved", "extensions" -> {
				return "expected field numbers or names after '" + prev + "', found " + found;
			}
			default -> {
				// below
			}
			}
			switch (enclosing()) {
			case "FieldDecl", "GroupDecl" -> {
				EObject field = semantic(enclosingNode());
				if (field != null && value(field, "type") == null && !prev.equals("group")) {
					return "expected a field type, found " + found;
				}
				return "expected a field name, found " + found;
			}
			case "MapFieldDecl" -> {
				return switch (prev) {
				case "map" -> "expected '<' after 'map', found " + found;
				case "<" -> "expected the map key type, found " + found;
				case "," -> "expected the map value type, found " + found;
				case ">" -> "expected a field name, found " + found;
				default -> expecting == t(",") ? "expected ',' after the map key type, found " + found
						: expecting == t(">") ? "expected '>' after the map value type, found " + found
								: "expected a field name, found " + found;
				};
			}
			case "EnumValueDecl" -> {
				return "expected an enum value in enum " + name(find("EnumDecl")) + ", found " + found;
			}
			case "MessageDecl", "EnumDecl", "OneofDecl", "ServiceDecl", "ExtendDecl" -> {
				if (expecting == t("{")) {
					return "expected '{' after the " + word(enclosing()) + " name, found " + found;
				}
			}
			default -> {
				// below
			}
			}
			if (inner.equals("MessageElement") || inner.equals("EnumElement") || inner.equals("ServiceElement")
					|| inner.equals("Statement")) {
				return unexpectedInBlock(found);
			}
			if (expecting != Integer.MIN_VALUE) {
				return "expected " + expected(expecting) + ", found " + found;
			}
			return found + " cannot appear here";
		}

		/** The block (or the file) the offending token stands in, and what may stand there. */
		private String unexpectedInBlock(String found) {
			ICompositeNode block = innermostBlock();
			if (block == null) {
				return "expected 'message', 'enum', 'import', 'package', 'option' or 'service', found " + found;
			}
			String name = name(block);
			return switch (ruleName(block)) {
			case "MessageDecl" -> "expected a field, 'message', 'enum' or 'oneof' in message " + name + ", found " + found;
			case "GroupDecl" -> "expected a field in group " + name + ", found " + found;
			case "OneofDecl" -> "expected a field in oneof " + name + ", found " + found;
			case "EnumDecl" -> "expected an enum value in enum " + name + ", found " + found;
			case "ServiceDecl" -> "expected 'rpc' or 'option' in service " + name + ", found " + found;
			case "ExtendDecl" -> "expected a field in the extension, found " + found;
			default -> "expected 'option' or '}' in rpc " + name + ", found " + found;
			};
		}

		/** "after field x", for a missing ';'. */
		private String after() {
			return switch (enclosing()) {
			case "FieldDecl", "MapFieldDecl" -> "after field " + name(enclosingNode());
			case "EnumValueDecl" -> "after enum value " + name(enclosingNode());
			case "SyntaxDecl" -> "after the syntax statement";
			case "EditionDecl" -> "after the edition statement";
			case "PackageDecl" -> "after the package name";
			case "ImportDecl" -> "after the import";
			case "OptionDecl" -> "after the option";
			case "ReservedDecl" -> "after the reserved ranges";
			case "ExtensionsDecl" -> "after the extension ranges";
			case "RpcDecl" -> "after rpc " + name(enclosingNode());
			default -> "after the statement";
			};
		}

		/** The innermost rule that makes an object (a statement), skipping data-type rules and alternatives. */
		private String enclosing() {
			ICompositeNode node = enclosingNode();
			return node == null ? "" : ruleName(node);
		}

		private ICompositeNode enclosingNode() {
			for (ICompositeNode node : rules) {
				String name = ruleName(node);
				if (name.endsWith("Decl")) {
					return node;
				}
			}
			return null;
		}

		private ICompositeNode innermostBlock() {
			for (ICompositeNode node : rules) {
				if (BLOCKS.contains(ruleName(node))) {
					return node;
				}
			}
			return null;
		}

		private ICompositeNode find(String rule) {
			for (ICompositeNode node : rules) {
				if (ruleName(node).equals(rule)) {
					return node;
				}
			}
			return null;
		}

		private int t(String keyword) {
			String quoted = "'" + keyword + "'";
			for (int i = 0; i < tokenNames.length; i++) {
				if (quoted.equals(tokenNames[i])) {
					return i;
				}
			}
			return Integer.MIN_VALUE + 1;
		}

		private String expected(int type) {
			if (type == Token.EOF) {
				return "end of file";
			}
			return switch (type) {
			case InternalProtoParser.RULE_ID -> "a name";
			case InternalProtoParser.RULE_NUMBER -> "a number";
			case InternalProtoParser.RULE_STRING -> "a string";
			default -> type >= 0 && type < tokenNames.length ? tokenNames[type] : "something else";
			};
		}
	}

	private static String declaration(String keyword) {
		return switch (keyword) {
		case "message" -> "MessageDecl";
		case "enum" -> "EnumDecl";
		case "oneof" -> "OneofDecl";
		case "service" -> "ServiceDecl";
		case "rpc" -> "RpcDecl";
		default -> "GroupDecl";
		};
	}

	private static String word(String rule) {
		return switch (rule) {
		case "MessageDecl" -> "message";
		case "EnumDecl" -> "enum";
		case "OneofDecl" -> "oneof";
		case "ServiceDecl" -> "service";
		case "GroupDecl" -> "group";
		case "RpcDecl" -> "rpc";
		default -> "extended message";
		};
	}

	/** "message A", "enum E", ... */
	private static String what(ICompositeNode block) {
		String rule = ruleName(block);
		return rule.equals("ExtendDecl") ? "the extension of " + name(block) : word(rule) + " " + name(block);
	}

	/** The called parser rule of a node made for a rule call (or an action), else null. */
	private static String ruleName(ICompositeNode node) {
		Object element = node.getGrammarElement();
		if (element instanceof RuleCall call) {
			return call.getRule() == null ? null : call.getRule().getName();
		}
		if (element instanceof Action action) {
			AbstractRule rule = GrammarUtil.containingRule(action);
			return rule == null ? null : rule.getName();
		}
		return null;
	}

	private static EObject semantic(ICompositeNode node) {
		if (node == null || !node.hasDirectSemanticElement()) {
			return null;
		}
		return node.getSemanticElement();
	}

	private static Object value(EObject object, String feature) {
		EStructuralFeature f = object.eClass().getEStructuralFeature(feature);
		return f == null ? null : object.eGet(f);
	}

	/** The declared name, or the word written after the keyword when the object has none yet. */
	private static String name(ICompositeNode node) {
		EObject object = semantic(node);
		Object name = object == null ? null : value(object, object.eClass().getEStructuralFeature("extendee") != null ? "extendee" : "name");
		return name instanceof String s && !s.isEmpty() ? s : "?";
	}

	private static String position(INode node) {
		LineAndColumn lc = NodeModelUtils.getLineAndColumn(node, node.getOffset());
		return lc.getLine() + ":" + lc.getColumn();
	}

	private static Token previousSignificant(TokenStream tokens, Token token) {
		int index = token.getType() == Token.EOF || token.getTokenIndex() < 0 ? tokens.size() : token.getTokenIndex();
		for (int i = Math.min(index, tokens.size()) - 1; i >= 0; i--) {
			Token candidate = tokens.get(i);
			if (!isHidden(candidate)) {
				return candidate;
			}
		}
		return null;
	}

	private static boolean isHidden(Token token) {
		int type = token.getType();
		return type == InternalProtoParser.RULE_WS || type == InternalProtoParser.RULE_ML_COMMENT
				|| type == InternalProtoParser.RULE_SL_COMMENT || type == InternalProtoParser.RULE_ANY_OTHER;
	}

	/** How a token is named in a message. */
	private static String describe(Token token) {
		if (token.getType() == Token.EOF) {
			return "end of file";
		}
		return ProtoTokens.describe(token.getText() == null ? "" : token.getText());
	}

	private static int start(Token token) {
		return token instanceof CommonToken common ? common.getStartIndex() : 0;
	}

	private static int stop(Token token) {
		return token instanceof CommonToken common ? common.getStopIndex() : 0;
	}
}
