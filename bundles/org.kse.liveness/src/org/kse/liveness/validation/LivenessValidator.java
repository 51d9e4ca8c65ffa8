package org.kse.liveness.validation;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.CheckType;
import org.kse.liveness.Formulas;
import org.kse.liveness.liveness.Expression;
import org.kse.liveness.liveness.Formula;
import org.kse.liveness.liveness.FormulaFile;
import org.kse.liveness.liveness.Group;
import org.kse.liveness.liveness.LivenessPackage.Literals;
import org.kse.liveness.liveness.Operator;
import org.kse.liveness.liveness.Option;
import org.kse.liveness.liveness.Reference;
import org.kse.liveness.liveness.Replication;
import org.kse.liveness.liveness.Term;

/**
 * The rules a formula file must satisfy before it can become a statechart. Every
 * problem the original tool crashed on, or silently mis-read, is reported here at
 * its position instead.
 */
public class LivenessValidator extends AbstractLivenessValidator {

	public static final String EMPTY_FORMULA = "kse.liveness.emptyFormula";
	public static final String EMPTY_GROUP = "kse.liveness.emptyGroup";
	public static final String NO_FORMULA = "kse.liveness.noFormula";
	public static final String DUPLICATE_DEFINITION = "kse.liveness.duplicateDefinition";
	public static final String REPLACED_DEFINITION = "kse.liveness.replacedDefinition";
	public static final String MIXED_OPERATORS = "kse.liveness.mixedOperators";
	public static final String RECURSIVE_DEFINITION = "kse.liveness.recursiveDefinition";
	public static final String UNDEFINED_CAPABILITY = "kse.liveness.undefinedCapability";
	public static final String UNUSED_CAPABILITY = "kse.liveness.unusedCapability";
	public static final String DUPLICATE_CHOICE = "kse.liveness.duplicateChoice";
	public static final String BAD_COUNT = "kse.liveness.badCount";
	public static final String AND_ROOT = "kse.liveness.andRoot";
	public static final String TOO_LARGE = "kse.liveness.tooLarge";

	/** KSE's limits, far above any behaviour (a team has five robots; the Goalie has 48 states): beyond them a formula is refused, not run out of memory. */
	public static final int MAX_COPIES = 10_000;
	public static final long MAX_STATES = 100_000;
	public static final int MAX_DEPTH = 1_000;

	@Check
	public void checkHasFormula(FormulaFile file) {
		// a line the parser could not read is no formula, but its syntax error says more
		if (file.getFormulas().isEmpty() && (file.eResource() == null || file.eResource().getErrors().isEmpty())) {
			if (file.getTitle() != null) {
				error("'" + file.getTitle() + "' names a model but no formula follows", Literals.FORMULA_FILE__TITLE, NO_FORMULA);
			} else {
				error("the file holds no formula; write one as 'name = expression'", null, NO_FORMULA);
			}
		}
	}

	@Check
	public void checkEmptyFormula(Formula formula) {
		if (formula.getExpression() == null && !hasSyntaxErrorOnItsLine(formula)) {
			error("'" + formula.getName() + "' has an empty right side", Literals.FORMULA__NAME, EMPTY_FORMULA);
		}
	}

	@Check
	public void checkEmptyGroup(Group group) {
		if (group.getExpression() == null && !hasSyntaxErrorOnItsLine(group)) {
			error("empty group '()'", null, EMPTY_GROUP);
		}
	}

	@Check
	public void checkEmptyOption(Option option) {
		if (option.getExpression() == null && !hasSyntaxErrorOnItsLine(option)) {
			error("empty option '[]'", null, EMPTY_GROUP);
		}
	}

	@Check
	public void checkReplicationCount(Replication replication) {
		List<INode> count = NodeModelUtils.findNodesForFeature(replication, Literals.REPLICATION__COUNT);
		boolean written = !count.isEmpty() && count.get(0).getSyntaxErrorMessage() == null;
		if (written && replication.getCount() < 1) {
			error("|x~|n needs n of at least 1", Literals.REPLICATION__COUNT, BAD_COUNT);
		}
		if (written && replication.getCount() > MAX_COPIES) {
			error("|x~|n makes at most " + String.format(Locale.ROOT, "%,d", MAX_COPIES) + " copies (KSE's limit)", Literals.REPLICATION__COUNT, BAD_COUNT);
		}
	}

	/**
	 * A name defined again replaces its earlier definitions, as in the original tool; each
	 * replaced one is marked, since the writer may have meant a new name.
	 */
	@Check
	public void checkDuplicateDefinitions(FormulaFile file) {
		Map<String, Formula> inForce = Formulas.capabilities(file);
		Map<String, Formula> folded = new HashMap<>();
		for (Formula formula : file.getFormulas()) {
			String name = formula.getName();
			if (name == null) {
				continue;
			}
			Formula last = inForce.get(name);
			if (last != formula) {
				warning("this definition of '" + name + "' is replaced by the one on line " + line(last), formula, Literals.FORMULA__NAME,
						REPLACED_DEFINITION);
				continue;
			}
			Formula similar = folded.putIfAbsent(name.toLowerCase(Locale.ROOT), formula);
			if (similar != null) {
				warning("'" + name + "' differs from '" + similar.getName() + "' (line " + line(similar)
						+ ") only in case; the original tool treated them as one", formula, Literals.FORMULA__NAME, DUPLICATE_DEFINITION);
			}
		}
	}

	@Check
	public void checkMixedOperators(Expression expression) {
		if (hasSyntaxErrorOnItsLine(expression)) {
			// the parser's recovery may have read an operator the writer did not mean
			return;
		}
		List<Operator> operators = expression.getOperators();
		for (int i = 1; i < operators.size(); i++) {
			if (operators.get(i) != operators.get(0)) {
				error("'" + operators.get(i).getLiteral() + "' mixed with '" + operators.get(0).getLiteral()
						+ "' at one level: add parentheses to say which binds first", expression, Literals.EXPRESSION__OPERATORS, i,
						MIXED_OPERATORS);
				return;
			}
		}
	}

	@Check
	public void checkDuplicateChoice(Expression expression) {
		if (Formulas.operator(expression) != Operator.CHOICE) {
			return;
		}
		Set<String> seen = new HashSet<>();
		for (Term term : expression.getTerms()) {
			String text = Formulas.text(term);
			if (!seen.add(text)) {
				warning("'" + text + "' is offered twice in this choice", term, null, DUPLICATE_CHOICE);
			}
		}
	}

	@Check
	public void checkReferences(FormulaFile file) {
		Map<String, Formula> capabilities = Formulas.capabilities(file);
		Map<String, String> byFoldedName = new HashMap<>();
		capabilities.keySet().forEach(name -> byFoldedName.putIfAbsent(name.toLowerCase(Locale.ROOT), name));
		for (Reference reference : Formulas.references(file)) {
			String name = reference.getName();
			if (name == null || capabilities.containsKey(name)) {
				continue;
			}
			String similar = byFoldedName.get(name.toLowerCase(Locale.ROOT));
			if (similar != null) {
				error("'" + name + "' is not defined; did you mean the capability '" + similar + "'?", reference,
						Literals.REFERENCE__NAME, UNDEFINED_CAPABILITY);
			} else if (Character.isLowerCase(name.charAt(0))) {
				warning("'" + name + "' is not defined as a capability, so it becomes an activity (a BASIC state)", reference,
						Literals.REFERENCE__NAME, UNDEFINED_CAPABILITY);
			}
		}
	}

	/**
	 * The original made the root of a lone |x~|n the AND state itself, and so do we; but the
	 * statechart rules want an OR root, so say so while the formula can still be changed.
	 */
	@Check
	public void checkAndRoot(FormulaFile file) {
		Formula root = Formulas.rootDefinition(file);
		Replication replication = root == null || root.getName() == null ? null : Formulas.loneReplication(root.getExpression());
		if (replication != null && replication.getCount() >= 1) {
			String name = root.getName();
			String copies = name + "Copies";
			warning("'" + name + "' is only " + Formulas.text(replication) + ", so the root becomes its AND state, as in the original tool, "
					+ "and statechart validation will refuse it (the root must be an OR state); to keep an OR root, write '" + name + " = "
					+ copies + "' and '" + copies + " = " + Formulas.text(replication) + "'", replication, null, AND_ROOT);
		}
	}

	@Check(CheckType.NORMAL)
	public void checkUnusedCapabilities(FormulaFile file) {
		Formula root = Formulas.rootDefinition(file);
		if (root == null || root.getName() == null) {
			return;
		}
		Map<String, Formula> capabilities = Formulas.capabilities(file);
		Set<String> reached = new HashSet<>();
		Deque<Formula> work = new ArrayDeque<>();
		reached.add(root.getName());
		work.push(root);
		while (!work.isEmpty()) {
			for (Reference reference : Formulas.references(work.pop().getExpression())) {
				Formula used = capabilities.get(reference.getName());
				if (used != null && reached.add(used.getName())) {
					work.push(used);
				}
			}
		}
		for (Formula formula : capabilities.values()) {
			if (!reached.contains(formula.getName())) {
				warning("the capability '" + formula.getName() + "' is never used by '" + root.getName() + "'", formula,
						Literals.FORMULA__NAME, UNUSED_CAPABILITY);
			}
		}
	}

	/** How many states a capability becomes, and how deeply they nest, both capped so that nothing overflows. */
	private record Extent(long states, int depth) {
		static final Extent ONE = new Extent(1, 1);

		Extent plus(Extent other) {
			return new Extent(Math.min(states + other.states, Long.MAX_VALUE / 4), Math.max(depth, other.depth));
		}

		Extent wrapped(int extraStates, int extraDepth) {
			return new Extent(Math.min(states + extraStates, Long.MAX_VALUE / 4), Math.min(depth + extraDepth, Integer.MAX_VALUE / 4));
		}

		Extent times(int copies) {
			return new Extent(states > Long.MAX_VALUE / 4 / Math.max(copies, 1) ? Long.MAX_VALUE / 4 : states * copies, depth);
		}
	}

	/**
	 * A formula small to write can stand for a statechart too large to build (|x~|10000 of a
	 * capability that is itself |y~|10000, or ten thousand definitions each nesting the next):
	 * refused at the first capability that passes a limit, instead of running out of memory.
	 * Capabilities are measured in dependency order without recursion across definitions, so a
	 * long chain cannot overflow the stack; the count is an estimate of the transformation's.
	 */
	@Check
	public void checkSize(FormulaFile file) {
		Map<String, Formula> capabilities = Formulas.capabilities(file);
		Map<String, Extent> measured = new HashMap<>();
		for (String start : capabilities.keySet()) {
			Deque<String> pending = new ArrayDeque<>();
			Set<String> waiting = new HashSet<>();
			pending.push(start);
			waiting.add(start);
			while (!pending.isEmpty()) {
				String name = pending.peek();
				if (measured.containsKey(name)) {
					waiting.remove(pending.pop());
					continue;
				}
				boolean ready = true;
				for (Reference reference : Formulas.references(capabilities.get(name).getExpression())) {
					String used = reference.getName();
					if (capabilities.containsKey(used) && !measured.containsKey(used)) {
						if (!waiting.add(used)) {
							return; // a cycle: checkRecursion reports it, and it has no size
						}
						pending.push(used);
						ready = false;
					}
				}
				if (!ready) {
					continue;
				}
				waiting.remove(pending.pop());
				Formula formula = capabilities.get(name);
				Extent extent = extent(formula.getExpression(), capabilities, measured).wrapped(2, 1);
				measured.put(name, extent);
				String problem = extent.states() > MAX_STATES ? "becomes more than " + String.format(Locale.ROOT, "%,d", MAX_STATES) + " states"
						: extent.depth() > MAX_DEPTH ? "nests states more than " + String.format(Locale.ROOT, "%,d", MAX_DEPTH) + " levels deep" : null;
				if (problem != null) {
					error("'" + name + "' " + problem + " (KSE's limit): split the behaviour, or use fewer copies", formula, Literals.FORMULA__NAME, TOO_LARGE);
					return;
				}
			}
		}
	}

	private static Extent extent(Expression expression, Map<String, Formula> capabilities, Map<String, Extent> measured) {
		if (expression == null) {
			return Extent.ONE;
		}
		boolean parallel = Formulas.operator(expression) == Operator.PARALLEL;
		Extent sum = new Extent(0, 0);
		for (Term term : expression.getTerms()) {
			Extent part = extent(term, capabilities, measured);
			sum = sum.plus(parallel ? part.wrapped(2, 1) : part);
		}
		return parallel ? sum.wrapped(1, 1) : sum.wrapped(2, 0);
	}

	private static Extent extent(Term term, Map<String, Formula> capabilities, Map<String, Extent> measured) {
		return switch (term) {
			case Reference reference -> capabilities.containsKey(reference.getName())
					? measured.getOrDefault(reference.getName(), Extent.ONE) // a cycle, reported by checkRecursion
					: Extent.ONE;
			case Group group -> extent(group.getExpression(), capabilities, measured).wrapped(1, 1);
			case Option option -> extent(option.getExpression(), capabilities, measured).wrapped(3, 1);
			case Replication replication -> extent(replication.getOperand(), capabilities, measured).wrapped(2, 1)
					.times(Math.max(replication.getCount(), 1)).wrapped(1, 1);
			case org.kse.liveness.liveness.Repetition repetition -> extent(repetition.getOperand(), capabilities, measured).wrapped(3, 1);
			default -> Extent.ONE;
		};
	}

	/**
	 * A capability that needs itself has no finite statechart. Cycles are found with an
	 * explicit stack, so that a long chain of definitions cannot overflow the Java stack.
	 */
	@Check
	public void checkRecursion(FormulaFile file) {
		Map<String, Formula> capabilities = Formulas.capabilities(file);
		Map<String, List<Reference>> uses = new LinkedHashMap<>();
		for (Formula formula : capabilities.values()) {
			List<Reference> used = new ArrayList<>();
			for (Reference reference : Formulas.references(formula.getExpression())) {
				if (capabilities.containsKey(reference.getName())) {
					used.add(reference);
				}
			}
			uses.put(formula.getName(), used);
		}
		Map<String, Integer> state = new HashMap<>(); // absent: new, 1: on the path, 2: done
		Set<Reference> reported = new HashSet<>();
		for (String start : uses.keySet()) {
			if (state.containsKey(start)) {
				continue;
			}
			Deque<String> path = new ArrayDeque<>();
			Deque<Integer> nextEdge = new ArrayDeque<>();
			path.push(start);
			nextEdge.push(0);
			state.put(start, 1);
			while (!path.isEmpty()) {
				String current = path.peek();
				int edge = nextEdge.pop();
				List<Reference> edges = uses.get(current);
				if (edge == edges.size()) {
					state.put(current, 2);
					path.pop();
					continue;
				}
				nextEdge.push(edge + 1);
				Reference reference = edges.get(edge);
				String target = reference.getName();
				Integer targetState = state.get(target);
				if (targetState == null) {
					state.put(target, 1);
					path.push(target);
					nextEdge.push(0);
				} else if (targetState == 1 && reported.add(reference)) {
					error("recursive definition: " + cycle(path, target), reference, Literals.REFERENCE__NAME, RECURSIVE_DEFINITION);
				}
			}
		}
	}

	private static String cycle(Deque<String> path, String target) {
		List<String> names = new ArrayList<>();
		for (var it = path.descendingIterator(); it.hasNext();) {
			names.add(it.next());
		}
		List<String> loop = names.subList(names.indexOf(target), names.size());
		return String.join(" \u2192 ", loop) + " \u2192 " + target;
	}

	private static int line(EObject element) {
		INode node = NodeModelUtils.findActualNodeFor(element);
		return node == null ? 0 : node.getStartLine();
	}

	/** Whether the parser stumbled on the element's line, so that what the element lacks is already explained. */
	private static boolean hasSyntaxErrorOnItsLine(EObject element) {
		int line = line(element);
		return element.eResource() != null && element.eResource().getErrors().stream().anyMatch(error -> error.getLine() == line);
	}
}
