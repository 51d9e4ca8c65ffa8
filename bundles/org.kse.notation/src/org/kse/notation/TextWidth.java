package org.kse.notation;

/**
 * How wide a text is drawn, estimated from the advance widths of DejaVu Sans (the widest of the
 * fonts the diagram names, and the one Linux browsers use), rounded up per class of character, so
 * that a box sized by it holds the text in any of those fonts.
 */
public final class TextWidth {

	private TextWidth() {
	}

	/** The width (px) of one line of text at this font size, bold or not. */
	public static double of(String text, double fontSize, boolean bold) {
		double ems = 0;
		for (int i = 0; i < text.length(); i++) {
			ems += em(text.charAt(i));
		}
		return Math.ceil(ems * fontSize * (bold ? 1.12 : 1));
	}

	/** A character's advance in ems (DejaVu Sans Book, rounded up). */
	private static double em(char c) {
		if ("iljI.,:;'!| ".indexOf(c) >= 0) {
			return 0.34;
		}
		if ("ftr()[]{}/\\-\"`".indexOf(c) >= 0) {
			return 0.45;
		}
		if ("mwMW".indexOf(c) >= 0) {
			return 1.0;
		}
		if ("=+<>~%&@#…".indexOf(c) >= 0 || Character.isUpperCase(c)) {
			return 0.86;
		}
		return 0.66;
	}
}
