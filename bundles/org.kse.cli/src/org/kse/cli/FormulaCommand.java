package org.kse.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.kse.formula.StatechartToFormula;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;

/**
 * {@code kse formula}: the liveness formulas a statechart stands for (issue 20, item 3), the
 * inverse of {@code kse transform}. The formulas go to standard output, or to a file; what
 * they cannot express goes to standard error, one warning per state, as {@code kse validate}
 * prints a model's diagnostics.
 */
final class FormulaCommand {

	private FormulaCommand() {
	}

	/**
	 * Recovers one model's formulas and writes them to {@code output} (null: standard output,
	 * after a comment line naming the model when {@code header} is set).
	 *
	 * @return {@link Kse#OK}, or {@link Kse#INVALID} when a part of the chart could not be expressed
	 */
	static int run(Path file, Path output, boolean header, PrintStream out, PrintStream err) throws IOException {
		Model model = StatechartResources.load(file);
		StatechartToFormula.Result result = StatechartToFormula.recover(model);
		if (output == null) {
			if (header) {
				out.println("// " + file);
			}
			out.print(result.fileText());
			out.flush();
		} else {
			Path parent = output.toAbsolutePath().getParent();
			if (parent != null) {
				Files.createDirectories(parent);
			}
			StatechartResources.writeAtomically(output, result.fileText().getBytes(StandardCharsets.UTF_8));
			out.println("wrote " + output + " (" + result.formulas().size() + (result.formulas().size() == 1 ? " formula)" : " formulas)"));
		}
		// after the formulas, so that on a terminal the warnings follow what they are about
		for (StatechartToFormula.Problem problem : result.problems()) {
			err.println(file + ": " + problem.label() + " (" + problem.name() + "): warning: " + problem.message());
		}
		if (result.problems().isEmpty()) {
			return Kse.OK;
		}
		int count = result.problems().size();
		err.println(file + ": " + count + (count == 1 ? " part" : " parts") + " of the statechart not expressed by the formulas");
		return Kse.INVALID;
	}
}
