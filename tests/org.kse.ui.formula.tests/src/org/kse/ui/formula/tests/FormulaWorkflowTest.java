package org.kse.ui.formula.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.jface.text.ITextSelection;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.contentassist.ICompletionProposal;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Tree;
import org.eclipse.swt.widgets.TreeItem;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.handlers.IHandlerService;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.views.contentoutline.IContentOutlinePage;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer.OrderAnnotation;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.ui.formula.FormulaContentAssist;
import org.kse.ui.formula.FormulaEditor;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * A behaviour developer's first steps in the workbench: a project with the Goalie's formulas,
 * an error marker that appears while typing and goes when fixed, content assist, and the
 * statechart transformed from the formulas. Each step leaves a screenshot in target/screenshots.
 */
@ExtendWith(UnexpectedDialogs.class)
@TestMethodOrder(OrderAnnotation.class)
class FormulaWorkflowTest {

	private static final String MARKER = "org.kse.ui.formulaProblem";
	private static IProject project;
	private static IFile formula;
	private static FormulaEditor editor;

	@BeforeAll
	static void createProject() throws CoreException, IOException {
		project = ResourcesPlugin.getWorkspace().getRoot().getProject("Robots");
		if (!project.exists()) {
			project.create(null);
		}
		project.open(null);
		Path goalie = Path.of(System.getProperty("kse.examples"), "Goalie", "Goalie.liveness");
		formula = project.getFile("Goalie.liveness");
		formula.create(new ByteArrayInputStream(Files.readAllBytes(goalie)), true, null);
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 800);
	}

	@AfterAll
	static void closeEditors() {
		Ui.page().closeAllEditors(false);
	}

	private static List<IMarker> errors() {
		try {
			List<IMarker> errors = new ArrayList<>();
			for (IMarker marker : formula.findMarkers(MARKER, false, IResource.DEPTH_ZERO)) {
				if (marker.getAttribute(IMarker.SEVERITY, -1) == IMarker.SEVERITY_ERROR) {
					errors.add(marker);
				}
			}
			return errors;
		} catch (CoreException e) {
			throw new AssertionError(e);
		}
	}

	private static IDocument document() {
		return editor.getDocumentProvider().getDocument(editor.getEditorInput());
	}

	@Test
	@Order(1)
	void theGoalieFormulasOpenInTheFormulaEditorWithoutErrors() throws CoreException {
		IEditorPart part = IDE.openEditor(Ui.page(), formula, FormulaEditor.ID);
		editor = assertInstanceOf(FormulaEditor.class, part);
		assertTrue(document().get().contains("goalie = Init"));
		Ui.settle(1500);
		assertEquals(List.of(), errors(), "the thesis' Goalie formulas are correct");
		Ui.screenshot("01-goalie-formulas");
	}

	/** A file is checked when it opens, before anyone types in it. */
	@Test
	@Order(6)
	void aBrokenFormulaFileShowsItsProblemOnOpening() throws Exception {
		IFile broken = project.getFile("Broken.liveness");
		broken.create(new ByteArrayInputStream("broken = Init.(Scan | \n".getBytes(java.nio.charset.StandardCharsets.UTF_8)), true, null);
		IEditorPart part = IDE.openEditor(Ui.page(), broken, FormulaEditor.ID);
		try {
			assertTrue(Ui.waitUntil(() -> problems(broken) > 0, 10_000), "the unclosed parenthesis is marked without a keystroke");
		} finally {
			Ui.page().closeEditor(part, false);
			broken.delete(true, null);
		}
	}

	private static int problems(IFile file) {
		try {
			return file.findMarkers(MARKER, false, IResource.DEPTH_ZERO).length;
		} catch (CoreException e) {
			throw new AssertionError(e);
		}
	}

	@Test
	@Order(2)
	void anErrorMarkerAppearsWhileTypingAndGoesWhenFixed() throws Exception {
		IDocument document = document();
		int end = document.getLength();
		String broken = "\nplaying = (Scan | Kick\n";
		document.replace(end, 0, broken);
		assertTrue(Ui.waitUntil(() -> !errors().isEmpty(), 10_000), "an error marker for the unclosed bracket");
		IMarker marker = errors().get(0);
		assertTrue(marker.getAttribute(IMarker.LINE_NUMBER, 0) >= document.getNumberOfLines() - 2, "on the line typed");
		assertTrue(editor.isDirty(), "while typing, unsaved");
		Ui.screenshot("02-error-marker-while-typing");

		document.replace(end, broken.length(), "");
		assertTrue(Ui.waitUntil(() -> errors().isEmpty(), 10_000), "the marker goes once the text is fixed");
		Ui.screenshot("03-fixed");
	}

	@Test
	@Order(3)
	void contentAssistOffersTheNamesOfTheFormulas() throws Exception {
		IDocument document = document();
		String typed = "\nextra = St";
		int end = document.getLength();
		document.replace(end, 0, typed);
		ISourceViewer viewer = (ISourceViewer) editor.getAdapter(ITextOperationTarget.class);
		int offset = end + typed.length();
		ICompletionProposal[] proposals = new FormulaContentAssist().computeCompletionProposals((ITextViewer) viewer, offset);
		List<String> shown = Arrays.stream(proposals).map(ICompletionProposal::getDisplayString).toList();
		assertTrue(shown.stream().anyMatch(text -> text.startsWith("Stare")), () -> "Stare offered after 'St': " + shown);
		assertTrue(shown.stream().noneMatch(text -> text.startsWith("Scan")), () -> "only names starting with 'St': " + shown);

		viewer.getTextWidget().setFocus();
		viewer.setSelectedRange(offset, 0);
		((ITextOperationTarget) viewer).doOperation(ISourceViewer.CONTENTASSIST_PROPOSALS);
		Ui.settle(800);
		// the only name starting with "St" is inserted at once
		assertTrue(document.get().endsWith("extra = Stare"), () -> "Stare completed in the text: " + document.get());
		Ui.screenshot("04-content-assist");
		viewer.getTextWidget().setFocus();
		document.replace(end, document.getLength() - end, "");
		editor.doSave(null);
		assertTrue(Ui.waitUntil(() -> errors().isEmpty(), 10_000));
	}

	@Test
	@Order(4)
	void theOutlineListsTheCapabilitiesAndF3GoesToADefinition() throws Exception {
		Ui.page().showView(IPageLayout.ID_OUTLINE);
		Ui.page().activate(editor);
		Ui.settle(500);
		// the editor's outline page, shown in a window of its own to read it
		IContentOutlinePage outline = editor.getAdapter(IContentOutlinePage.class);
		Shell window = new Shell(Ui.display());
		List<String> shown;
		try {
			outline.createControl(window);
			shown = Arrays.stream(((Tree) outline.getControl()).getItems()).map(TreeItem::getText).toList();
		} finally {
			window.dispose();
		}
		assertEquals(List.of("goalie = Init.(playing | nonPlaying)+", "nonPlaying = NoPlay .[GoToPosition+]",
				"playing = Scan+ | ApproachBall+ | Kick | followBall", "followBall = Stare+.[SpecialAction]"), shown);

		String text = document().get();
		int use = text.indexOf("followBall", text.indexOf("playing = "));
		editor.selectAndReveal(use + 3, 0);
		PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand("org.kse.ui.openDefinition", null);
		ITextSelection selection = (ITextSelection) editor.getSelectionProvider().getSelection();
		assertEquals(text.indexOf("followBall = "), selection.getOffset(), "the cursor is on the definition of followBall");
		assertEquals("followBall".length(), selection.getLength());
		Ui.screenshot("06-outline-and-definition");
	}

	@Test
	@Order(5)
	void transformWritesTheStatechartNextToTheFormulas() throws Exception {
		IFile model = project.getFile("Goalie.stct");
		assertTrue(!model.exists());
		PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand("org.kse.ui.transform", null);
		assertTrue(Ui.waitUntil(model::exists, 30_000), "Goalie.stct written and refreshed");
		assertEquals("Goalie.stct", Ui.page().getActiveEditor().getEditorInput().getName(), "the new model opens");
		Model statechart = StatechartResources.load(Path.of(model.getLocationURI()));
		List<String> activities = new ArrayList<>();
		for (var contents = statechart.eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && "BASIC".equals(node.getType())) {
				activities.add(node.getName());
			}
		}
		assertTrue(activities.containsAll(List.of("Init", "NoPlay", "Scan", "ApproachBall", "Kick", "Stare", "SpecialAction", "GoToPosition")),
				() -> "the Goalie's activities: " + activities);
		project.refreshLocal(IResource.DEPTH_INFINITE, null);
		Ui.screenshot("05-transformed");
		assertTrue(Files.size(Path.of(model.getLocationURI())) > 1000);
	}
}
