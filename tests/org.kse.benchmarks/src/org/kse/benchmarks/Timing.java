package org.kse.benchmarks;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.Callable;

/** What the Java benchmarks share: the median of warm runs, and a result line with its ratio to a baseline. */
final class Timing {

	private Timing() {
	}

	/** Milliseconds: the median of {@code runs} runs after {@code warmups} unmeasured ones. */
	static double median(int warmups, int runs, Callable<?> work) throws Exception {
		return percentile(sample(warmups, runs, work), 50);
	}

	/**
	 * Milliseconds of the calling thread's CPU time, the median of {@code runs} runs after
	 * {@code warmups}: on a busy machine, wall time also counts other processes and a slow disk.
	 */
	static double cpuMedian(int warmups, int runs, Callable<?> work) throws Exception {
		ThreadMXBean threads = ManagementFactory.getThreadMXBean();
		for (int i = 0; i < warmups; i++) {
			work.call();
		}
		double[] times = new double[runs];
		for (int i = 0; i < runs; i++) {
			long start = threads.getCurrentThreadCpuTime();
			work.call();
			times[i] = (threads.getCurrentThreadCpuTime() - start) / 1e6;
		}
		Arrays.sort(times);
		return percentile(times, 50);
	}

	/** Milliseconds of {@code runs} runs after {@code warmups} unmeasured ones, sorted. */
	static double[] sample(int warmups, int runs, Callable<?> work) throws Exception {
		for (int i = 0; i < warmups; i++) {
			work.call();
		}
		double[] times = new double[runs];
		for (int i = 0; i < runs; i++) {
			long start = System.nanoTime();
			work.call();
			times[i] = (System.nanoTime() - start) / 1e6;
		}
		Arrays.sort(times);
		return times;
	}

	/** The value below which {@code percent} % of the sorted times lie (nearest rank). */
	static double percentile(double[] sorted, int percent) {
		int rank = (int) Math.ceil(percent / 100.0 * sorted.length);
		return sorted[Math.max(0, Math.min(sorted.length - 1, rank - 1))];
	}

	/** A result line; with a baseline above 0, also the ratio to it. */
	static void report(String what, double millis, double baseline) {
		if (baseline > 0) {
			System.out.printf(Locale.ROOT, "%-40s %9.1f ms  (%.2fx baseline)%n", what, millis, millis / baseline);
		} else {
			System.out.printf(Locale.ROOT, "%-40s %9.1f ms%n", what, millis);
		}
	}
}
