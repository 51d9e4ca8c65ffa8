package org.kse.scxml;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.OptionalInt;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.EObject;
import org.kse.expression.transitionExpression.Action;
import org.kse.expression.transitionExpression.Binary;
import org.kse.expression.transitionExpression.Call;
import org.kse.expression.transitionExpression.Condition;
import org.kse.expression.transitionExpression.Constant;
import org.kse.expression.transitionExpression.Literal;
import org.kse.expression.transitionExpression.MemberCall;
import org.kse.expression.transitionExpression.MessageAccess;
import org.kse.expression.transitionExpression.Not;
import org.kse.expression.transitionExpression.NumberLiteral;
import org.kse.expression.transitionExpression.ProcessMessages;
import org.kse.expression.transitionExpression.Publish;
import org.kse.expression.transitionExpression.PublishAll;
import org.kse.expression.transitionExpression.StringLiteral;
import org.kse.expression.transitionExpression.TimeoutAction;
import org.kse.messages.EnumType;
import org.kse.messages.MessageCatalog;

/**
 * A transition's condition and actions as ECMAScript over the data model's blackboards
 * (docs/adr/0038-scxml-mapping.md). The condition keeps the generated C++'s meaning: every message
 * it names is read once, first (a Signal read consumes it), a TimeoutCheck guard then refreshes
 * its blackboard, and the expression decides on what was read; a term that reads a missing
 * message is false, also under negation.
 */
final class ScxmlExportGuards {

	static final String TIMEOUT_CHECK = "TimeoutCheck";

	/** The guard helpers of kse/behavior/Guards.h, which the data model's script defines. */
	private static final Map<String, Integer> HELPERS = Map.of("readyToKick", 1, "ballAway", 1, "robotInPosition", 2);

	/** kse/behavior/BehaviorConst.h: constants the generated C++ uses unqualified. */
	private static final Map<String, Integer> BEHAVIOR_CONSTANTS = Map.of("PLAYER_INITIAL", 0, "PLAYER_READY", 1, "PLAYER_SET", 2,
			"PLAYER_PLAYING", 3, "PLAYER_FINISHED", 4, "PLAYER_PENALISED", 5);

	/** Why an expression has no faithful ECMAScript form. */
	static final class Unfaithful extends Exception {
		private static final long serialVersionUID = 1L;

		Unfaithful(String message) {
			super(message);
		}
	}

	/** One message read: topic, kind, type (TimeoutCheck reads the topic's TimeoutMsg State). */
	record Read(String topic, String kind, String type) {
		String js() {
			return "[" + quote(topic) + "," + quote(kind) + "," + quote(type) + "]";
		}
	}

	/** A condition as a function of the read messages {@code m[0..]}. */
	record Guard(List<Read> reads, boolean checksTimeouts, String body) {
		String js(String board) {
			return "kse.guard(" + quote(board) + ",[" + reads.stream().map(Read::js).collect(Collectors.joining(",")) + "],"
					+ checksTimeouts + ",function(m){return " + body + ";})";
		}
	}

	private final MessageCatalog catalog;
	private final Map<String, Read> reads = new LinkedHashMap<>();

	private ScxmlExportGuards(MessageCatalog catalog) {
		this.catalog = catalog;
	}

	static Guard condition(Condition condition, MessageCatalog catalog) throws Unfaithful {
		ScxmlExportGuards translator = new ScxmlExportGuards(catalog);
		String body = translator.guarded(condition);
		List<Read> all = new ArrayList<>(translator.reads.values());
		boolean timeouts = translator.reads.keySet().stream().anyMatch(key -> key.startsWith(TIMEOUT_CHECK + " "));
		return new Guard(all, timeouts, body);
	}

	/** Whether evaluating the condition changes a blackboard (a Signal consumed, a TimeoutCheck's refresh). */
	static boolean hasSideEffects(Guard guard) {
		return guard.checksTimeouts() || guard.reads().stream().anyMatch(read -> read.kind().equals("Signal"));
	}

	/** The actions as statements on the board, in order. */
	static String actions(List<Action> actions, String board) throws Unfaithful {
		StringBuilder js = new StringBuilder();
		for (Action action : actions) {
			if (action instanceof TimeoutAction timeout) {
				js.append("kse.setTimeout(").append(quote(board)).append(',').append(quote(timeout.getTopic())).append(',')
						.append(timeout.getMilliseconds()).append(");");
			} else if (action instanceof ProcessMessages) {
				js.append("kse.processMessages(").append(quote(board)).append(");");
			} else if (action instanceof PublishAll) {
				// each publish reached the hub when it was made, as in the generated C++
			} else if (action instanceof Publish publish) {
				List<MemberCall> members = publish.getMembers();
				StringBuilder path = new StringBuilder("[");
				for (int i = 0; i < members.size() - 1; i++) {
					MemberCall member = members.get(i);
					String name = member.getName();
					if (!name.startsWith("mutable_") || member.getArgument() != null) {
						throw new Unfaithful("the publish goes through '" + name + "()', which has no SCXML form (only mutable_<field>() and set_<field>(value))");
					}
					path.append(i == 0 ? "" : ",").append(quote(name.substring("mutable_".length())));
				}
				path.append(']');
				MemberCall setter = members.get(members.size() - 1);
				if (!setter.getName().startsWith("set_") || setter.getArgument() == null) {
					throw new Unfaithful("the publish ends in '" + setter.getName() + "()', which has no SCXML form (only set_<field>(value))");
				}
				js.append("kse.publish(").append(quote(board)).append(',').append(quote(publish.getTopic())).append(',')
						.append(quote(publish.getKind())).append(',').append(quote(publish.getMessage())).append(',').append(path)
						.append(',').append(quote(setter.getName().substring("set_".length()))).append(',')
						.append(new ScxmlExportGuards(null).literal(setter.getArgument())).append(");");
			} else {
				throw new Unfaithful("the action '" + action.eClass().getName() + "' has no SCXML form");
			}
		}
		return js.toString();
	}

	// ------------------------------------------------------------ the term with its missing-message checks

	private String guarded(Condition condition) throws Unfaithful {
		if (condition instanceof Binary binary) {
			if (isLogical(binary)) {
				return "(" + guarded(binary.getLeft()) + " " + binary.getOperator() + " " + guarded(binary.getRight()) + ")";
			}
			MessageAccess nullTest = nullTest(binary);
			return nullTest != null ? presenceTest(nullTest, binary.getOperator()) : guard(binary, comparison(binary));
		}
		if (condition instanceof Not not) {
			List<String> checks = required(not.getOperand());
			String negated = "!" + raw(not.getOperand());
			return checks.isEmpty() ? negated : "(" + present(checks) + " && " + negated + ")";
		}
		if (condition instanceof Call call) {
			return TIMEOUT_CHECK.equals(call.getFunction()) ? value(call) : guard(call, value(call));
		}
		if (condition instanceof MessageAccess access) {
			return access.getMembers().isEmpty() ? presence(access) : guard(access, value(access));
		}
		return "(" + value(condition) + ")";
	}

	private String raw(Condition condition) throws Unfaithful {
		if (condition instanceof Binary binary) {
			if (isLogical(binary)) {
				return "(" + raw(binary.getLeft()) + " " + binary.getOperator() + " " + raw(binary.getRight()) + ")";
			}
			MessageAccess nullTest = nullTest(binary);
			return nullTest != null ? presenceTest(nullTest, binary.getOperator()) : "(" + comparison(binary) + ")";
		}
		if (condition instanceof Not not) {
			return "!" + raw(not.getOperand());
		}
		if (condition instanceof MessageAccess access && access.getMembers().isEmpty()) {
			return presence(access);
		}
		if (condition instanceof Call || condition instanceof MessageAccess) {
			return value(condition);
		}
		return "(" + value(condition) + ")";
	}

	/** The read variables a term dereferences; a presence test dereferences nothing. */
	private List<String> required(Condition condition) throws Unfaithful {
		if (condition instanceof Binary binary) {
			if (isLogical(binary)) {
				List<String> all = new ArrayList<>(required(binary.getLeft()));
				for (String variable : required(binary.getRight())) {
					if (!all.contains(variable)) {
						all.add(variable);
					}
				}
				return all;
			}
			return nullTest(binary) != null ? List.of() : accessed(binary);
		}
		if (condition instanceof Not not) {
			return required(not.getOperand());
		}
		if (condition instanceof Call call) {
			return TIMEOUT_CHECK.equals(call.getFunction()) ? List.of() : accessed(call);
		}
		if (condition instanceof MessageAccess access) {
			return access.getMembers().isEmpty() ? List.of() : accessed(access);
		}
		return List.of();
	}

	private List<String> accessed(EObject element) throws Unfaithful {
		List<String> variables = new ArrayList<>();
		List<MessageAccess> accesses = new ArrayList<>();
		if (element instanceof MessageAccess access) {
			accesses.add(access);
		}
		element.eAllContents().forEachRemaining(content -> {
			if (content instanceof MessageAccess access) {
				accesses.add(access);
			}
		});
		for (MessageAccess access : accesses) {
			String variable = variable(access);
			if (!variables.contains(variable)) {
				variables.add(variable);
			}
		}
		return variables;
	}

	private String guard(EObject element, String value) throws Unfaithful {
		List<String> checks = accessed(element);
		return checks.isEmpty() ? "(" + value + ")" : "(" + present(checks) + " && " + value + ")";
	}

	private static String present(List<String> variables) {
		return variables.stream().map(v -> v + " != null").collect(Collectors.joining(" && "));
	}

	private String presence(MessageAccess access) throws Unfaithful {
		return "(" + variable(access) + " != null)";
	}

	private String presenceTest(MessageAccess access, String operator) throws Unfaithful {
		return "(" + variable(access) + " " + operator + " null)";
	}

	private String comparison(Binary binary) throws Unfaithful {
		return value(binary.getLeft()) + " " + binary.getOperator() + " " + value(binary.getRight());
	}

	private static boolean isLogical(Binary binary) {
		return binary.getOperator().equals("||") || binary.getOperator().equals("&&");
	}

	private static MessageAccess nullTest(Binary binary) {
		if (!binary.getOperator().equals("==") && !binary.getOperator().equals("!=")) {
			return null;
		}
		if (binary.getLeft() instanceof MessageAccess left && left.getMembers().isEmpty() && isNull(binary.getRight())) {
			return left;
		}
		if (binary.getRight() instanceof MessageAccess right && right.getMembers().isEmpty() && isNull(binary.getLeft())) {
			return right;
		}
		return null;
	}

	private static boolean isNull(EObject element) {
		return element instanceof Constant constant && "NULL".equals(constant.getName());
	}

	// ------------------------------------------------------------ values

	private String value(Condition condition) throws Unfaithful {
		if (condition instanceof MessageAccess access) {
			String variable = variable(access);
			if (access.getMembers().isEmpty()) {
				return variable;
			}
			StringBuilder path = new StringBuilder("[");
			for (int i = 0; i < access.getMembers().size(); i++) {
				MemberCall member = access.getMembers().get(i);
				if (member.getName().startsWith("has_")) {
					throw new Unfaithful("'" + member.getName() + "()' asks whether a field is set, which the messages of the SCXML data model (JSON) cannot tell");
				}
				path.append(i == 0 ? "" : ",").append('[').append(quote(member.getName()));
				if (member.getArgument() != null) {
					path.append(',').append(literal(member.getArgument()));
				}
				path.append(']');
			}
			return "kse.member(" + variable + "," + quote(access.getMessage()) + "," + path + "])";
		}
		if (condition instanceof Call call) {
			if (TIMEOUT_CHECK.equals(call.getFunction())) {
				if (call.getArguments().size() != 1 || !(call.getArguments().get(0) instanceof Constant topic)) {
					throw new Unfaithful("TimeoutCheck takes one topic");
				}
				return "kse.timeoutCheck(" + timeoutVariable(topic.getName()) + ")";
			}
			Integer arity = HELPERS.get(call.getFunction());
			if (arity == null || arity != call.getArguments().size()) {
				throw new Unfaithful("the helper '" + call.getFunction() + "' with " + call.getArguments().size()
						+ " arguments is not one the SCXML data model defines (" + String.join(", ", HELPERS.keySet().stream().sorted().toList()) + ")");
			}
			List<String> arguments = new ArrayList<>();
			for (Condition argument : call.getArguments()) {
				arguments.add(value(argument));
			}
			return "kse.helpers." + call.getFunction() + "(" + String.join(",", arguments) + ")";
		}
		if (condition instanceof Binary binary) {
			return "(" + value(binary.getLeft()) + " " + binary.getOperator() + " " + value(binary.getRight()) + ")";
		}
		if (condition instanceof Not not) {
			return "!" + value(not.getOperand());
		}
		if (condition instanceof Literal literal) {
			return literal(literal);
		}
		throw new Unfaithful("the term '" + condition.eClass().getName() + "' has no SCXML form");
	}

	private String literal(Literal literal) throws Unfaithful {
		if (literal instanceof NumberLiteral number) {
			return number.getValue();
		}
		if (literal instanceof StringLiteral string) {
			return quote(string.getValue());
		}
		if (literal instanceof Constant constant) {
			String name = constant.getName();
			switch (name) {
				case "NULL":
					return "null";
				case "true", "false":
					return name;
				default:
					break;
			}
			Integer known = BEHAVIOR_CONSTANTS.get(name);
			if (known != null) {
				return known.toString();
			}
			if (catalog != null) {
				for (EnumType type : catalog.enums()) {
					OptionalInt value = type.value(name);
					if (value.isPresent()) {
						return Integer.toString(value.getAsInt());
					}
				}
			}
			throw new Unfaithful("the constant '" + name + "' has no value known to the export (neither kse/behavior/BehaviorConst.h nor an enum of the messages)");
		}
		throw new Unfaithful("the literal has no SCXML form");
	}

	private String variable(MessageAccess access) throws Unfaithful {
		if (!List.of("State", "Signal", "Data").contains(access.getKind())) {
			throw new Unfaithful("'" + access.getKind() + "' is not a kind of message (State, Signal or Data)");
		}
		return variable(access.getTopic() + "." + access.getKind() + "." + access.getMessage(),
				new Read(access.getTopic(), access.getKind(), access.getMessage()));
	}

	private String timeoutVariable(String topic) {
		return variable(TIMEOUT_CHECK + " " + topic, new Read(topic, "State", "TimeoutMsg"));
	}

	private String variable(String key, Read read) {
		if (!reads.containsKey(key)) {
			reads.put(key, read);
		}
		int index = new ArrayList<>(reads.keySet()).indexOf(key);
		return "m[" + index + "]";
	}

	/** A JavaScript string literal. */
	static String quote(String text) {
		StringBuilder out = new StringBuilder("'");
		for (char c : text.toCharArray()) {
			switch (c) {
				case '\'' -> out.append("\\'");
				case '\\' -> out.append("\\\\");
				case '\n' -> out.append("\\n");
				case '\r' -> out.append("\\r");
				default -> {
					if (c < 0x20 || c == 0x2028 || c == 0x2029) {
						out.append(String.format("\\u%04x", (int) c));
					} else {
						out.append(c);
					}
				}
			}
		}
		return out.append('\'').toString();
	}
}
