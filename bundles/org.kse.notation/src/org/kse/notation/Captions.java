package org.kse.notation;

import java.util.List;

import org.kse.model.statechart.Node;

/**
 * What a state's box shows as its name. The states that the transformation makes for the
 * operators of a liveness formula are named by spelling the operators out
 * ({@code _open_group_playing_or_nonPlaying_close_group__one_or_more_times_}); their box shows the
 * formula instead ({@code (playing | nonPlaying)+}), and the spelled name stays the state's name,
 * shown on hover and in the properties.
 */
public final class Captions {

	/** A spelled operator and how the formula writes it (the liveness grammar's literals). */
	private record Operator(String spelled, String written) {
	}

	/** Longest first, so that {@code _one_or_more_times_} is not read as {@code _or_}. */
	private static final List<Operator> OPERATORS = List.of(new Operator("_zero_or_more_times_", "*"), new Operator("_one_or_more_times_", "+"),
			new Operator("_forever__or_", "~|"), new Operator("_open_option_", "["), new Operator("_close_option_", "]"),
			new Operator("_open_group_", "("), new Operator("_close_group_", ")"), new Operator("_sequence_", " . "),
			new Operator("_parallel_", " || "), new Operator("_forever_", "~"), new Operator("_or_", " | "));

	/**
	 * Only a name holding one of these was spelled by the transformation: a name a user gave, such
	 * as {@code left_or_right}, is shown as it is.
	 */
	private static final List<String> GENERATED_MARKS = List.of("_open_group_", "_open_option_", "_one_or_more_times_", "_zero_or_more_times_",
			"_forever_");

	private Captions() {
	}

	/** The text a state's box shows: its name, or for a state named after a formula, the formula. */
	public static String of(Node node) {
		String name = node.getName() == null ? "" : node.getName();
		return isSpelledFormula(name) ? formula(name) : name;
	}

	public static boolean isSpelledFormula(String name) {
		return GENERATED_MARKS.stream().anyMatch(name::contains);
	}

	/** The formula a spelled name stands for. */
	public static String formula(String spelled) {
		StringBuilder written = new StringBuilder();
		int at = 0;
		next: while (at < spelled.length()) {
			for (Operator operator : OPERATORS) {
				if (spelled.startsWith(operator.spelled(), at)) {
					written.append(operator.written());
					at += operator.spelled().length();
					continue next;
				}
			}
			written.append(spelled.charAt(at++));
		}
		// a replication |x~|n is spelled _or_x_forever__or_n: its leading bar has no left operand
		String text = written.toString().replace("( ", "(").replace(" )", ")").replace("[ ", "[").replace(" ]", "]");
		return text.startsWith(" | ") ? "|" + text.substring(3) : text;
	}
}
