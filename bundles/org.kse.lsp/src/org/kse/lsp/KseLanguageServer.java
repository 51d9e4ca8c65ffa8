package org.kse.lsp;

import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.function.Supplier;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionOptions;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DidChangeConfigurationParams;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.DidCloseTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DidSaveTextDocumentParams;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.LocationLink;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ServerCapabilities;
import org.eclipse.lsp4j.ServerInfo;
import org.eclipse.lsp4j.SymbolInformation;
import org.eclipse.lsp4j.TextDocumentSyncKind;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageClientAware;
import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.lsp4j.services.TextDocumentService;
import org.eclipse.lsp4j.services.WorkspaceService;
import org.eclipse.xtext.ide.server.Document;

/**
 * {@code kse lsp}: the language server of KSE's formula files and of the transition expressions
 * in statechart files (ADR 0037). Each open document is checked on its own, as the languages have
 * no references between files; a document goes to its language by its extension ({@code .liveness}
 * and {@code .txt}: formulas, {@code .stct}: statecharts), else by the language the client names.
 * Requests are answered in the order they come, on the connection's thread.
 */
public final class KseLanguageServer implements LanguageServer, LanguageClientAware, TextDocumentService, WorkspaceService {

	private final FormulaLanguage formulas = new FormulaLanguage();
	private final StatechartLanguage statecharts = new StatechartLanguage();
	private final Map<String, Document> documents = new ConcurrentHashMap<>();
	private final Map<String, DocumentLanguage> languages = new ConcurrentHashMap<>();
	private final CompletableFuture<Integer> exited = new CompletableFuture<>();
	private final PrintStream log;
	private LanguageClient client;
	private volatile boolean shutDown;

	private KseLanguageServer(PrintStream log) {
		this.log = log;
	}

	/**
	 * Serves one client on the two streams until it says exit or closes its end. Whatever else
	 * would print to standard output goes to standard error: the output stream carries only the
	 * protocol.
	 *
	 * @return the exit code the protocol asks for: 0 after a shutdown request, 1 without one
	 */
	public static int serve(InputStream in, OutputStream out, PrintStream log) {
		System.setOut(log);
		logProtocolErrorsTo(log);
		KseLanguageServer server = new KseLanguageServer(log);
		Launcher<LanguageClient> launcher = LSPLauncher.createServerLauncher(server, in, out);
		server.connect(launcher.getRemoteProxy());
		Future<Void> listening = launcher.startListening();
		Thread input = new Thread(() -> {
			try {
				listening.get();
			} catch (InterruptedException e) {
				Thread.currentThread().interrupt();
			} catch (ExecutionException e) {
				log.println("kse lsp: the connection failed: " + e.getCause());
			}
			// the client closed its end without exit: the protocol's code for an exit without shutdown
			server.exited.complete(server.shutDown ? 0 : 1);
		}, "kse-lsp-input");
		input.setDaemon(true);
		input.start();
		return server.exited.join();
	}

	/** Kept: java.util.logging holds its loggers weakly, and would drop the handler with it. */
	private static final Logger PROTOCOL_LOG = Logger.getLogger("org.eclipse.lsp4j");

	/**
	 * lsp4j reports what a client sent wrong (malformed JSON, an unknown method) through
	 * java.util.logging, with a stack trace; one line each says it as the command line does.
	 */
	private static void logProtocolErrorsTo(PrintStream log) {
		PROTOCOL_LOG.setUseParentHandlers(false);
		PROTOCOL_LOG.addHandler(new Handler() {
			@Override
			public void publish(LogRecord record) {
				if (record.getLevel().intValue() < Level.WARNING.intValue()) {
					return;
				}
				String message = record.getThrown() != null && record.getThrown().getMessage() != null ? record.getThrown().getMessage() : record.getMessage();
				log.println("kse lsp: " + (record.getLevel() == Level.SEVERE ? "error: " : "warning: ") + String.valueOf(message).lines().findFirst().orElse(""));
				if (record.getThrown() != null && System.getenv("KSE_DEBUG") != null) {
					record.getThrown().printStackTrace(log);
				}
			}

			@Override
			public void flush() {
				log.flush();
			}

			@Override
			public void close() {
				// the stream is the process's standard error
			}
		});
	}

	@Override
	public void connect(LanguageClient languageClient) {
		this.client = languageClient;
	}

	@Override
	public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
		ServerCapabilities capabilities = new ServerCapabilities();
		capabilities.setTextDocumentSync(TextDocumentSyncKind.Full);
		capabilities.setCompletionProvider(new CompletionOptions(false, List.of(".", "[", "/", "(", "|")));
		capabilities.setHoverProvider(true);
		capabilities.setDefinitionProvider(true);
		capabilities.setDocumentSymbolProvider(true);
		return CompletableFuture.completedFuture(new InitializeResult(capabilities, new ServerInfo("kse", version())));
	}

	private static String version() {
		Package own = KseLanguageServer.class.getPackage();
		return own != null && own.getImplementationVersion() != null ? own.getImplementationVersion() : "0.1.0";
	}

	@Override
	public CompletableFuture<Object> shutdown() {
		shutDown = true;
		return CompletableFuture.completedFuture(null);
	}

	@Override
	public void exit() {
		exited.complete(shutDown ? 0 : 1);
	}

	@Override
	public TextDocumentService getTextDocumentService() {
		return this;
	}

	@Override
	public WorkspaceService getWorkspaceService() {
		return this;
	}

	@Override
	public void didOpen(DidOpenTextDocumentParams params) {
		String uri = params.getTextDocument().getUri();
		DocumentLanguage language = languageOf(uri, params.getTextDocument().getLanguageId());
		if (language == null) {
			return;
		}
		languages.put(uri, language);
		documents.put(uri, new Document(params.getTextDocument().getVersion(), params.getTextDocument().getText()));
		publish(uri);
	}

	@Override
	public void didChange(DidChangeTextDocumentParams params) {
		String uri = params.getTextDocument().getUri();
		Document document = documents.get(uri);
		if (document == null) {
			return;
		}
		documents.put(uri, document.applyTextDocumentChanges(params.getContentChanges()));
		publish(uri);
	}

	@Override
	public void didClose(DidCloseTextDocumentParams params) {
		String uri = params.getTextDocument().getUri();
		if (documents.remove(uri) != null) {
			languages.remove(uri);
			client.publishDiagnostics(new PublishDiagnosticsParams(uri, List.of()));
		}
	}

	@Override
	public void didSave(DidSaveTextDocumentParams params) {
		// the open document already has what was saved
	}

	private void publish(String uri) {
		Document document = documents.get(uri);
		List<Diagnostic> diagnostics = answer("checking " + uri, () -> languages.get(uri).diagnostics(uri, document), List.of());
		client.publishDiagnostics(new PublishDiagnosticsParams(uri, diagnostics, document.getVersion()));
	}

	@Override
	public CompletableFuture<Either<List<CompletionItem>, CompletionList>> completion(CompletionParams params) {
		return request(params.getTextDocument().getUri(), params.getPosition(), List.<CompletionItem>of(),
				(language, uri, document, offset) -> language.completion(uri, document, offset), items -> Either.forRight(new CompletionList(false, items)));
	}

	@Override
	public CompletableFuture<Hover> hover(HoverParams params) {
		return request(params.getTextDocument().getUri(), params.getPosition(), null,
				(language, uri, document, offset) -> language.hover(uri, document, offset), hover -> hover);
	}

	@Override
	public CompletableFuture<Either<List<? extends Location>, List<? extends LocationLink>>> definition(DefinitionParams params) {
		return request(params.getTextDocument().getUri(), params.getPosition(), List.<Location>of(),
				(language, uri, document, offset) -> language.definition(uri, document, offset), Either::forLeft);
	}

	@Override
	public CompletableFuture<List<Either<SymbolInformation, DocumentSymbol>>> documentSymbol(DocumentSymbolParams params) {
		String uri = params.getTextDocument().getUri();
		Document document = documents.get(uri);
		List<DocumentSymbol> symbols = document == null ? List.of()
				: answer("listing the symbols of " + uri, () -> languages.get(uri).symbols(uri, document), List.of());
		return CompletableFuture.completedFuture(symbols.stream().map(Either::<SymbolInformation, DocumentSymbol>forRight).toList());
	}

	/** What a request at a position of an open document computes. */
	private interface Query<T> {
		T at(DocumentLanguage language, String uri, Document document, int offset);
	}

	private <T, R> CompletableFuture<R> request(String uri, Position position, T nothing, Query<T> query, java.util.function.Function<T, R> shape) {
		Document document = documents.get(uri);
		if (document == null) {
			return CompletableFuture.completedFuture(shape.apply(nothing));
		}
		T result = answer("answering at " + uri + ":" + (position.getLine() + 1) + ":" + (position.getCharacter() + 1), () -> {
			int offset = document.getOffSet(position);
			return query.at(languages.get(uri), uri, document, offset);
		}, nothing);
		return CompletableFuture.completedFuture(shape.apply(result));
	}

	/**
	 * A failure inside a language answers with nothing and a line on standard error: an editor
	 * keeps its server, and the user learns what went wrong.
	 */
	private <T> T answer(String what, Supplier<T> work, T nothing) {
		try {
			return work.get();
		} catch (RuntimeException | StackOverflowError e) {
			log.println("kse lsp: " + what + " failed: " + e);
			if (System.getenv("KSE_DEBUG") != null) {
				e.printStackTrace(log);
			}
			return nothing;
		}
	}

	private DocumentLanguage languageOf(String uri, String languageId) {
		String path = uri.toLowerCase(java.util.Locale.ROOT);
		if (path.endsWith(".liveness") || path.endsWith(".txt") || "liveness".equals(languageId)) {
			return formulas;
		}
		if (path.endsWith(".stct") || "kse-statechart".equals(languageId)) {
			return statecharts;
		}
		return null;
	}

	@Override
	public void didChangeConfiguration(DidChangeConfigurationParams params) {
		// no settings
	}

	@Override
	public void didChangeWatchedFiles(DidChangeWatchedFilesParams params) {
		// nothing to refresh: a statechart's messages folder is read again at each check
	}
}
