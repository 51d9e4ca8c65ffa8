package org.kse.benchmarks;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.URI;
import org.kse.labeling.Labeler;
import org.kse.liveness.FormulaLoader;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.transform.FormulaToStatechart;
import org.kse.transform.FormulaTransformation;
import org.kse.validation.ModelValidation;

/**
 * Foundation benchmark (issue: transform, validate, load+save for a formula with
 * 10,000 activities). Each figure is the median of several warm runs, printed with a
 * baseline measured in the same run:
 * <ul>
 * <li>transform: against parsing and checking the same formulas (the work every tool does first);</li>
 * <li>validate: against a plain walk over every element of the model;</li>
 * <li>load+save: against reading and writing the same bytes as a plain file.</li>
 * </ul>
 * Run with {@code bench/foundation.sh}.
 */
public final class FoundationBenchmark {

	private static final int CAPABILITIES = 100;
	private static final int ACTIVITIES_PER_CAPABILITY = 100;
	private static final int RUNS = 7;

	public static void main(String[] args) throws Exception {
		String formulas = generatedFormulas();
		URI uri = URI.createURI("bench.liveness");
		Path directory = Files.createTempDirectory("kse-bench");
		Path modelFile = directory.resolve("bench.stct");
		Path copyFile = directory.resolve("copy.stct");

		System.out.printf(Locale.ROOT, "KSE foundation benchmark: %d activities in %d capabilities (%d lines, %d KiB of formulas), median of %d warm runs%n",
				CAPABILITIES * ACTIVITIES_PER_CAPABILITY, CAPABILITIES, CAPABILITIES + 1, formulas.length() / 1024, RUNS);

		double parse = Timing.median(4, RUNS, () -> FormulaLoader.load(formulas, uri));
		FormulaLoader.Result parsed = FormulaLoader.load(formulas, uri);
		double build = Timing.median(4, RUNS, () -> new FormulaToStatechart().transform(parsed.file(), "Bench"));
		double transform = Timing.median(4, RUNS, () -> FormulaTransformation.run(formulas, uri, "Bench"));
		Model model = FormulaTransformation.run(formulas, uri, "Bench").model();
		int[] counts = counts(model);
		System.out.printf(Locale.ROOT, "model: %d states, %d transitions%n", counts[0], model.getTransitions().size());
		Timing.report("parse+check formulas (baseline)", parse, 0);
		Timing.report("build the statechart", build, parse);
		Timing.report("transform (parse+check+build)", transform, parse);

		double walk = Timing.median(4, RUNS, () -> counts(model));
		double validate = Timing.median(4, RUNS, () -> ModelValidation.validate(model));
		Diagnostic diagnostic = ModelValidation.validate(model);
		long errors = diagnostic.getChildren().stream().filter(d -> d.getSeverity() == Diagnostic.ERROR).count();
		Timing.report("walk every element (baseline)", walk, 0);
		Timing.report("validate", validate, walk);
		System.out.printf(Locale.ROOT, "  validation found %d errors%n", errors);

		double label = Timing.median(4, RUNS, () -> {
			Labeler.label(model);
			return null;
		});
		Timing.report("label", label, walk);

		StatechartResources.save(model, modelFile);
		byte[] bytes = Files.readAllBytes(modelFile);
		double copy = Timing.median(4, RUNS, () -> {
			Files.write(copyFile, Files.readAllBytes(modelFile));
			return null;
		});
		double loadSave = Timing.median(4, RUNS, () -> {
			Model loaded = StatechartResources.load(modelFile);
			StatechartResources.save(loaded, copyFile);
			return null;
		});
		// The same in CPU time of this thread: wall time on a shared machine swings with the disk.
		double copyCpu = Timing.cpuMedian(4, RUNS, () -> {
			Files.write(copyFile, Files.readAllBytes(modelFile));
			return null;
		});
		double loadSaveCpu = Timing.cpuMedian(4, RUNS, () -> {
			Model loaded = StatechartResources.load(modelFile);
			StatechartResources.save(loaded, copyFile);
			return null;
		});
		// the two halves on their own, to see which one a change moves
		double loadCpu = Timing.cpuMedian(4, RUNS, () -> StatechartResources.load(modelFile));
		Model loaded = StatechartResources.load(modelFile);
		double saveCpu = Timing.cpuMedian(4, RUNS, () -> {
			StatechartResources.save(loaded, copyFile);
			return null;
		});
		System.out.printf(Locale.ROOT, "file: %d KiB%n", bytes.length / 1024);
		Timing.report("read+write the bytes (baseline)", copy, 0);
		Timing.report("load+save the model", loadSave, copy);
		Timing.report("read+write the bytes, CPU (baseline)", copyCpu, 0);
		Timing.report("load+save the model, CPU", loadSaveCpu, copyCpu);
		Timing.report("  load alone, CPU", loadCpu, copyCpu);
		Timing.report("  save alone, CPU", saveCpu, copyCpu);

		boolean goal = transform < 1000 && validate < 1000 && loadSave < 1000;
		System.out.printf(Locale.ROOT, "goal (each under 1 s): %s%n", goal ? "met" : "NOT met");
		Files.deleteIfExists(modelFile);
		Files.deleteIfExists(copyFile);
		Files.deleteIfExists(directory);
	}

	/** 100 capabilities of 100 activities each, every operator and suffix represented. */
	static String generatedFormulas() {
		StringBuilder out = new StringBuilder("Bench\nbench = ");
		for (int c = 0; c < CAPABILITIES; c++) {
			out.append(c == 0 ? "" : " . ").append("cap").append(c).append(c % 2 == 0 ? "+" : "");
		}
		out.append('\n');
		String[] operators = { " . ", " | ", " || " };
		String[] shapes = { "%s", "%s+", "[%s]", "%s*", "(%s)~", "|%s~|2" };
		for (int c = 0; c < CAPABILITIES; c++) {
			out.append("cap").append(c).append(" = ");
			for (int a = 0; a < ACTIVITIES_PER_CAPABILITY; a++) {
				if (a > 0) {
					out.append(operators[c % 3]);
				}
				out.append(String.format(shapes[(a + c) % shapes.length], "Act" + c + "_" + a));
			}
			out.append('\n');
		}
		return out.toString();
	}

	private static int[] counts(Model model) {
		int[] counts = new int[2];
		model.eAllContents().forEachRemaining(element -> counts[element instanceof org.kse.model.statechart.Node ? 0 : 1]++);
		return counts;
	}

	private FoundationBenchmark() {
	}
}
