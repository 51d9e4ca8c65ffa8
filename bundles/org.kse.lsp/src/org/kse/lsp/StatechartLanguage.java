package org.kse.lsp;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

import org.eclipse.emf.common.util.URI;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.SymbolKind;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.server.Document;
import org.kse.expression.ExpressionParser;
import org.kse.expression.ide.TransitionExpressionIdeSetup;
import org.kse.messages.Field;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;
import org.kse.messages.StandardMessages;
import org.kse.validation.ExpressionChecks;

import com.google.inject.Injector;

/**
 * Statechart files ({@code .stct}): the transition expressions in their {@code TE} attributes,
 * each checked as {@code kse validate} checks it (grammar, events, topics, message types and
 * fields), with its problems at their place in the file; completion inside an expression; hover
 * on a message type; each transition with an expression a symbol. Messages are the standard ones
 * and those of a {@code messages} folder beside the model, as a Monas source tree has them.
 */
final class StatechartLanguage implements DocumentLanguage {

	private static final URI EXPRESSION_URI = URI.createURI("inmemory:/assist.texpr");

	private static final class Holder {
		static final Injector INJECTOR = create();

		private static Injector create() {
			ExpressionParser.injector(); // registers the language with EMF first
			return new TransitionExpressionIdeSetup().createInjector();
		}
	}

	private final CheckedExpressions checked = new CheckedExpressions();

	@Override
	public List<Diagnostic> diagnostics(String uri, Document document) {
		MessageCatalog catalog = catalog(uri);
		List<Diagnostic> diagnostics = new ArrayList<>();
		for (ExpressionAttributes.Attribute attribute : ExpressionAttributes.of(document.getContents())) {
			for (ExpressionChecks.Problem problem : checked.problems(attribute.value(), catalog)) {
				int start = problem.offset();
				int length = problem.issue() != null && problem.issue().getLength() != null ? problem.issue().getLength() : wordLength(attribute.value(), start);
				int end = Math.min(attribute.value().length(), start + length);
				String where = attribute.transition().isEmpty() ? "" : "transition " + attribute.transition() + ": ";
				diagnostics.add(Protocol.diagnostic(Protocol.range(document, attribute.fileOffset(start), attribute.fileOffset(end)), where + problem.message(),
						problem.error()));
			}
		}
		return diagnostics;
	}

	private static int wordLength(String text, int start) {
		int end = start;
		while (end < text.length() && (Character.isLetterOrDigit(text.charAt(end)) || text.charAt(end) == '_')) {
			end++;
		}
		return Math.max(1, end - start);
	}

	@Override
	public List<CompletionItem> completion(String uri, Document document, int offset) {
		ExpressionAttributes.Attribute attribute = attributeAt(document, offset);
		if (attribute == null) {
			return List.of();
		}
		int at = attribute.valueOffset(offset);
		ExpressionProposals provider = Holder.INJECTOR.getInstance(ExpressionProposals.class);
		provider.setCatalog(catalog(uri));
		List<CompletionItem> items = new ArrayList<>();
		for (ContentAssistEntry entry : XtextProposals.at(Holder.INJECTOR, provider, EXPRESSION_URI, attribute.value(), at)) {
			int prefix = entry.getPrefix() == null ? 0 : entry.getPrefix().length();
			int start = attribute.fileOffset(Math.max(0, at - prefix));
			items.add(Protocol.item(entry, Protocol.range(document, start, offset), ExpressionAttributes.escape(entry.getProposal())));
		}
		return items;
	}

	@Override
	public Hover hover(String uri, Document document, int offset) {
		ExpressionAttributes.Attribute attribute = attributeAt(document, offset);
		if (attribute == null) {
			return null;
		}
		String value = attribute.value();
		int at = attribute.valueOffset(offset);
		int start = at;
		while (start > 0 && isNamePart(value.charAt(start - 1))) {
			start--;
		}
		int end = at;
		while (end < value.length() && isNamePart(value.charAt(end))) {
			end++;
		}
		if (start == end) {
			return null;
		}
		String word = value.substring(start, end);
		Optional<MessageType> message = catalog(uri).message(word);
		String text;
		if (message.isPresent()) {
			StringBuilder fields = new StringBuilder();
			for (Field field : message.get().fields()) {
				fields.append("\n- `").append(field.name()).append("()`: ").append(field.typeName());
			}
			Path file = message.get().file();
			text = "message **" + message.get().fullName() + "**" + (file == null ? "" : " (" + file.getFileName() + ")") + fields;
		} else if (MessageCatalog.standardTopics().contains(word)) {
			text = "topic **" + word + "**";
		} else {
			text = ExpressionProposals.HELPERS.stream().filter(helper -> helper[0].equals(word)).findFirst()
					.map(helper -> "guard helper **" + word + "**: " + helper[1]).orElse(null);
		}
		Hover hover = text == null ? null : new Hover(new MarkupContent(MarkupKind.MARKDOWN, text));
		if (hover != null) {
			hover.setRange(Protocol.range(document, attribute.fileOffset(start), attribute.fileOffset(end)));
		}
		return hover;
	}

	private static boolean isNamePart(char c) {
		return Character.isLetterOrDigit(c) || c == '_';
	}

	@Override
	public List<Location> definition(String uri, Document document, int offset) {
		return List.of();
	}

	@Override
	public List<DocumentSymbol> symbols(String uri, Document document) {
		List<DocumentSymbol> symbols = new ArrayList<>();
		for (ExpressionAttributes.Attribute attribute : ExpressionAttributes.of(document.getContents())) {
			String name = attribute.transition().isEmpty() ? "transition" : attribute.transition();
			symbols.add(new DocumentSymbol(name, SymbolKind.Event, Protocol.range(document, attribute.elementStart(), attribute.elementEnd()),
					Protocol.range(document, attribute.fileOffset(0), attribute.fileOffset(attribute.value().length())), attribute.value()));
		}
		return symbols;
	}

	private static ExpressionAttributes.Attribute attributeAt(Document document, int offset) {
		for (ExpressionAttributes.Attribute attribute : ExpressionAttributes.of(document.getContents())) {
			if (attribute.valueOffset(offset) >= 0) {
				return attribute;
			}
		}
		return null;
	}

	/** The standard messages, and those of the model's {@code messages} folder when it has one. */
	private MessageCatalog catalog(String uri) {
		Path folder = folder(uri);
		Path messages = folder == null ? null : folder.resolve("messages");
		if (messages == null || !Files.isDirectory(messages)) {
			return Standard.CATALOG;
		}
		return catalogs.of(messages);
	}

	private final MessageFolders catalogs = new MessageFolders();

	private static final class Standard {
		static final MessageCatalog CATALOG = StandardMessages.catalog();
	}

	private static Path folder(String uri) {
		try {
			java.net.URI parsed = java.net.URI.create(uri);
			return "file".equals(parsed.getScheme()) ? Path.of(parsed).getParent() : null;
		} catch (IllegalArgumentException | java.nio.file.FileSystemNotFoundException e) {
			return null;
		}
	}
}
