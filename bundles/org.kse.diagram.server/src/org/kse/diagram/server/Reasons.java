package org.kse.diagram.server;

import java.util.regex.Pattern;

/**
 * Why something a diagram client sent failed, in words fit for a terminal or a page: the message
 * of the exception that says it (not of its wrappers), one line, without Java's class names
 * (a helpful NullPointerException names them all), without the character that a client could
 * use to drive a terminal, and short.
 */
public final class Reasons {

	private static final Pattern QUALIFIED = Pattern.compile("\\b(?:[a-z_][\\w$]*\\.)+([A-Z][\\w$]*)(?:@[0-9a-f]+)?");
	private static final Pattern THROWABLE_PREFIX = Pattern.compile("^(?:[A-Z][\\w$]*(?:Exception|Error): )+");
	/** Gson's advice to programmers, which names its own classes. */
	private static final Pattern GSON_LENIENT = Pattern.compile("Use JsonReader\\.setStrictness\\([^)]*\\) to accept malformed JSON");
	private static final Pattern GSON_ADVICE = Pattern.compile("\\s*To override this behavior, use [^.]*\\.\\w+\\(\\) method\\.");
	private static final int LONGEST = 300;

	private Reasons() {
	}

	/** The exception that says what went wrong, under the ones that only carry it. */
	public static Throwable unwrap(Throwable failure) {
		Throwable cause = failure;
		while (cause.getCause() != null && cause.getCause() != cause && !(cause instanceof org.eclipse.glsp.server.types.GLSPServerException)
				&& (cause instanceof java.util.concurrent.CompletionException || cause instanceof java.util.concurrent.ExecutionException
						|| cause instanceof java.lang.reflect.InvocationTargetException || cause.getMessage() == null
						|| cause.getMessage().equals(cause.getCause().toString()))) {
			cause = cause.getCause();
		}
		return cause;
	}

	/** What went wrong, in a line. */
	public static String of(Throwable failure) {
		Throwable cause = unwrap(failure);
		if (cause instanceof NullPointerException) {
			return "a value is missing";
		}
		if (cause instanceof ClassCastException) {
			return "a value is of the wrong kind"; // its message names Java classes and class loaders
		}
		if (cause instanceof StackOverflowError) {
			return "it nests too deeply";
		}
		if (cause instanceof OutOfMemoryError) {
			return "it is too large";
		}
		String message = cause.getMessage();
		if (message == null || message.isBlank()) {
			return "an internal error";
		}
		if (cause instanceof org.eclipse.glsp.server.types.GLSPServerException) {
			return clean(message); // KSE's own words, which may name model elements such as a.b.C
		}
		String line = message.strip().lines().findFirst().orElse("");
		line = GSON_ADVICE.matcher(GSON_LENIENT.matcher(line).replaceAll("malformed JSON")).replaceAll("");
		return clean(THROWABLE_PREFIX.matcher(QUALIFIED.matcher(line).replaceAll("$1")).replaceFirst(""));
	}

	/** The text as one safe, short line: its first line, control characters shown as '?'. */
	public static String clean(String text) {
		String line = text.strip().lines().findFirst().orElse("");
		StringBuilder safe = new StringBuilder();
		line.codePoints().limit(LONGEST).forEach(c -> safe.appendCodePoint(Character.isISOControl(c) || c == 0x2028 || c == 0x2029 ? '?' : c));
		return line.codePointCount(0, line.length()) > LONGEST ? safe + "…" : safe.toString();
	}

	/** A name a client sent, quoted, made safe and cut short. */
	public static String quote(String text) {
		if (text == null) {
			return "null";
		}
		String safe = clean(text.length() > 80 ? text.substring(0, 80) + "…" : text);
		return "'" + safe + "'";
	}
}
