package org.kse.generator.monas

import java.util.LinkedHashMap
import java.util.LinkedHashSet
import java.util.List
import java.util.Set
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
 * variable read from the blackboard. A term that reads a message is false while that message
 * is missing, negated or not: its null checks stand outside any {@code !}, so
 * {@code !m.f()} is {@code (m != nullptr && !m->f())}, as the original generator guarded it.
 * {@code m == NULL} and {@code m != NULL} (and a bare {@code m}) test whether the message is
 * there, and keep that meaning under {@code !}.
 * <p>
 * {@code TimeoutCheck(topic)} reads the topic's {@code TimeoutMsg}; a guard that has one
 * processes the blackboard's messages after its reads and before it decides (see
 * {@link #checksTimeouts()}).
 */
class ConditionCode {

	/**
	 * One blackboard read: a member {@code kse::messaging::Reader<type> name_} bound to the topic in
	 * {@code UserInit()}, read as {@code auto name = name_.Read<kind>();} in {@code Eval()}.
	 */
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

	static val TIMEOUT_CHECK = 'TimeoutCheck'

	val reads = new LinkedHashMap<String, MessageRead>
	var messageCount = 0
	var timeoutCount = 0

	/** The C++ boolean expression of a condition; {@link #reads} then lists what it reads. */
	def String translate(Condition condition) {
		condition.guarded
	}

	/** Every read, in order of first use. */
	def List<MessageRead> reads() {
		reads.values.toList
	}

	/** Topics the condition subscribes to, in order of first use. */
	def List<String> topics() {
		reads.values.map[topic].toSet.toList
	}

	/** Whether the condition uses TimeoutCheck, so that its guard must process messages before deciding. */
	def boolean checksTimeouts() {
		reads.keySet.exists[startsWith(TIMEOUT_CHECK + ' ')]
	}

	// ---------------------------------------------------------------- the term with its null checks

	def private dispatch String guarded(Binary binary) {
		switch binary.operator {
			case '||', case '&&': '''(«binary.left.guarded» «binary.operator» «binary.right.guarded»)'''
			default: {
				val nullTest = binary.nullTest
				if (nullTest !== null) '''(«nullTest.read.variable» «binary.operator» nullptr)''' else guard(binary, binary.comparison)
			}
		}
	}

	/** The operand's null checks stay outside the negation: a negated read of a missing message is false too. */
	def private dispatch String guarded(Not not) {
		val checks = not.operand.required
		val negated = '''!«not.operand.raw»'''
		if (checks.empty) negated else '''(«checks.map['''«it» != nullptr'''].join(' && ')» && «negated»)'''
	}

	def private dispatch String guarded(Call call) {
		if (call.function == TIMEOUT_CHECK) call.value else guard(call, call.value)
	}

	def private dispatch String guarded(MessageAccess access) {
		if (access.members.empty) access.presence else guard(access, access.value)
	}

	def private dispatch String guarded(Condition other) '''(«other.value»)'''

	// ---------------------------------------------------------------- the term alone, its checks made by a negation around it

	def private dispatch String raw(Binary binary) {
		switch binary.operator {
			case '||', case '&&': '''(«binary.left.raw» «binary.operator» «binary.right.raw»)'''
			default: {
				val nullTest = binary.nullTest
				if (nullTest !== null) '''(«nullTest.read.variable» «binary.operator» nullptr)''' else '''(«binary.comparison»)'''
			}
		}
	}

	def private dispatch String raw(Not not) '''!«not.operand.raw»'''

	def private dispatch String raw(Call call) {
		call.value
	}

	def private dispatch String raw(MessageAccess access) {
		if (access.members.empty) access.presence else access.value
	}

	def private dispatch String raw(Condition other) '''(«other.value»)'''

	// ---------------------------------------------------------------- what a term dereferences

	/** Variables of the messages a term reads from; a test of a message's presence reads nothing from it. */
	def private dispatch Set<String> required(Binary binary) {
		switch binary.operator {
			case '||', case '&&': {
				val all = new LinkedHashSet(binary.left.required)
				all += binary.right.required
				all
			}
			default: if (binary.nullTest !== null) emptySet else binary.accessed
		}
	}

	def private dispatch Set<String> required(Not not) {
		not.operand.required
	}

	def private dispatch Set<String> required(Call call) {
		if (call.function == TIMEOUT_CHECK) emptySet else call.accessed
	}

	def private dispatch Set<String> required(MessageAccess access) {
		if (access.members.empty) emptySet else access.accessed
	}

	def private dispatch Set<String> required(Condition other) {
		emptySet
	}

	/** The element's own message accesses and those inside it, as read variables in document order. */
	def private Set<String> accessed(EObject element) {
		val accesses = newArrayList
		if (element instanceof MessageAccess) {
			accesses += element
		}
		element.eAllContents.filter(MessageAccess).forEach[accesses += it]
		new LinkedHashSet(accesses.map[read.variable])
	}

	def private String guard(EObject element, CharSequence value) {
		val checks = element.accessed
		if (checks.empty) '''(«value»)''' else '''(«checks.map['''«it» != nullptr'''].join(' && ')» && «value»)'''
	}

	def private String presence(MessageAccess access) '''(«access.read.variable» != nullptr)'''

	def private String comparison(Binary binary) '''«binary.left.value» «binary.operator» «binary.right.value»'''

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

	// ---------------------------------------------------------------- values

	def private dispatch String value(MessageAccess access) {
		val read = access.read
		if (access.members.empty) {
			return '''(*«read.variable»)'''
		}
		'''«read.variable»->«access.members.map[call].join('.')»'''
	}

	def private dispatch String value(Call call) {
		if (call.function == TIMEOUT_CHECK) {
			val topic = (call.arguments.head as Constant)?.name ?: ''
			return '''statechart_engine::TimeoutCheck(*_blk, «timeout(topic).variable»)'''
		}
		'''«call.function»(«call.arguments.map[value].join(', ')»)'''
	}

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
			new MessageRead('msg' + messageCount++, access.topic, access.kind, CppNames.identifier(access.message))
		]
	}

	/** The wake-up time of a topic's timer, published by its TimeoutAction as a State message. */
	def private MessageRead timeout(String topic) {
		reads.computeIfAbsent(TIMEOUT_CHECK + ' ' + topic)[
			new MessageRead('timeout' + timeoutCount++, topic, 'State', 'TimeoutMsg')
		]
	}
}
