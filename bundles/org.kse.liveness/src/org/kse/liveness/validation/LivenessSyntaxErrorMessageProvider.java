package org.kse.liveness.validation;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Locale;

import org.antlr.runtime.CommonToken;
import org.antlr.runtime.RecognitionException;
import org.antlr.runtime.Token;
import org.antlr.runtime.TokenStream;
import org.antlr.runtime.UnwantedTokenException;
import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.SyntaxErrorMessage;
import org.eclipse.xtext.parser.antlr.SyntaxErrorMessageProvider;
import org.kse.liveness.parser.antlr.internal.InternalLivenessParser;

/**
 * Syntax errors in the words of formulas. The parser only knows which token it did not
 * expect; a writer needs to know what the formula lacks at that point. So the message is
 * worked out from the line as written up to the error: which brackets are still open,
 * whether a term or an operator comes next, and how far an {@code |x~|n} got. The position
 * stays the parser's (the token it stopped at).
 */
public class LivenessSyntaxErrorMessageProvider extends SyntaxErrorMessageProvider {

	private static final String OPERATORS = "'.' (sequence), '|' (choice) or '||' (parallel)";
	private static final String A_TERM = "an activity, a capability or a bracketed group";
	private static final String A_NAME = "an activity or capability name";

	@Override
	public SyntaxErrorMessage getSyntaxErrorMessage(IParserErrorContext context) {
		RecognitionException exception = context.getRecognitionException();
		String message;
		if (exception != null && exception.input instanceof TokenStream tokens) {
			// an unwanted token has already been skipped when it is reported; otherwise the
			// error is placed at the next token still to be read
			Token offending = exception instanceof UnwantedTokenException ? exception.token : tokens.LT(1);
			message = explain(tokens, offending);
		} else {
			// ANY_OTHER makes a token of every character, so the lexer has nothing of its own
			// to report; should it report something all the same, say what a formula holds
			message = "a character that cannot appear in a formula: use names, operators, brackets and counts";
		}
		return new SyntaxErrorMessage(message, Diagnostic.SYNTAX_DIAGNOSTIC);
	}

	/** The only value converted from text is the count of {@code |x~|n}; it fails when it does not fit an int. */
	@Override
	public SyntaxErrorMessage getSyntaxErrorMessage(IValueConverterErrorContext context) {
		INode node = context.getValueConverterException().getNode();
		String text = node == null ? "" : node.getText().strip();
		String message = text.chars().allMatch(Character::isDigit) && !text.isEmpty()
				? "the count " + text + " is too large: |x~|n makes at most " + Integer.MAX_VALUE + " copies"
				: "'" + text + "' is not a count of copies: write a whole number after '~|'";
		return new SyntaxErrorMessage(message, Diagnostic.SYNTAX_DIAGNOSTIC);
	}

	private static String explain(TokenStream tokens, Token offending) {
		int index = offending.getType() == Token.EOF || offending.getTokenIndex() < 0 ? tokens.size() : offending.getTokenIndex();
		int lineStart = index;
		while (lineStart > 0 && symbol(tokens.get(lineStart - 1)) != Symbol.LINE_END) {
			lineStart--;
		}
		Line line = new Line(lineStart == 0 ? 0 : stop(tokens.get(lineStart - 1)) + 1);
		for (int i = lineStart; i < index; i++) {
			Token token = tokens.get(i);
			if (token.getChannel() == Token.DEFAULT_CHANNEL) {
				line.read(token);
			}
		}
		Symbol symbol = symbol(offending);
		if (symbol == Symbol.STRAY) {
			return stray(tokens, offending, index);
		}
		return line.whyNot(offending, symbol);
	}

	private enum Symbol {
		NAME, NUMBER, EQUALS, SEQUENCE, CHOICE, PARALLEL, SUFFIX, OPEN_GROUP, CLOSE_GROUP, OPEN_OPTION, CLOSE_OPTION, LINE_END, STRAY
	}

	private static Symbol symbol(Token token) {
		return switch (token.getType()) {
			case Token.EOF, InternalLivenessParser.RULE_NL -> Symbol.LINE_END;
			case InternalLivenessParser.RULE_ID -> Symbol.NAME;
			case InternalLivenessParser.RULE_INT -> Symbol.NUMBER;
			case InternalLivenessParser.RULE_ANY_OTHER -> Symbol.STRAY;
			default -> switch (token.getText() == null ? "" : token.getText()) {
				case "=" -> Symbol.EQUALS;
				case "." -> Symbol.SEQUENCE;
				case "|" -> Symbol.CHOICE;
				case "||" -> Symbol.PARALLEL;
				case "*", "+", "~" -> Symbol.SUFFIX;
				case "(" -> Symbol.OPEN_GROUP;
				case ")" -> Symbol.CLOSE_GROUP;
				case "[" -> Symbol.OPEN_OPTION;
				case "]" -> Symbol.CLOSE_OPTION;
				default -> Symbol.STRAY;
			};
		};
	}

	/** What the line lets come next. */
	private enum Next {
		DEFINED_NAME, EQUALS, TERM, OPERATOR, COPIED_TERM, COPIES_TILDE, COPIES_BAR, COPIES_COUNT
	}

	/**
	 * A bracket still open, or the '|' of an |x~|n not yet complete (symbol CHOICE).
	 * {@code copied} when the bracket is the x of an |x~|n.
	 */
	private static final class Open {
		final Token token;
		final Symbol symbol;
		final boolean copied;
		final boolean afterChoice;
		Token operandEnd;

		Open(Token token, Symbol symbol, boolean copied, boolean afterChoice) {
			this.token = token;
			this.symbol = symbol;
			this.copied = copied;
			this.afterChoice = afterChoice;
		}
	}

	/**
	 * The line read token by token up to the error, as far as it makes sense: after an
	 * earlier error on the same line it goes on with its best guess rather than stopping.
	 */
	private static final class Line {
		private final int startOffset;
		private final Deque<Open> open = new ArrayDeque<>();
		private Next next = Next.DEFINED_NAME;
		private Token previous;
		private Token definedName;

		Line(int startOffset) {
			this.startOffset = startOffset;
		}

		void read(Token token) {
			Symbol symbol = symbol(token);
			switch (symbol) {
				case NAME -> {
					if (next == Next.DEFINED_NAME) {
						definedName = token;
						next = Next.EQUALS;
					} else if (next == Next.COPIED_TERM) {
						open.peek().operandEnd = token;
						next = Next.COPIES_TILDE;
					} else {
						next = Next.OPERATOR;
					}
				}
				case NUMBER -> {
					if (next == Next.COPIES_COUNT) {
						open.pop();
					}
					next = Next.OPERATOR;
				}
				case EQUALS, SEQUENCE, PARALLEL -> next = Next.TERM;
				case CHOICE -> {
					if (next == Next.TERM || next == Next.COPIED_TERM) {
						boolean afterChoice = previous != null && symbol(previous) == Symbol.CHOICE;
						open.push(new Open(token, Symbol.CHOICE, next == Next.COPIED_TERM, afterChoice));
						next = Next.COPIED_TERM;
					} else if (next == Next.COPIES_TILDE || next == Next.COPIES_BAR) {
						next = Next.COPIES_COUNT;
					} else {
						next = Next.TERM;
					}
				}
				case SUFFIX -> next = next == Next.COPIES_TILDE && "~".equals(token.getText()) ? Next.COPIES_BAR : Next.OPERATOR;
				case OPEN_GROUP, OPEN_OPTION -> {
					open.push(new Open(token, symbol, next == Next.COPIED_TERM, false));
					next = Next.TERM;
				}
				case CLOSE_GROUP, CLOSE_OPTION -> {
					Open closed = !open.isEmpty() && open.peek().symbol == opening(symbol) ? open.pop() : null;
					if (closed != null && closed.copied && !open.isEmpty()) {
						open.peek().operandEnd = token;
						next = Next.COPIES_TILDE;
					} else {
						next = Next.OPERATOR;
					}
				}
				default -> {
					// a stray character changes nothing of what the line expects
				}
			}
			if (symbol != Symbol.STRAY) {
				previous = token;
			}
		}

		String whyNot(Token token, Symbol symbol) {
			return switch (next) {
				case DEFINED_NAME -> lineStart(token, symbol);
				case EQUALS -> afterDefinedName(symbol);
				case TERM -> termExpected(token, symbol);
				case OPERATOR -> operatorExpected(token, symbol);
				case COPIED_TERM -> symbol == Symbol.SUFFIX ? misplacedSuffix(token)
						: "expected the term to copy after '|': write |x~|n with x " + A_TERM + ", as in |Player~|3";
				case COPIES_TILDE -> symbol == Symbol.SUFFIX
						? "'" + token.getText() + "' cannot follow the x of |x~|n: put x and '" + token.getText() + "' in brackets, as in |("
								+ copied() + token.getText() + ")~|3"
						: "expected '~|' and a count after '|" + copied() + "', as in |" + copied() + "~|3"
								+ (open.peek().afterChoice ? " (or, if you meant a choice, remove the second '|')" : "");
				case COPIES_BAR -> "expected '|' and a count after '|" + copied() + "~', as in |" + copied() + "~|3";
				case COPIES_COUNT -> "|x~|n needs its count: write the number of copies after '~|', as in |" + copied() + "~|3";
			};
		}

		private String lineStart(Token token, Symbol symbol) {
			return switch (symbol) {
				case EQUALS -> "'=' needs the name being defined on its left: write 'name = expression'";
				case NUMBER -> "a name cannot start with a digit: a line starts with the name it defines, as in 'name = expression'";
				default -> describe(token) + " cannot start a line: a line starts with the name it defines, as in 'name = expression'";
			};
		}

		private String afterDefinedName(Symbol symbol) {
			String name = definedName.getText();
			return switch (symbol) {
				case LINE_END -> "'" + name + "' stands alone on its line: write '" + name
						+ " = expression' (only the first line may hold the model's name alone)";
				case NAME -> "expected '=' after '" + name + "': a name is one word of letters, digits and '_', without blanks";
				default -> "expected '=' after '" + name + "', as in '" + name + " = expression'";
			};
		}

		private String termExpected(Token token, Symbol symbol) {
			boolean afterOperator = previous != null && switch (symbol(previous)) {
				case SEQUENCE, CHOICE, PARALLEL -> true;
				default -> false;
			};
			return switch (symbol) {
				case SUFFIX -> misplacedSuffix(token);
				case SEQUENCE, CHOICE, PARALLEL -> afterOperator
						? "expected " + A_NAME + " between '" + previous.getText() + "' and '" + token.getText() + "'"
						: "'" + token.getText() + "' needs a term on its left: write " + A_TERM + " before it";
				case LINE_END -> afterOperator
						? "expected " + A_NAME + " after '" + previous.getText() + "' (a formula cannot go on to the next line)"
						: unclosed();
				case CLOSE_GROUP, CLOSE_OPTION -> {
					String wrong = closesWrongly(token, symbol);
					yield wrong != null ? wrong : "expected " + A_NAME + " after '" + previous.getText() + "', before '" + token.getText() + "'";
				}
				case EQUALS -> "a line holds one definition: '=' cannot appear on the right side";
				case NUMBER -> "'" + token.getText() + "' is not a name: names start with a letter or '_', and a number only counts the copies of |x~|n";
				default -> outOfPlace(token);
			};
		}

		private String operatorExpected(Token token, Symbol symbol) {
			return switch (symbol) {
				case NAME, OPEN_GROUP, OPEN_OPTION -> "expected an operator "
						+ (symbol(previous) == Symbol.NAME ? "between '" + previous.getText() + "' and '" : "before '") + token.getText() + "': "
						+ OPERATORS;
				case NUMBER -> "'" + token.getText() + "' cannot follow '" + previous.getText()
						+ "': a number only counts the copies of |x~|n, as in |B~|" + token.getText();
				case CLOSE_GROUP, CLOSE_OPTION -> {
					String wrong = closesWrongly(token, symbol);
					yield wrong != null ? wrong : outOfPlace(token);
				}
				case LINE_END -> open.isEmpty() ? outOfPlace(token) : unclosed();
				case EQUALS -> "a line holds one definition: start a new line for the next 'name = expression'";
				default -> outOfPlace(token);
			};
		}

		private static String misplacedSuffix(Token token) {
			return "'" + token.getText() + "' must follow a term: write it after an activity, a capability or a bracketed group";
		}

		/** Why a closing bracket closes nothing or the wrong bracket; null when it closes the innermost one. */
		private String closesWrongly(Token token, Symbol symbol) {
			Open innermost = open.peek();
			if (innermost == null) {
				return "unbalanced '" + token.getText() + "': no matching '" + (symbol == Symbol.CLOSE_GROUP ? "(" : "[") + "' before it";
			}
			if (innermost.symbol == Symbol.CHOICE) {
				return "'" + token.getText() + "' comes before the |x~|n started at column " + column(innermost.token)
						+ " is complete, as in |Player~|3";
			}
			if (innermost.symbol != opening(symbol)) {
				return "'" + token.getText() + "' cannot close the '" + innermost.token.getText() + "' at column " + column(innermost.token)
						+ ": close it with '" + closing(innermost.symbol) + "' first";
			}
			return null;
		}

		private String unclosed() {
			Open innermost = open.peek();
			if (innermost == null) {
				return "the formula stops too early: expected " + A_TERM;
			}
			if (innermost.symbol == Symbol.CHOICE) {
				return "the |x~|n started at column " + column(innermost.token) + " is not complete: write it as in |Player~|3";
			}
			return "unbalanced '" + innermost.token.getText() + "' at column " + column(innermost.token) + ": no matching '"
					+ closing(innermost.symbol) + "' before the end of the line";
		}

		private static String outOfPlace(Token token) {
			return describe(token) + " is out of place here: a line is 'name = expression', its terms joined by " + OPERATORS;
		}

		/** The x of the |x~|n being written, as written. */
		private String copied() {
			Open copies = open.peek();
			if (copies == null || copies.symbol != Symbol.CHOICE || copies.operandEnd == null || copies.token.getInputStream() == null) {
				return "x";
			}
			String text = copies.token.getInputStream().substring(stop(copies.token) + 1, stop(copies.operandEnd)).strip();
			return text.isEmpty() || text.length() > 40 ? "x" : text;
		}

		private int column(Token token) {
			return start(token) - startOffset + 1;
		}
	}

	/** Xtext's lexer makes CommonTokens, which know where they lie in the text. */
	private static int start(Token token) {
		return token instanceof CommonToken common ? common.getStartIndex() : 0;
	}

	private static int stop(Token token) {
		return token instanceof CommonToken common ? common.getStopIndex() : 0;
	}

	private static Symbol opening(Symbol closing) {
		return closing == Symbol.CLOSE_GROUP ? Symbol.OPEN_GROUP : Symbol.OPEN_OPTION;
	}

	private static String closing(Symbol opening) {
		return opening == Symbol.OPEN_GROUP ? ")" : "]";
	}

	private static String describe(Token token) {
		return switch (symbol(token)) {
			case LINE_END -> token.getType() == Token.EOF ? "the end of the file" : "the end of the line";
			default -> "'" + token.getText() + "'";
		};
	}

	/** A character that is no part of the language: say which, and what was probably meant. */
	private static String stray(TokenStream tokens, Token token, int index) {
		String text = token.getText() == null ? "" : token.getText();
		int codePoint = text.isEmpty() ? 0 : text.codePointAt(0);
		if (!text.isEmpty() && Character.isHighSurrogate(text.charAt(0)) && index + 1 < tokens.size()) {
			String next = tokens.get(index + 1).getText();
			if (next != null && !next.isEmpty() && Character.isLowSurrogate(next.charAt(0))) {
				codePoint = Character.toCodePoint(text.charAt(0), next.charAt(0));
			}
		}
		String shown = shown(codePoint);
		if (Character.isLetterOrDigit(codePoint)) {
			return shown + " cannot be part of a name: names use only the letters a-z and A-Z, the digits 0-9 and '_'";
		}
		if (Character.isWhitespace(codePoint) || Character.isSpaceChar(codePoint) || Character.getType(codePoint) == Character.FORMAT) {
			return shown + ", a blank or invisible character, cannot appear in a formula: use spaces or tabs";
		}
		if (codePoint == '/') {
			return "a single '/' is not an operator: a comment starts with '//'";
		}
		if (codePoint == '&' || codePoint == ',' || codePoint == ';') {
			return shown + " is not an operator: join terms with " + OPERATORS;
		}
		return shown + " cannot appear in a formula: a line holds names, the operators '.', '|' and '||', the suffixes '*', '+' and '~', "
				+ "brackets and counts";
	}

	private static String shown(int codePoint) {
		if (codePoint > 0x20 && codePoint < 0x7F) {
			return "'" + (char) codePoint + "'";
		}
		String code = String.format(Locale.ROOT, "U+%04X", codePoint);
		boolean visible = switch (Character.getType(codePoint)) {
			case Character.CONTROL, Character.FORMAT, Character.SURROGATE, Character.PRIVATE_USE, Character.UNASSIGNED,
					Character.SPACE_SEPARATOR, Character.LINE_SEPARATOR, Character.PARAGRAPH_SEPARATOR -> false;
			default -> true;
		};
		return visible ? "'" + new String(Character.toChars(codePoint)) + "' (" + code + ")" : code;
	}
}
