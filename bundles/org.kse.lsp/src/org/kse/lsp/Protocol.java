package org.kse.lsp;

import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionItemKind;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.server.Document;
import org.kse.messages.LineStarts;

/** The protocol's shapes of what the languages find: ranges, diagnostics, completion items. */
final class Protocol {

	static final String SOURCE = "kse";

	private Protocol() {
	}

	/** The range between two offsets of the document, each kept inside its text. */
	static Range range(Document document, int start, int end) {
		String text = document.getContents();
		int from = Math.max(0, Math.min(start, text.length()));
		int to = Math.max(from, Math.min(end, text.length()));
		int[] lines = lineStarts(text);
		return new Range(position(lines, from), position(lines, to));
	}

	private static String indexed;
	private static int[] indexedLineStarts;

	/**
	 * Where each line of the text starts; the last text's are kept, as a statechart's many
	 * problems are all placed in one text (Document.getPosition counts from the start each time).
	 */
	private static synchronized int[] lineStarts(String text) {
		if (text != indexed) {
			indexedLineStarts = LineStarts.of(text);
			indexed = text;
		}
		return indexedLineStarts;
	}

	private static Position position(int[] lineStarts, int offset) {
		int line = LineStarts.lineIndex(lineStarts, offset);
		return new Position(line, offset - lineStarts[line]);
	}

	static Diagnostic diagnostic(Range range, String message, boolean error) {
		return new Diagnostic(range, message, error ? DiagnosticSeverity.Error : DiagnosticSeverity.Warning, SOURCE);
	}

	/** A completion item that replaces what the entry's prefix covers before the cursor with {@code text}. */
	static CompletionItem item(ContentAssistEntry entry, Range replaced, String text) {
		CompletionItem item = new CompletionItem(entry.getLabel() != null ? entry.getLabel() : entry.getProposal());
		item.setDetail(entry.getDescription());
		item.setKind(kind(entry.getKind()));
		item.setTextEdit(Either.forLeft(new TextEdit(replaced, text)));
		item.setFilterText(entry.getProposal());
		return item;
	}

	private static CompletionItemKind kind(String kind) {
		if (kind == null) {
			return CompletionItemKind.Value;
		}
		return switch (kind) {
			case ContentAssistEntry.KIND_KEYWORD -> CompletionItemKind.Keyword;
			case ContentAssistEntry.KIND_REFERENCE -> CompletionItemKind.Reference;
			case ContentAssistEntry.KIND_FUNCTION -> CompletionItemKind.Function;
			case ContentAssistEntry.KIND_CLASS -> CompletionItemKind.Class;
			case ContentAssistEntry.KIND_FIELD -> CompletionItemKind.Field;
			case ContentAssistEntry.KIND_MODULE -> CompletionItemKind.Module;
			case ContentAssistEntry.KIND_ENUM -> CompletionItemKind.EnumMember;
			default -> CompletionItemKind.Value;
		};
	}
}
