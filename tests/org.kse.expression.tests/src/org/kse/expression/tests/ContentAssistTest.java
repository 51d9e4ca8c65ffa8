package org.kse.expression.tests;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.kse.testing.ContentAssist.assertNotOffered;
import static org.kse.testing.ContentAssist.assertOffered;

import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.util.Modules2;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.kse.expression.ExpressionParser;
import org.kse.expression.TransitionExpressionRuntimeModule;
import org.kse.expression.ide.TransitionExpressionIdeModule;
import org.kse.expression.ide.TransitionExpressionIdeSetup;
import org.kse.testing.ContentAssist;

import com.google.inject.Guice;
import com.google.inject.Injector;

/**
 * Content assist of the transition-expression language through Xtext's generic IDE services
 * (no Eclipse UI): what an editor offers at a cursor position in a .texpr text.
 */
class ContentAssistTest {

	private static Injector expression;
	private static ExecutorService pool;

	@BeforeAll
	static void createInjector() {
		// the standalone setup registers the language with EMF; the IDE injector reuses that
		ExpressionParser.injector();
		expression = new TransitionExpressionIdeSetup() {
			@Override
			public Injector createInjector() {
				return Guice.createInjector(Modules2.mixin(new TransitionExpressionRuntimeModule(), new TransitionExpressionIdeModule(),
						ContentAssist.WITHOUT_LSP_RENAME));
			}
		}.createInjector();
		pool = Executors.newSingleThreadExecutor();
	}

	@AfterAll
	static void stopPool() {
		pool.shutdownNow();
	}

	private static List<String> proposals(Injector injector, String text, int offset) {
		return ContentAssist.proposals(injector, "texpr", text, offset, pool);
	}

	private static List<String> expressionProposals(String text) {
		return proposals(expression, text, -1);
	}

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

	// ---------------------------------------------------------------- the IDE setup as generated

	/**
	 * The IDE setup exactly as generated creates its injector when lsp4j is installed (as in
	 * the Tycho test runtime). Skipped where lsp4j is absent, as in the KSE product.
	 */
	@Test
	void generatedIdeSetupCreatesInjectorWithLsp4j() {
		assumeTrue(ContentAssist.lsp4jInstalled(), "lsp4j is not installed: the generated IDE module binds RenameService2, which needs it");
		ExpressionParser.injector();
		Injector expressionIde = new TransitionExpressionIdeSetup().createInjector();
		assertNotNull(expressionIde.getInstance(IdeContentProposalProvider.class));
		assertOffered(proposals(expressionIde, "/", -1), "process_messages", "publish");
	}
}
