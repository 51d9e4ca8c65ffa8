package org.kse.benchmarks;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.Locale;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.kse.generator.monas.MonasGenerator;
import org.kse.labeling.Labeler;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Transition;
import org.kse.transform.FormulaTransformation;

/**
 * Generation time of the Monas C++ for a model of about 1,000 states whose transitions
 * carry Goalie-like guards and timeouts, against writing the same files with plain
 * {@code Files.write} (the baseline), measured in the same run. Run with {@code bench/generator.sh}.
 */
public final class GeneratorBenchmark {

	private static final int RUNS = 7;
	private static final String[] GUARDS = {
			"[worldstate.State.GameStateMessage==NULL || worldstate.State.GameStateMessage.player_state()!=PLAYER_PLAYING]",
			"[behavior.State.HeadToBMessage.ballfound()>0 && !ballAway(worldstate.Data.WorldInfo)]",
			"[TimeoutCheck(behavior) && worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING]/TimeoutAction.behavior.250",
			"/TimeoutAction.behavior.250",
			"" };

	public static void main(String[] args) throws Exception {
		StringBuilder formulas = new StringBuilder("Big\nbig = ");
		for (int c = 0; c < 32; c++) {
			formulas.append(c == 0 ? "" : " . ").append("cap").append(c).append('+');
		}
		formulas.append('\n');
		for (int c = 0; c < 32; c++) {
			formulas.append("cap").append(c).append(" = ");
			for (int a = 0; a < 12; a++) {
				formulas.append(a == 0 ? "" : " | ").append("Act").append(c).append('_').append(a).append(a % 3 == 0 ? "+" : "");
			}
			formulas.append('\n');
		}
		Model model = FormulaTransformation.run(formulas.toString(), URI.createURI("big.liveness"), null).model();
		Labeler.label(model);
		int i = 0;
		for (Transition transition : model.getTransitions()) {
			transition.setTE(GUARDS[i++ % GUARDS.length]);
		}
		int[] states = { 0 };
		model.eAllContents().forEachRemaining(e -> states[0] += e instanceof org.kse.model.statechart.Node ? 1 : 0);
		System.out.printf(Locale.ROOT, "KSE generator benchmark: %d states, %d transitions, median of %d warm runs%n", states[0],
				model.getTransitions().size(), RUNS);

		Path scratch = Files.createTempDirectory("kse-gen-bench");
		Path reference = scratch.resolve("reference");
		MonasGenerator.Report report = MonasGenerator.generate(model, reference, MonasGenerator.Options.DEFAULT);
		System.out.printf(Locale.ROOT, "output: %d files%n", report.written().size());

		int[] run = { 0 };
		double baseline = Timing.median(3, RUNS, () -> {
			Path target = scratch.resolve("copy" + run[0]++);
			for (Path file : report.written()) {
				Files.createDirectories(target.resolve(file).getParent());
				Files.write(target.resolve(file), Files.readAllBytes(reference.resolve(file)));
			}
			return null;
		});
		double generate = Timing.median(3, RUNS, () -> MonasGenerator.generate(model, scratch.resolve("gen" + run[0]++), MonasGenerator.Options.DEFAULT));
		double regenerate = Timing.median(3, RUNS, () -> MonasGenerator.generate(model, reference, MonasGenerator.Options.DEFAULT));
		Timing.report("copy the files (baseline)", baseline, 0);
		Timing.report("generate into an empty folder", generate, baseline);
		Timing.report("regenerate, nothing changed", regenerate, baseline);
		try (Stream<Path> walk = Files.walk(scratch)) {
			walk.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
		}
	}

	private GeneratorBenchmark() {
	}
}
