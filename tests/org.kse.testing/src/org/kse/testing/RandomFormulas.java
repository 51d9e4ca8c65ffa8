package org.kse.testing;

import java.util.List;
import java.util.Random;

/**
 * Random valid formula files: capabilities only use later ones, so there is no recursion. Every
 * operator, suffix chains, options, groups and |x~|n appear; one seed always gives one file, so a
 * failing case names a reproducible formula. Shared by the transformation's property test and
 * the round trip of the inverse transformation.
 */
public final class RandomFormulas {
	private final Random random;
	private int activities;
	private int capabilities;

	public RandomFormulas(Random random) {
		this.random = random;
	}

	public String file() {
		capabilities = 1 + random.nextInt(4);
		StringBuilder out = new StringBuilder();
		for (int i = 0; i < capabilities; i++) {
			out.append("cap").append(i).append(" = ").append(expression(i, 0)).append('\n');
		}
		return out.toString();
	}

	private String expression(int capability, int depth) {
		int terms = 1 + random.nextInt(depth > 1 ? 2 : 4);
		String operator = List.of(".", "|", "||").get(random.nextInt(3));
		StringBuilder out = new StringBuilder();
		for (int i = 0; i < terms; i++) {
			if (i > 0) {
				out.append(' ').append(operator).append(' ');
			}
			out.append(term(capability, depth));
		}
		return out.toString();
	}

	private String term(int capability, int depth) {
		int choice = random.nextInt(depth > 2 ? 2 : 7);
		return switch (choice) {
			case 0 -> "Act" + activities++;
			case 1 -> capability + 1 < capabilities && random.nextBoolean() ? "cap" + (capability + 1 + random.nextInt(capabilities - capability - 1))
					: "Act" + activities++;
			case 2 -> "(" + expression(capability, depth + 1) + ")" + suffix(false);
			case 3 -> "[" + expression(capability, depth + 1) + "]";
			case 4 -> "Act" + activities++ + suffix(true);
			case 5 -> "|" + "Act" + activities++ + "~|" + (1 + random.nextInt(3)) + suffix(false);
			default -> "(" + expression(capability, depth + 1) + ")" + suffix(true);
		};
	}

	/** None, one, or (one time in four) a chain of two, which applies the second to the first. */
	private String suffix(boolean required) {
		int choice = random.nextInt(required ? 3 : 4);
		String suffix = switch (choice) {
			case 0 -> "*";
			case 1 -> "+";
			case 2 -> "~";
			default -> "";
		};
		return !suffix.isEmpty() && random.nextInt(4) == 0 ? suffix + suffix(true) : suffix;
	}
}
