package org.kse.validation;

import java.util.Collection;
import java.util.Locale;
import java.util.Optional;

/** The known name a misspelt one was most likely meant to be, when one is close enough to say so. */
final class Suggestions {

	private Suggestions() {
	}

	/**
	 * The single nearest of {@code known} by edit distance (case ignored, a swap of two neighbours
	 * counts once); empty when none is close for a name of that length, or when two are equally near,
	 * since a guess between two would mislead more than it helps.
	 */
	static Optional<String> nearest(String wrong, Collection<String> known) {
		if (wrong == null || wrong.isEmpty()) {
			return Optional.empty();
		}
		String folded = wrong.toLowerCase(Locale.ROOT);
		int limit = folded.length() <= 4 ? 1 : folded.length() <= 11 ? 2 : 3;
		String best = null;
		int bestDistance = Integer.MAX_VALUE;
		boolean tie = false;
		for (String candidate : known.stream().distinct().toList()) {
			if (candidate.equals(wrong)) {
				continue;
			}
			int distance = distance(folded, candidate.toLowerCase(Locale.ROOT));
			if (distance < bestDistance) {
				best = candidate;
				bestDistance = distance;
				tie = false;
			} else if (distance == bestDistance) {
				tie = true;
			}
		}
		return best != null && !tie && bestDistance <= limit ? Optional.of(best) : Optional.empty();
	}

	/** "; did you mean 'x'?" or nothing. */
	static String didYouMean(String wrong, Collection<String> known) {
		return nearest(wrong, known).map(name -> "; did you mean '" + name + "'?").orElse("");
	}

	/** Optimal string alignment distance: insertions, deletions, substitutions and adjacent swaps. */
	static int distance(String a, String b) {
		int[][] d = new int[a.length() + 1][b.length() + 1];
		for (int i = 0; i <= a.length(); i++) {
			d[i][0] = i;
		}
		for (int j = 0; j <= b.length(); j++) {
			d[0][j] = j;
		}
		for (int i = 1; i <= a.length(); i++) {
			for (int j = 1; j <= b.length(); j++) {
				int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
				d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
				if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
					d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
				}
			}
		}
		return d[a.length()][b.length()];
	}
}
