package org.kse.model;

import java.io.IOException;
import java.io.InputStream;
import java.lang.ref.SoftReference;
import java.util.ArrayDeque;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicReference;

/**
 * The large byte arrays of the streaming reader and writer (ADR 0026), kept from one load or save
 * for the next. A large model's file is read into one array as large as the file, and written
 * through as many 64 KB chunks as it has: new ones every time would make the garbage collector
 * run (and copy the model just read) for every load and save. One thread at a time takes what is
 * kept and gives it back when done, so two loads never share an array; the memory is only softly
 * held.
 */
final class SpareBuffers {

	static final int CHUNK = 1 << 16;

	private static final AtomicReference<SoftReference<byte[]>> INPUT = new AtomicReference<>();
	private static final AtomicReference<SoftReference<ArrayDeque<byte[]>>> CHUNKS = new AtomicReference<>();

	private SpareBuffers() {
	}

	/** The whole of a stream, in an array that may be longer: the length is in {@code length[0]}. Give it back with {@link #giveInput}. */
	static byte[] readAll(InputStream input, int[] length) throws IOException {
		SoftReference<byte[]> kept = INPUT.getAndSet(null);
		byte[] buffer = kept == null ? null : kept.get();
		int expected = Math.max(input.available(), 8192) + 1;
		if (buffer == null || buffer.length < expected) {
			buffer = new byte[expected];
		}
		int size = 0;
		while (true) {
			if (size == buffer.length) {
				buffer = Arrays.copyOf(buffer, buffer.length * 2);
			}
			int read = input.read(buffer, size, buffer.length - size);
			if (read < 0) {
				break;
			}
			size += read;
		}
		length[0] = size;
		return buffer;
	}

	static void giveInput(byte[] buffer) {
		INPUT.set(new SoftReference<>(buffer));
	}

	/** Chunks kept from earlier saves, to be taken with {@link #chunk}; never null. */
	static ArrayDeque<byte[]> takeChunks() {
		SoftReference<ArrayDeque<byte[]>> kept = CHUNKS.getAndSet(null);
		ArrayDeque<byte[]> chunks = kept == null ? null : kept.get();
		return chunks == null ? new ArrayDeque<>() : chunks;
	}

	/** A chunk from those kept, or a new one. */
	static byte[] chunk(ArrayDeque<byte[]> spare) {
		byte[] chunk = spare.poll();
		return chunk == null ? new byte[CHUNK] : chunk;
	}

	static void giveChunks(ArrayDeque<byte[]> chunks) {
		CHUNKS.set(new SoftReference<>(chunks));
	}
}
