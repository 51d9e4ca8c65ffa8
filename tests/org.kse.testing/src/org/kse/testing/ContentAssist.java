package org.kse.testing;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.ide.editor.contentassist.antlr.ContentAssistContextFactory;
import org.eclipse.xtext.ide.refactoring.IRenameStrategy2;
import org.eclipse.xtext.ide.server.rename.IRenameService2;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.TextRegion;

import com.google.inject.Injector;
import com.google.inject.Module;

/**
 * Content assist of an Xtext language through Xtext's generic IDE services (no Eclipse UI):
 * what an editor offers at a cursor position. Used by the content-assist tests of the liveness
 * and the expression language.
 */
public final class ContentAssist {

	/**
	 * The generated IDE modules bind Xtext's LSP rename service, whose classes need lsp4j;
	 * lsp4j is an optional dependency of org.eclipse.xtext.ide and absent from the KSE
	 * product. Content assist does not use renaming, so mixing this module in after the IDE
	 * module replaces that binding, and the tests run wherever the IDE bundles do.
	 */
	public static final Module WITHOUT_LSP_RENAME = binder -> {
		binder.bind(IRenameService2.class).toProvider(() -> {
			throw new UnsupportedOperationException("renaming needs lsp4j");
		});
		binder.bind(IRenameStrategy2.class).toProvider(() -> {
			throw new UnsupportedOperationException("renaming needs lsp4j");
		});
	};

	private ContentAssist() {
	}

	/** Whether lsp4j can be loaded next to Xtext's IDE services (as in the Tycho test runtime). */
	public static boolean lsp4jInstalled() {
		try {
			Class.forName("org.eclipse.lsp4j.WorkspaceEdit", false, IdeContentProposalProvider.class.getClassLoader());
			return true;
		} catch (ClassNotFoundException | LinkageError e) {
			return false;
		}
	}

	/**
	 * The proposal texts offered at {@code offset} (end of text when -1), in the acceptor's
	 * order, for a text loaded into a resource named {@code assist.<extension>}; {@code pool}
	 * runs the content-assist parser.
	 */
	public static List<String> proposals(Injector injector, String extension, String text, int offset, ExecutorService pool) {
		int at = offset < 0 ? text.length() : offset;
		XtextResource resource = injector.getInstance(XtextResource.class);
		resource.setURI(URI.createURI("assist." + extension));
		injector.getInstance(XtextResourceSet.class).getResources().add(resource);
		try {
			resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), Map.of(XtextResource.OPTION_ENCODING, "UTF-8"));
		} catch (IOException e) {
			throw new AssertionError(e);
		}
		ContentAssistContextFactory factory = injector.getInstance(ContentAssistContextFactory.class);
		factory.setPool(pool);
		ContentAssistContext[] contexts = factory.create(text, new TextRegion(at, 0), at, resource);
		IdeContentProposalAcceptor acceptor = injector.getInstance(IdeContentProposalAcceptor.class);
		injector.getInstance(IdeContentProposalProvider.class).createProposals(Arrays.asList(contexts), acceptor);
		List<String> result = new ArrayList<>();
		for (ContentAssistEntry entry : acceptor.getEntries()) {
			result.add(entry.getProposal());
		}
		return result;
	}

	public static void assertOffered(List<String> proposals, String... expected) {
		for (String keyword : expected) {
			assertTrue(proposals.contains(keyword), () -> "'" + keyword + "' not offered; got " + proposals);
		}
	}

	public static void assertNotOffered(List<String> proposals, String... unexpected) {
		for (String keyword : unexpected) {
			assertFalse(proposals.contains(keyword), () -> "'" + keyword + "' offered where it cannot go; got " + proposals);
		}
	}
}
