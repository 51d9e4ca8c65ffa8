package org.kse.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.actions.ActionFactory;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.views.properties.PropertySheet;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Node;
import org.kse.ui.model.diagram.DiagramPage;
import org.kse.ui.model.editor.StatechartEditor;

/**
 * The statechart editor's Diagram tab inside the KSE workbench: the diagram page in an SWT Browser,
 * served by the workbench's diagram server, editing the editor's own model. Selections go both
 * ways, a rename in the Properties view is drawn, an edit on the diagram is the editor's (dirty,
 * undone by the workbench's Undo), and a save from either writes the model and its notation.
 */
class DiagramEditorTest {

	private static final long PAGE_TIMEOUT = 90_000;

	private IFile file;
	private StatechartEditor editor;
	private DiagramPage diagram;

	@BeforeEach
	void openTheGoalie() throws Exception {
		file = Ui.exampleModel("Diagrams", null, "Goalie");
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 900);
		editor = assertInstanceOf(StatechartEditor.class, IDE.openEditor(Ui.page(), file, StatechartEditor.ID));
		diagram = editor.getDiagram();
		assertTrue(diagram.isAvailable(), String.valueOf(diagram.getProblem()));
		assertTrue(editor.isDiagramShown(), "a statechart opens on its diagram");
		assertTrue(Ui.waitUntil(() -> "ready".equals(page("return document.body.dataset.kse")), PAGE_TIMEOUT),
				"the diagram page shows the model; it says: " + page("return document.getElementById('kse-status') ? document.getElementById('kse-status').textContent : document.body.textContent"));
	}

	@AfterEach
	void close() {
		Ui.page().closeAllEditors(false);
	}

	private Object page(String script) {
		return diagram.evaluate(script);
	}

	/** The text drawn on the diagram. */
	private String drawn() {
		return String.valueOf(page("return document.getElementById(window.kse.clientId).textContent"));
	}

	private Node state(String name) {
		for (var contents = editor.getModel().eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && name.equals(node.getName())) {
				return node;
			}
		}
		throw new AssertionError("no state " + name);
	}

	private static String id(Node node) {
		return node.eResource().getURIFragment(node);
	}

	private Object selectedInEditor() {
		return editor.getViewer().getStructuredSelection().getFirstElement();
	}

	@Test
	void aNameEditedInThePropertiesViewIsDrawnAndSavedWithTheDiagram() throws Exception {
		assertTrue(drawn().contains("Kick") && drawn().contains("Scan"), "the Goalie's states are drawn: " + drawn());
		Ui.screenshot("30-diagram-editor");

		// selected on the diagram: the editor's selection, which the Properties view shows
		Node kick = state("Kick");
		PropertySheet view = (PropertySheet) Ui.page().showView(IPageLayout.ID_PROP_SHEET, null, IWorkbenchPage.VIEW_VISIBLE);
		Ui.page().activate(editor);
		page("window.kse.select(['" + id(kick) + "']); return true");
		assertTrue(Ui.waitUntil(() -> selectedInEditor() == kick, 10_000), "a state selected on the diagram is the editor's selection: " + selectedInEditor());
		TabbedPropertySheetPage sheet = assertInstanceOf(TabbedPropertySheetPage.class, view.getCurrentPage());
		assertTrue(Ui.waitUntil(() -> sheet.getSelectedTab() != null, 5000));
		sheet.setSelectedTab("org.kse.ui.tab.state");
		Ui.settle(300);
		List<Text> texts = Ui.find(sheet.getControl(), Text.class);
		Text name = texts.stream().filter(text -> "Kick".equals(text.getText())).findFirst()
				.orElseThrow(() -> new AssertionError("the Properties view shows the state selected on the diagram"));

		// renamed in the Properties view: drawn on the diagram, the editor dirty
		name.setFocus();
		name.setText("KickBall");
		name.notifyListeners(SWT.DefaultSelection, null);
		assertEquals("KickBall", kick.getName());
		assertTrue(editor.isDirty());
		assertTrue(Ui.waitUntil(() -> drawn().contains("KickBall"), 10_000), "the diagram draws the new name: " + drawn());
		assertTrue(Ui.waitUntil(() -> "true".equals(page("return document.body.dataset.kseDirty")), 5000), "the page shows unsaved changes");
		Ui.screenshot("31-diagram-renamed-in-properties");

		// selected in the tree: selected on the diagram
		Node scan = state("Scan");
		editor.getViewer().setSelection(new org.eclipse.jface.viewers.StructuredSelection(scan), true);
		assertTrue(Ui.waitUntil(() -> id(scan).equals(page("return window.kse.selection().join(' ')")), 10_000),
				"the tree's selection is shown on the diagram: " + page("return window.kse.selection().join(' ')"));

		// saved from the editor: the model, and the diagram's notation beside it; the page is clean again
		editor.doSave(null);
		assertFalse(editor.isDirty());
		Path saved = Path.of(file.getLocationURI());
		assertEquals("KickBall", ((Node) StatechartResources.load(saved).eResource().getEObject(id(kick))).getName());
		Path notation = org.kse.notation.NotationFiles.beside(saved);
		assertTrue(Files.exists(notation), "the diagram's notation is saved beside the model");
		assertTrue(Files.readString(notation).contains(id(kick)), "with the positions of the states");
		assertTrue(Ui.waitUntil(() -> "false".equals(page("return document.body.dataset.kseDirty")), 5000), "the page shows the save");
		assertTrue(file.getParent().findMember(notation.getFileName().toString()) != null, "the workspace knows the notation file");
	}

	@Test
	void anEditOnTheDiagramIsTheEditorsToUndoAndToSave() throws Exception {
		Node scan = state("Scan");
		page("window.kse.dispatch({ kind: 'applyLabelEdit', labelId: '" + id(scan) + "#name', text: 'LookAround' }); return true");
		assertTrue(Ui.waitUntil(() -> "LookAround".equals(scan.getName()), 10_000), "the diagram renamed the editor's state");
		assertTrue(Ui.waitUntil(editor::isDirty, 5000), "the editor is dirty");
		editor.getViewer().expandAll();
		assertTrue(Ui.waitUntil(() -> treeShows("LookAround"), 5000),
				"the tree shows the new name");

		editor.getEditorSite().getActionBars().getGlobalActionHandler(ActionFactory.UNDO.getId()).run();
		assertEquals("Scan", scan.getName(), "the workbench's Undo takes the diagram's edit back");
		assertTrue(Ui.waitUntil(() -> drawn().contains("Scan") && !drawn().contains("LookAround"), 10_000), "and the diagram shows it");
		editor.getEditorSite().getActionBars().getGlobalActionHandler(ActionFactory.REDO.getId()).run();
		assertTrue(Ui.waitUntil(() -> drawn().contains("LookAround"), 10_000));

		// saved from the page's toolbar: the editor saves and is clean
		page("window.kse.run('save'); return true");
		assertTrue(Ui.waitUntil(() -> !editor.isDirty(), 10_000), "a save on the page is the editor's save");
		assertEquals("LookAround", ((Node) StatechartResources.load(Path.of(file.getLocationURI())).eResource().getEObject(id(scan))).getName());
		Ui.screenshot("32-diagram-edited-and-saved");

		editor.showDiagram(false);
		assertNotNull(editor.getEditorSite().getActionBars().getGlobalActionHandler(ActionFactory.DELETE.getId()), "the tree's Delete on the Tree tab");
		editor.showDiagram(true);
		assertEquals(null, editor.getEditorSite().getActionBars().getGlobalActionHandler(ActionFactory.DELETE.getId()),
				"the page's own Delete on the Diagram tab (its text fields need the key)");
	}

	@Test
	void aBrokenGuardIsMarkedOnTheDiagramAndTheKseCommandsRunFromIt() throws Exception {
		var transition = editor.getModel().getTransitions().stream().filter(t -> t.getTE() != null && t.getTE().contains("ballfound()>0")).findFirst()
				.orElseThrow(() -> new AssertionError("a guard to break"));
		String id = transition.eResource().getURIFragment(transition);
		// as the Properties view applies an expression: a command on the editor's stack
		var domain = editor.getEditingDomain();
		domain.getCommandStack().execute(org.eclipse.emf.edit.command.SetCommand.create(domain, transition,
				org.kse.model.statechart.StatechartPackage.Literals.TRANSITION__TE, transition.getTE().replace("ballfound()>0", "ballfound()>")));
		assertTrue(Ui.waitUntil(() -> Boolean.TRUE.equals(page("return document.querySelector('#kse-diagram [data-id=\"" + id + "\"] .sprotty-issue') !== null")), 15_000),
				"the diagram marks the broken guard");
		Ui.screenshot("33-diagram-marks-a-broken-guard");

		// the KSE menu's Validate, with the Diagram tab in front, checks the editor's model file
		editor.doSave(null);
		Ui.page().activate(editor);
		assertTrue(editor.isDiagramShown());
		Ui.run("org.kse.ui.validate");
		assertTrue(Ui.waitUntil(() -> errorsNaming(transition.getName()) > 0, 20_000), "Validate from the diagram marks the transition");
	}

	@Test
	void aProjectOutsideTheWorkspaceFolderHasItsDiagramToo() throws Exception {
		Path elsewhere = Files.createTempDirectory("kse-elsewhere");
		IFile model = Ui.exampleModel("Elsewhere", elsewhere, "Attacker");
		IProject outside = model.getProject();
		try {
			assertFalse(Path.of(model.getLocationURI()).startsWith(Path.of(ResourcesPlugin.getWorkspace().getRoot().getLocationURI())),
					"the project lies outside the workspace folder");
			StatechartEditor attacker = assertInstanceOf(StatechartEditor.class, IDE.openEditor(Ui.page(), model, StatechartEditor.ID));
			assertTrue(Ui.waitUntil(() -> "ready".equals(attacker.getDiagram().evaluate("return document.body.dataset.kse")), PAGE_TIMEOUT),
					"its diagram is shown: " + attacker.getDiagram().evaluate("return document.body.textContent"));
			Ui.page().closeEditor(attacker, false);
		} finally {
			outside.delete(true, true, null);
		}
	}

	@Test
	void aPageOpensOnlyWhatAnEditorHasOpen() throws Exception {
		String url = diagram.getBrowser().getUrl();
		assertTrue(url.startsWith("http://127.0.0.1:") && url.contains("token="), "served on loopback with a token: " + url);
		String base = url.substring(0, url.indexOf("&model="));
		for (String model : List.of("editor-00000000000000000000000000000000/Goalie.stct", "Diagrams/Goalie.stct", "../Diagrams/Goalie.stct")) {
			diagram.getBrowser().setUrl(base + "&model=" + java.net.URLEncoder.encode(model, java.nio.charset.StandardCharsets.UTF_8));
			// this page's own refusal (it names the file asked for), not the last page's
			assertTrue(Ui.waitUntil(() -> String.valueOf(page("return document.body.textContent")).contains("refused: " + model + " is not open in a statechart editor"), 30_000),
					model + " is refused, and the page says why: " + page("return document.body.textContent"));
			assertEquals("error", page("return document.body.dataset.kse"), "nothing is shown");
		}
	}

	private int errorsNaming(String name) {
		try {
			int count = 0;
			for (var marker : file.findMarkers(org.kse.ui.model.ModelMarkers.MARKER, false, IResource.DEPTH_ZERO)) {
				if (marker.getAttribute(org.eclipse.core.resources.IMarker.SEVERITY, -1) == org.eclipse.core.resources.IMarker.SEVERITY_ERROR
						&& marker.getAttribute(org.eclipse.core.resources.IMarker.MESSAGE, "").contains(name)) {
					count++;
				}
			}
			return count;
		} catch (org.eclipse.core.runtime.CoreException e) {
			return -1;
		}
	}

	private boolean treeShows(String text) {
		return shows(editor.getViewer().getTree().getItems(), text);
	}

	private static boolean shows(org.eclipse.swt.widgets.TreeItem[] items, String text) {
		for (var item : items) {
			if (item.getText().contains(text) || shows(item.getItems(), text)) {
				return true;
			}
		}
		return false;
	}
}
