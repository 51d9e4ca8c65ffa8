package org.kse.scxml;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.EObject;
import org.kse.expression.ExpressionParser;
import org.kse.labeling.Labeler;
import org.kse.messages.StandardMessages;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.scxml.ScxmlImportReader.Element;
import org.kse.validation.Labels;
import org.kse.validation.ModelValidation;

/**
 * SCXML into a KSE statechart (issue 20). A document the export wrote ({@code kse:export="1"})
 * is rebuilt from its {@code kse:} annotations, exactly (ADR 0038); any other document is mapped
 * construct by construct ({@link ScxmlImportForeign}), labelled, and validated.
 * <p>
 * What KSE cannot represent is reported per element, with the element's tag, id and line:column:
 * an ERROR where leaving it out would change where or when the chart moves (events, conditions
 * that are not KSE's, history, several or deep targets, targetless transitions): then there is no
 * model. A WARNING where only side effects KSE has no place for are left out (executable content,
 * {@code <invoke>}, {@code <datamodel>}): the model is made without them ({@link Result#leftOut()}). The validator's problems follow; an error among them also means no model.
 */
public final class ScxmlImport {

	/**
	 * What the import made.
	 *
	 * @param model the statechart, labelled; null when the import was refused (an error among the problems)
	 * @param problems the import's problems, then the validator's
	 * @param leftOut the parts of the document the model was made without (the import's warnings)
	 */
	public record Result(Model model, List<ScxmlProblem> problems, List<ScxmlProblem> leftOut) {
		public boolean hasErrors() {
			return problems.stream().anyMatch(ScxmlProblem::isError);
		}

		/** Whether the model carries the whole document (the validator may still warn). */
		public boolean complete() {
			return model != null && leftOut.isEmpty();
		}
	}

	private static final Pattern POSITION = Pattern.compile("^(.*) at (\\d+):(\\d+)$");

	private ScxmlImport() {
	}

	/**
	 * Imports a file; a file that cannot be read at all (missing, a folder) is an IOException with
	 * a message naming it, a file that is not SCXML is a result with an error.
	 */
	public static Result read(Path file) throws IOException {
		StatechartResources.checkReadable(file);
		try (InputStream input = Files.newInputStream(file)) {
			return read(input, modelName(file));
		}
	}

	/**
	 * Imports a document read from {@code input}.
	 *
	 * @param fallbackName the model's name when the document's {@code <scxml>} has no {@code name}
	 */
	public static Result read(InputStream input, String fallbackName) throws IOException {
		Element root;
		try {
			root = ScxmlImportReader.read(input);
		} catch (ScxmlImportReader.Unreadable e) {
			return refused(ScxmlProblem.error("the document at " + e.line + ":" + e.column, e.getMessage()));
		}
		if (!root.is("scxml")) {
			return refused(ScxmlProblem.error(root.describe(), "not an SCXML document: its root element is <" + root.name + ">"
					+ (root.namespace.isEmpty() ? "" : " of " + root.namespace) + ", not <scxml> of " + ScxmlImportReader.SCXML_NAMESPACE));
		}
		List<ScxmlProblem> problems = new ArrayList<>();
		boolean exported = "1".equals(root.kse.get("export"));
		ExpressionParser.Session expressions = ExpressionParser.session();
		ScxmlImportForeign foreign = exported ? null : new ScxmlImportForeign(problems, expressions);
		Model model = exported ? ScxmlImportAnnotated.build(root, problems) : foreign.build(root, fallbackName);
		// in the order of the document, as a reader goes through it
		problems.sort(java.util.Comparator.comparingLong(ScxmlImport::position));
		List<ScxmlProblem> leftOut = List.copyOf(problems);
		if (model == null || problems.stream().anyMatch(ScxmlProblem::isError)) {
			return new Result(null, leftOut, List.of());
		}
		if (!exported) {
			Labeler.label(model);
		}
		boolean valid = true;
		for (Diagnostic diagnostic : ModelValidation.validate(model, StandardMessages.catalog(), expressions).getChildren()) {
			boolean error = diagnostic.getSeverity() == Diagnostic.ERROR;
			valid &= !error;
			EObject object = diagnostic.getData().isEmpty() || !(diagnostic.getData().get(0) instanceof EObject first) ? model : first;
			String element = Labels.describe(object);
			String message = diagnostic.getMessage().startsWith(element + ": ") ? diagnostic.getMessage().substring(element.length() + 2) : diagnostic.getMessage();
			String kind = object instanceof org.kse.model.statechart.Node ? "state " : object instanceof org.kse.model.statechart.Transition ? "transition " : "";
			// a chart of another tool: the problem at the element of the document it comes from
			Element origin = foreign == null ? null : foreign.origin(object);
			problems.add(new ScxmlProblem(error ? ScxmlProblem.Severity.ERROR : ScxmlProblem.Severity.WARNING,
					origin == null ? kind + element : origin.describe(), origin == null ? message : kind + element + ": " + message));
		}
		return new Result(valid ? model : null, List.copyOf(problems), leftOut);
	}

	/**
	 * One problem as a line for a terminal or a list: {@code source:line:column: severity: element: message}
	 * for an element of the SCXML document, {@code source: element: severity: message} for a state of
	 * the statechart (as {@code kse validate} prints them).
	 */
	public static String format(String source, ScxmlProblem problem) {
		String severity = problem.isError() ? "error" : "warning";
		Matcher positioned = POSITION.matcher(problem.element());
		if (positioned.matches()) {
			String what = positioned.group(1);
			return source + ":" + positioned.group(2) + ":" + positioned.group(3) + ": " + severity + ": "
					+ (what.equals("the document") ? "" : what + ": ") + problem.message();
		}
		return source + ": " + problem.element() + ": " + severity + ": " + problem.message();
	}

	/** Where in the document a problem of the import is, as one number that sorts by line, then column. */
	private static long position(ScxmlProblem problem) {
		Matcher positioned = POSITION.matcher(problem.element());
		return positioned.matches() ? Long.parseLong(positioned.group(2)) * 1_000_000L + Long.parseLong(positioned.group(3)) : Long.MAX_VALUE;
	}

	/** The model name a file gives when its document names none: the file's name without extension, made an identifier. */
	static String modelName(Path file) {
		String name = file.getFileName() == null ? "" : file.getFileName().toString().replaceFirst("\\.[^.]*$", "");
		String identifier = name.replaceAll("[^A-Za-z0-9_]", "_");
		return identifier.isEmpty() ? "Statechart" : Character.isDigit(identifier.charAt(0)) ? "_" + identifier : identifier;
	}

	private static Result refused(ScxmlProblem problem) {
		return new Result(null, List.of(problem), List.of());
	}
}
