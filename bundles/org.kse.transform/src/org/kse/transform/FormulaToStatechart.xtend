package org.kse.transform

import java.util.Map
import org.kse.liveness.Formulas
import org.kse.liveness.liveness.Expression
import org.kse.liveness.liveness.Formula
import org.kse.liveness.liveness.FormulaFile
import org.kse.liveness.liveness.Group
import org.kse.liveness.liveness.Option
import org.kse.liveness.liveness.Reference
import org.kse.liveness.liveness.Repetition
import org.kse.liveness.liveness.RepetitionKind
import org.kse.liveness.liveness.Replication
import org.kse.liveness.liveness.Term
import org.kse.model.NodeKind
import org.kse.model.statechart.Model
import org.kse.model.statechart.Node
import org.kse.model.statechart.StatechartFactory

/**
 * Liveness formulas to statechart, by the rules of the original KSE (docs/original-kse.md §3):
 * the same labels, node kinds, names, transitions and even the same order of
 * elements in the saved file. Where the original crashed (a lone name on the right
 * side), the expression becomes a sequence of one term. A name defined twice means its
 * last definition. A root that is a lone |x~|n becomes that AND state itself, as in the
 * original, although the statechart rules want an OR root (the formula validator warns).
 *
 * Expects a formula file without validation errors (no recursion, no mixed operators).
 */
class FormulaToStatechart {

	extension StatechartFactory factory = StatechartFactory.eINSTANCE

	Model model
	Map<String, Formula> capabilities

	def Model transform(FormulaFile file, String modelName) {
		capabilities = Formulas.capabilities(file)
		val rootFormula = Formulas.rootDefinition(file)
		model = createModel => [name = modelName ?: file.title ?: rootFormula.name]
		val root = createNode => [
			label = "0"
			name = rootFormula.name
			type = NodeKind.OR.name
		]
		model.nodes += root
		expand(rootFormula.expression, root)
		return model
	}

	/** An expression placed into a composite state: its layout, then each term's content. */
	def private void expand(Expression expression, Node father) {
		if (expression.terms.size == 1) {
			val term = expression.terms.head
			switch term {
				Reference: sequence(expression, father)
				Group: expand(term.expression, father)
				default: layout(term, father)
			}
			return
		}
		switch Formulas.operator(expression) {
			case SEQUENCE: sequence(expression, father)
			case CHOICE: choice(expression, father)
			case PARALLEL: parallel(expression, father)
		}
	}

	def private sequence(Expression expression, Node father) {
		father.type = NodeKind.OR.name
		var previous = father.child(1, NodeKind.START)
		val termNodes = newArrayList
		for (term : expression.terms) {
			val node = father.termChild(termNodes.size + 2, term)
			termNodes += node
			previous.connect(node)
			previous = node
		}
		previous.connect(father.child(expression.terms.size + 2, NodeKind.END))
		expression.terms.forEach[term, i|content(term, termNodes.get(i))]
	}

	def private choice(Expression expression, Node father) {
		father.type = NodeKind.OR.name
		val start = father.child(1, NodeKind.START)
		val condition = father.child(2, NodeKind.CONDITION)
		start.connect(condition)
		val termNodes = newArrayList
		for (term : expression.terms) {
			val node = father.termChild(termNodes.size + 3, term)
			termNodes += node
			condition.connect(node)
		}
		val end = father.child(expression.terms.size + 3, NodeKind.END)
		termNodes.reverseView.forEach[connect(end)]
		expression.terms.forEach[term, i|content(term, termNodes.get(i))]
	}

	def private parallel(Expression expression, Node father) {
		father.type = NodeKind.OR.name
		val start = father.child(1, NodeKind.START)
		val and = father.newChild(2) => [
			name = Formulas.stateName(expression)
			type = NodeKind.AND.name
		]
		start.connect(and)
		and.connect(father.child(3, NodeKind.END))
		val termNodes = newArrayList
		for (term : expression.terms) {
			val region = and.newChild(termNodes.size + 1) => [
				name = label
				type = NodeKind.OR.name
			]
			val regionStart = region.child(1, NodeKind.START)
			val node = region.termChild(2, term)
			val regionEnd = region.child(3, NodeKind.END)
			regionStart.connect(node)
			node.connect(regionEnd)
			termNodes += node
		}
		expression.terms.forEach[term, i|content(term, termNodes.get(i))]
	}

	/** What a term's own state holds. */
	def private void content(Term term, Node node) {
		switch term {
			Reference: {
				val capability = capabilities.get(term.name)
				if (capability === null) {
					node.type = NodeKind.BASIC.name
				} else {
					node.type = NodeKind.OR.name
					expand(capability.expression, node)
				}
			}
			Group: expand(term.expression, node)
			default: layout(term, node)
		}
	}

	/** The fixed shapes of [x], x*, x+, x~ and |x~|n, built inside node Q. */
	def private void layout(Term term, Node q) {
		switch term {
			Option: {
				q.type = NodeKind.OR.name
				val start = q.child(1, NodeKind.START)
				val condition = q.child(2, NodeKind.CONDITION)
				val inner = q.newChild(3) => [name = Formulas.stateName(term.expression)]
				inner(term.expression, inner)
				val end = q.child(4, NodeKind.END)
				start.connect(condition)
				condition.connect(inner)
				condition.connect(end)
				inner.connect(end)
			}
			Repetition case term.kind == RepetitionKind.ZERO_OR_MORE: {
				q.type = NodeKind.OR.name
				val start = q.child(1, NodeKind.START)
				val condition = q.child(2, NodeKind.CONDITION)
				val inner = q.termChild(3, term.operand)
				content(term.operand, inner)
				val end = q.child(4, NodeKind.END)
				start.connect(condition)
				condition.connect(inner)
				inner.connect(inner)
				condition.connect(end)
				inner.connect(end)
			}
			Repetition case term.kind == RepetitionKind.ONE_OR_MORE: {
				q.type = NodeKind.OR.name
				val start = q.child(1, NodeKind.START)
				val inner = q.termChild(2, term.operand)
				content(term.operand, inner)
				val end = q.child(3, NodeKind.END)
				start.connect(inner)
				inner.connect(inner)
				inner.connect(end)
			}
			Repetition: {
				q.type = NodeKind.OR.name
				val start = q.child(1, NodeKind.START)
				val inner = q.termChild(2, term.operand)
				content(term.operand, inner)
				start.connect(inner)
				inner.connect(inner)
			}
			Replication: {
				q.type = NodeKind.AND.name
				for (k : 1 .. term.count) {
					val region = q.newChild(k) => [
						name = label
						type = NodeKind.OR.name
					]
					val start = region.child(1, NodeKind.START)
					val inner = region.termChild(2, term.operand)
					content(term.operand, inner)
					val end = region.child(3, NodeKind.END)
					start.connect(inner)
					inner.connect(end)
				}
			}
		}
	}

	/** The inside of [x]: a lone term is the inner state itself, several terms are laid out in it. */
	def private inner(Expression expression, Node node) {
		if (expression.terms.size == 1) {
			content(expression.terms.head, node)
		} else {
			node.type = NodeKind.OR.name
			expand(expression, node)
		}
	}

	def private Node newChild(Node father, int index) {
		val node = createNode => [label = father.label + "." + index]
		father.children += node
		return node
	}

	/** An auxiliary state (START, END, CONDITION), named by its label. */
	def private Node child(Node father, int index, NodeKind kind) {
		father.newChild(index) => [
			name = label
			type = kind.name
		]
	}

	def private Node termChild(Node father, int index, Term term) {
		father.newChild(index) => [name = Formulas.stateName(term)]
	}

	def private connect(Node source, Node target) {
		model.transitions += createTransition => [
			it.source = source
			it.target = target
			name = source.name + "TO" + target.name
		]
	}
}
