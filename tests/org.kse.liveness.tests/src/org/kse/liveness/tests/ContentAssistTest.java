package org.kse.liveness.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
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
import org.kse.liveness.FormulaLoader;
import org.kse.liveness.LivenessRuntimeModule;
import org.kse.liveness.ide.LivenessIdeModule;
import org.kse.liveness.ide.LivenessIdeSetup;
import org.kse.testing.ContentAssist;

import com.google.inject.Guice;
import com.google.inject.Injector;

/**
 * Content assist of the formula language through Xtext's generic IDE services (no Eclipse UI):
 * what an editor offers at a cursor position in a .liveness text.
 */
class ContentAssistTest {

	private static Injector liveness;
	private static ExecutorService pool;

	@BeforeAll
	static void createInjector() {
		// the standalone setup registers the language with EMF; the IDE injector reuses that
		FormulaLoader.injector();
		liveness = new LivenessIdeSetup() {
			@Override
			public Injector createInjector() {
				return Guice.createInjector(
						Modules2.mixin(new LivenessRuntimeModule(), new LivenessIdeModule(), ContentAssist.WITHOUT_LSP_RENAME));
			}
		}.createInjector();
		pool = Executors.newSingleThreadExecutor();
	}

	@AfterAll
	static void stopPool() {
		pool.shutdownNow();
	}

	private static List<String> proposals(Injector injector, String text, int offset) {
		return ContentAssist.proposals(injector, "liveness", text, offset, pool);
	}

	private static List<String> formulaProposals(String text) {
		return proposals(liveness, text, -1);
	}

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
		List<String> proposals = proposals(liveness, text, "a = ".length());
		assertOffered(proposals, "(", "[");
		assertNotOffered(proposals, ")");
	}

	// ---------------------------------------------------------------- the IDE setup as generated

	/**
	 * The IDE setup exactly as generated creates its injector when lsp4j is installed (as in
	 * the Tycho test runtime). Skipped where lsp4j is absent, as in the KSE product.
	 */
	@Test
	void generatedIdeSetupCreatesInjectorWithLsp4j() {
		assumeTrue(ContentAssist.lsp4jInstalled(), "lsp4j is not installed: the generated IDE module binds RenameService2, which needs it");
		FormulaLoader.injector();
		Injector livenessIde = new LivenessIdeSetup().createInjector();
		assertNotNull(livenessIde.getInstance(IdeContentProposalProvider.class));
		assertOffered(proposals(livenessIde, "a = ", -1), "(", "[");
	}
}
