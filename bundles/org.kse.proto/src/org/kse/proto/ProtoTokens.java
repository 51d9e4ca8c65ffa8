package org.kse.proto;

/** How a token of a {@code .proto} file is named in a message to the user. */
public final class ProtoTokens {

	private static final int LONGEST = 40;

	private ProtoTokens() {
	}

	/** A string literal as {@code string "text"}, anything else quoted; long ones shortened. */
	public static String describe(String token) {
		if (isString(token)) {
			String inner = token.length() >= 2 && token.charAt(token.length() - 1) == token.charAt(0) ? token.substring(1, token.length() - 1)
					: token.substring(1);
			return "string \"" + abbreviate(inner) + "\"";
		}
		return "'" + abbreviate(token) + "'";
	}

	/** Whether a token is a string literal (its closing quote may be missing). */
	public static boolean isString(String token) {
		return !token.isEmpty() && (token.charAt(0) == '"' || token.charAt(0) == '\'');
	}

	private static String abbreviate(String text) {
		return text.length() <= LONGEST ? text : text.substring(0, LONGEST - 3) + "...";
	}
}
