package org.kse.benchmarks;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import org.eclipse.emf.common.util.URI;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.notation.Arrange;
import org.kse.notation.Notation;
import org.kse.transform.FormulaTransformation;

/**
 * Opening a diagram of a statechart with about 1,000 states that has no notation yet: load the
 * model and arrange every state with ELK (the goal is under 2 s). The baseline, measured in the
 * same run, is loading the model alone. Run with {@code bench/notation.sh}.
 */
public final class NotationBenchmark {

	private static final int CAPABILITIES = 10;
	private static final int ACTIVITIES_PER_CAPABILITY = 24;
	private static final int RUNS = 7;

	public static void main(String[] args) throws Exception {
		Model model = FormulaTransformation.run(formulas(), URI.createURI("layout.liveness"), "Layout").model();
		Path directory = Files.createTempDirectory("kse-bench");
		Path file = directory.resolve("Layout.stct");
		StatechartResources.save(model, file);
		int[] states = new int[1];
		model.eAllContents().forEachRemaining(each -> states[0] += each instanceof org.kse.model.statechart.Node ? 1 : 0);
		System.out.printf(Locale.ROOT, "KSE notation benchmark: %d states, %d transitions, %d levels deep; median of %d warm runs%n", states[0],
				model.getTransitions().size(), depth(model), RUNS);

		double load = Timing.median(3, RUNS, () -> StatechartResources.load(file));
		double open = Timing.median(3, RUNS, () -> Arrange.all(StatechartResources.load(file)));
		Notation notation = Arrange.all(StatechartResources.load(file));
		Timing.report("load the model (baseline)", load, 0);
		Timing.report("load and arrange every state (ELK)", open, load);
		System.out.printf(Locale.ROOT, "placed %d states; goal (open and lay out under 2 s): %s%n", notation.size(), open < 2000 ? "met" : "NOT met");
		Files.deleteIfExists(file);
		Files.deleteIfExists(directory);
	}

	/** A choice of capabilities, each a choice of repeated activities: nested OR states, as behaviours are. */
	static String formulas() {
		return formulas(CAPABILITIES, ACTIVITIES_PER_CAPABILITY);
	}

	/** {@code capabilities} × {@code activities} repeated activities: about 4 states each. */
	static String formulas(int capabilities, int activities) {
		StringBuilder out = new StringBuilder("Layout\nlayout = Init.(");
		for (int c = 0; c < capabilities; c++) {
			out.append(c == 0 ? "" : " | ").append("cap").append(c);
		}
		out.append(")+\n");
		for (int c = 0; c < capabilities; c++) {
			out.append("cap").append(c).append(" = ");
			for (int a = 0; a < activities; a++) {
				out.append(a == 0 ? "" : " | ").append("Act").append(c).append('_').append(a).append('+');
			}
			out.append('\n');
		}
		return out.toString();
	}

	private static int depth(Model model) {
		int[] deepest = new int[1];
		model.eAllContents().forEachRemaining(each -> {
			int level = 0;
			for (var container = each.eContainer(); container != null; container = container.eContainer()) {
				level++;
			}
			deepest[0] = Math.max(deepest[0], level);
		});
		return deepest[0];
	}
}
