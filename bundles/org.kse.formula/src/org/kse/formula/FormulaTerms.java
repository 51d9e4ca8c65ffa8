package org.kse.formula;

import java.util.List;

/**
 * The terms of a liveness formula as the inverse transformation builds them: a small tree of
 * its own rather than the Xtext model, because a recovered formula is made, not parsed, and is
 * printed and spelled (the transformation's state names) before it is ever read back.
 */
final class FormulaTerms {

	static final String OPEN_GROUP = "_open_group_";
	static final String CLOSE_GROUP = "_close_group_";

	private FormulaTerms() {
	}

	sealed interface Term permits Ref, Grp, Opt, Rep, Repl {
	}

	/** An activity or a capability, by name. */
	record Ref(String name) implements Term {
	}

	/** (e) */
	record Grp(Expr expression) implements Term {
	}

	/** [e] */
	record Opt(Expr expression) implements Term {
	}

	/** x*, x+ or x~ ({@code kind} is the suffix character). */
	record Rep(Term operand, char kind) implements Term {
	}

	/** |x~|n */
	record Repl(Term operand, int count) implements Term {
	}

	/** Terms joined by one operator ({@code "."}, {@code "|"} or {@code "||"}; null for a single term). */
	record Expr(List<Term> terms, String operator) {
		static Expr of(Term term) {
			return new Expr(List.of(term), null);
		}
	}

	/**
	 * What the transformation built inside a composite state: either an expression laid out by
	 * its operator (a sequence, a choice, a parallel) or the fixed shape of one term ([x], x*, x+,
	 * x~, |x~|n) that the state itself takes.
	 */
	record Shape(Expr expression, Term layout) {
		static Shape of(Expr expression) {
			return new Shape(expression, null);
		}

		static Shape of(Term layout) {
			return new Shape(null, layout);
		}

		Expr asExpression() {
			return expression != null ? expression : Expr.of(layout);
		}

		String text() {
			return expression != null ? print(expression) : print(layout);
		}
	}

	/** Formula text as a person writes it: '.' tight, '|' and '||' spaced. */
	static String print(Expr expression) {
		StringBuilder out = new StringBuilder();
		print(expression, out);
		return out.toString();
	}

	static String print(Term term) {
		StringBuilder out = new StringBuilder();
		print(term, out);
		return out.toString();
	}

	private static void print(Expr expression, StringBuilder out) {
		String separator = expression.operator() == null || expression.operator().equals(".") ? "." : " " + expression.operator() + " ";
		for (int i = 0; i < expression.terms().size(); i++) {
			if (i > 0) {
				out.append(separator);
			}
			print(expression.terms().get(i), out);
		}
	}

	private static void print(Term term, StringBuilder out) {
		switch (term) {
			case Ref ref -> out.append(ref.name());
			case Grp group -> {
				out.append('(');
				print(group.expression(), out);
				out.append(')');
			}
			case Opt option -> {
				out.append('[');
				print(option.expression(), out);
				out.append(']');
			}
			case Rep repetition -> {
				print(repetition.operand(), out);
				out.append(repetition.kind());
			}
			case Repl replication -> {
				out.append('|');
				print(replication.operand(), out);
				out.append("~|").append(replication.count());
			}
		}
	}

	/** The name the transformation gives the state of this expression (org.kse.liveness.Formulas.stateName). */
	static String spell(Expr expression) {
		StringBuilder out = new StringBuilder();
		spell(expression, out);
		return out.toString();
	}

	static String spell(Term term) {
		StringBuilder out = new StringBuilder();
		spell(term, out);
		return out.toString();
	}

	private static void spell(Expr expression, StringBuilder out) {
		String operator = expression.operator() == null ? "" : switch (expression.operator()) {
			case "." -> "_sequence_";
			case "|" -> "_or_";
			default -> "_parallel_";
		};
		for (int i = 0; i < expression.terms().size(); i++) {
			if (i > 0) {
				out.append(operator);
			}
			spell(expression.terms().get(i), out);
		}
	}

	private static void spell(Term term, StringBuilder out) {
		switch (term) {
			case Ref ref -> out.append(ref.name());
			case Grp group -> {
				out.append(OPEN_GROUP);
				spell(group.expression(), out);
				out.append(CLOSE_GROUP);
			}
			case Opt option -> {
				out.append("_open_option_");
				spell(option.expression(), out);
				out.append("_close_option_");
			}
			case Rep repetition -> {
				spell(repetition.operand(), out);
				out.append(switch (repetition.kind()) {
					case '*' -> "_zero_or_more_times_";
					case '+' -> "_one_or_more_times_";
					default -> "_forever_";
				});
			}
			case Repl replication -> {
				out.append("_or_");
				spell(replication.operand(), out);
				out.append("_forever__or_").append(replication.count());
			}
		}
	}
}
