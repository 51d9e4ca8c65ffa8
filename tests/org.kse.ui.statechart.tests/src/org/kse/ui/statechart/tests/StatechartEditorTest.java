package org.kse.ui.statechart.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CCombo;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.actions.ActionFactory;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.views.properties.PropertySheet;
import org.eclipse.ui.views.properties.tabbed.ISection;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;
import org.kse.ui.statechart.editor.StatechartEditor;
import org.kse.model.edit.StatechartEdits;
import org.kse.ui.statechart.editor.properties.ModelSection;
import org.kse.ui.statechart.editor.properties.StateSection;
import org.kse.ui.statechart.editor.properties.TransitionSection;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * The statechart editor as a user works in it: the tabbed Properties view (State, Transition,
 * Model, Advanced), states and transitions added and deleted from the context menu, states
 * moved, every edit undoable; Revert, and a file changed on disk reloaded.
 */
@ExtendWith(UnexpectedDialogs.class)
class StatechartEditorTest {

	private IFile file;
	private StatechartEditor editor;

	@BeforeEach
	void openTheGoalie() throws Exception {
		file = Ui.exampleModel("Editing", null, "Goalie");
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 860);
		editor = assertInstanceOf(StatechartEditor.class, IDE.openEditor(Ui.page(), file, StatechartEditor.ID));
		// these tests are about the Tree tab and its actions (the Diagram tab: DiagramEditorTest)
		editor.showDiagram(false);
	}

	@AfterEach
	void close() {
		Ui.page().closeAllEditors(false);
	}

	private Node state(String name) {
		for (var contents = editor.getModel().eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && name.equals(node.getName())) {
				return node;
			}
		}
		throw new AssertionError("no state " + name);
	}

	private Transition transition(String name) {
		return editor.getModel().getTransitions().stream().filter(t -> name.equals(t.getName())).findFirst()
				.orElseThrow(() -> new AssertionError("no transition " + name));
	}

	/** Selects an element in the editor and shows its tab in the Properties view; the section of that tab. */
	private <T extends ISection> T show(Object element, String tab, Class<T> type) throws Exception {
		PropertySheet view = (PropertySheet) Ui.page().showView(IPageLayout.ID_PROP_SHEET, null, IWorkbenchPage.VIEW_VISIBLE);
		Ui.page().activate(editor);
		editor.getViewer().setSelection(StructuredSelection.EMPTY);
		editor.getViewer().setSelection(new StructuredSelection(element), true);
		Ui.settle(300);
		TabbedPropertySheetPage sheet = assertInstanceOf(TabbedPropertySheetPage.class, view.getCurrentPage(), "tabbed properties");
		sheet.setSelectedTab(tab);
		Ui.settle(300);
		assertNotNull(sheet.getSelectedTab(), tab);
		assertEquals(tab, sheet.getSelectedTab().getId());
		return Arrays.stream(sheet.getCurrentTab().getSections()).filter(type::isInstance).map(type::cast).findFirst()
				.orElseThrow(() -> new AssertionError("no " + type.getSimpleName() + " on " + tab));
	}

	/** The controls of the Properties view's page: where the sections' fields are. */
	private static Control properties() {
		PropertySheet view = (PropertySheet) Ui.page().findView(IPageLayout.ID_PROP_SHEET);
		return ((TabbedPropertySheetPage) view.getCurrentPage()).getControl();
	}

	private static void type(Text text, String value) {
		text.setFocus();
		text.setText(value);
		text.notifyListeners(SWT.DefaultSelection, null);
	}

	private void undo() {
		editor.getEditorSite().getActionBars().getGlobalActionHandler(ActionFactory.UNDO.getId()).run();
		Ui.settle(200);
	}

	@Test
	void theStateTabEditsNameTypeAndVariablesEachUndoable() throws Exception {
		Node kick = state("Kick");
		StateSection section = show(kick, "org.kse.ui.tab.state", StateSection.class);
		Control controls = properties();
		List<Text> texts = Ui.find(controls, Text.class);
		Text name = texts.stream().filter(text -> "Kick".equals(text.getText())).findFirst().orElseThrow(() -> new AssertionError("no name field"));
		assertTrue(texts.stream().anyMatch(text -> "0.2.2.3.5".equals(text.getText())), "the label is shown");
		CCombo kind = Ui.find(controls, CCombo.class).get(0);
		assertEquals("BASIC", kind.getText());
		Ui.screenshot("20-state-tab");

		type(name, "KickBall");
		assertEquals("KickBall", kick.getName(), "Enter in the name field renames the state");
		assertTrue(editor.isDirty());
		kind.select(Arrays.asList(kind.getItems()).indexOf("OR"));
		kind.notifyListeners(SWT.Selection, null);
		assertEquals("OR", kick.getType());
		undo();
		assertEquals("BASIC", kick.getType(), "the kind change is undone on its own");
		undo();
		assertEquals("Kick", kick.getName());
		assertFalse(editor.isDirty(), "back to the file");
	}

	@Test
	void theModelTabAddsAVariableThatAStateThenReads() throws Exception {
		ModelSection models = show(editor.getModel(), "org.kse.ui.tab.model", ModelSection.class);
		Variable variable = models.addVariable();
		assertEquals(List.of(variable), editor.getModel().getVariables());
		assertEquals("variable1", variable.getName());
		Ui.settle(200);
		Ui.screenshot("21-model-tab");

		Node scan = state("Scan");
		show(scan, "org.kse.ui.tab.state", StateSection.class);
		var table = Ui.find(properties(), org.eclipse.swt.widgets.Table.class).stream().filter(t -> (t.getStyle() & SWT.CHECK) != 0).findFirst()
				.orElseThrow(() -> new AssertionError("no variables list"));
		assertEquals(1, table.getItemCount(), "the model's variable is offered");
		table.getItem(0).setChecked(true);
		var event = new org.eclipse.swt.widgets.Event();
		event.item = table.getItem(0);
		event.detail = SWT.CHECK;
		table.notifyListeners(SWT.Selection, event);
		assertEquals(List.of(variable), scan.getVariables(), "Scan reads the variable");
		undo();
		assertEquals(List.of(), scan.getVariables());
		undo();
		assertEquals(List.of(), editor.getModel().getVariables());
	}

	@Test
	void theTransitionTabEditsTheGuardWithCompletionAndChecksItWhileTyped() throws Exception {
		Transition transition = transition("0.2.2.2_TO_playing");
		String before = transition.getTE();
		TransitionSection section = show(transition, "org.kse.ui.tab.transition", TransitionSection.class);
		var field = section.getExpression();
		assertEquals(before, field.getText(), "the field shows the expression");
		List<CCombo> combos = Ui.find(properties(), CCombo.class);
		assertTrue(combos.get(0).getText().contains("0.2.2.2") && combos.get(1).getText().contains("playing"), "source and target");

		var viewer = field.getViewer();
		var document = viewer.getDocument();
		viewer.getTextWidget().setFocus();
		document.set("[worldstate.State.GameStateMessage.player_s");
		viewer.setSelectedRange(document.getLength(), 0);
		viewer.doOperation(ISourceViewer.CONTENTASSIST_PROPOSALS);
		assertTrue(Ui.waitUntil(() -> document.get().endsWith("player_state()"), 5000), () -> "the only field is completed: " + document.get());
		Label problem = Ui.find(properties(), Label.class).stream().filter(label -> label.getText().startsWith("1:")).findFirst()
				.orElseThrow(() -> new AssertionError("the unfinished guard's problem is shown under the field"));
		assertTrue(problem.getText().contains("1:"), problem.getText());
		Ui.screenshot("22-transition-tab-guard-error");

		document.set("[worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING &&\n behavior.State.HeadToBMessage.ballfound()>0]");
		assertNull(ExpressionFieldSummary.of(field), "a correct guard has no problem");
		assertEquals(before, transition.getTE(), "nothing is changed while typing");
		// the user clicks elsewhere: the field loses the focus (sent here, as Xvfb has no window manager to move it)
		viewer.getTextWidget().notifyListeners(SWT.FocusOut, new org.eclipse.swt.widgets.Event());
		Ui.settle(300);
		assertEquals(document.get(), transition.getTE(), "set when the field loses the focus");
		Ui.screenshot("23-transition-tab-guard");
		undo();
		assertEquals(before, transition.getTE(), "one undo takes the whole edit back");
	}

	@Test
	void theAdvancedTabListsEveryAttribute() throws Exception {
		show(state("Stare"), "org.kse.ui.tab.advanced", ISection.class);
		var tree = Ui.find(properties(), org.eclipse.swt.widgets.Tree.class).get(0);
		List<String> shown = new ArrayList<>();
		for (var item : tree.getItems()) {
			shown.add(item.getText(0));
			Arrays.stream(item.getItems()).forEach(child -> shown.add(child.getText(0)));
		}
		assertTrue(shown.containsAll(List.of("Name", "Label", "Type", "Activity")), () -> "attributes: " + shown);
	}

	@Test
	void theContextMenuAddsAndDeletesStatesAndTransitionsAsOneUndoableStepEach() throws Exception {
		Node playing = state("playing");
		int children = playing.getChildren().size();
		editor.getViewer().setSelection(new StructuredSelection(playing), true);
		Menu menu = editor.getViewer().getControl().getMenu();
		menu.notifyListeners(SWT.Show, new org.eclipse.swt.widgets.Event());
		List<String> items = Arrays.stream(menu.getItems()).map(item -> item.getText().replaceFirst("\t.*", "")).toList();
		assertTrue(items.containsAll(List.of("New State", "New Transition (self-loop)", "Delete", "Edit Activity...", "Validate")),
				() -> "the context menu: " + items);
		assertTrue(items.stream().noneMatch(item -> item.contains("Team")), () -> "no menus of the file in the model's menu: " + items);
		MenuItem basic = Arrays.stream(menu.getItems()).filter(item -> "New State".equals(item.getText())).findFirst().orElseThrow().getMenu().getItems()[2];
		basic.getParent().notifyListeners(SWT.Show, new org.eclipse.swt.widgets.Event());
		assertEquals("BASIC", basic.getText());
		basic.notifyListeners(SWT.Selection, new org.eclipse.swt.widgets.Event());
		menu.notifyListeners(SWT.Hide, new org.eclipse.swt.widgets.Event());
		Ui.settle(300);
		assertEquals(children + 1, playing.getChildren().size(), "a state was added inside 'playing'");
		Node added = playing.getChildren().get(children);
		assertEquals("NewActivity", added.getName());
		assertEquals("BASIC", added.getType());
		assertEquals("0.2.2.3." + (children + 1), added.getLabel(), "with the next free label");
		assertEquals(added, editor.getViewer().getStructuredSelection().getFirstElement(), "and selected");
		Ui.screenshot("24-state-added");

		Node kick = state("Kick");
		editor.execute(StatechartEdits.newTransition(editor.getEditingDomain(), editor.getModel(), List.of(kick, added)));
		Transition link = editor.getModel().getTransitions().get(editor.getModel().getTransitions().size() - 1);
		assertEquals(kick, link.getSource());
		assertEquals(added, link.getTarget());
		assertEquals("Kick_TO_NewActivity", link.getName(), "named as Label names transitions");

		int transitions = editor.getModel().getTransitions().size();
		long touchingKick = editor.getModel().getTransitions().stream().filter(t -> t.getSource() == kick || t.getTarget() == kick).count();
		editor.getViewer().setSelection(new StructuredSelection(kick), true);
		editor.getEditorSite().getActionBars().getGlobalActionHandler(ActionFactory.DELETE.getId()).run();
		Ui.settle(200);
		assertFalse(playing.getChildren().contains(kick), "Kick is deleted");
		assertEquals(transitions - touchingKick, editor.getModel().getTransitions().size(), "with every transition that touched it");
		assertTrue(editor.getModel().getTransitions().stream().noneMatch(t -> t.getSource() == null || t.getTarget() == null), "no dangling transition");
		undo();
		assertTrue(playing.getChildren().contains(kick), "undone");
		assertEquals(transitions, editor.getModel().getTransitions().size(), "its transitions are back");
		assertTrue(editor.getModel().getTransitions().stream().filter(t -> t.getSource() == kick || t.getTarget() == kick).count() == touchingKick);
	}

	@Test
	void aStateIsMovedIntoAnotherAndNeverIntoItself() throws Exception {
		Node special = state("SpecialAction");
		Node nonPlaying = state("nonPlaying");
		var move = StatechartEdits.move(editor.getEditingDomain(), editor.getModel(), List.of(nonPlaying), state("NoPlay"));
		assertFalse(move.canExecute(), "not into a state inside itself");
		editor.execute(StatechartEdits.move(editor.getEditingDomain(), editor.getModel(), List.of(special), nonPlaying));
		assertEquals(nonPlaying, special.eContainer(), "moved");
		Ui.settle(200);
		undo();
		assertEquals("_open_option_SpecialAction_close_option_", ((Node) special.eContainer()).getName(), "moved back");
	}

	@Test
	void revertGoesBackToTheFileAndAChangeOnDiskIsReloaded() throws Exception {
		editor.execute(StatechartEdits.delete(editor.getEditingDomain(), editor.getModel(), List.of(state("Scan"))));
		assertTrue(editor.isDirty());
		var revert = editor.getEditorSite().getActionBars().getGlobalActionHandler(ActionFactory.REVERT.getId());
		Ui.settle(200);
		assertTrue(revert.isEnabled(), "File > Revert is offered for a changed model");
		revert.run();
		assertFalse(editor.isDirty(), "reverted");
		assertNotNull(state("Scan"), "the deleted state is back");
		assertFalse(editor.getEditorSite().getActionBars().getGlobalActionHandler(ActionFactory.UNDO.getId()).isEnabled(), "nothing to undo");

		Path path = Path.of(file.getLocationURI());
		Files.writeString(path, Files.readString(path).replace("name=\"Stare\"", "name=\"Watch\""));
		file.refreshLocal(IResource.DEPTH_ZERO, null);
		assertTrue(Ui.waitUntil(() -> {
			try {
				state("Watch");
				return true;
			} catch (AssertionError notYet) {
				return false;
			}
		}, 10_000), "the editor without unsaved edits shows the file as it is now");
	}

	@Test
	void labelFromTheEditorAsksToSaveFirstAndTheEditorShowsTheNewLabels() throws Exception {
		Node kick = state("Kick");
		editor.execute(org.eclipse.emf.edit.command.SetCommand.create(editor.getEditingDomain(), kick,
				org.kse.model.statechart.StatechartPackage.Literals.NODE__LABEL, "9.9"));
		assertTrue(editor.isDirty());
		Ui.page().activate(editor);
		editor.getViewer().setSelection(new StructuredSelection(kick), true);
		Ui.Answered asked = Ui.whenShown(shell -> shell.getParent() != null && Ui.offers(shell, "Save"), dialog -> {
			Ui.screenshotOf(dialog, "25-save-before-label");
			Ui.press(dialog, "Save");
		});
		Ui.run("org.kse.ui.label");
		asked.check("save-before-labelling (the user is asked to save the edited model first)");
		assertTrue(Ui.waitUntil(() -> !editor.isDirty() && "0.2.2.3.5".equals(state("Kick").getLabel()), 20_000),
				"saved, labelled, and the editor shows the labels again");
	}

	@Test
	void aCompositeIsCopiedAndPastedIntoAnotherWithNewLabelsAndOneUndo() throws Exception {
		Node followBall = state("followBall");
		Node nonPlaying = state("nonPlaying");
		int children = nonPlaying.getChildren().size();
		int transitions = editor.getModel().getTransitions().size();
		var actions = editor.getEditorSite().getActionBars();
		editor.getViewer().setSelection(new StructuredSelection(followBall), true);
		actions.getGlobalActionHandler(ActionFactory.COPY.getId()).run();
		editor.getViewer().setSelection(new StructuredSelection(nonPlaying), true);
		Ui.settle(100);
		assertTrue(actions.getGlobalActionHandler(ActionFactory.PASTE.getId()).isEnabled(), "Paste is offered after Copy");
		actions.getGlobalActionHandler(ActionFactory.PASTE.getId()).run();
		Ui.settle(300);
		assertEquals(children + 1, nonPlaying.getChildren().size(), "pasted into nonPlaying");
		Node pasted = nonPlaying.getChildren().get(children);
		assertEquals("followBall", pasted.getName());
		assertEquals("0.2.2.4.5", pasted.getLabel(), "the next label of nonPlaying");
		assertTrue(editor.getModel().getTransitions().size() > transitions, "with its inner transitions");
		List<String> labels = new ArrayList<>();
		editor.getModel().eAllContents().forEachRemaining(each -> {
			if (each instanceof Node node) {
				labels.add(node.getLabel());
			}
		});
		assertEquals(labels.size(), new java.util.HashSet<>(labels).size(), () -> "labels stay unique: " + labels);
		assertEquals(pasted, editor.getViewer().getStructuredSelection().getFirstElement(), "the pasted state is selected");
		Ui.screenshot("26-pasted-composite");
		undo();
		assertEquals(children, nonPlaying.getChildren().size(), "one undo takes the paste back");
		assertEquals(transitions, editor.getModel().getTransitions().size());
	}

	/** The problem line of an expression field, as the section shows it. */
	private static final class ExpressionFieldSummary {
		static String of(org.kse.ui.statechart.editor.ExpressionField field) {
			return org.kse.ui.statechart.editor.ExpressionField.summary(field.problems());
		}
	}
}
