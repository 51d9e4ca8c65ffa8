package org.kse.validation;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.kse.expression.transitionExpression.MemberCall;
import org.kse.expression.transitionExpression.MessageAccess;
import org.kse.expression.transitionExpression.Publish;
import org.kse.expression.transitionExpression.TransitionExpression;
import org.kse.expression.transitionExpression.TransitionExpressionPackage.Literals;
import org.kse.messages.Field;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;

/**
 * What a transition expression says about messages, checked against the message
 * catalog: known topics, known message types, fields that exist. Each problem carries
 * its position inside the expression text.
 */
final class MessageChecks {

	/** A problem at {@code line:column} (1-based) of the expression text. */
	record Problem(int line, int column, String message) {
	}

	private final MessageCatalog catalog;
	private final List<String> topics;

	MessageChecks(MessageCatalog catalog, List<String> topics) {
		this.catalog = catalog;
		this.topics = topics;
	}

	List<Problem> check(TransitionExpression expression, String text) {
		List<Problem> problems = new ArrayList<>();
		for (var it = expression.eAllContents(); it.hasNext();) {
			EObject element = it.next();
			if (element instanceof MessageAccess access) {
				check(access, access.getTopic(), Literals.MESSAGE_ACCESS__TOPIC, access.getMessage(), Literals.MESSAGE_ACCESS__MESSAGE,
						access.getMembers(), false, text, problems);
			} else if (element instanceof Publish publish) {
				check(publish, publish.getTopic(), Literals.PUBLISH__TOPIC, publish.getMessage(), Literals.PUBLISH__MESSAGE,
						publish.getMembers(), true, text, problems);
			}
		}
		return problems;
	}

	/** A variable's type, topic.Kind.Message: null when it is known, else what is wrong. */
	String checkType(String topic, String message) {
		if (!topics.contains(topic)) {
			return unknownTopic(topic);
		}
		if (catalog.message(message).isEmpty()) {
			return unknownMessage(message);
		}
		return null;
	}

	/** The nearest topic when one is close, else every known one. */
	private String unknownTopic(String topic) {
		return "unknown topic '" + topic + "'" + Suggestions.nearest(topic, topics).map(near -> "; did you mean '" + near + "'?")
				.orElse("; known topics: " + String.join(", ", topics));
	}

	private String unknownMessage(String message) {
		return "unknown message type '" + message + "'" + Suggestions.didYouMean(message, catalog.messages().stream().map(MessageType::name).toList());
	}

	private void check(EObject owner, String topic, EStructuralFeature topicFeature, String message, EStructuralFeature messageFeature,
			List<MemberCall> members, boolean setter, String text, List<Problem> problems) {
		if (topic != null && !topics.contains(topic)) {
			problems.add(at(owner, topicFeature, text, unknownTopic(topic)));
		}
		if (message == null) {
			return;
		}
		Optional<MessageType> type = catalog.message(message);
		if (type.isEmpty()) {
			problems.add(at(owner, messageFeature, text, unknownMessage(message)));
			return;
		}
		MessageType current = type.get();
		int fields = setter ? members.size() - 1 : members.size();
		for (int i = 0; i < fields; i++) {
			MemberCall member = members.get(i);
			Optional<Field> field = field(current, member.getName());
			if (field.isEmpty()) {
				problems.add(at(member, Literals.MEMBER_CALL__NAME, text, "'" + current.name() + "' has no field '" + member.getName() + "'"
						+ Suggestions.didYouMean(member.getName(), current.fields().stream().map(Field::name).toList())));
				return;
			}
			Optional<MessageType> next = field.get().messageType();
			if (next.isEmpty()) {
				if (i < fields - 1) {
					problems.add(at(members.get(i + 1), Literals.MEMBER_CALL__NAME, text,
							"'" + member.getName() + "' of '" + current.name() + "' is not a message, it has no fields"));
				}
				return;
			}
			current = next.get();
		}
		if (setter && !members.isEmpty()) {
			MemberCall last = members.get(members.size() - 1);
			String name = last.getName();
			String fieldName = name.startsWith("set_") ? name.substring(4) : name.startsWith("add_") ? name.substring(4) : null;
			if (fieldName == null || field(current, fieldName).isEmpty()) {
				problems.add(at(last, Literals.MEMBER_CALL__NAME, text,
						"'" + name + "' sets no field of '" + current.name() + "'; use set_<field> or add_<field>"));
			}
		}
	}

	/** protoc lower-cases C++ accessors, so a field matches its name in any case. */
	private static Optional<Field> field(MessageType type, String name) {
		Optional<Field> exact = type.field(name);
		if (exact.isPresent()) {
			return exact;
		}
		String folded = name.toLowerCase(Locale.ROOT);
		return type.fields().stream().filter(f -> f.name().toLowerCase(Locale.ROOT).equals(folded)).findFirst();
	}

	static Problem at(EObject element, EStructuralFeature feature, String text, String message) {
		List<INode> nodes = NodeModelUtils.findNodesForFeature(element, feature);
		INode node = nodes.isEmpty() ? NodeModelUtils.findActualNodeFor(element) : nodes.get(0);
		int offset = node == null ? 0 : node.getOffset();
		int line = 1;
		int column = 1;
		for (int i = 0; i < offset && i < text.length(); i++) {
			if (text.charAt(i) == '\n') {
				line++;
				column = 1;
			} else {
				column++;
			}
		}
		return new Problem(line, column, message);
	}
}
