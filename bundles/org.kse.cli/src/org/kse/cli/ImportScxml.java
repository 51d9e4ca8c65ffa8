package org.kse.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;

import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.scxml.ScxmlImport;
import org.kse.scxml.ScxmlProblem;

/**
 * {@code kse import-scxml}: an SCXML file (another tool's, or one kse export-scxml wrote) as a
 * statechart. Problems go to standard error, one line each with the SCXML element and its
 * line:column; an error means no model is written.
 */
final class ImportScxml {

	static final String HELP = """
			usage: kse import-scxml <chart.scxml> [-o model.stct]

			Reads a W3C SCXML document and writes it as a labelled KSE statechart. A document that
			kse export-scxml wrote comes back as the model it was (its kse: annotations). Another
			tool's chart is mapped: <scxml> the root OR state, a <state> with child states an OR
			state whose START enters its initial child, an atomic <state> a BASIC state, <parallel>
			an AND state (its regions OR states), <final> the END state; a condition (cond) that
			is a KSE condition is the transition's guard.
			Each problem is printed as 'file:line:column: severity: <element id="...">: message',
			then the validator's as kse validate prints them ('file: state label (name): ...').
			  errors     what would change where or when the chart moves: events (KSE's engine
			             raises none; done.state.<id> of the state itself is kept), conditions that
			             are not KSE's, history states, targetless transitions, several or deep
			             targets; nothing is written, exit code 1
			  warnings   side effects KSE has no place for (onentry/onexit content, <invoke>,
			             <datamodel>, a transition's executable content): left out, the model is
			             written, exit code 1
			Exit code 0 when the whole document was carried over (the validator's warnings are
			printed and do not count), 2 when the file cannot be read.
			  -o, --output FILE   where to write the model (default: the SCXML file with .stct)""";

	private ImportScxml() {
	}

	/** Imports one SCXML document into {@code target}; the problems go to {@code err} with their line and column. */
	static int run(Path file, Path target, PrintStream out, PrintStream err) throws IOException {
		ScxmlImport.Result result = ScxmlImport.read(file);
		int errors = 0;
		for (ScxmlProblem problem : result.problems()) {
			errors += problem.isError() ? 1 : 0;
			err.println(ScxmlImport.format(file.toString(), problem));
		}
		Model model = result.model();
		if (model == null) {
			err.println("kse: " + file + ": " + errors + (errors == 1 ? " error" : " errors") + ", no model written");
			return Kse.INVALID;
		}
		StatechartResources.save(model, target);
		out.println("wrote " + target + " (" + statistics(model) + ")");
		if (!result.complete()) {
			int leftOut = result.leftOut().size();
			err.println(file + ": " + leftOut + (leftOut == 1 ? " part" : " parts") + " of the document left out of the model");
			return Kse.INVALID;
		}
		return Kse.OK;
	}

	private static String statistics(Model model) {
		int[] states = { 0 };
		model.eAllContents().forEachRemaining(element -> states[0] += element instanceof org.kse.model.statechart.Node ? 1 : 0);
		return states[0] + " states, " + model.getTransitions().size() + " transitions";
	}
}
