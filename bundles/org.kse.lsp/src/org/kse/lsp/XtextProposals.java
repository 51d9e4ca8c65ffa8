package org.kse.lsp;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import org.eclipse.emf.common.util.URI;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.ide.editor.contentassist.antlr.ContentAssistContextFactory;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.TextRegion;

import com.google.inject.Injector;

/**
 * Content assist of one of KSE's Xtext languages on a text, with the language's IDE services
 * (its content-assist parser finds what the grammar allows at the offset) and a proposal
 * provider of ours that knows the names the grammar leaves open.
 */
final class XtextProposals {

	/** What Xtext's context factory parses on; one daemon thread, as requests come one at a time. */
	private static final ExecutorService POOL = Executors.newSingleThreadExecutor(runnable -> {
		Thread thread = new Thread(runnable, "kse-lsp-assist");
		thread.setDaemon(true);
		return thread;
	});

	private XtextProposals() {
	}

	/** The proposals at {@code offset}, best first; none when the text cannot be parsed at all. */
	static List<ContentAssistEntry> at(Injector injector, IdeContentProposalProvider provider, URI uri, String text, int offset) {
		XtextResource resource = injector.getInstance(XtextResource.class);
		resource.setURI(uri);
		injector.getInstance(XtextResourceSet.class).getResources().add(resource);
		try {
			resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), Map.of(XtextResource.OPTION_ENCODING, "UTF-8"));
		} catch (IOException | RuntimeException | StackOverflowError e) {
			return List.of();
		}
		ContentAssistContextFactory factory = injector.getInstance(ContentAssistContextFactory.class);
		factory.setPool(POOL);
		ContentAssistContext[] contexts = factory.create(text, new TextRegion(offset, 0), offset, resource);
		IdeContentProposalAcceptor acceptor = injector.getInstance(IdeContentProposalAcceptor.class);
		provider.createProposals(Arrays.asList(contexts), acceptor);
		List<ContentAssistEntry> entries = new ArrayList<>();
		List<String> seen = new ArrayList<>();
		for (ContentAssistEntry entry : acceptor.getEntries()) {
			if (entry.getProposal() != null && !entry.getProposal().isBlank() && !seen.contains(entry.getProposal())) {
				seen.add(entry.getProposal());
				entries.add(entry);
			}
		}
		return entries;
	}
}
