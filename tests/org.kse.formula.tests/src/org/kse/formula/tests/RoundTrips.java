package org.kse.formula.tests;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.kse.liveness.FormulaLoader;
import org.kse.liveness.Formulas;
import org.kse.liveness.liveness.Expression;
import org.kse.liveness.liveness.Formula;
import org.kse.liveness.liveness.FormulaFile;
import org.kse.liveness.liveness.Group;
import org.kse.liveness.liveness.Reference;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.transform.FormulaTransformation;

/** What the round-trip tests share: the corpus, transforming, and the two comparisons. */
final class RoundTrips {

	static final Path REPOSITORY = Path.of(System.getProperty("kse.repository", "../.."));

	/** The first string argument of each case of the transformation's tests: their formulas. */
	private static final Pattern CASE = Pattern.compile("(?:Arguments\\.of|Statecharts\\.run|Statecharts\\.transform)\\(\\s*\"((?:[^\"\\\\]|\\\\.)*)\"");

	private RoundTrips() {
	}

	/**
	 * Every formula of the transformation's tests (read from their sources, so a case added there
	 * is round-tripped here too), the examples' formulas and the legacy models' .txt files.
	 */
	static List<String> corpus() {
		List<String> formulas = new ArrayList<>();
		Path tests = REPOSITORY.resolve("tests/org.kse.transform.tests/src/org/kse/transform/tests");
		try (Stream<Path> files = Files.list(tests)) {
			for (Path file : files.filter(path -> path.toString().endsWith(".java")).sorted().toList()) {
				Matcher matcher = CASE.matcher(Files.readString(file, StandardCharsets.UTF_8));
				while (matcher.find()) {
					if (!matcher.group(1).isEmpty()) {
						formulas.add(unescape(matcher.group(1)));
					}
				}
			}
			for (String[] folder : new String[][] { { "examples", ".liveness" }, { "tests/data/legacy-kse", ".txt" } }) {
				try (Stream<Path> found = Files.walk(REPOSITORY.resolve(folder[0]))) {
					for (Path file : found.filter(path -> path.toString().endsWith(folder[1])).sorted().toList()) {
						formulas.add(Files.readString(file, StandardCharsets.UTF_8));
					}
				}
			}
		} catch (IOException e) {
			throw new UncheckedIOException(e);
		}
		return formulas;
	}

	private static String unescape(String literal) {
		StringBuilder out = new StringBuilder();
		for (int i = 0; i < literal.length(); i++) {
			char c = literal.charAt(i);
			if (c == '\\' && i + 1 < literal.length()) {
				char next = literal.charAt(++i);
				out.append(switch (next) {
					case 'n' -> '\n';
					case 't' -> '\t';
					case 'r' -> '\r';
					default -> next;
				});
			} else {
				out.append(c);
			}
		}
		return out.toString();
	}

	static FormulaTransformation.Outcome run(String formulas) {
		return FormulaTransformation.run(formulas, URI.createURI("roundtrip.liveness"), null);
	}

	static Model transform(String formulas) {
		FormulaTransformation.Outcome outcome = run(formulas);
		assertNotNull(outcome.model(), () -> formulas + "\nrejected: " + outcome.issues());
		assertFalse(outcome.issues().stream().anyMatch(issue -> issue.getSeverity() == Severity.ERROR), () -> formulas + "\n" + outcome.issues());
		return outcome.model();
	}

	/**
	 * The chart as a person compares two: the model's name, each state ("label KIND name", the
	 * name left out for START, END, CONDITION and regions, which the transformation names by
	 * their label), then each transition by the labels it joins, in the model's order.
	 */
	static String render(Model model) {
		List<String> lines = new ArrayList<>();
		lines.add("model " + model.getName());
		model.eAllContents().forEachRemaining(element -> {
			if (element instanceof Node node) {
				boolean auxiliary = NodeKind.of(node) != null && NodeKind.of(node).isAuxiliary() || node.getLabel().equals(node.getName());
				lines.add(node.getLabel() + " " + node.getType() + (auxiliary ? "" : " " + node.getName()));
			}
		});
		for (Transition transition : model.getTransitions()) {
			lines.add(transition.getSource().getLabel() + "->" + transition.getTarget().getLabel() + " " + transition.getName());
		}
		return String.join("\n", lines);
	}

	/**
	 * The formulas in force that the root uses, each without blanks and without the parentheses
	 * around a whole right side (the transformation lays such a group out in place, so no chart
	 * remembers them), the root first and the others by name.
	 */
	static String normalize(String text) {
		FormulaLoader.Result loaded = FormulaLoader.load(text, URI.createURI("normalize.liveness"));
		assertFalse(loaded.hasErrors(), () -> text + "\n" + loaded.issues());
		FormulaFile file = loaded.file();
		Map<String, Formula> capabilities = Formulas.capabilities(file);
		Formula root = Formulas.rootDefinition(file);
		Map<String, String> used = new TreeMap<>();
		Set<String> seen = new LinkedHashSet<>();
		Deque<Formula> queue = new ArrayDeque<>(List.of(root));
		seen.add(root.getName());
		while (!queue.isEmpty()) {
			Formula formula = queue.removeFirst();
			used.put(formula.getName(), Formulas.text(withoutOuterGroups(formula.getExpression())));
			for (Reference reference : Formulas.references(formula.getExpression())) {
				Formula definition = capabilities.get(reference.getName());
				if (definition != null && seen.add(reference.getName())) {
					queue.addLast(definition);
				}
			}
		}
		StringBuilder out = new StringBuilder(root.getName() + " = " + used.remove(root.getName()) + "\n");
		used.forEach((name, expression) -> out.append(name).append(" = ").append(expression).append('\n'));
		return out.toString();
	}

	private static Expression withoutOuterGroups(Expression expression) {
		Expression level = expression;
		while (level.getTerms().size() == 1 && level.getTerms().get(0) instanceof Group group && group.getExpression() != null) {
			level = group.getExpression();
		}
		return level;
	}

	/** Labels of the states whose transitions carry an expression, for the problems a chart's guards must give. */
	static Set<String> guardedSources(Model model) {
		Set<String> labels = new TreeSet<>();
		for (Transition transition : model.getTransitions()) {
			if (transition.getTE() != null && !transition.getTE().isBlank()) {
				labels.add(transition.getSource().getLabel());
			}
		}
		return labels;
	}
}
