package org.kse.ui.messages;

import java.util.List;
import java.util.Set;

import org.eclipse.jface.text.TextAttribute;
import org.eclipse.jface.text.rules.EndOfLineRule;
import org.eclipse.jface.text.rules.ICharacterScanner;
import org.eclipse.jface.text.rules.IPredicateRule;
import org.eclipse.jface.text.rules.IRule;
import org.eclipse.jface.text.rules.IToken;
import org.eclipse.jface.text.rules.IWordDetector;
import org.eclipse.jface.text.rules.MultiLineRule;
import org.eclipse.jface.text.rules.RuleBasedPartitionScanner;
import org.eclipse.jface.text.rules.RuleBasedScanner;
import org.eclipse.jface.text.rules.SingleLineRule;
import org.eclipse.jface.text.rules.Token;
import org.eclipse.jface.text.rules.WordRule;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;
import org.kse.messages.ScalarKind;

/**
 * Colours of a {@code .proto} file. Comments and strings are partitions of their own, so that a
 * {@code /*} typed on one line recolours every line after it, and {@code "//"} in a string is no
 * comment; the rest is scanned for keywords, scalar types and numbers.
 */
class ProtoScanner extends RuleBasedScanner {

	static final String PARTITIONING = "org.kse.ui.messages.partitioning";
	static final String COMMENT_PARTITION = "__proto_comment";
	static final String STRING_PARTITION = "__proto_string";
	static final String[] PARTITIONS = { COMMENT_PARTITION, STRING_PARTITION };

	static final Color KEYWORD = new Color(0x7f, 0x00, 0x55);
	static final Color SCALAR = new Color(0x1f, 0x4e, 0x9c);
	static final Color COMMENT = new Color(0x3f, 0x7f, 0x5f);
	static final Color STRING = new Color(0x2a, 0x00, 0xff);
	static final Color NUMBER = new Color(0xb7, 0x1c, 0x1c);
	/** Outline colours of declarations, in the scanner's palette. */
	static final Color MESSAGE = new Color(0x2e, 0x7d, 0x32);
	static final Color ENUM = new Color(0x8e, 0x24, 0xaa);

	/**
	 * The words protoc gives a meaning to. They stay names where protoc takes them as names (a
	 * field called {@code message}), which a scanner cannot tell: like every protobuf editor,
	 * they are coloured as keywords wherever they stand.
	 */
	static final Set<String> KEYWORDS = Set.of("syntax", "edition", "package", "import", "public", "weak", "option",
			"message", "enum", "oneof", "map", "optional", "required", "repeated", "reserved", "extensions", "extend",
			"to", "max", "service", "rpc", "returns", "stream", "group", "true", "false");

	ProtoScanner() {
		IToken keyword = new Token(new TextAttribute(KEYWORD, null, SWT.BOLD));
		IToken scalar = new Token(new TextAttribute(SCALAR, null, SWT.BOLD));
		IToken number = new Token(new TextAttribute(NUMBER));
		WordRule words = new WordRule(new NameDetector(), Token.UNDEFINED);
		KEYWORDS.forEach(word -> words.addWord(word, keyword));
		for (ScalarKind kind : ScalarKind.values()) {
			words.addWord(kind.protoName(), scalar);
		}
		setRules(new IRule[] { words, new NumberRule(number) });
	}

	/** Finds comments and strings: the partitions the code scanner never sees. */
	static RuleBasedPartitionScanner partitions() {
		IToken comment = new Token(COMMENT_PARTITION);
		IToken string = new Token(STRING_PARTITION);
		RuleBasedPartitionScanner scanner = new RuleBasedPartitionScanner();
		// An unclosed comment or string runs to the end of the file or line, as the grammar reads it.
		List<IPredicateRule> rules = List.of(new MultiLineRule("/*", "*/", comment, (char) 0, true),
				new EndOfLineRule("//", comment), new SingleLineRule("\"", "\"", string, '\\', true),
				new SingleLineRule("'", "'", string, '\\', true));
		scanner.setPredicateRules(rules.toArray(IPredicateRule[]::new));
		return scanner;
	}

	/** One colour for a whole partition (a comment, a string). */
	static RuleBasedScanner whole(Color colour, int style) {
		RuleBasedScanner scanner = new RuleBasedScanner();
		scanner.setDefaultReturnToken(new Token(new TextAttribute(colour, null, style)));
		return scanner;
	}

	static boolean isNameStart(int c) {
		return c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z' || c == '_';
	}

	static boolean isNamePart(int c) {
		return isNameStart(c) || c >= '0' && c <= '9';
	}

	private static final class NameDetector implements IWordDetector {
		@Override
		public boolean isWordStart(char c) {
			return isNameStart(c);
		}

		@Override
		public boolean isWordPart(char c) {
			return isNamePart(c);
		}
	}

	/** Decimal, hex, octal and floating point numbers: digits and whatever letters and dots follow them. */
	private record NumberRule(IToken number) implements IRule {
		@Override
		public IToken evaluate(ICharacterScanner scanner) {
			int c = scanner.read();
			if (c < '0' || c > '9') {
				scanner.unread();
				return Token.UNDEFINED;
			}
			int previous;
			do {
				previous = c;
				c = scanner.read();
			} while (isNamePart(c) || c == '.' || (c == '+' || c == '-') && (previous == 'e' || previous == 'E'));
			scanner.unread();
			return number;
		}
	}
}
