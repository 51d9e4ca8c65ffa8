package org.kse.formula;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicReference;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.formula.FormulaTerms.Expr;
import org.kse.formula.FormulaTerms.Grp;
import org.kse.formula.FormulaTerms.Opt;
import org.kse.formula.FormulaTerms.Ref;
import org.kse.formula.FormulaTerms.Rep;
import org.kse.formula.FormulaTerms.Repl;
import org.kse.formula.FormulaTerms.Shape;
import org.kse.formula.FormulaTerms.Term;
import org.kse.liveness.FormulaLoader;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/**
 * Statechart to liveness formulas: the inverse of {@code org.kse.transform.FormulaToStatechart}.
 * <p>
 * Each composite state is matched against the shapes the transformation builds (a sequence
 * START → x1 → … → xn → END, a choice through one CONDITION, a parallel START → AND → END, the
 * fixed shapes of [x], x*, x+, x~ and |x~|n). Which term a state stands for is decided by its
 * name, since the transformation names every state by the spelled text of its term
 * ({@code _open_group_B_sequence_C_close_group_}): a composite state whose name is that spelling
 * is written in place, any other name is a capability of that name. So a chart the
 * transformation made gives back its formulas, up to what the transformation forgets (the
 * parentheses around a whole right side, unused capabilities).
 * <p>
 * A chart edited by hand gets the closest formula and a {@link Problem} for each state whose
 * part a formula cannot hold: guards and timers on transitions, transitions between levels,
 * states that form none of the shapes (written as the sequence of their states), names that are
 * not formula names.
 */
public final class StatechartToFormula {

	/** What a formula cannot say about one state, named by its label and name. */
	public record Problem(String label, String name, String message) {
		@Override
		public String toString() {
			return label + " (" + name + "): " + message;
		}
	}

	/** One line of the formula file. */
	public record Definition(String name, String expression) {
		@Override
		public String toString() {
			return name + " = " + expression;
		}
	}

	/**
	 * The recovered formulas, the root first, and every problem, in the order of the states.
	 * {@code title} is the model's name when the root's name would not give it back (the
	 * original tool's title line), else null.
	 */
	public record Result(String title, List<Definition> formulas, List<Problem> problems) {
		/** One {@code name = expression} per line, the root first. */
		public String text() {
			StringBuilder out = new StringBuilder();
			for (Definition definition : formulas) {
				out.append(definition).append('\n');
			}
			return out.toString();
		}

		/** The text of a formula file that {@code kse transform} turns back into the chart: the title line, then the formulas. */
		public String fileText() {
			return (title == null ? "" : title + "\n") + text();
		}
	}

	private static final Pattern ID = Pattern.compile("[A-Za-z_][A-Za-z0-9_]*");
	/** Stands for the root's definition while its content is recovered, so no capability takes its name. */
	private static final String RESERVED = "\0";

	private final List<Problem> problems = new ArrayList<>();
	private final Set<String> problemKeys = new HashSet<>();
	private final Map<String, String> definitions = new LinkedHashMap<>();
	private final Map<String, Node> definedAt = new HashMap<>();
	private final Set<String> activities = new HashSet<>();
	private final Map<Node, Integer> documentOrder = new IdentityHashMap<>();
	private final Map<Node, List<Transition>> outgoing = new IdentityHashMap<>();

	private StatechartToFormula() {
	}

	/** Deeply nested charts recurse deeply (as deeply as the transformation that made them): give the recovery room. */
	private static final long STACK_SIZE = 512L * 1024 * 1024;

	/** The formulas the model stands for, and what they cannot express. */
	public static Result recover(Model model) {
		AtomicReference<Result> result = new AtomicReference<>();
		AtomicReference<Throwable> failure = new AtomicReference<>();
		Thread worker = new Thread(null, () -> {
			try {
				result.set(new StatechartToFormula().run(model));
			} catch (Throwable e) {
				failure.set(e);
			}
		}, "kse-formula", STACK_SIZE);
		worker.start();
		try {
			worker.join();
		} catch (InterruptedException e) {
			Thread.currentThread().interrupt();
			throw new IllegalStateException("interrupted while recovering the formulas", e);
		}
		if (failure.get() instanceof RuntimeException e) {
			throw e;
		}
		if (failure.get() instanceof Error e) {
			throw e;
		}
		return result.get();
	}

	private Result run(Model model) {
		List<Node> all = new ArrayList<>();
		model.eAllContents().forEachRemaining(element -> {
			if (element instanceof Node node) {
				documentOrder.put(node, all.size());
				all.add(node);
			}
		});
		if (model.getNodes().isEmpty()) {
			problems.add(new Problem("-", String.valueOf(model.getName()), "the model has no states: there is no formula to write"));
			return new Result(null, List.of(), List.copyOf(problems));
		}
		for (Transition transition : model.getTransitions()) {
			if (transition.getSource() != null) {
				outgoing.computeIfAbsent(transition.getSource(), key -> new ArrayList<>()).add(transition);
			}
		}
		checkTransitions(model);
		Node root = model.getNodes().get(0);
		for (Node other : model.getNodes().subList(1, model.getNodes().size())) {
			problem(other, "a second top-level state: a formula file has one root, so this state and what it holds are left out");
		}
		if (!model.getVariables().isEmpty()) {
			problem(root, "the model's variables (" + String.join(", ", model.getVariables().stream().map(v -> String.valueOf(v.getName())).toList())
					+ ") have no place in a formula: left out");
		}
		for (Node node : all) {
			if (NodeKind.BASIC.is(node) && isInside(node, root)) {
				activities.add(formulaName(node.getName(), node.getLabel()));
			}
		}
		String rootName = formulaName(root.getName(), root.getLabel());
		if (!ID.matcher(String.valueOf(root.getName())).matches()) {
			problem(root, "'" + root.getName() + "' is not a formula name: the root is written as " + rootName);
		}
		String expression;
		if (isComposite(root) && !isEmpty(root)) {
			definitions.put(rootName, RESERVED);
			definedAt.put(rootName, root);
			expression = shapeOf(root).text();
		} else {
			String activity = rootName;
			rootName = rootName + "Root";
			problem(root, isComposite(root) ? "the root holds no state: written as the activity " + activity
					: "the root is a " + root.getType() + " state, which a formula's root cannot be: written as the root " + rootName + " doing the activity " + activity);
			expression = activity;
		}
		definitions.put(rootName, expression);
		definedAt.put(rootName, root);

		List<Definition> formulas = new ArrayList<>();
		formulas.add(new Definition(rootName, expression));
		String rootKey = rootName;
		definitions.entrySet().stream().filter(entry -> !entry.getKey().equals(rootKey))
				.sorted(Comparator.comparingInt(entry -> documentOrder.getOrDefault(definedAt.get(entry.getKey()), Integer.MAX_VALUE)))
				.forEach(entry -> formulas.add(new Definition(entry.getKey(), entry.getValue())));
		String title = ID.matcher(String.valueOf(model.getName())).matches() && !model.getName().equals(rootName) ? model.getName() : null;
		Result result = new Result(title, List.copyOf(formulas), problems);
		readBack(result, root);
		List<Problem> sorted = new ArrayList<>(problems);
		sorted.sort(Comparator.comparing(Problem::label, StatechartToFormula::compareLabels));
		return new Result(title, result.formulas(), List.copyOf(sorted));
	}

	/**
	 * The formulas must read back without error; whatever the recovery missed (a capability whose
	 * name differs from an activity's only by case, say) is said here rather than left to the
	 * user's next kse transform.
	 */
	private void readBack(Result result, Node root) {
		FormulaLoader.Result loaded = FormulaLoader.load(result.fileText(), URI.createURI("recovered.liveness"));
		for (Issue issue : loaded.issues()) {
			if (issue.getSeverity() == Severity.ERROR) {
				problem(root, "the formulas written do not read back: line " + issue.getLineNumber() + ": " + issue.getMessage());
			}
		}
	}

	// ------------------------------------------------------------------ what a formula cannot hold

	private void checkTransitions(Model model) {
		for (Transition transition : model.getTransitions()) {
			Node source = transition.getSource();
			Node target = transition.getTarget();
			if (source == null || target == null) {
				continue;
			}
			String te = transition.getTE();
			if (te != null && !te.isBlank()) {
				problem(source, "its transition to " + shown(target) + " has the expression '" + oneLine(te)
						+ "': a formula has no guards, events, timers or actions, so it keeps the transition without it");
			}
			if (source.eContainer() != target.eContainer()) {
				problem(source, "its transition to " + shown(target)
						+ " goes to another level of the hierarchy: a formula only orders states inside one composite state, so it is left out");
			}
		}
	}

	// ------------------------------------------------------------------ terms

	/** The term whose state this is (what the transformation's termChild and content made). */
	private Term termOf(Node node) {
		NodeKind kind = NodeKind.of(node);
		if (kind == NodeKind.BASIC) {
			return new Ref(activityName(node));
		}
		if (kind == null || kind.isAuxiliary()) {
			problem(node, "a state of kind " + node.getType() + " where the formula has a term: written as an activity");
			return new Ref(activityName(node));
		}
		if (isEmpty(node)) {
			problem(node, "an " + kind + " state that holds no activity or composite state: written as the activity " + activityName(node));
			return new Ref(activityName(node));
		}
		return termOf(node, shapeOf(node));
	}

	/**
	 * A composite state is its term written in place when its name is that term's spelling
	 * (with as many groups around it as the name says: {@code ((B.C))}), else a capability.
	 */
	private Term termOf(Node node, Shape shape) {
		Term inline = shape.expression() != null ? new Grp(shape.expression()) : shape.layout();
		String spelled = FormulaTerms.spell(inline);
		String rest = node.getName() == null ? "" : node.getName();
		int groups = 0;
		while (!rest.equals(spelled)) {
			if (rest.length() > FormulaTerms.OPEN_GROUP.length() + FormulaTerms.CLOSE_GROUP.length() && rest.startsWith(FormulaTerms.OPEN_GROUP)
					&& rest.endsWith(FormulaTerms.CLOSE_GROUP)) {
				rest = rest.substring(FormulaTerms.OPEN_GROUP.length(), rest.length() - FormulaTerms.CLOSE_GROUP.length());
				groups++;
			} else {
				return new Ref(capability(node, shape));
			}
		}
		for (int i = 0; i < groups; i++) {
			inline = new Grp(Expr.of(inline));
		}
		return inline;
	}

	private Shape shapeOf(Node node) {
		return NodeKind.AND.is(node) ? andShape(node, regionTerms(node)) : orShape(node);
	}

	// ------------------------------------------------------------------ AND states

	private List<Term> regionTerms(Node and) {
		List<Term> terms = new ArrayList<>();
		for (Node region : and.getChildren()) {
			terms.add(regionTerm(region));
		}
		return terms;
	}

	/** A region START → x → END is x's term; any other region is what it holds, as a group. */
	private Term regionTerm(Node region) {
		if (!NodeKind.OR.is(region)) {
			problem(region, "a region of an AND state that is not an OR state: written as its own term");
			return termOf(region);
		}
		List<Node> states = states(region);
		List<Node> starts = ofKind(region, NodeKind.START);
		List<Node> ends = ofKind(region, NodeKind.END);
		if (states.size() == 1 && starts.size() == 1 && ends.size() == 1 && region.getChildren().size() == 3 && internal(region).size() == 2
				&& has(starts.get(0), states.get(0)) && has(states.get(0), ends.get(0))) {
			return termOf(states.get(0));
		}
		if (isEmpty(region)) {
			problem(region, "a region that holds no activity or composite state: left out of the parallel");
			return null;
		}
		Shape shape = orShape(region);
		return shape.expression() != null ? new Grp(shape.expression()) : shape.layout();
	}

	/** Copies of one term are |x~|n; different terms are their parallel (which a term can only be as a group). */
	private Shape andShape(Node and, List<Term> regionTerms) {
		List<Term> terms = regionTerms.stream().filter(term -> term != null).toList();
		if (terms.isEmpty()) {
			problem(and, "an AND state without regions");
			return Shape.of(Expr.of(new Ref(activityName(and))));
		}
		if (uniform(terms)) {
			Term operand = terms.get(0);
			// the x of |x~|n is a name, a group or an option: a repeated term is copied as a group
			if (operand instanceof Rep || operand instanceof Repl) {
				operand = new Grp(Expr.of(operand));
			}
			return Shape.of(new Repl(operand, terms.size()));
		}
		return Shape.of(new Expr(terms, "||"));
	}

	private static boolean uniform(List<Term> terms) {
		String first = FormulaTerms.print(terms.get(0));
		return terms.stream().allMatch(term -> FormulaTerms.print(term).equals(first));
	}

	// ------------------------------------------------------------------ OR states

	private Shape orShape(Node node) {
		List<Node> states = states(node);
		List<Node> starts = ofKind(node, NodeKind.START);
		List<Node> ends = ofKind(node, NodeKind.END);
		List<Node> conditions = ofKind(node, NodeKind.CONDITION);
		List<Transition> inside = internal(node);
		int count = inside.size();
		if (starts.size() == 1 && ends.size() <= 1 && conditions.size() <= 1) {
			Node start = starts.get(0);
			Node end = ends.isEmpty() ? null : ends.get(0);
			Node condition = conditions.isEmpty() ? null : conditions.get(0);
			if (states.size() == 1) {
				Node x = states.get(0);
				boolean loop = has(x, x);
				if (condition == null && end == null && loop && count == 2 && has(start, x)) {
					return Shape.of(new Rep(termOf(x), '~'));
				}
				if (condition == null && end != null && loop && count == 3 && has(start, x) && has(x, end)) {
					return Shape.of(new Rep(termOf(x), '+'));
				}
				if (condition != null && end != null && has(start, condition) && has(condition, x) && has(condition, end) && has(x, end)) {
					if (loop && count == 5) {
						return Shape.of(new Rep(termOf(x), '*'));
					}
					if (!loop && count == 4) {
						return Shape.of(new Opt(optionInner(x)));
					}
				}
				if (condition == null && end != null && !loop && count == 2 && has(start, x) && has(x, end)) {
					return sequenceOfOne(x);
				}
			}
			if (condition != null && end != null && states.size() >= 2 && count == 1 + 2 * states.size() && has(start, condition)) {
				List<Node> targets = targets(condition, node);
				if (targets.size() == states.size() && new HashSet<>(targets).containsAll(states) && states.stream().allMatch(x -> has(x, end))) {
					return Shape.of(new Expr(targets.stream().map(this::termOf).toList(), "|"));
				}
			}
			if (condition == null && end != null && states.size() >= 2 && count == states.size() + 1) {
				List<Node> chain = chain(start, end, node);
				if (chain != null && chain.size() == states.size()) {
					return Shape.of(new Expr(chain.stream().map(this::termOf).toList(), "."));
				}
			}
		}
		return closest(node, states, inside);
	}

	/**
	 * START → x → END: the transformation makes it of a lone name, or of a parallel (START → AND →
	 * END, the AND named by the parallel's spelling). Anything else here was edited by hand and
	 * is written in place, which is what it means.
	 */
	private Shape sequenceOfOne(Node x) {
		if (NodeKind.AND.is(x) && !isEmpty(x)) {
			List<Term> terms = regionTerms(x).stream().filter(term -> term != null).toList();
			Expr parallel = new Expr(terms, "||");
			if (terms.size() >= 2 && (!uniform(terms) || FormulaTerms.spell(parallel).equals(x.getName()))) {
				return Shape.of(parallel);
			}
			return inPlace(termOf(x, andShape(x, terms)));
		}
		return inPlace(termOf(x));
	}

	/** A term written where the transformation would have laid out a whole right side: its groups fall away. */
	private static Shape inPlace(Term term) {
		if (term instanceof Grp group) {
			Expr expression = group.expression();
			while (expression.terms().size() == 1 && expression.terms().get(0) instanceof Grp inner) {
				expression = inner.expression();
			}
			return Shape.of(expression);
		}
		return term instanceof Ref ? Shape.of(Expr.of(term)) : Shape.of(term);
	}

	/** The x of [x]: several terms laid out in the option's state (named by their spelling, no group), or one term. */
	private Expr optionInner(Node x) {
		if (isComposite(x) && !isEmpty(x)) {
			Shape shape = shapeOf(x);
			if (shape.expression() != null && shape.expression().terms().size() >= 2 && FormulaTerms.spell(shape.expression()).equals(x.getName())) {
				return shape.expression();
			}
			return Expr.of(termOf(x, shape));
		}
		return Expr.of(termOf(x));
	}

	/**
	 * A composite state of no known shape: the sequence of its states in the order a walk from
	 * START reaches them (then the unreached ones), a state with a transition to itself repeated.
	 */
	private Shape closest(Node node, List<Node> states, List<Transition> inside) {
		if (states.isEmpty()) {
			problem(node, "holds no activity or composite state: written as an activity");
			return Shape.of(Expr.of(new Ref(activityName(node))));
		}
		Set<Node> order = new LinkedHashSet<>();
		Deque<Node> queue = new ArrayDeque<>(ofKind(node, NodeKind.START));
		Set<Node> seen = new HashSet<>(queue);
		while (!queue.isEmpty()) {
			Node current = queue.removeFirst();
			if (!isAuxiliary(current)) {
				order.add(current);
			}
			for (Node target : targets(current, node)) {
				if (seen.add(target)) {
					queue.addLast(target);
				}
			}
		}
		order.addAll(states);
		List<Term> terms = new ArrayList<>();
		for (Node state : order) {
			Term term = termOf(state);
			terms.add(has(state, state) ? new Rep(term, '+') : term);
		}
		Expr expression = new Expr(terms, terms.size() == 1 ? null : ".");
		List<String> transitions = inside.stream().limit(12).map(t -> t.getSource().getLabel() + "->" + t.getTarget().getLabel()).toList();
		problem(node, "its states form none of a formula's shapes (a sequence, a choice, an option, a repetition, a parallel)"
				+ (inside.isEmpty() ? " with no transitions between them" : " with its transitions " + String.join(" ", transitions) + (inside.size() > 12 ? " ..." : ""))
				+ ": written as the sequence " + FormulaTerms.print(expression) + " in the order they are reached from START");
		return Shape.of(expression);
	}

	// ------------------------------------------------------------------ names

	/** The capability a composite state stands for; a second state of that name with other content gets another. */
	private String capability(Node node, Shape shape) {
		String wanted = formulaName(node.getName(), node.getLabel());
		if (!ID.matcher(String.valueOf(node.getName())).matches()) {
			problem(node, "'" + node.getName() + "' is not a formula name: written as the capability " + wanted);
		}
		String text = shape.text();
		String name = wanted;
		for (int i = 2;; i++) {
			String existing = definitions.get(name);
			if (existing == null && !activities.contains(name)) {
				definitions.put(name, text);
				definedAt.put(name, node);
				break;
			}
			if (text.equals(existing)) {
				break;
			}
			name = wanted + "_" + i;
		}
		if (!name.equals(wanted)) {
			Node other = definedAt.get(wanted);
			problem(node, (activities.contains(wanted) && other == null ? "an activity is named " + wanted + " too"
					: "the state " + shown(other) + " has the same name and stands for another formula") + ": written as the capability " + name);
		}
		return name;
	}

	private String activityName(Node node) {
		String name = formulaName(node.getName(), node.getLabel());
		if (!ID.matcher(String.valueOf(node.getName())).matches()) {
			problem(node, "'" + node.getName() + "' is not a formula name: written as the activity " + name);
		}
		return name;
	}

	/** A name the formula grammar reads: other characters become '_', an empty name the label's. */
	private static String formulaName(String name, String label) {
		String base = name == null || name.isBlank() ? "state_" + String.valueOf(label) : name.strip();
		String cleaned = base.replaceAll("[^A-Za-z0-9_]", "_");
		return Character.isDigit(cleaned.charAt(0)) ? "_" + cleaned : cleaned;
	}

	// ------------------------------------------------------------------ structure

	private static boolean isComposite(Node node) {
		NodeKind kind = NodeKind.of(node);
		return kind != null && kind.isComposite();
	}

	/** A composite without any state but START, END and CONDITION. */
	private static boolean isEmpty(Node node) {
		return node.getChildren().stream().allMatch(StatechartToFormula::isAuxiliary);
	}

	private static boolean isAuxiliary(Node node) {
		NodeKind kind = NodeKind.of(node);
		return kind != null && kind.isAuxiliary();
	}

	private static boolean isInside(Node node, Node ancestor) {
		for (Node current = node; current != null; current = current.getFather_of()) {
			if (current == ancestor) {
				return true;
			}
		}
		return false;
	}

	/** The children that are terms: everything but START, END and CONDITION. */
	private static List<Node> states(Node node) {
		return node.getChildren().stream().filter(child -> !isAuxiliary(child)).toList();
	}

	private static List<Node> ofKind(Node node, NodeKind kind) {
		return node.getChildren().stream().filter(kind::is).toList();
	}

	/** Transitions between two children of the node, in the model's order. */
	private List<Transition> internal(Node node) {
		List<Transition> result = new ArrayList<>();
		for (Node child : node.getChildren()) {
			for (Transition transition : outgoing.getOrDefault(child, List.of())) {
				if (transition.getTarget() != null && transition.getTarget().eContainer() == node) {
					result.add(transition);
				}
			}
		}
		return result;
	}

	/** Where the transitions of a state lead inside its composite, in the model's order (a CONDITION's priority order). */
	private List<Node> targets(Node source, Node composite) {
		List<Node> result = new ArrayList<>();
		for (Transition transition : outgoing.getOrDefault(source, List.of())) {
			if (transition.getTarget() != null && transition.getTarget().eContainer() == composite && transition.getTarget() != source) {
				result.add(transition.getTarget());
			}
		}
		return result;
	}

	private boolean has(Node source, Node target) {
		return outgoing.getOrDefault(source, List.of()).stream().anyMatch(transition -> transition.getTarget() == target);
	}

	/** START → x1 → … → xn → END with one transition out of each, or null. */
	private List<Node> chain(Node start, Node end, Node composite) {
		List<Node> chain = new ArrayList<>();
		Node current = start;
		while (true) {
			List<Node> next = targets(current, composite);
			if (next.size() != 1 || has(current, current)) {
				return null;
			}
			current = next.get(0);
			if (current == end) {
				return chain;
			}
			if (chain.contains(current) || current == start || isAuxiliary(current)) {
				return null;
			}
			chain.add(current);
		}
	}

	// ------------------------------------------------------------------ problems

	private void problem(Node node, String message) {
		String label = node == null ? "-" : String.valueOf(node.getLabel());
		String name = node == null ? "-" : String.valueOf(node.getName());
		if (problemKeys.add(label + "\n" + name + "\n" + message)) {
			problems.add(new Problem(label, name, message));
		}
	}

	private static String shown(Node node) {
		return node == null ? "-" : node.getLabel() + " (" + node.getName() + ")";
	}

	private static String oneLine(String text) {
		String line = text.replaceAll("\\s+", " ").strip();
		return line.length() > 80 ? line.substring(0, 77) + "..." : line;
	}

	/** Labels in the order of their numbers (0.2 before 0.10), anything else after them as text. */
	private static int compareLabels(String a, String b) {
		String[] left = a.split("\\.");
		String[] right = b.split("\\.");
		for (int i = 0; i < Math.min(left.length, right.length); i++) {
			int order;
			try {
				order = Integer.compare(Integer.parseInt(left[i]), Integer.parseInt(right[i]));
			} catch (NumberFormatException e) {
				order = left[i].compareTo(right[i]);
			}
			if (order != 0) {
				return order;
			}
		}
		return Integer.compare(left.length, right.length);
	}
}
