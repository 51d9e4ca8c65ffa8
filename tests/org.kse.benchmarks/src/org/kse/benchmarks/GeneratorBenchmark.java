package org.kse.benchmarks;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.kse.expression.ExpressionParser;
import org.kse.generator.monas.MonasGenerator;
import org.kse.labeling.Labeler;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Transition;
import org.kse.transform.FormulaTransformation;

/**
 * Generation time of the Monas C++ for a model of about 1,000 states whose transitions
 * carry Goalie-like guards and timeouts, against writing the same files with plain
 * {@code Files.write} (the baseline), measured in the same run; then the same model with every
 * transition's expression its own text, and parsing those texts each alone (as every generation
 * did before issue 17) against parsing them in one session (as a generation does now). Run with
 * {@code bench/generator.sh}.
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
		Model model = bigModel(false);
		int[] states = { 0 };
		model.eAllContents().forEachRemaining(e -> states[0] += e instanceof org.kse.model.statechart.Node ? 1 : 0);
		System.out.printf(Locale.ROOT, "KSE generator benchmark: %d states, %d transitions, median of %d warm runs%n", states[0],
				model.getTransitions().size(), RUNS);

		Path scratch = Files.createTempDirectory("kse-gen-bench");
		Path reference = scratch.resolve("reference");
		long start = System.nanoTime();
		MonasGenerator.Report report = MonasGenerator.generate(model, reference, MonasGenerator.Options.DEFAULT);
		double cold = (System.nanoTime() - start) / 1e6;
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

		// Every transition its own text: nothing is shared between transitions, only the resource set between texts.
		Model distinct = bigModel(true);
		Path distinctReference = scratch.resolve("distinct");
		MonasGenerator.generate(distinct, distinctReference, MonasGenerator.Options.DEFAULT);
		double generateDistinct = Timing.median(3, RUNS,
				() -> MonasGenerator.generate(distinct, scratch.resolve("gen" + run[0]++), MonasGenerator.Options.DEFAULT));
		double regenerateDistinct = Timing.median(3, RUNS, () -> MonasGenerator.generate(distinct, distinctReference, MonasGenerator.Options.DEFAULT));
		List<String> texts = distinct.getTransitions().stream().map(Transition::getTE).toList();
		double parseAlone = Timing.cpuMedian(3, RUNS, () -> {
			texts.forEach(ExpressionParser::parse);
			return null;
		});
		double parseSession = Timing.cpuMedian(3, RUNS, () -> {
			ExpressionParser.Session session = ExpressionParser.session();
			texts.forEach(session::parse);
			return null;
		});
		double generateCpu = Timing.cpuMedian(1, RUNS, () -> MonasGenerator.generate(model, scratch.resolve("gen" + run[0]++), MonasGenerator.Options.DEFAULT));
		double regenerateCpu = Timing.cpuMedian(1, RUNS, () -> MonasGenerator.generate(model, reference, MonasGenerator.Options.DEFAULT));

		Timing.report("copy the files (baseline)", baseline, 0);
		Timing.report("first generation in this JVM (1 run)", cold, baseline);
		Timing.report("generate into an empty folder", generate, baseline);
		Timing.report("regenerate, nothing changed", regenerate, baseline);
		Timing.report("generate, CPU of the generating thread", generateCpu, 0);
		Timing.report("regenerate, CPU of the generating thread", regenerateCpu, 0);
		System.out.printf(Locale.ROOT, "every transition with its own expression (%d texts):%n", texts.stream().distinct().count());
		Timing.report("generate into an empty folder", generateDistinct, baseline);
		Timing.report("regenerate, nothing changed", regenerateDistinct, baseline);
		Timing.report("parse each text alone, CPU (baseline)", parseAlone, 0);
		Timing.report("parse them in one session, CPU", parseSession, parseAlone);
		try (Stream<Path> walk = Files.walk(scratch)) {
			walk.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
		}
	}

	/**
	 * About 1,000 states from formulas, Goalie-like guards and timeouts on the transitions: five
	 * texts in turn, or with {@code distinct} each transition's text made its own by its numbers.
	 */
	private static Model bigModel(boolean distinct) {
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
			String guard = GUARDS[i % GUARDS.length];
			transition.setTE(distinct ? guard.replace("250", Integer.toString(250 + i)).replace(">0", ">" + i)
					.replace("==NULL ||", "==NULL || behavior.State.HeadToBMessage.ballfound()==" + i + " ||") : guard);
			i++;
		}
		return model;
	}

	private GeneratorBenchmark() {
	}
}
