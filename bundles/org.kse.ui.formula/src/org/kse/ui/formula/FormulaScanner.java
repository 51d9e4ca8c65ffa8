package org.kse.ui.formula;

import org.eclipse.jface.text.TextAttribute;
import org.eclipse.jface.text.rules.EndOfLineRule;
import org.eclipse.jface.text.rules.ICharacterScanner;
import org.eclipse.jface.text.rules.IRule;
import org.eclipse.jface.text.rules.IToken;
import org.eclipse.jface.text.rules.RuleBasedScanner;
import org.eclipse.jface.text.rules.Token;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Color;

/**
 * Colours of the formula language: activities (capitalised names, the statechart's BASIC
 * states) apart from capabilities (lower-case names, defined by a formula), operators and comments.
 */
class FormulaScanner extends RuleBasedScanner {

	static final Color ACTIVITY = new Color(0x1f, 0x4e, 0x9c);
	static final Color CAPABILITY = new Color(0x2e, 0x7d, 0x32);
	static final Color OPERATOR = new Color(0x8e, 0x24, 0xaa);
	static final Color COMMENT = new Color(0x80, 0x80, 0x80);
	static final Color NUMBER = new Color(0xb7, 0x1c, 0x1c);

	FormulaScanner() {
		IToken activity = new Token(new TextAttribute(ACTIVITY, null, SWT.BOLD));
		IToken capability = new Token(new TextAttribute(CAPABILITY));
		IToken operator = new Token(new TextAttribute(OPERATOR, null, SWT.BOLD));
		IToken comment = new Token(new TextAttribute(COMMENT, null, SWT.ITALIC));
		IToken number = new Token(new TextAttribute(NUMBER));
		setRules(new IRule[] { new EndOfLineRule("//", comment), new NameRule(activity, capability), new NumberRule(number),
				new OperatorRule(operator) });
	}

	static boolean isNameStart(int c) {
		return c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z' || c == '_';
	}

	static boolean isNamePart(int c) {
		return isNameStart(c) || c >= '0' && c <= '9';
	}

	/** A name, coloured by the case of its first letter. */
	private record NameRule(IToken activity, IToken capability) implements IRule {
		@Override
		public IToken evaluate(ICharacterScanner scanner) {
			int first = scanner.read();
			if (!isNameStart(first)) {
				scanner.unread();
				return Token.UNDEFINED;
			}
			int c;
			do {
				c = scanner.read();
			} while (isNamePart(c));
			scanner.unread();
			return Character.isUpperCase(first) ? activity : capability;
		}
	}

	private record NumberRule(IToken number) implements IRule {
		@Override
		public IToken evaluate(ICharacterScanner scanner) {
			int c = scanner.read();
			if (c < '0' || c > '9') {
				scanner.unread();
				return Token.UNDEFINED;
			}
			do {
				c = scanner.read();
			} while (c >= '0' && c <= '9');
			scanner.unread();
			return number;
		}
	}

	private record OperatorRule(IToken operator) implements IRule {
		@Override
		public IToken evaluate(ICharacterScanner scanner) {
			int c = scanner.read();
			if ("=.|*+~[]()".indexOf(c) >= 0) {
				return operator;
			}
			scanner.unread();
			return Token.UNDEFINED;
		}
	}
}
