package org.kse.generator.monas

import java.util.LinkedHashMap
import java.util.List
import org.eclipse.emf.ecore.EObject
import org.kse.expression.transitionExpression.Binary
import org.kse.expression.transitionExpression.Call
import org.kse.expression.transitionExpression.Condition
import org.kse.expression.transitionExpression.Constant
import org.kse.expression.transitionExpression.Literal
import org.kse.expression.transitionExpression.MessageAccess
import org.kse.expression.transitionExpression.MemberCall
import org.kse.expression.transitionExpression.Not
import org.kse.expression.transitionExpression.NumberLiteral
import org.kse.expression.transitionExpression.StringLiteral

/**
 * A transition's condition as C++. Every message the condition reads becomes one local
 * variable read from the blackboard; every atom that touches a message is guarded by a
 * null check, so a condition on a missing message is false (reference §6), and
 * {@code msg == NULL} tests that the message is absent.
 */
class ConditionCode {

	/** One blackboard read: {@code auto name = _blk->Read<kind><type>(topic);} */
	static class MessageRead {
		public val String variable
		public val String topic
		public val String kind
		public val String type

		new(String variable, String topic, String kind, String type) {
			this.variable = variable
			this.topic = topic
			this.kind = kind
			this.type = type
		}
	}

	val reads = new LinkedHashMap<String, MessageRead>

	/** The C++ boolean expression of a condition; {@link #reads} then lists what it reads. */
	def String translate(Condition condition) {
		condition.cpp
	}

	def List<MessageRead> reads() {
		reads.values.toList
	}

	/** Topics the condition subscribes to, in order of first use. */
	def List<String> topics() {
		reads.values.map[topic].toSet.toList
	}

	def private dispatch String cpp(Binary binary) {
		switch binary.operator {
			case '||', case '&&': '''(«binary.left.cpp» «binary.operator» «binary.right.cpp»)'''
			default: comparison(binary)
		}
	}

	def private dispatch String cpp(Not not) '''!«not.operand.cpp»'''

	def private dispatch String cpp(Call call) {
		if (call.function == 'TimeoutCheck') {
			val topic = (call.arguments.head as Constant)?.name ?: ''
			return '''_blk->TimeoutExpired(«CppNames.string(topic)»)'''
		}
		guarded(call, call.value)
	}

	def private dispatch String cpp(MessageAccess access) {
		val read = access.read
		if (access.members.empty) '''(«read.variable» != nullptr)''' else guarded(access, access.value)
	}

	def private dispatch String cpp(Condition other) '''(«other.value»)'''

	def private String comparison(Binary binary) {
		val nullTest = binary.nullTest
		if (nullTest !== null) {
			return '''(«nullTest.read.variable» «binary.operator» nullptr)'''
		}
		guarded(binary, '''«binary.left.value» «binary.operator» «binary.right.value»''')
	}

	/** {@code m == NULL} or {@code NULL != m}: the access, when it names a whole message. */
	def private MessageAccess nullTest(Binary binary) {
		if (binary.operator != '==' && binary.operator != '!=') {
			return null
		}
		val left = binary.left
		val right = binary.right
		if (left instanceof MessageAccess && (left as MessageAccess).members.empty && right.isNull) {
			return left as MessageAccess
		}
		if (right instanceof MessageAccess && (right as MessageAccess).members.empty && left.isNull) {
			return right as MessageAccess
		}
		return null
	}

	def private boolean isNull(EObject element) {
		element instanceof Constant && (element as Constant).name == 'NULL'
	}

	def private String guarded(EObject element, CharSequence value) {
		val accesses = newArrayList
		if (element instanceof MessageAccess) {
			accesses += element
		}
		element.eAllContents.filter(MessageAccess).forEach[accesses += it]
		val checks = accesses.map[read.variable].toSet.map['''«it» != nullptr''']
		if (checks.empty) '''(«value»)''' else '''(«checks.join(' && ')» && «value»)'''
	}

	def private dispatch String value(MessageAccess access) {
		val read = access.read
		if (access.members.empty) {
			return '''(*«read.variable»)'''
		}
		'''«read.variable»->«access.members.map[call].join('.')»'''
	}

	def private dispatch String value(Call call) '''«call.function»(«call.arguments.map[value].join(', ')»)'''

	def private dispatch String value(Binary binary) '''(«binary.left.value» «binary.operator» «binary.right.value»)'''

	def private dispatch String value(Not not) '''!«not.operand.value»'''

	def private dispatch String value(NumberLiteral number) {
		number.value
	}

	def private dispatch String value(StringLiteral string) {
		CppNames.string(string.value)
	}

	def private dispatch String value(Constant constant) {
		if (constant.name == 'NULL') 'nullptr' else constant.name
	}

	def private dispatch String value(Condition other) {
		''
	}

	/** A literal as C++, for setter values and member indexes. */
	def static String literal(Literal literal) {
		switch literal {
			NumberLiteral: literal.value
			StringLiteral: CppNames.string(literal.value)
			Constant: if (literal.name == 'NULL') 'nullptr' else literal.name
			default: ''
		}
	}

	/** protoc names C++ accessors after the field in lower case (myPosition → myposition()). */
	def private String call(MemberCall member) '''«member.name.toLowerCase»(«IF member.argument !== null»«member.argument.value»«ENDIF»)'''

	def private MessageRead read(MessageAccess access) {
		val key = access.topic + '.' + access.kind + '.' + access.message
		reads.computeIfAbsent(key)[
			new MessageRead('msg' + reads.size, access.topic, access.kind, CppNames.identifier(access.message))
		]
	}
}
