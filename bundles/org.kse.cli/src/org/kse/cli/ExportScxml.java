package org.kse.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.scxml.ScxmlExport;
import org.kse.scxml.ScxmlProblem;

/**
 * {@code kse export-scxml}: a statechart as a W3C SCXML document that runs in an SCXML processor
 * as on KSE's engine (docs/adr/0038-scxml-mapping.md). Refused per element when something has no
 * faithful SCXML form; nothing is written then.
 */
final class ExportScxml {

	static final String HELP = """
			usage: kse export-scxml <model.stct>... [-o chart.scxml|folder]

			Writes the statechart as a W3C SCXML document (ECMAScript data model) whose transitions
			are those of KSE's engine, in its order: regions become <parallel> children, START the
			initial state, END a <final>, connector chains one transition per path, guards functions
			over per-region blackboards in the data model, activities an entry the host starts and a
			done.activity.<Name> event it sends back, timers a clock the host keeps
			(docs/adr/0038-scxml-mapping.md says what a host does). KSE's own facts (labels, names,
			the transition expressions, the connectors) are kept in the http://kse/scxml/1.0
			namespace, so kse import-scxml gives the model back.
			Where a state or transition has no faithful SCXML form, each is printed as
			'file: ERROR <label> '<name>': why' and nothing is written: exit code 1.
			Several models in one call are each written (a refused one is reported, the others
			still written), into the folder -o names.
			Exit code 0 when all were written, 1 when one was refused, 2 when a model cannot be read
			or a file not written.
			  -o, --output PATH   where to write (default: the model's file with .scxml): a file
			                      when PATH ends in .scxml and one model is given, else a folder""";

	private ExportScxml() {
	}

	/** Exports one model to {@code target}; the problems go to {@code err}, each naming the model file. */
	static int run(Path file, Path target, PrintStream out, PrintStream err) throws IOException {
		Model model = StatechartResources.load(file);
		ScxmlExport.Result result = ScxmlExport.export(model);
		int errors = 0;
		for (ScxmlProblem problem : result.problems()) {
			errors += problem.isError() ? 1 : 0;
			err.println(file + ": " + problem);
		}
		if (result.scxml() == null) {
			err.println("kse: " + file + ": " + errors + (errors == 1 ? " element has" : " elements have")
					+ " no faithful SCXML form, nothing written");
			return Kse.INVALID;
		}
		StatechartResources.writeAtomically(target, result.scxml().getBytes(StandardCharsets.UTF_8));
		out.println("wrote " + target);
		return Kse.OK;
	}
}
