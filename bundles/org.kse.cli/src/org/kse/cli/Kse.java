package org.kse.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.charset.MalformedInputException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.generator.monas.MonasGenerator;
import org.kse.labeling.Labeler;
import org.kse.messages.ProtoProblem;
import org.kse.messages.StandardMessages;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.simulation.RuntimePrefix;
import org.kse.simulation.Script;
import org.kse.simulation.SimulationException;
import org.kse.simulation.SimulationSession;
import org.kse.simulation.SimulatorBuilder;
import org.kse.transform.FormulaTransformation;
import org.kse.validation.ModelValidation;

/**
 * The {@code kse} command line: transform, validate, label. Plain Java, so that it runs
 * the same inside the Equinox application and in tests.
 * <p>
 * Exit codes: 0 success, 1 the input has errors, 2 the command could not run (usage, missing or unreadable file).
 */
public final class Kse {

	public static final int OK = 0;
	public static final int INVALID = 1;
	public static final int FAILED = 2;

	private static final String USAGE = """
			usage: kse <command> [options]

			commands:
			  transform <formula>... [-o model.stct|folder] [--name NAME]
			                      turn liveness formulas into statechart models
			  validate <model.stct>... [--source DIR] [--messages DIR]
			                      check models against the statechart rules
			  label <model.stct>... [-o out.stct]
			                      renumber labels and rename states and transitions
			  formula <model.stct>... [-o out.liveness|folder]
			                      the liveness formulas a statechart stands for (transform's inverse)
			  import-scxml <chart.scxml> [-o model.stct]
			                      an SCXML statechart (another tool's, or exported) as a model
			  export-scxml <model.stct>... [-o chart.scxml|folder]
			                      a statechart as W3C SCXML that runs as the engine does
			  generate <model.stct>... <source-folder> | -o <source-folder> [--logger]
			                      write the Monas C++ of models into a source tree
			  new-behaviour NAME [-o DIR]
			                      start a project of your own behaviour that builds and plays
			  diagram <model.stct>... [-o diagram.svg] [--arrange] [--save-notation]
			                      draw statecharts as SVG pictures
			  edit-transition <model.stct> <from> <to> --expression TEXT
			                      set the expression of a transition, checked first
			  serve <folder> [--port N] [--pages DIR]
			                      edit the folder's statecharts as diagrams in a local browser
			  simulate <model.stct> [--runtime DIR] [--script FILE] [--save-case DIR/NAME]
			                      run a statechart on the engine without a robot, by commands
			  lsp                 a language server over stdio for formulas and the expressions
			                      of statecharts (editors: VS Code, any LSP client)
			  demo [--seed N] [--half SECONDS] [--out DIR]
			                      the pipeline on the examples, then a match (the repository's ./kse)
			  help [command]      show help
			  version             show the versions of KSE and of what it runs on

			Run 'kse <command> --help' for a command's options.""";

	private static final String TRANSFORM_HELP = """
			usage: kse transform <formula>... [-o model.stct|folder] [--name NAME] [--quiet]

			Reads liveness formulas (one 'name = expression' per line; the original tool's .txt
			files with the model's name on the first line are read too) and writes the statechart
			built by the rules of the original KSE. Problems are printed as file:line:column.
			Each formula file gives one model.
			  -o, --output FILE   where to write the model (default: the formula file with .stct);
			                      with several formula files, the folder to write them into
			  --name NAME         the model's name (default: the file's first line, else the root formula)
			  -q, --quiet         no progress lines""";

	private static final String VALIDATE_HELP = """
			usage: kse validate <model.stct>... [--source DIR] [--messages DIR]...

			Checks statecharts against the KSE rules and the transition-expression grammar;
			topics, message types and fields are checked against the standard messages, the
			source folder's messages/*.proto (as kse generate reads them: a message defined
			there replaces the standard one of the same name) and each --messages folder.
			Prints one diagnostic per line as 'file: label (name): severity: message', then a
			count per model. Exit code 0 when no model has an error, 1 when one has errors.
			  --source DIR   the Monas source folder the models are generated into
			                 ('kse validate model.stct DIR' says the same for one model)""";

	private static final String LABEL_HELP = """
			usage: kse label <model.stct>... [-o out.stct]

			Gives every state a unique hierarchical label in execution order (START first, then
			the order a walk along the transitions reaches the states, END last), names auxiliary
			states after their label and transitions '<source>_TO_<target>'. Labeling twice
			changes nothing. Writes each model in place unless -o is given (with one model).""";

	private static final String FORMULA_HELP = """
			usage: kse formula <model.stct>... [-o out.liveness|folder]

			Writes the liveness formulas a statechart stands for, the root first, as kse transform
			reads them: a chart that kse transform made gives its formulas back (up to parentheses
			around a whole right side and capabilities nothing uses), and transforms into the same
			chart. A state of the transformation's shape whose name is not the spelling of its term
			is a capability of that name. For a chart edited by hand, the closest formulas, and on
			standard error one line per state for what they cannot express (guards and timers,
			transitions between levels, states that form no formula's shape), as
			'file: label (name): warning: message'. Exit code 0 when the formulas express the whole
			chart, 1 when something was not expressed (the formulas are still written).
			  -o, --output FILE   where to write the formulas (default: standard output); with
			                      several models, the folder to write <model>.liveness files into""";

	private static final String GENERATE_HELP = """
			usage: kse generate <model.stct>... (<source-folder> | -o <source-folder>)
			                    [--logger] [--no-activities] [--no-statechart] [--messages DIR]... [--quiet]

			Writes the Monas C++ of each valid model into a source folder: statecharts/<Model>/
			(the statechart class, one class per guard and per action list, CMakeLists.txt) and
			activities/<Activity>/ skeletons. Activities that exist are never overwritten; files
			whose content would not change are not touched. A model with errors is refused (the
			other models are still generated, and the exit code is 1).
			Messages are checked against the standard set, <source-folder>/messages/*.proto
			(compiled by the generated CMake) and each --messages folder. A message the source
			folder defines again replaces the standard one in the checks (a note says which);
			the C++ still uses the runtime's, which every program links.
			  -o, --output DIR   the source folder (instead of the last argument)
			  --logger           conditions print their result when evaluated
			  --no-activities    write the statecharts only, no activity skeletons (for a build
			                     that generates into its build tree: CMake's kse_add_statechart)
			  --no-statechart    write only the skeletons of new activities (for a project whose
			                     build generates the statechart: kse new-behaviour's)
			  -q, --quiet        no progress lines""";

	private static final String NEW_BEHAVIOUR_HELP = """
			usage: kse new-behaviour NAME [-o DIR]

			Makes a project of your own behaviour NAME that builds and plays as made, Monas-style:
			NAME.liveness (its formula), NAME.stct (the formula's statechart, labelled, with the
			guards and timers that make it play: 0 errors, 0 warnings), src/activities/ (its two
			activities, Wait and Chase, which compile as written and walk at the ball),
			CMakeLists.txt (finds the installed KSE runtime and examples, generates the statechart
			while building, builds kse-match with NAME and the example behaviours) and README.md.
			Prints the commands that build it and play it against the examples.
			NAME is a C++ identifier starting with a capital letter, and not the name of an
			example behaviour or activity. The folder must not exist, or be empty.
			  -o, --output DIR   the project's folder (default: ./NAME)""";

	private static final String DIAGRAM_HELP = """
			usage: kse diagram <model.stct>... [-o diagram.svg] [--arrange] [--save-notation]

			Draws the statechart in the thesis' notation as SVG: START a black disc, END a white
			disc with a black centre, CONDITION a circled C, BASIC green, OR yellow, AND light blue;
			transitions labelled with the first line of their expression (all of it on hover).
			Positions come from <Model>.notation.json beside the model, else from the original
			tool's <Model>.kse diagram, else ELK arranges the states.
			  -o, --output FILE   where to write the picture, with one model (default: the model
			                      file with .svg)
			  --arrange           arrange every state anew with ELK
			  --save-notation     write the positions used to <Model>.notation.json""";

	private static final String EDIT_TRANSITION_HELP = """
			usage: kse edit-transition <model.stct> <from> <to> --expression TEXT [--index N]
			                           [--source DIR] [--messages DIR]... [-o out.stct]

			Sets the expression (event[condition]/actions) of the transition from state <from> to
			state <to>, each named by its label (0.2.3) or its name, after the checks the
			Properties view makes: the grammar, and topics, message types and fields against the
			standard messages, the source folder's messages/*.proto and each --messages folder.
			An expression with an error is refused and nothing is written (exit 1); warnings are
			printed and the expression is set. An empty TEXT removes the expression.
			  --expression TEXT   the new expression, e.g. '[TimeoutCheck(behavior)]/TimeoutAction.behavior.250'
			  --index N           which of several transitions between the two states (from 1,
			                      in the model's order; without it several are an error that lists them)
			  --source DIR        the Monas source folder the model is generated into
			  -o, --output FILE   where to write the model (default: in place)""";

	private static final String DEMO_HELP = """
			usage: kse demo [--seed N] [--half SECONDS] [--out DIR]

			Runs the whole pipeline on the example behaviours: validates their models, builds the
			C++ runtime and the examples with CMake (which generates their statecharts), and plays
			Goalie, Defender and Attacker against themselves on the simulated field; prints the
			result and where the log and the picture are. Only the repository's ./kse runs it
			(releng/demo.sh): it needs the examples and the runtime's sources.
			  --seed N           seed of the match (default 1)
			  --half SECONDS     PLAYING seconds of the half (default 600)
			  --out DIR          where the builds, the log and the picture go (default target/demo)""";

	private static final String SERVE_HELP = """
			usage: kse serve <folder> [--port N] [--pages DIR]

			Serves the statecharts in the folder (and its subfolders) to the diagram editor in
			a browser on this machine, until stopped with Ctrl+C. Prints the address of each
			model's page. The server listens on 127.0.0.1 only, every connection must present
			the random token in the address, and only .stct files inside the folder can be opened.
			Positions are saved beside each model in <Model>.notation.json.
			  --port N            the port to listen on (default: any free port)
			  --pages DIR         serve the editor's page from DIR instead of the built-in one""";

	private static final String LSP_HELP = """
			usage: kse lsp

			A language server (the Language Server Protocol) on standard input and output, for an
			editor to start: formula files (.liveness, and the original tool's .txt) get their
			problems as kse transform reports them, completion of operators and names, hover, go to
			definition of a capability and an outline of their formulas; statecharts (.stct) get the
			problems of each transition expression (TE attribute) at its place in the file, as kse
			validate checks it, and completion of topics, kinds, message types, fields and helpers
			inside it. Messages are the standard ones and those of a messages/ folder beside the
			model. No port, no network; it runs until the editor stops it. The VS Code extension of
			editors/vscode starts it.""";

	private static final String SIMULATE_HELP = """
			usage: kse simulate <model.stct> [--runtime DIR] [--script FILE] [--save-case DIR/NAME]
			                    [--build-dir DIR] [-q]

			Runs the statechart on the C++ engine without a robot. Its simulator is built first
			(kse generate, then CMake and the C++ compiler, against the KSE runtime installed in
			DIR; once per model, again only for what changed). Then each command, read from
			standard input or from the script, runs, and what it caused is printed under it:
			  start                                  activate the statechart
			  publish <topic> <State|Signal|Data> <Type> { fields }
			                                         a message, fields in protobuf text format
			  finish <Activity>...  fail <Activity>...
			                                         running activities return (or throw)
			  advance <ms>                           time moves on; timers fire on the way
			  active  running  read <topic> <Kind> <Type>
			                                         print the active states, the running
			                                         activities, a message
			  breakpoints [state:<label>]... [transition:<index>]...
			                                         an advance stops where one of them hits
			  save DIR/NAME                          the trace so far as a conformance case
			  quit
			A script that lists, indented under its commands, the lines each must cause (a
			conformance case) is checked: a difference is reported and the exit code is 1.
			  --runtime DIR       the runtime's install prefix (default: $KSE_RUNTIME_PREFIX)
			  --script FILE       commands from FILE instead of standard input
			  --save-case DIR/NAME
			                      at the end, save the trace as the case NAME: DIR/NAME.case and
			                      DIR/NAME.stct, a copy of the model named NAME
			  --build-dir DIR     where the simulator is built (default: ~/.cache/kse/simulators/...)
			  -q, --quiet         no progress lines""";

	private final PrintStream out;
	private final PrintStream err;
	private boolean quiet;

	public Kse(PrintStream out, PrintStream err) {
		this.out = out;
		this.err = err;
	}

	/** The {@code kse} command on a plain class path (the launcher of ADR 0023). */
	public static void main(String[] args) {
		int code = new Kse(System.out, System.err).run(args);
		System.out.flush();
		System.err.flush();
		System.exit(code);
	}

	public int run(String... args) {
		if (args.length == 0) {
			err.println(USAGE);
			return FAILED;
		}
		List<String> rest = List.of(args).subList(1, args.length);
		try {
			return switch (args[0]) {
				case "transform" -> transform(rest);
				case "validate" -> validate(rest);
				case "label" -> label(rest);
				case "formula" -> formula(rest);
				case "import-scxml" -> importScxml(rest);
				case "export-scxml" -> exportScxml(rest);
				case "generate" -> generate(rest);
				case "new-behaviour" -> newBehaviour(rest);
				case "diagram" -> diagram(rest);
				case "edit-transition" -> editTransition(rest);
				case "demo" -> rest.contains("--help") || rest.contains("-h") ? help(List.of("demo"))
						: usage("kse demo runs from the repository's ./kse, which has the examples and the runtime's sources");
				case "serve" -> serve(rest);
				case "simulate" -> simulate(rest);
				case "lsp" -> lsp(rest);
				case "help", "-h", "--help" -> help(rest);
				case "version", "--version" -> version();
				default -> usage("unknown command '" + args[0] + "'");
			};
		} catch (UsageException e) {
			return usage(e.getMessage());
		} catch (IOException e) {
			err.println("kse: " + e.getMessage());
			return FAILED;
		} catch (UncheckedIOException e) {
			err.println("kse: " + e.getCause().getMessage());
			return FAILED;
		} catch (RuntimeException | Error e) {
			return internalError(args[0], e);
		}
	}

	/**
	 * Nothing may end a command silently (an uncaught error used to leave the Equinox
	 * application with exit code 0 and its trace in the product's log only): say what happened,
	 * exit with 2, and show the trace only when KSE_DEBUG is set.
	 */
	private int internalError(String command, Throwable e) {
		String what = e instanceof OutOfMemoryError ? "out of memory: the input is too large for it"
				: e instanceof StackOverflowError ? "the input is nested too deeply for it"
				: e.getMessage() == null ? "an internal error" : "an internal error: " + e.getMessage();
		boolean debug = System.getenv("KSE_DEBUG") != null;
		err.println("kse: " + command + " stopped: " + what + (debug ? "" : " (set KSE_DEBUG=1 for details)"));
		if (debug) {
			e.printStackTrace(err);
		}
		return FAILED;
	}

	private int help(List<String> args) {
		String topic = args.isEmpty() ? "" : args.get(0);
		out.println(switch (topic) {
			case "transform" -> TRANSFORM_HELP;
			case "validate" -> VALIDATE_HELP;
			case "label" -> LABEL_HELP;
			case "formula" -> FORMULA_HELP;
			case "import-scxml" -> ImportScxml.HELP;
			case "export-scxml" -> ExportScxml.HELP;
			case "generate" -> GENERATE_HELP;
			case "new-behaviour" -> NEW_BEHAVIOUR_HELP;
			case "diagram" -> DIAGRAM_HELP;
			case "edit-transition" -> EDIT_TRANSITION_HELP;
			case "demo" -> DEMO_HELP;
			case "serve" -> SERVE_HELP;
			case "simulate" -> SIMULATE_HELP;
			case "lsp" -> LSP_HELP;
			default -> USAGE;
		});
		return OK;
	}

	private int version() {
		out.println("kse " + bundleVersion(Kse.class));
		out.println("EMF " + bundleVersion(org.eclipse.emf.ecore.EObject.class) + ", Xtext " + bundleVersion(org.eclipse.xtext.validation.Issue.class)
				+ ", Java " + System.getProperty("java.version"));
		return OK;
	}

	/** The version of the bundle (or jar) a class comes from, or "development" outside a build. */
	private static String bundleVersion(Class<?> type) {
		var bundle = org.osgi.framework.FrameworkUtil.getBundle(type);
		if (bundle != null) {
			return bundle.getVersion().toString();
		}
		// on the plain class path of the launcher the jars are still bundles: read their manifest
		var source = type.getProtectionDomain().getCodeSource();
		if (source != null && source.getLocation() != null && source.getLocation().getPath().endsWith(".jar")) {
			try (var jar = new java.util.jar.JarFile(new java.io.File(source.getLocation().toURI()))) {
				String version = jar.getManifest() == null ? null : jar.getManifest().getMainAttributes().getValue("Bundle-Version");
				if (version != null) {
					return version;
				}
			} catch (IOException | java.net.URISyntaxException | SecurityException e) {
				// fall through to the package's version
			}
		}
		String version = type.getPackage() == null ? null : type.getPackage().getImplementationVersion();
		return version == null ? "development" : version;
	}

	private int usage(String problem) {
		err.println("kse: " + problem);
		err.println("Run 'kse --help' for usage.");
		return FAILED;
	}

	private int transform(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("-o", "--output", "--name"), List.of("-q", "--quiet"));
		if (options.help) {
			out.println(TRANSFORM_HELP);
			return OK;
		}
		List<Path> formulas = options.many("formula file");
		quiet = options.flag("-q", "--quiet");
		String output = options.value("-o", "--output");
		if (formulas.size() > 1 && options.value("--name") != null) {
			throw new UsageException("--name names one model: give one formula file with it");
		}
		Path folder = formulas.size() > 1 && output != null ? folder(Path.of(output)) : null;
		return each(formulas, formula -> transform(formula,
				folder != null ? folder.resolve(withExtension(formula, "stct").getFileName())
						: output != null ? Path.of(output) : withExtension(formula, "stct"),
				options.value("--name")));
	}

	private int transform(Path formula, Path output, String name) throws IOException {
		progress(1, 3, "reading and checking " + formula);
		String text = readText(formula);
		FormulaTransformation.Outcome outcome = FormulaTransformation.run(text, URI.createFileURI(formula.toAbsolutePath().toString()), name);
		int errors = report(formula, outcome.issues());
		if (outcome.model() == null) {
			err.println("kse: " + formula + ": " + errors + (errors == 1 ? " error" : " errors") + ", no model written");
			return INVALID;
		}
		progress(2, 3, "built " + statistics(outcome.model()));
		progress(3, 3, "writing " + output);
		StatechartResources.save(outcome.model(), output);
		out.println("wrote " + output + " (" + statistics(outcome.model()) + ")");
		return OK;
	}

	private int validate(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("--messages", "--source"), List.of());
		if (options.help) {
			out.println(VALIDATE_HELP);
			return OK;
		}
		List<Path> models = options.many("model file");
		Path sourceFolder = options.value("--source") != null ? folderThatExists(Path.of(options.value("--source"))) : null;
		// the form of the first release: one model and a source folder as the second argument
		if (sourceFolder == null && models.size() == 2 && (Files.isDirectory(models.get(1)) || !models.get(1).toString().endsWith(".stct"))) {
			sourceFolder = folderThatExists(models.get(1));
			models = models.subList(0, 1);
		}
		List<Path> folders = new ArrayList<>(options.paths("--messages"));
		if (sourceFolder != null) {
			folders.add(sourceFolder.resolve(MonasGenerator.MESSAGES_FOLDER));
		}
		StandardMessages.Merged messages = StandardMessages.merge(folders);
		for (ProtoProblem problem : messages.problems()) {
			out.println(messageProblem(problem));
		}
		Path shownFolder = sourceFolder;
		return each(models, model -> validate(model, messages, shownFolder));
	}

	private int validate(Path file, StandardMessages.Merged messages, Path sourceFolder) throws IOException {
		Model model = StatechartResources.load(file);
		note(file, messages.replacements(), sourceFolder, false);
		int errors = 0;
		int warnings = messages.problems().size();
		for (Diagnostic diagnostic : ModelValidation.validate(model, messages.catalog()).getChildren()) {
			boolean error = diagnostic.getSeverity() == Diagnostic.ERROR;
			errors += error ? 1 : 0;
			warnings += error ? 0 : 1;
			out.println(file + ": " + withSeverity(diagnostic.getMessage(), error ? "error" : "warning"));
		}
		err.println(file + ": " + errors + (errors == 1 ? " error, " : " errors, ") + warnings + (warnings == 1 ? " warning" : " warnings"));
		return errors == 0 ? OK : INVALID;
	}

	private int label(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("-o", "--output"), List.of());
		if (options.help) {
			out.println(LABEL_HELP);
			return OK;
		}
		List<Path> files = options.many("model file");
		String output = options.value("-o", "--output");
		if (output != null && files.size() > 1) {
			throw new UsageException("-o names one output: give one model file with it (without -o each model is labeled in place)");
		}
		return each(files, file -> {
			Path target = output != null ? Path.of(output) : file;
			Model model = StatechartResources.load(file);
			Labeler.label(model);
			StatechartResources.save(model, target);
			out.println("labeled " + target + " (" + statistics(model) + ")");
			return OK;
		});
	}

	private int formula(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("-o", "--output"), List.of());
		if (options.help) {
			out.println(FORMULA_HELP);
			return OK;
		}
		List<Path> models = options.many("model file");
		String output = options.value("-o", "--output");
		// several models, or a folder that exists: one <model>.liveness each in that folder
		Path folder = output != null && (models.size() > 1 || Files.isDirectory(Path.of(output))) ? folder(Path.of(output)) : null;
		return each(models, model -> FormulaCommand.run(model,
				folder != null ? folder.resolve(withExtension(model, "liveness").getFileName()) : output != null ? Path.of(output) : null,
				models.size() > 1, out, err));
	}

	private int exportScxml(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("-o", "--output"), List.of());
		if (options.help) {
			out.println(ExportScxml.HELP);
			return OK;
		}
		List<Path> models = options.many("model file");
		String output = options.value("-o", "--output");
		// -o names a file only for one model and a name ending in .scxml; else the folder to write into
		Path folder = output != null && (models.size() > 1 || !output.endsWith(".scxml") || Files.isDirectory(Path.of(output))) ? folder(Path.of(output)) : null;
		return each(models, model -> ExportScxml.run(model,
				folder != null ? folder.resolve(withExtension(model, "scxml").getFileName()) : output != null ? Path.of(output) : withExtension(model, "scxml"),
				out, err));
	}

	private int importScxml(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("-o", "--output"), List.of());
		if (options.help) {
			out.println(ImportScxml.HELP);
			return OK;
		}
		Path document = options.single("SCXML file");
		String output = options.value("-o", "--output");
		return each(List.of(document), file -> ImportScxml.run(file,
				output != null ? Path.of(output) : withExtension(file, StatechartResources.FILE_EXTENSION), out, err));
	}

	private int generate(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("--messages", "-o", "--output"), List.of("--logger", "--no-activities", "--no-statechart", "-q", "--quiet"));
		if (options.help) {
			out.println(GENERATE_HELP);
			return OK;
		}
		String output = options.value("-o", "--output");
		List<String> models = output != null ? options.positional : options.positional.subList(0, Math.max(0, options.positional.size() - 1));
		if (models.isEmpty()) {
			throw new UsageException("expected one or more model files and a source folder (as the last argument or with -o)");
		}
		quiet = options.flag("-q", "--quiet");
		if (options.flag("--no-activities") && options.flag("--no-statechart")) {
			throw new UsageException("--no-activities and --no-statechart together leave nothing to write");
		}
		Path folder = Path.of(output != null ? output : options.positional.get(options.positional.size() - 1));
		return each(models.stream().map(Path::of).toList(), model -> generate(model, folder, options));
	}

	private int generate(Path file, Path folder, Options options) throws IOException {
		Model model = StatechartResources.load(file);
		try {
			MonasGenerator.Report report = MonasGenerator.generate(model, folder, new MonasGenerator.Options(options.flag("--logger"), options.paths("--messages"), !options.flag("--no-activities"),
					!options.flag("--no-statechart")),
					(step, steps, what) -> progress(step, steps, what));
			note(file, report.replacements(), folder, true);
			for (ProtoProblem problem : report.messageProblems()) {
				err.println(messageProblem(problem));
			}
			for (String warning : report.warnings()) {
				err.println(file + ": " + withSeverity(warning, "warning"));
			}
			out.println("generated " + model.getName() + " into " + folder + ": " + report.written().size() + " written, "
					+ report.unchanged().size() + " unchanged, " + report.kept().size() + " activities kept"
					+ (report.removed().isEmpty() ? "" : ", " + report.removed().size() + " stale removed"));
			return OK;
		} catch (MonasGenerator.ModelHasErrorsException e) {
			for (String error : e.errors()) {
				err.println(file + ": " + withSeverity(error, "error"));
			}
			err.println("kse: " + file + ": " + e.errors().size() + (e.errors().size() == 1 ? " error" : " errors") + ", nothing generated");
			return INVALID;
		}
	}

	private int newBehaviour(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("-o", "--output"), List.of());
		if (options.help) {
			out.println(NEW_BEHAVIOUR_HELP);
			return OK;
		}
		String name = options.single("behaviour NAME").toString();
		String problem = NewBehaviour.nameProblem(name);
		if (problem != null) {
			throw new UsageException(problem);
		}
		Path folder = Path.of(options.value("-o", "--output") != null ? options.value("-o", "--output") : name);
		if (Files.exists(folder) && !Files.isDirectory(folder)) {
			throw new UsageException(folder + " is a file, not a folder: nothing was written");
		}
		if (Files.isDirectory(folder)) {
			try (var entries = Files.list(folder)) {
				if (entries.findAny().isPresent()) {
					throw new UsageException(folder + " exists and is not empty: nothing was written (choose another NAME, or -o DIR)");
				}
			}
		}
		NewBehaviour.Made made = NewBehaviour.make(name, folder);
		for (Path file : made.files()) {
			out.println("wrote " + file);
		}
		out.println("made " + folder + ": the behaviour " + name + " (" + statistics(made.model()) + "; activities "
				+ String.join(", ", NewBehaviour.ACTIVITIES) + ")");
		String prefix = System.getenv("KSE_PREFIX");
		String build = folder.resolve("build").toString();
		out.println();
		out.println("Build it and play it against the examples (the runtime and the examples installed in the prefix,");
		out.println("and kse on the PATH: " + folder.resolve("README.md") + " says more):");
		out.println("  cmake -S " + folder + " -B " + build + " -DCMAKE_PREFIX_PATH=" + (prefix == null || prefix.isBlank() ? "<prefix>" : prefix));
		out.println("  cmake --build " + build + " -j 2");
		out.println("  " + Path.of(build, "kse-match") + " --home Goalie:1," + name + ":2," + name + ":3 --away Goalie:1,Defender:2,Attacker:3 --log "
				+ folder.resolve("match.jsonl") + " --svg " + folder.resolve("match.svg"));
		return OK;
	}

	private int diagram(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("-o", "--output"), List.of("--arrange", "--save-notation"));
		if (options.help) {
			out.println(DIAGRAM_HELP);
			return OK;
		}
		List<Path> files = options.many("model file");
		String output = options.value("-o", "--output");
		if (output != null && files.size() > 1) {
			throw new UsageException("-o names one picture: give one model file with it (without -o each picture is written beside its model)");
		}
		return each(files, file -> diagram(file,
				output != null ? Path.of(output) : file.resolveSibling(file.getFileName().toString().replaceFirst("\\.stct$", "") + ".svg"), options));
	}

	private int diagram(Path file, Path picture, Options options) throws IOException {
		Model model = StatechartResources.load(file);
		org.kse.notation.Notation notation;
		String from;
		if (options.flag("--arrange")) {
			notation = org.kse.notation.Arrange.all(model);
			from = "arranged with ELK";
		} else {
			var opened = org.kse.notation.NotationFiles.open(file, model);
			if (opened.problem() != null) {
				err.println("kse: warning: " + opened.problem() + "; the states are arranged anew");
			}
			notation = opened.notation();
			from = switch (opened.source()) {
				case SIDECAR -> "from " + org.kse.notation.NotationFiles.beside(file).getFileName();
				case LEGACY_DIAGRAM -> "from the original diagram " + org.kse.notation.LegacyNotation.beside(file).getFileName();
				case ARRANGED -> "arranged with ELK";
			};
		}
		if (options.flag("--save-notation")) {
			org.kse.notation.NotationFiles.write(file, model, notation);
		}
		StatechartResources.writeAtomically(picture, org.kse.notation.SvgDiagram.render(model, notation).getBytes(StandardCharsets.UTF_8));
		out.println("drew " + picture + " (" + statistics(model) + "; positions " + from + ")");
		return OK;
	}

	private int editTransition(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("--expression", "--index", "--source", "--messages", "-o", "--output"), List.of());
		if (options.help) {
			out.println(EDIT_TRANSITION_HELP);
			return OK;
		}
		if (options.positional.size() != 3) {
			throw new UsageException("expected a model file, the state the transition leaves and the state it enters");
		}
		String expression = options.value("--expression");
		if (expression == null) {
			throw new UsageException("--expression TEXT is required (an empty TEXT removes the expression)");
		}
		Path file = Path.of(options.positional.get(0));
		Path output = options.value("-o", "--output") != null ? Path.of(options.value("-o", "--output")) : file;
		Model model = StatechartResources.load(file);
		org.kse.model.statechart.Node from = state(file, model, options.positional.get(1));
		org.kse.model.statechart.Node to = state(file, model, options.positional.get(2));
		if (from == null || to == null) {
			return INVALID;
		}
		List<org.kse.model.statechart.Transition> between = model.getTransitions().stream()
				.filter(transition -> transition.getSource() == from && transition.getTarget() == to).toList();
		org.kse.model.statechart.Transition transition;
		String index = options.value("--index");
		if (between.isEmpty()) {
			err.println("kse: " + file + ": no transition from " + shown(from) + " to " + shown(to));
			return INVALID;
		} else if (index != null) {
			int n;
			try {
				n = Integer.parseInt(index);
			} catch (NumberFormatException e) {
				throw new UsageException("--index takes a number, not '" + index + "'");
			}
			if (n < 1 || n > between.size()) {
				err.println("kse: " + file + ": --index " + n + ": there " + (between.size() == 1 ? "is 1 transition" : "are " + between.size() + " transitions")
						+ " from " + shown(from) + " to " + shown(to));
				return INVALID;
			}
			transition = between.get(n - 1);
		} else if (between.size() > 1) {
			err.println("kse: " + file + ": " + between.size() + " transitions from " + shown(from) + " to " + shown(to) + "; say which with --index:");
			for (int i = 0; i < between.size(); i++) {
				String text = between.get(i).getTE();
				err.println("  --index " + (i + 1) + ": " + (text == null || text.isBlank() ? "(no expression)" : text.replace("\n", " ")));
			}
			return INVALID;
		} else {
			transition = between.get(0);
		}
		List<Path> folders = new ArrayList<>(options.paths("--messages"));
		if (options.value("--source") != null) {
			folders.add(folderThatExists(Path.of(options.value("--source"))).resolve(MonasGenerator.MESSAGES_FOLDER));
		}
		String where = file + ": " + shown(from) + "->" + shown(to) + ": ";
		List<org.kse.validation.ExpressionChecks.Problem> problems = expression.isBlank() ? List.of()
				: org.kse.validation.ExpressionChecks.check(expression, StandardMessages.merge(folders).catalog());
		boolean refused = false;
		for (org.kse.validation.ExpressionChecks.Problem problem : problems) {
			refused |= problem.error();
			err.println(where + (problem.error() ? "error" : "warning") + ": expression " + problem);
		}
		if (refused) {
			err.println("kse: " + file + ": the expression was not set, the model is unchanged");
			return INVALID;
		}
		String before = transition.getTE();
		transition.setTE(expression.isBlank() ? null : expression);
		StatechartResources.save(model, output);
		out.println("set " + shown(from) + "->" + shown(to) + " in " + output + ": " + (expression.isBlank() ? "(no expression)" : expression)
				+ (before == null || before.isBlank() ? "" : " (was " + before.replace("\n", " ") + ")"));
		return OK;
	}

	/** A state named by its label, else by its name; null (and a message) when none or several. */
	private org.kse.model.statechart.Node state(Path file, Model model, String id) {
		List<org.kse.model.statechart.Node> all = new ArrayList<>();
		model.eAllContents().forEachRemaining(element -> {
			if (element instanceof org.kse.model.statechart.Node node) {
				all.add(node);
			}
		});
		List<org.kse.model.statechart.Node> byLabel = all.stream().filter(node -> id.equals(node.getLabel())).toList();
		List<org.kse.model.statechart.Node> found = byLabel.isEmpty() ? all.stream().filter(node -> id.equals(node.getName())).toList() : byLabel;
		if (found.size() == 1) {
			return found.get(0);
		}
		if (found.isEmpty()) {
			err.println("kse: " + file + ": no state labeled or named '" + id + "'");
		} else {
			err.println("kse: " + file + ": " + found.size() + " states named '" + id + "'; name one by its label: "
					+ String.join(", ", found.stream().map(org.kse.model.statechart.Node::getLabel).toList()));
		}
		return null;
	}

	/** A state as diagnostics show it: its label, and its name when it has another one. */
	private static String shown(org.kse.model.statechart.Node node) {
		String label = node.getLabel() == null ? "?" : node.getLabel();
		return node.getName() == null || node.getName().equals(label) ? label : label + " (" + node.getName() + ")";
	}

	private int simulate(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("--runtime", "--script", "--save-case", "--build-dir"), List.of("-q", "--quiet"));
		if (options.help) {
			out.println(SIMULATE_HELP);
			return OK;
		}
		Path file = options.single("model file");
		quiet = options.flag("-q", "--quiet");
		Model model = StatechartResources.load(file);
		String script = options.value("--script");
		List<Script.Step> steps = null;
		if (script != null) {
			try (BufferedReader reader = Files.newBufferedReader(Path.of(script), StandardCharsets.UTF_8)) {
				steps = Script.read(reader);
			} catch (NoSuchFileException e) {
				throw new IOException(script + ": no such file");
			} catch (IOException e) {
				throw new IOException(script + ": " + e.getMessage());
			}
		}
		Simulate simulate = new Simulate(out, err);
		try {
			Path prefix = RuntimePrefix.resolve(options.value("--runtime"));
			Path folder = options.value("--build-dir") != null ? Path.of(options.value("--build-dir")).toAbsolutePath()
					: SimulatorBuilder.defaultFolder(file);
			var simulator = SimulatorBuilder.build(model, prefix, folder, Simulate.progress(err, quiet));
			try (var session = SimulationSession.start(simulator)) {
				boolean same = true;
				if (steps != null) {
					same = simulate.runScript(session, script, steps);
				} else {
					simulate.runInteractive(session, model, file,
							new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8)));
				}
				if (options.value("--save-case") != null && simulate.save(session, model, file, Path.of(options.value("--save-case"))) == null) {
					return FAILED;
				}
				return same ? OK : INVALID;
			}
		} catch (MonasGenerator.ModelHasErrorsException e) {
			for (String error : e.errors()) {
				err.println(file + ": " + withSeverity(error, "error"));
			}
			err.println("kse: " + file + ": " + e.errors().size() + (e.errors().size() == 1 ? " error" : " errors") + ", nothing simulated");
			return INVALID;
		} catch (SimulationException e) {
			err.println("kse simulate: " + e.getMessage());
			return FAILED;
		}
	}

	/** The protocol owns standard output from here on: the server sends everything else to {@code err}. */
	private int lsp(List<String> args) throws UsageException {
		// --stdio: what LSP clients add to say the transport, the only one there is
		Options options = Options.parse(args, List.of(), List.of("--stdio"));
		if (options.help) {
			out.println(LSP_HELP);
			return OK;
		}
		if (!options.positional.isEmpty()) {
			throw new UsageException("kse lsp takes no arguments");
		}
		return org.kse.lsp.KseLanguageServer.serve(System.in, out, err);
	}

	private int serve(List<String> args) throws IOException, UsageException {
		Options options = Options.parse(args, List.of("--port", "--pages"), List.of());
		if (options.help) {
			out.println(SERVE_HELP);
			return OK;
		}
		Path folder = options.single("folder");
		if (!Files.isDirectory(folder)) {
			throw new NoSuchFileException(folder + " (not a folder)");
		}
		int port = 0;
		String portOption = options.value("--port");
		if (portOption != null) {
			try {
				port = Integer.parseInt(portOption);
			} catch (NumberFormatException e) {
				throw new UsageException("--port takes a number, not '" + portOption + "'");
			}
		}
		String pagesOption = options.value("--pages");
		java.net.URL pages = pagesOption != null ? Path.of(pagesOption).toAbsolutePath().toUri().toURL() : org.kse.diagram.server.websocket.DiagramPages.builtIn();
		if (pages == null) {
			err.println("kse: the diagram editor's page is not installed (bundle org.kse.diagram.client); use --pages DIR");
			return FAILED;
		}
		org.kse.diagram.server.websocket.DiagramSocketServer server;
		try {
			server = org.kse.diagram.server.websocket.DiagramSocketServer.start(folder, port, pages);
		} catch (IOException e) {
			throw e;
		} catch (Exception e) {
			err.println("kse: cannot start the diagram server on port " + port + ": " + e.getMessage());
			return FAILED;
		}
		java.util.concurrent.CountDownLatch stopped = new java.util.concurrent.CountDownLatch(1);
		Runtime.getRuntime().addShutdownHook(new Thread(() -> {
			try {
				server.close();
			} catch (Exception e) {
				// the process ends anyway
			}
			stopped.countDown();
		}, "kse serve shutdown"));
		List<String> models = server.models();
		out.println("serving " + models.size() + " statechart" + (models.size() == 1 ? "" : "s") + " of " + folder.toAbsolutePath().normalize()
				+ " on 127.0.0.1:" + server.port() + " (stop with Ctrl+C)");
		for (String model : models) {
			out.println("  " + server.page(model));
		}
		out.flush();
		try {
			stopped.await();
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
		}
		return OK;
	}

	/** One file's step of a command that takes many files. */
	@FunctionalInterface
	private interface FileStep {
		int run(Path file) throws IOException;
	}

	/**
	 * Runs a step on each file in one JVM (what a build with many models needs). A file that
	 * cannot be read is reported and the others still run; the exit code is the worst one.
	 */
	private int each(List<Path> files, FileStep step) {
		int result = OK;
		for (Path file : files) {
			try {
				result = Math.max(result, step.run(file));
			} catch (IOException e) {
				err.println("kse: " + e.getMessage());
				result = FAILED;
			} catch (UncheckedIOException e) {
				err.println("kse: " + e.getCause().getMessage());
				result = FAILED;
			}
		}
		return result;
	}

	/** A folder to write into: created when missing, refused when it is a file. */
	private static Path folder(Path path) throws IOException {
		if (Files.exists(path) && !Files.isDirectory(path)) {
			throw new IOException(path + ": not a folder (with several inputs, -o names the folder to write into)");
		}
		Files.createDirectories(path);
		return path;
	}

	private static Path folderThatExists(Path path) throws NoSuchFileException {
		if (!Files.isDirectory(path)) {
			throw new NoSuchFileException(path + " (not a folder)");
		}
		return path;
	}

	/**
	 * A problem in a source tree's own .proto file. A warning, not an error: the model may not use
	 * the message, and KSE's reading of .proto is not protoc's; protoc decides when the tree is built.
	 */
	private static String messageProblem(ProtoProblem problem) {
		return problem.file() + ":" + problem.line() + ":" + problem.column() + ": warning: " + problem.message();
	}

	/**
	 * One line naming the standard messages that the user's .proto files replaced, and by which
	 * file: a migrated Monas tree brings its own, and its users should know which definitions
	 * their expressions were checked against.
	 */
	private void note(Path model, List<StandardMessages.Replacement> replacements, Path sourceFolder, boolean generated) {
		if (replacements.isEmpty()) {
			return;
		}
		java.util.Map<Path, List<String>> byFile = new java.util.LinkedHashMap<>();
		for (StandardMessages.Replacement replacement : replacements) {
			byFile.computeIfAbsent(shown(replacement.file(), sourceFolder), key -> new ArrayList<>()).add(replacement.type());
		}
		List<String> parts = new ArrayList<>();
		byFile.forEach((path, types) -> parts.add(String.join(", ", types) + " by " + path));
		err.println(model + ": note: built-in messages replaced by the source tree's own: " + String.join("; ", parts)
				+ (generated ? " (the generated C++ uses the runtime's definitions: see the statechart's CMakeLists.txt)" : ""));
	}

	/** A file under the source folder as the user named that folder, else as it is. */
	private static Path shown(Path file, Path sourceFolder) {
		if (sourceFolder != null) {
			Path absolute = sourceFolder.toAbsolutePath().normalize();
			Path normalized = file.toAbsolutePath().normalize();
			if (normalized.startsWith(absolute)) {
				return sourceFolder.resolve(absolute.relativize(normalized));
			}
		}
		return file;
	}

	/** "label (name): message" becomes "label (name): severity: message". */
	private static String withSeverity(String message, String severity) {
		int split = message.indexOf("): ");
		return split < 0 ? severity + ": " + message : message.substring(0, split + 3) + severity + ": " + message.substring(split + 3);
	}

	private int report(Path file, List<Issue> issues) {
		int errors = 0;
		List<Issue> sorted = new ArrayList<>(issues);
		sorted.sort(java.util.Comparator.comparingInt((Issue issue) -> issue.getLineNumber() == null ? 0 : issue.getLineNumber())
				.thenComparingInt(issue -> issue.getColumn() == null ? 0 : issue.getColumn()));
		for (Issue issue : sorted) {
			if (issue.getSeverity() == Severity.IGNORE || issue.getSeverity() == Severity.INFO) {
				continue;
			}
			boolean error = issue.getSeverity() == Severity.ERROR;
			errors += error ? 1 : 0;
			err.println(file + ":" + issue.getLineNumber() + ":" + issue.getColumn() + ": " + (error ? "error" : "warning") + ": " + issue.getMessage());
		}
		return errors;
	}

	private void progress(int step, int steps, String what) {
		if (!quiet) {
			err.println("[" + step + "/" + steps + "] " + what);
		}
	}

	private static String statistics(Model model) {
		int[] states = { 0 };
		model.eAllContents().forEachRemaining(element -> states[0] += element instanceof org.kse.model.statechart.Node ? 1 : 0);
		return states[0] + " states, " + model.getTransitions().size() + " transitions";
	}

	private static String readText(Path file) throws IOException {
		StatechartResources.checkReadable(file);
		try {
			return Files.readString(file, StandardCharsets.UTF_8);
		} catch (NoSuchFileException e) {
			throw new IOException(file + ": no such file");
		} catch (MalformedInputException e) {
			throw new IOException(file + ": not a text file (it is not UTF-8)");
		}
	}

	private static Path withExtension(Path file, String extension) {
		String name = file.getFileName().toString();
		int dot = name.lastIndexOf('.');
		return file.resolveSibling((dot > 0 ? name.substring(0, dot) : name) + "." + extension);
	}

	static final class UsageException extends Exception {
		private static final long serialVersionUID = 1L;

		UsageException(String message) {
			super(message);
		}
	}

	/** Tiny option parser: positional arguments, options with one value, flags. */
	private static final class Options {
		final List<String> positional = new ArrayList<>();
		final java.util.Map<String, List<String>> values = new java.util.HashMap<>();
		final java.util.Set<String> flags = new java.util.HashSet<>();
		boolean help;

		static Options parse(List<String> args, List<String> valued, List<String> flagNames) throws UsageException {
			Options options = new Options();
			for (int i = 0; i < args.size(); i++) {
				String arg = args.get(i);
				if (arg.equals("-h") || arg.equals("--help")) {
					options.help = true;
				} else if (valued.contains(arg)) {
					if (i + 1 >= args.size()) {
						throw new UsageException("option " + arg + " needs a value");
					}
					options.values.computeIfAbsent(arg, key -> new ArrayList<>()).add(args.get(++i));
				} else if (flagNames.contains(arg)) {
					options.flags.add(arg);
				} else if (arg.startsWith("-") && arg.length() > 1) {
					throw new UsageException("unknown option " + arg);
				} else {
					options.positional.add(arg);
				}
			}
			return options;
		}

		List<Path> many(String what) throws UsageException {
			if (positional.isEmpty()) {
				throw new UsageException("missing " + what);
			}
			return positional.stream().map(Path::of).toList();
		}

		Path single(String what) throws UsageException {
			if (positional.size() != 1) {
				throw new UsageException(positional.isEmpty() ? "missing " + what : "expected one " + what + ", got " + positional.size());
			}
			return Path.of(positional.get(0));
		}

		String value(String... names) {
			for (String name : names) {
				if (values.containsKey(name)) {
					List<String> given = values.get(name);
					return given.get(given.size() - 1);
				}
			}
			return null;
		}

		List<Path> paths(String name) {
			return values.getOrDefault(name, List.of()).stream().map(Path::of).toList();
		}

		boolean flag(String... names) {
			for (String name : names) {
				if (flags.contains(name)) {
					return true;
				}
			}
			return false;
		}
	}
}
