package org.kse.lsp;

import java.util.List;

import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.Location;
import org.eclipse.xtext.ide.server.Document;

/** What the server answers for one kind of file; offsets count in the document's text. */
interface DocumentLanguage {

	List<Diagnostic> diagnostics(String uri, Document document);

	List<CompletionItem> completion(String uri, Document document, int offset);

	/** Null when there is nothing to say at the offset. */
	Hover hover(String uri, Document document, int offset);

	List<Location> definition(String uri, Document document, int offset);

	List<DocumentSymbol> symbols(String uri, Document document);
}
