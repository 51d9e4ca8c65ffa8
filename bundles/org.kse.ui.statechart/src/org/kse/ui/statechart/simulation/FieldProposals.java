package org.kse.ui.statechart.simulation;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;

import org.eclipse.jface.fieldassist.ContentProposal;
import org.eclipse.jface.fieldassist.IContentProposal;
import org.eclipse.jface.fieldassist.IContentProposalProvider;
import org.kse.messages.EnumType;
import org.kse.messages.Field;
import org.kse.messages.MessageType;

/**
 * Completion of a message's fields in protobuf text format ({@code ballfound: 0 pos { x: 1 }}), as
 * the simulator reads them: at a field's place the fields of the message being written (inside
 * {@code name { ... }} those of that field's message), after {@code name:} an enum's values. Each
 * proposal is the rest of the word, inserted at the cursor.
 */
final class FieldProposals implements IContentProposalProvider {

	private final Supplier<Optional<MessageType>> type;

	/** @param type the message the fields belong to (the one chosen now) */
	FieldProposals(Supplier<Optional<MessageType>> type) {
		this.type = type;
	}

	@Override
	public IContentProposal[] getProposals(String contents, int position) {
		Optional<MessageType> root = type.get();
		if (root.isEmpty()) {
			return new IContentProposal[0];
		}
		String before = contents.substring(0, Math.min(position, contents.length()));
		int start = before.length();
		while (start > 0 && isWordPart(before.charAt(start - 1))) {
			start--;
		}
		String prefix = before.substring(start);
		Scope scope = scope(root.get(), before.substring(0, start));
		List<IContentProposal> proposals = new ArrayList<>();
		if (scope.message() == null) {
			return new IContentProposal[0];
		}
		if (scope.valueOf() != null) {
			Optional<EnumType> values = scope.valueOf().enumType();
			if (values.isPresent()) {
				for (String value : values.get().values().keySet()) {
					if (value.startsWith(prefix)) {
						proposals.add(new ContentProposal(value.substring(prefix.length()) + " ", value, scope.valueOf().name() + " is a " + values.get().name()));
					}
				}
			}
			return proposals.toArray(IContentProposal[]::new);
		}
		for (Field field : scope.message().fields()) {
			if (field.name().startsWith(prefix)) {
				// a message field opens its braces: its own fields are proposed inside them
				String rest = field.name().substring(prefix.length()) + (field.messageType().isPresent() ? " { " : ": ");
				String label = field.name() + " : " + (field.isRepeated() ? "repeated " : "") + field.typeName();
				proposals.add(new ContentProposal(rest, label, field.name() + " (" + field.typeName() + ") of " + scope.message().name()));
			}
		}
		return proposals.toArray(IContentProposal[]::new);
	}

	/**
	 * Where the cursor is: in which message (null when in a field that is not a message, or in
	 * text that cannot be read), and the field whose value it is after {@code name:} (else null).
	 */
	record Scope(MessageType message, Field valueOf) {
	}

	static Scope scope(MessageType root, String text) {
		Deque<MessageType> open = new ArrayDeque<>();
		open.push(root);
		boolean unknown = false;
		int unknownDepth = 0;
		String lastName = null;
		Field valueOf = null;
		int i = 0;
		while (i < text.length()) {
			char c = text.charAt(i);
			if (c == '"' || c == '\'') {
				int end = text.indexOf(c, i + 1);
				i = end < 0 ? text.length() : end + 1;
				lastName = null;
				valueOf = null;
			} else if (Character.isLetter(c) || c == '_') {
				int end = i;
				while (end < text.length() && isWordPart(text.charAt(end))) {
					end++;
				}
				String word = text.substring(i, end);
				if (valueOf != null) {
					valueOf = null; // the value written: a field comes next
					lastName = null;
				} else {
					lastName = word;
				}
				i = end;
			} else if (c == ':') {
				valueOf = unknown || lastName == null ? null : open.peek().field(lastName).orElse(null);
				i++;
			} else if (c == '{') {
				Optional<MessageType> inner = unknown || lastName == null ? Optional.empty()
						: open.peek().field(lastName).flatMap(Field::messageType);
				if (unknown || inner.isEmpty()) {
					unknown = true;
					unknownDepth++;
				} else {
					open.push(inner.get());
				}
				lastName = null;
				valueOf = null;
				i++;
			} else if (c == '}') {
				if (unknown) {
					unknownDepth--;
					unknown = unknownDepth > 0;
				} else if (open.size() > 1) {
					open.pop();
				}
				lastName = null;
				valueOf = null;
				i++;
			} else {
				if (!Character.isWhitespace(c)) {
					// a number or a sign: a value, after which a field comes
					valueOf = null;
					lastName = null;
				}
				i++;
			}
		}
		return new Scope(unknown ? null : open.peek(), valueOf);
	}

	private static boolean isWordPart(char c) {
		return Character.isLetterOrDigit(c) || c == '_';
	}
}
