package org.kse.messages;

import java.util.ArrayList;
import java.util.List;

/**
 * Where the lines of a text start, as protoc counts lines: {@code \r\n}, {@code \n} and a lone
 * {@code \r} each end one. What turns offsets into lines and columns for the proto reader, the
 * workbench's proto links and the language server.
 */
public final class LineStarts {

	private LineStarts() {
	}

	/** The offset of each line's first character, the first line's (0) first. */
	public static int[] of(String text) {
		List<Integer> starts = new ArrayList<>(List.of(0));
		for (int i = 0; i < text.length(); i++) {
			char c = text.charAt(i);
			if (c == '\n' || c == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n')) {
				starts.add(i + 1);
			}
		}
		return starts.stream().mapToInt(Integer::intValue).toArray();
	}

	/** The 0-based line an offset is on (an offset before the text is on the first line). */
	public static int lineIndex(int[] starts, int offset) {
		int low = 0;
		int high = starts.length - 1;
		while (low < high) {
			int mid = (low + high + 1) >>> 1;
			if (starts[mid] <= offset) {
				low = mid;
			} else {
				high = mid - 1;
			}
		}
		return low;
	}
}
