package org.kse.testing;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Random;

/**
 * Turns a well-formed seed into a hostile variant: bytes flipped, ranges cut, repeated or
 * swapped, words from a dictionary of what breaks parsers and generators put in, or the seed
 * replaced by noise. Everything depends on the {@link Random}, so a seed replays a run.
 */
public final class ByteMutator {

	private final Random random;
	private final List<String> dictionary;

	/** {@code dictionary}: what breaks the parser under test (its delimiters, escapes, hostile values). */
	public ByteMutator(Random random, List<String> dictionary) {
		this.random = random;
		this.dictionary = dictionary;
	}

	/** A hostile variant of {@code seed}: one to four steps, or (one time in 50) noise. */
	public byte[] mutate(byte[] seed) {
		if (random.nextInt(50) == 0) {
			return noise();
		}
		byte[] input = seed;
		int steps = 1 + random.nextInt(4);
		for (int i = 0; i < steps; i++) {
			input = step(input);
		}
		return input;
	}

	public String mutate(String seed) {
		return new String(mutate(seed.getBytes(StandardCharsets.UTF_8)), StandardCharsets.UTF_8);
	}

	private byte[] step(byte[] input) {
		int length = input.length;
		return switch (random.nextInt(8)) {
			case 0 -> { // flip a byte
				if (length == 0) {
					yield input;
				}
				byte[] out = input.clone();
				out[random.nextInt(length)] = (byte) random.nextInt(256);
				yield out;
			}
			case 1 -> cut(input, random.nextInt(length + 1), random.nextInt(Math.min(length, 64) + 1));
			case 2 -> { // repeat a range, sometimes many times (nesting, long lists)
				int from = random.nextInt(length + 1);
				int size = Math.min(random.nextInt(80) + 1, length - from);
				int times = random.nextInt(10) == 0 ? 200 + random.nextInt(2000) : 1 + random.nextInt(3);
				byte[] range = java.util.Arrays.copyOfRange(input, from, from + size);
				byte[] repeated = new byte[range.length * times];
				for (int t = 0; t < times; t++) {
					System.arraycopy(range, 0, repeated, t * range.length, range.length);
				}
				yield insert(input, from, repeated);
			}
			case 3 -> java.util.Arrays.copyOf(input, random.nextInt(length + 1)); // truncate
			case 4, 5, 6 -> insert(cut(input, random.nextInt(length + 1), random.nextInt(3) == 0 ? random.nextInt(12) : 0),
					-1, dictionary.get(random.nextInt(dictionary.size())).getBytes(StandardCharsets.UTF_8));
			default -> { // swap two ranges' order by moving one
				int from = random.nextInt(length + 1);
				int size = Math.min(random.nextInt(40) + 1, length - from);
				byte[] range = java.util.Arrays.copyOfRange(input, from, from + size);
				byte[] rest = cut(input, from, size);
				yield insert(rest, random.nextInt(rest.length + 1), range);
			}
		};
	}

	private byte[] noise() {
		byte[] out = new byte[random.nextInt(600)];
		random.nextBytes(out);
		return out;
	}

	private static byte[] cut(byte[] input, int from, int size) {
		int end = Math.min(input.length, from + size);
		byte[] out = new byte[input.length - (end - from)];
		System.arraycopy(input, 0, out, 0, from);
		System.arraycopy(input, end, out, from, input.length - end);
		return out;
	}

	/** Inserts at {@code at}, or at a random place when {@code at} is negative. */
	private byte[] insert(byte[] input, int at, byte[] what) {
		int where = at < 0 ? random.nextInt(input.length + 1) : at;
		byte[] out = new byte[input.length + what.length];
		System.arraycopy(input, 0, out, 0, where);
		System.arraycopy(what, 0, out, where, what.length);
		System.arraycopy(input, where, out, where + what.length, input.length - where);
		return out;
	}
}
