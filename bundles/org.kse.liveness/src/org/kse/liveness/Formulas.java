package org.kse.liveness;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.kse.liveness.liveness.Expression;
import org.kse.liveness.liveness.Formula;
import org.kse.liveness.liveness.FormulaFile;
import org.kse.liveness.liveness.Group;
import org.kse.liveness.liveness.Operator;
import org.kse.liveness.liveness.Option;
import org.kse.liveness.liveness.Reference;
import org.kse.liveness.liveness.Repetition;
import org.kse.liveness.liveness.Replication;
import org.kse.liveness.liveness.Term;

/**
 * Queries over a parsed formula file shared by the validator, the transformation
 * and the IDE services.
 */
public final class Formulas {

	private Formulas() {
	}

	/**
	 * The definition in force for each name, in the order the names first appear: a name
	 * defined again is replaced by its last definition, as in the original tool.
	 */
	public static Map<String, Formula> capabilities(FormulaFile file) {
		Map<String, Formula> result = new LinkedHashMap<>();
		for (Formula formula : file.getFormulas()) {
			if (formula.getName() != null) {
				result.put(formula.getName(), formula);
			}
		}
		return result;
	}

	/** The root formula: the first one in the file, which names the root; null for a file without formulas. */
	public static Formula root(FormulaFile file) {
		return file.getFormulas().isEmpty() ? null : file.getFormulas().get(0);
	}

	/** What the root stands for: the last definition of the root's name; null for a file without formulas. */
	public static Formula rootDefinition(FormulaFile file) {
		Formula root = root(file);
		if (root == null || root.getName() == null) {
			return root;
		}
		return capabilities(file).get(root.getName());
	}

	/**
	 * The |x~|n that an expression consists of, looking through groups without a suffix
	 * (they are laid out in place), or null when the expression is anything else.
	 */
	public static Replication loneReplication(Expression expression) {
		Expression level = expression;
		while (level != null && level.getTerms().size() == 1) {
			Term term = level.getTerms().get(0);
			if (term instanceof Replication replication) {
				return replication;
			}
			level = term instanceof Group group ? group.getExpression() : null;
		}
		return null;
	}

	/** Every name referenced anywhere inside the given element, in document order. */
	public static List<Reference> references(EObject element) {
		List<Reference> result = new ArrayList<>();
		if (element == null) {
			return result;
		}
		for (var it = EcoreUtil.<EObject>getAllContents(element, false); it.hasNext();) {
			if (it.next() instanceof Reference reference) {
				result.add(reference);
			}
		}
		return result;
	}

	/** The operator used at this level, or null for a single term. Assumes a validated expression. */
	public static Operator operator(Expression expression) {
		return expression.getOperators().isEmpty() ? null : expression.getOperators().get(0);
	}

	/** The formula text of a term or expression without blanks, as the original tool kept it. */
	public static String text(EObject element) {
		StringBuilder out = new StringBuilder();
		print(element, out);
		return out.toString();
	}

	/**
	 * The name of the state that a term becomes: its text with every operator spelled
	 * out (the original's naming scheme, so that models stay comparable).
	 */
	public static String stateName(EObject element) {
		StringBuilder out = new StringBuilder();
		spell(element, out);
		return out.toString();
	}

	private static void print(EObject element, StringBuilder out) {
		if (element instanceof Expression expression) {
			for (int i = 0; i < expression.getTerms().size(); i++) {
				if (i > 0 && i - 1 < expression.getOperators().size()) {
					out.append(expression.getOperators().get(i - 1).getLiteral());
				}
				print(expression.getTerms().get(i), out);
			}
		} else if (element instanceof Reference reference) {
			out.append(reference.getName());
		} else if (element instanceof Group group) {
			out.append('(');
			print(group.getExpression(), out);
			out.append(')');
		} else if (element instanceof Option option) {
			out.append('[');
			print(option.getExpression(), out);
			out.append(']');
		} else if (element instanceof Repetition repetition) {
			print(repetition.getOperand(), out);
			out.append(repetition.getKind().getLiteral());
		} else if (element instanceof Replication replication) {
			out.append('|');
			print(replication.getOperand(), out);
			out.append("~|").append(replication.getCount());
		}
	}

	private static void spell(EObject element, StringBuilder out) {
		if (element instanceof Expression expression) {
			for (int i = 0; i < expression.getTerms().size(); i++) {
				if (i > 0 && i - 1 < expression.getOperators().size()) {
					out.append(switch (expression.getOperators().get(i - 1)) {
						case SEQUENCE -> "_sequence_";
						case CHOICE -> "_or_";
						case PARALLEL -> "_parallel_";
					});
				}
				spell(expression.getTerms().get(i), out);
			}
		} else if (element instanceof Reference reference) {
			out.append(reference.getName());
		} else if (element instanceof Group group) {
			out.append("_open_group_");
			spell(group.getExpression(), out);
			out.append("_close_group_");
		} else if (element instanceof Option option) {
			out.append("_open_option_");
			spell(option.getExpression(), out);
			out.append("_close_option_");
		} else if (element instanceof Repetition repetition) {
			spell(repetition.getOperand(), out);
			out.append(switch (repetition.getKind()) {
				case ZERO_OR_MORE -> "_zero_or_more_times_";
				case ONE_OR_MORE -> "_one_or_more_times_";
				case FOREVER -> "_forever_";
			});
		} else if (element instanceof Replication replication) {
			// |x~|n spelled character by character, as the original did
			out.append("_or_");
			spell(replication.getOperand(), out);
			out.append("_forever__or_").append(replication.getCount());
		}
	}

	/** True for a term that is a plain name (activity or capability). */
	public static boolean isName(Term term) {
		return term instanceof Reference;
	}
}
