package org.kse.ui.statechart.tests;

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
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.ui.statechart.diagram.DiagramPage;
import org.kse.ui.statechart.diagram.WorkspaceDiagramServer;
import org.kse.ui.statechart.editor.StatechartEditor;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * The statechart editor's Diagram tab inside the KSE workbench: the diagram page in an SWT Browser,
 * served by the workbench's diagram server, editing the editor's own model. Selections go both
 * ways, a rename in the Properties view is drawn, an edit on the diagram is the editor's (dirty,
 * undone by the workbench's Undo), and a save from either writes the model and its notation.
 */
@ExtendWith(UnexpectedDialogs.class)
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

	/**
	 * The texts of the diagram the page holds (the client's model: the page draws only what lies in
	 * its window, and it opens at a readable zoom that does not show the whole Goalie).
	 */
	private String drawn() {
		return String.valueOf(page("""
				const texts = [];
				if (window.kse && document.body.dataset.kse === 'ready') {
					(function walk(element) {
						if (element.text) { texts.push(element.text); }
						(element.children || []).forEach(walk);
					})(window.kse.modelRoot());
				}
				return texts.join(' ');"""));
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
	void aTabWhoseConnectionIsLostOpensAgainByItselfWithItsUnsavedEdits() throws Exception {
		Node scan = state("Scan");
		page("window.kse.dispatch({ kind: 'applyLabelEdit', labelId: '" + id(scan) + "#name', text: 'LookAround' }); return true");
		assertTrue(Ui.waitUntil(() -> "LookAround".equals(scan.getName()), 10_000), "the diagram renamed the editor's state");
		page("window.kse.select(['" + id(scan) + "']); return true");
		assertTrue(Ui.waitUntil(() -> id(scan).equals(page("return window.kse.selection().join(' ')")), 10_000));

		// the server goes away with every connection (as when it fails): the tab opens again on its own
		WorkspaceDiagramServer.stop();
		assertTrue(Ui.waitUntil(() -> "reconnected".equals(page("return document.body.dataset.kseConnection"))
				&& "ready".equals(page("return document.body.dataset.kse")), PAGE_TIMEOUT),
				"the page reconnects by itself; it says: " + page("return [document.body.dataset.kse, document.body.dataset.kseConnection, location.href, document.getElementById('kse-status').textContent].join(' | ')"));
		assertTrue(String.valueOf(page("return JSON.stringify(window.kse.messages())")).contains("Reconnected"), "and says so: " + page("return JSON.stringify(window.kse.messages())"));
		Ui.screenshot("34-diagram-reconnected");
		assertTrue(drawn().contains("LookAround"), "the unsaved rename is still drawn: " + drawn());
		assertEquals(id(scan), page("return window.kse.selection().join(' ')"), "the selection is kept");
		assertTrue(editor.isDirty(), "and still unsaved in the editor");
		assertTrue(Ui.waitUntil(() -> "true".equals(page("return document.body.dataset.kseDirty")), 5000), "the page shows unsaved changes");

		// the command stack is the editor's: the page's Undo still takes the rename back, its Save saves
		page("window.kse.run('undo'); return true");
		assertTrue(Ui.waitUntil(() -> "Scan".equals(scan.getName()), 10_000), "undo after reconnecting");
		page("window.kse.run('redo'); return true");
		assertTrue(Ui.waitUntil(() -> "LookAround".equals(scan.getName()), 10_000), "redo after reconnecting");
		page("window.kse.run('save'); return true");
		assertTrue(Ui.waitUntil(() -> !editor.isDirty(), 10_000), "a save from the reconnected page");
		assertEquals("LookAround", ((Node) StatechartResources.load(Path.of(file.getLocationURI())).eResource().getEObject(id(scan))).getName());
	}

	@Test
	void aFileChangedOnDiskIsReloadedWhenCleanAndOtherwiseTheUserChooses() throws Exception {
		Path onDisk = Path.of(file.getLocationURI());
		String original = Files.readString(onDisk);

		// no unsaved edits: another program's change is shown at once, in the tree and on the diagram
		file.setContents(new java.io.ByteArrayInputStream(original.replace("name=\"Kick\"", "name=\"KickedOnDisk\"").getBytes(java.nio.charset.StandardCharsets.UTF_8)),
				IResource.FORCE, null);
		assertTrue(Ui.waitUntil(() -> named("KickedOnDisk") != null, 10_000), "the editor reloads the changed file");
		assertTrue(Ui.waitUntil(() -> drawn().contains("KickedOnDisk"), PAGE_TIMEOUT), "and the diagram shows it: " + drawn());
		assertFalse(editor.isDirty());

		// unsaved edits: the user is asked; Keep My Edits keeps them, and their save then replaces the change knowingly
		Node scan = state("Scan");
		page("window.kse.dispatch({ kind: 'applyLabelEdit', labelId: '" + id(scan) + "#name', text: 'LookAround' }); return true");
		assertTrue(Ui.waitUntil(() -> "LookAround".equals(scan.getName()) && editor.isDirty(), 10_000));
		var asked = answering("Keep My Edits");
		file.setContents(new java.io.ByteArrayInputStream(Files.readString(onDisk).replace("name=\"Stare\"", "name=\"StareOnDisk\"").getBytes(java.nio.charset.StandardCharsets.UTF_8)),
				IResource.FORCE, null);
		assertTrue(Ui.waitUntil(() -> asked.get() != null, 20_000), "the user is asked");
		assertTrue(asked.get().contains("changed on disk by another program"), asked.get());
		assertEquals("LookAround", scan.getName(), "the edits are kept");
		assertTrue(editor.isDirty());
		editor.doSave(null);
		assertFalse(editor.isDirty(), "saved without a second question");
		assertTrue(Files.readString(onDisk).contains("LookAround") && !Files.readString(onDisk).contains("StareOnDisk"));

		// Reload drops the edits for the file's contents
		page("window.kse.dispatch({ kind: 'applyLabelEdit', labelId: '" + id(state("LookAround")) + "#name', text: 'Dropped' }); return true");
		assertTrue(Ui.waitUntil(editor::isDirty, 10_000));
		var reload = answering("Reload");
		file.setContents(new java.io.ByteArrayInputStream(Files.readString(onDisk).replace("name=\"ApproachBall\"", "name=\"ApproachOnDisk\"").getBytes(java.nio.charset.StandardCharsets.UTF_8)),
				IResource.FORCE, null);
		assertTrue(Ui.waitUntil(() -> reload.get() != null && named("ApproachOnDisk") != null, 20_000), "reloaded from disk");
		assertFalse(editor.isDirty());
		assertEquals(null, named("Dropped"));
		assertTrue(Ui.waitUntil(() -> drawn().contains("ApproachOnDisk") && !drawn().contains("Dropped"), PAGE_TIMEOUT), "the diagram shows the file: " + drawn());

		// a change the editor was never told of (the workspace not refreshed): Save asks before overwriting it
		page("window.kse.dispatch({ kind: 'applyLabelEdit', labelId: '" + id(state("ApproachOnDisk")) + "#name', text: 'Mine' }); return true");
		assertTrue(Ui.waitUntil(editor::isDirty, 10_000));
		String theirs = Files.readString(onDisk).replace("name=\"Stare\"", "name=\"Theirs\"");
		Files.writeString(onDisk, theirs);
		var overwrite = answering("No");
		editor.doSave(null);
		assertTrue(overwrite.get() != null && overwrite.get().contains("has been changed on disk"), "Save asks: " + overwrite.get());
		assertEquals(theirs, Files.readString(onDisk), "answered No, the other program's change stays");
		assertTrue(editor.isDirty(), "and the edits stay unsaved");
	}

	/** A state of the editor's model by name, or null. */
	private Node named(String name) {
		for (var contents = editor.getModel().eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && name.equals(node.getName())) {
				return node;
			}
		}
		return null;
	}

	/** Answers the next dialog that offers {@code button} with it (within 20 s); holds the dialog's text once answered. */
	private static java.util.concurrent.atomic.AtomicReference<String> answering(String button) {
		var asked = new java.util.concurrent.atomic.AtomicReference<String>();
		Ui.whenShown(shell -> Ui.offers(shell, button), dialog -> {
			asked.set(String.join(" ", Ui.find(dialog, org.eclipse.swt.widgets.Label.class).stream().map(org.eclipse.swt.widgets.Label::getText).toList()));
			Ui.press(dialog, button);
		});
		return asked;
	}

	/**
	 * A behaviour of about 5,000 states, made as a user makes it (formulas transformed, no
	 * notation yet: the server arranges it), opens on the Diagram tab, takes an edit and saves.
	 */
	@Test
	void aStatechartOfFiveThousandStatesOpensEditsAndSaves() throws Exception {
		StringBuilder formula = new StringBuilder("Large\nlarge = Init.(" + String.join(" | ", java.util.stream.IntStream.range(0, 25).mapToObj(c -> "cap" + c).toList()) + ")+\n");
		for (int c = 0; c < 25; c++) {
			final int capability = c;
			formula.append("cap").append(c).append(" = ")
					.append(String.join(" | ", java.util.stream.IntStream.range(0, 50).mapToObj(a -> "Act" + capability + "_" + a + "+").toList())).append('\n');
		}
		var outcome = org.kse.transform.FormulaTransformation.run(formula.toString(), org.eclipse.emf.common.util.URI.createURI("Large.txt"), null);
		assertNotNull(outcome.model(), () -> "the formulas transform: " + outcome.issues());
		IFile large = file.getProject().getFile("Large.stct");
		StatechartResources.save(outcome.model(), Path.of(large.getLocationURI()));
		large.refreshLocal(IResource.DEPTH_ZERO, null);
		int states = 0;
		for (var contents = outcome.model().eAllContents(); contents.hasNext();) {
			states += contents.next() instanceof Node ? 1 : 0;
		}
		assertTrue(states >= 5000, "about 5,000 states: " + states);

		StatechartEditor big = assertInstanceOf(StatechartEditor.class, IDE.openEditor(Ui.page(), large, StatechartEditor.ID));
		DiagramPage page = big.getDiagram();
		long start = System.nanoTime();
		assertTrue(Ui.waitUntil(() -> "ready".equals(page.evaluate("return document.body.dataset.kse")), 5 * PAGE_TIMEOUT),
				"the diagram of " + states + " states is shown; the page says: " + page.evaluate("return document.getElementById('kse-status').textContent"));
		System.out.printf("DiagramEditorTest: %d states shown on the Diagram tab in %.1f s%n", states, (System.nanoTime() - start) / 1e9);
		Ui.screenshot("35-diagram-5000-states");

		Node last = null;
		for (var contents = big.getModel().eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && "Act24_49".equals(node.getName())) {
				last = node;
			}
		}
		assertNotNull(last, "the last activity's state");
		Node renamed = last;
		page.evaluate("window.kse.dispatch({ kind: 'applyLabelEdit', labelId: '" + id(renamed) + "#name', text: 'LastOne' }); return true");
		assertTrue(Ui.waitUntil(() -> "LastOne".equals(renamed.getName()), 60_000), "the diagram renames a state of the big model");
		page.evaluate("window.kse.run('save'); return true");
		assertTrue(Ui.waitUntil(() -> !big.isDirty(), 60_000), "and saves it");
		Model saved = StatechartResources.load(Path.of(large.getLocationURI()));
		assertEquals("LastOne", ((Node) saved.eResource().getEObject(id(renamed))).getName());
		int savedStates = 0;
		for (var contents = saved.eAllContents(); contents.hasNext();) {
			savedStates += contents.next() instanceof Node ? 1 : 0;
		}
		assertEquals(states, savedStates, "no state is lost");
		assertTrue(Files.exists(org.kse.notation.NotationFiles.beside(Path.of(large.getLocationURI()))), "the layout is saved beside it");
		Ui.page().closeEditor(big, false);
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
			for (var marker : file.findMarkers(org.kse.ui.statechart.ModelMarkers.MARKER, false, IResource.DEPTH_ZERO)) {
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
