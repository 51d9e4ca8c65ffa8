package org.kse.ui.statechart.editor;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.contentassist.ICompletionProposal;
import org.kse.messages.Field;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;
import org.kse.ui.CompletionProcessor;

/**
 * Completion in transition expressions from the message catalog: topics and helper functions,
 * then after {@code topic.} the kinds, after {@code topic.Kind.} the message types, after
 * {@code topic.Kind.Type.} the fields, and the actions after {@code /}.
 */
public class ExpressionAssist extends CompletionProcessor {

	static final List<String> KINDS = List.of("State", "Data", "Signal");
	static final List<String> HELPERS = List.of("readyToKick(", "ballAway(", "robotInPosition(", "TimeoutCheck(");
	static final List<String> ACTIONS = List.of("process_messages", "publish_all", "publish(", "TimeoutAction.");

	private static final Pattern FIELD = Pattern.compile("([A-Za-z_]\\w*)\\.(State|Data|Signal)\\.([A-Za-z_]\\w*)\\.(\\w*)$");
	private static final Pattern TYPE = Pattern.compile("([A-Za-z_]\\w*)\\.(State|Data|Signal)\\.(\\w*)$");
	private static final Pattern KIND = Pattern.compile("([A-Za-z_]\\w*)\\.(\\w*)$");
	private static final Pattern WORD = Pattern.compile("(\\w*)$");

	private final MessageCatalog catalog;

	public ExpressionAssist(MessageCatalog catalog) {
		this.catalog = catalog;
	}

	@Override
	public ICompletionProposal[] computeCompletionProposals(ITextViewer viewer, int offset) {
		String before = viewer.getDocument().get().substring(0, offset);
		List<ICompletionProposal> proposals = new ArrayList<>();
		for (String[] proposal : proposals(before)) {
			proposals.add(proposal(proposal[0], proposal[1], offset, proposal[2]));
		}
		return proposals.toArray(ICompletionProposal[]::new);
	}

	/** {text, the prefix it replaces, what it is} for the text before the cursor. */
	public List<String[]> proposals(String before) {
		List<String[]> result = new ArrayList<>();
		Matcher field = FIELD.matcher(before);
		if (field.find()) {
			catalog.message(field.group(3)).ifPresent(type -> {
				for (Field each : type.fields()) {
					add(result, each.name() + "()", field.group(4), "field of " + type.name());
				}
			});
			return result;
		}
		Matcher type = TYPE.matcher(before);
		if (type.find()) {
			TreeSet<String> names = new TreeSet<>();
			for (MessageType message : catalog.messages()) {
				names.add(message.name());
			}
			names.forEach(name -> add(result, name, type.group(3), "message type"));
			return result;
		}
		Matcher kind = KIND.matcher(before);
		if (kind.find() && MessageCatalog.standardTopics().contains(kind.group(1))) {
			KINDS.forEach(name -> add(result, name, kind.group(2), "kind"));
			return result;
		}
		Matcher word = WORD.matcher(before);
		word.find();
		String prefix = word.group(1);
		if (before.contains("/") && before.lastIndexOf('/') > before.lastIndexOf(']')) {
			ACTIONS.forEach(name -> add(result, name, prefix, "action"));
			return result;
		}
		MessageCatalog.standardTopics().forEach(name -> add(result, name, prefix, "topic"));
		HELPERS.forEach(name -> add(result, name, prefix, "guard helper"));
		return result;
	}

	private static void add(List<String[]> result, String text, String prefix, String what) {
		if (text.startsWith(prefix) && !text.equals(prefix)) {
			result.add(new String[] { text, prefix, what });
		}
	}


	@Override
	public char[] getCompletionProposalAutoActivationCharacters() {
		return new char[] { '.', '[', '/' };
	}



}
