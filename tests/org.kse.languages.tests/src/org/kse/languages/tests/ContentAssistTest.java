package org.kse.languages.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

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
import org.eclipse.xtext.ide.refactoring.IRenameStrategy2;
import org.eclipse.xtext.ide.server.rename.IRenameService2;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.resource.XtextResourceSet;
import org.eclipse.xtext.util.Modules2;
import org.eclipse.xtext.util.TextRegion;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.kse.expression.ExpressionParser;
import org.kse.expression.TransitionExpressionRuntimeModule;
import org.kse.expression.ide.TransitionExpressionIdeModule;
import org.kse.expression.ide.TransitionExpressionIdeSetup;
import org.kse.liveness.FormulaLoader;
import org.kse.liveness.LivenessRuntimeModule;
import org.kse.liveness.ide.LivenessIdeModule;
import org.kse.liveness.ide.LivenessIdeSetup;

import com.google.inject.Guice;
import com.google.inject.Injector;
import com.google.inject.Module;

/**
 * Content assist of both languages through Xtext's generic IDE services (no Eclipse UI):
 * what an editor offers at a cursor position.
 */
class ContentAssistTest {

	/**
	 * The generated IDE modules bind Xtext's LSP rename service, whose classes need lsp4j;
	 * lsp4j is an optional dependency of org.eclipse.xtext.ide and absent from the KSE
	 * product. Content assist does not use renaming, so these tests replace that binding
	 * and run wherever the IDE bundles do.
	 */
	private static final Module WITHOUT_LSP_RENAME = binder -> {
		binder.bind(IRenameService2.class).toProvider(() -> {
			throw new UnsupportedOperationException("renaming needs lsp4j");
		});
		binder.bind(IRenameStrategy2.class).toProvider(() -> {
			throw new UnsupportedOperationException("renaming needs lsp4j");
		});
	};

	private static Injector liveness;
	private static Injector expression;
	private static ExecutorService pool;

	@BeforeAll
	static void createInjectors() {
		// the standalone setups register the languages with EMF; the IDE injectors reuse that
		FormulaLoader.injector();
		ExpressionParser.injector();
		liveness = new LivenessIdeSetup() {
			@Override
			public Injector createInjector() {
				return Guice.createInjector(Modules2.mixin(new LivenessRuntimeModule(), new LivenessIdeModule(), WITHOUT_LSP_RENAME));
			}
		}.createInjector();
		expression = new TransitionExpressionIdeSetup() {
			@Override
			public Injector createInjector() {
				return Guice.createInjector(
						Modules2.mixin(new TransitionExpressionRuntimeModule(), new TransitionExpressionIdeModule(), WITHOUT_LSP_RENAME));
			}
		}.createInjector();
		pool = Executors.newSingleThreadExecutor();
	}

	@AfterAll
	static void stopPool() {
		pool.shutdownNow();
	}

	/** The proposal texts offered at {@code offset} (end of text when -1), in the acceptor's order. */
	private static List<String> proposals(Injector injector, String extension, String text, int offset) {
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

	private static List<String> formulaProposals(String text) {
		return proposals(liveness, "liveness", text, -1);
	}

	private static List<String> expressionProposals(String text) {
		return proposals(expression, "texpr", text, -1);
	}

	private static void assertOffered(List<String> proposals, String... expected) {
		for (String keyword : expected) {
			assertTrue(proposals.contains(keyword), () -> "'" + keyword + "' not offered; got " + proposals);
		}
	}

	private static void assertNotOffered(List<String> proposals, String... unexpected) {
		for (String keyword : unexpected) {
			assertFalse(proposals.contains(keyword), () -> "'" + keyword + "' offered where it cannot go; got " + proposals);
		}
	}

	// ---------------------------------------------------------------- formulas

	@Test
	void afterTheEqualsSignATermStarts() {
		List<String> proposals = formulaProposals("a = ");
		assertOffered(proposals, "(", "[", "|");
		assertNotOffered(proposals, ")", "]", ".", "||", "*", "=");
	}

	@Test
	void afterANameComeOperatorsAndRepetitions() {
		List<String> proposals = formulaProposals("a = B");
		assertOffered(proposals, ".", "|", "||", "*", "+", "~");
		assertNotOffered(proposals, "(", "[", "=");
	}

	@Test
	void insideAGroupItsClosingBracketIsOffered() {
		assertOffered(formulaProposals("a = (B"), ")", ".", "|");
		assertOffered(formulaProposals("a = [B"), "]");
	}

	@Test
	void replicationIsCompletedStepByStep() {
		assertEquals(List.of("~"), formulaProposals("a = |B"));
		assertOffered(formulaProposals("a = |B~"), "|");
	}

	@Test
	void afterTheLeftSideTheEqualsSignIsOffered() {
		assertEquals(List.of("="), formulaProposals("a"));
	}

	@Test
	void proposalsAtACursorInsideTheText() {
		String text = "a = \nb = C";
		List<String> proposals = proposals(liveness, "liveness", text, "a = ".length());
		assertOffered(proposals, "(", "[");
		assertNotOffered(proposals, ")");
	}

	// ---------------------------------------------------------------- transition expressions

	@Test
	void afterTheSlashEveryActionIsOffered() {
		assertOffered(expressionProposals("/"), "process_messages", "publish_all", "publish", "TimeoutAction");
		assertOffered(expressionProposals("/process_messages;"), "process_messages", "publish_all", "publish", "TimeoutAction");
	}

	@Test
	void afterAnEventComeConditionAndActions() {
		List<String> proposals = expressionProposals("ev");
		assertOffered(proposals, "[", "/");
		assertNotOffered(proposals, "]", "process_messages");
	}

	@Test
	void insideAConditionOperatorsAndTheClosingBracketAreOffered() {
		assertOffered(expressionProposals("["), "!", "(", "]");
		assertOffered(expressionProposals("[a==1"), "&&", "||", "]");
		assertOffered(expressionProposals("[a==1]"), "/");
	}

	// ---------------------------------------------------------------- the IDE setups as generated

	/**
	 * The IDE setups exactly as generated create their injectors when lsp4j is installed (as
	 * in the Tycho test runtime). Skipped where lsp4j is absent, as in the KSE product.
	 */
	@Test
	void generatedIdeSetupsCreateInjectorsWithLsp4j() {
		boolean lsp4j;
		try {
			Class.forName("org.eclipse.lsp4j.WorkspaceEdit", false, IdeContentProposalProvider.class.getClassLoader());
			lsp4j = true;
		} catch (ClassNotFoundException | LinkageError e) {
			lsp4j = false;
		}
		assumeTrue(lsp4j, "lsp4j is not installed: the generated IDE modules bind RenameService2, which needs it");
		FormulaLoader.injector();
		ExpressionParser.injector();
		Injector livenessIde = new LivenessIdeSetup().createInjector();
		Injector expressionIde = new TransitionExpressionIdeSetup().createInjector();
		assertNotNull(livenessIde.getInstance(IdeContentProposalProvider.class));
		assertOffered(proposals(livenessIde, "liveness", "a = ", -1), "(", "[");
		assertOffered(proposals(expressionIde, "texpr", "/", -1), "process_messages", "publish");
	}
}
