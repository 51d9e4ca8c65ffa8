package org.kse.ui.formula;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.contentassist.ICompletionProposal;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.ide.editor.contentassist.antlr.ContentAssistContextFactory;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.TextRegion;
import org.kse.liveness.FormulaLoader;
import org.kse.liveness.ide.LivenessIdeSetup;
import org.kse.liveness.liveness.Formula;
import org.kse.liveness.liveness.FormulaFile;
import org.kse.liveness.liveness.Reference;
import org.kse.ui.CompletionProcessor;

import com.google.inject.Injector;

/**
 * Completion in formulas: the grammar's operators and brackets where they may go (Xtext's IDE
 * services), and the names of the file, capabilities and activities, for the name being typed.
 */
public class FormulaContentAssist extends CompletionProcessor {

	private static final class Holder {
		static final Injector INJECTOR = create();

		private static Injector create() {
			FormulaLoader.injector(); // registers the language with EMF first
			return new LivenessIdeSetup().createInjector();
		}
	}

	private static final ExecutorService POOL = Executors.newSingleThreadExecutor(runnable -> {
		Thread thread = new Thread(runnable, "kse-formula-assist");
		thread.setDaemon(true);
		return thread;
	});

	@Override
	public ICompletionProposal[] computeCompletionProposals(ITextViewer viewer, int offset) {
		String text = viewer.getDocument().get();
		String prefix = namePrefix(text, offset);
		List<ICompletionProposal> proposals = new ArrayList<>();
		for (String name : names(text)) {
			if (name.startsWith(prefix) && !name.equals(prefix)) {
				proposals.add(proposal(name, prefix, offset, Character.isUpperCase(name.charAt(0)) ? "activity" : "capability"));
			}
		}
		if (prefix.isEmpty()) {
			for (String keyword : grammarProposals(text.substring(0, offset), offset)) {
				proposals.add(proposal(keyword, "", offset, "operator"));
			}
		}
		return proposals.toArray(ICompletionProposal[]::new);
	}

	static String namePrefix(String text, int offset) {
		int[] name = Definitions.wordAt(text.substring(0, offset), offset);
		return name == null ? "" : text.substring(name[0], offset);
	}

	/** Every name the formulas define or use, sorted. */
	static TreeSet<String> names(String text) {
		TreeSet<String> names = new TreeSet<>();
		FormulaFile file = FormulaLoader.load(text, URI.createURI("assist.liveness")).file();
		if (file == null) {
			return names;
		}
		for (Formula formula : file.getFormulas()) {
			if (formula.getName() != null) {
				names.add(formula.getName());
			}
		}
		for (var contents = file.eAllContents(); contents.hasNext();) {
			EObject element = contents.next();
			if (element instanceof Reference reference && reference.getName() != null) {
				names.add(reference.getName());
			}
		}
		return names;
	}

	/** The keywords the grammar allows at the end of {@code text}. */
	static List<String> grammarProposals(String text, int offset) {
		Injector injector = Holder.INJECTOR;
		XtextResource resource = injector.getInstance(XtextResource.class);
		resource.setURI(URI.createURI("assist.liveness"));
		injector.getInstance(XtextResourceSet.class).getResources().add(resource);
		try {
			resource.load(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), Map.of(XtextResource.OPTION_ENCODING, "UTF-8"));
		} catch (IOException | RuntimeException e) {
			return List.of();
		}
		ContentAssistContextFactory factory = injector.getInstance(ContentAssistContextFactory.class);
		factory.setPool(POOL);
		ContentAssistContext[] contexts = factory.create(text, new TextRegion(offset, 0), offset, resource);
		IdeContentProposalAcceptor acceptor = injector.getInstance(IdeContentProposalAcceptor.class);
		injector.getInstance(IdeContentProposalProvider.class).createProposals(Arrays.asList(contexts), acceptor);
		List<String> keywords = new ArrayList<>();
		for (ContentAssistEntry entry : acceptor.getEntries()) {
			if (entry.getProposal() != null && !entry.getProposal().isBlank() && !keywords.contains(entry.getProposal())) {
				keywords.add(entry.getProposal());
			}
		}
		return keywords;
	}


	@Override
	public char[] getCompletionProposalAutoActivationCharacters() {
		return new char[] { '=', '.', '(', '[' };
	}



}
