package org.kse.lsp;

import java.util.List;
import java.util.Optional;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IIdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.kse.expression.transitionExpression.MessageAccess;
import org.kse.expression.transitionExpression.Publish;
import org.kse.messages.EnumType;
import org.kse.messages.Field;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;

/**
 * Completion in transition expressions: the grammar's keywords and operators (Xtext's), and
 * where the grammar wants a name, the names the message catalog knows: topics, kinds, message
 * types, a message's fields, the guard helpers of the runtime and the constants of its enums.
 */
public class ExpressionProposals extends IdeContentProposalProvider {

	static final List<String> KINDS = List.of("State", "Data", "Signal");

	/** The runtime's guard helpers (docs: transition expressions), each with what it says. */
	static final List<String[]> HELPERS = List.of(
			new String[] { "TimeoutCheck", "true once the wake-up time set by TimeoutAction on the topic has passed" },
			new String[] { "readyToKick", "the ball is at the foot (worldstate.Data.WorldInfo)" },
			new String[] { "ballAway", "the ball is farther than 0.8 m (worldstate.Data.WorldInfo)" },
			new String[] { "robotInPosition", "the robot stands where the position message says" });

	/** The message a member call belongs to, from the text before it while the model is incomplete. */
	private static final Pattern MEMBER = Pattern.compile("\\b\\w+\\.(?:State|Data|Signal)\\.(\\w+)(?:\\.\\w+\\([^()]*\\))*\\.\\w*$");

	private MessageCatalog catalog = MessageCatalog.of(List.of());

	/** The catalog whose names are proposed. */
	void setCatalog(MessageCatalog catalog) {
		this.catalog = catalog;
	}

	@Override
	protected void _createProposals(Assignment assignment, ContentAssistContext context, IIdeContentProposalAcceptor acceptor) {
		String place = GrammarUtil.containingParserRule(assignment).getName() + "." + assignment.getFeature();
		switch (place) {
			case "MessageAccess.topic", "Publish.topic", "TimeoutAction.topic" ->
				MessageCatalog.standardTopics().forEach(topic -> propose(topic, "topic", ContentAssistEntry.KIND_MODULE, context, acceptor));
			case "MessageAccess.kind", "Publish.kind" -> KINDS.forEach(kind -> propose(kind, "kind", ContentAssistEntry.KIND_KEYWORD, context, acceptor));
			case "MessageAccess.message", "Publish.message" -> {
				TreeSet<String> names = new TreeSet<>();
				catalog.messages().forEach(message -> names.add(message.name()));
				names.forEach(name -> propose(name, "message type", ContentAssistEntry.KIND_CLASS, context, acceptor));
			}
			case "MemberCall.name" -> messageOf(context).ifPresent(message -> {
				for (Field field : message.fields()) {
					propose(field.name(), "field of " + message.name() + ": " + field.typeName(), ContentAssistEntry.KIND_FIELD, context, acceptor);
				}
			});
			case "Call.function" -> HELPERS.forEach(helper -> propose(helper[0], helper[1], ContentAssistEntry.KIND_FUNCTION, context, acceptor));
			case "Constant.name" -> {
				TreeSet<String> constants = new TreeSet<>(List.of("NULL", "true", "false"));
				for (EnumType type : catalog.enums()) {
					constants.addAll(type.values().keySet());
				}
				constants.forEach(constant -> propose(constant, "constant", ContentAssistEntry.KIND_ENUM, context, acceptor));
			}
			default -> super._createProposals(assignment, context, acceptor);
		}
	}

	/** The message type whose member is being typed: from the parsed model, else from the text. */
	private Optional<MessageType> messageOf(ContentAssistContext context) {
		for (EObject model : new EObject[] { context.getCurrentModel(), context.getPreviousModel() }) {
			String name = model instanceof MessageAccess access ? access.getMessage() : model instanceof Publish publish ? publish.getMessage() : null;
			if (name != null) {
				return catalog.message(name);
			}
		}
		String text = context.getRootNode() == null ? "" : context.getRootNode().getText();
		Matcher matcher = MEMBER.matcher(text.substring(0, Math.min(context.getOffset(), text.length())));
		return matcher.find() ? catalog.message(matcher.group(1)) : Optional.empty();
	}

	private void propose(String name, String description, String kind, ContentAssistContext context, IIdeContentProposalAcceptor acceptor) {
		ContentAssistEntry entry = getProposalCreator().createProposal(name, context, kind, it -> it.setDescription(description));
		if (entry != null) {
			acceptor.accept(entry, getProposalPriorities().getDefaultPriority(entry) + 100);
		}
	}
}
