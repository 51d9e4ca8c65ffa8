package org.kse.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.ILogListener;
import org.eclipse.core.runtime.IStatus;
import org.eclipse.core.runtime.Platform;
import org.eclipse.core.runtime.jobs.IJobChangeEvent;
import org.eclipse.core.runtime.jobs.IJobChangeListener;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.core.runtime.jobs.JobChangeAdapter;
import org.eclipse.emf.common.util.URI;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.wizard.WizardDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.views.properties.PropertySheet;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.model.statechart.Node;
import org.kse.transform.FormulaTransformation;
import org.kse.ui.formula.FormulaEditor;
import org.kse.ui.statechart.editor.StatechartEditor;
import org.kse.ui.formula.wizards.NewFormulaWizard;
import org.kse.ui.wizards.NewProjectWizard;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * What a newcomer tripped over in the tutorial (issue 15): closing an editor while the Properties
 * view shows a state, Ctrl+Alt+G on the diagram, the root name New Formula chose, and formula
 * files that opened in the plain text editor. No step may show an error dialog or log an error.
 */
@ExtendWith(UnexpectedDialogs.class)
class NewcomerBugsTest {

	private static IProject project;
	private final List<IStatus> logged = new ArrayList<>();
	private final ILogListener logListener = (status, plugin) -> {
		if (status.getSeverity() == IStatus.ERROR) {
			logged.add(status);
		}
	};

	@BeforeAll
	static void createTheKseProject() throws Exception {
		project = ResourcesPlugin.getWorkspace().getRoot().getProject("Newcomer");
		if (!project.exists()) {
			NewProjectWizard.create(project, null, true, null);
		}
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 900);
	}

	@BeforeEach
	void listenToTheLog() {
		Platform.addLogListener(logListener);
	}

	@AfterEach
	void closeEditors() {
		Ui.page().closeAllEditors(false);
		Ui.settle(200);
		Platform.removeLogListener(logListener);
	}

	private String errorsLogged() {
		return logged.stream().map(status -> status.getMessage() + (status.getException() == null ? "" : " (" + status.getException() + ")"))
				.collect(Collectors.joining("; "));
	}

	private StatechartEditor openTheGoalie() throws Exception {
		return assertInstanceOf(StatechartEditor.class, IDE.openEditor(Ui.page(), project.getFile("models/Goalie.stct"), StatechartEditor.ID));
	}

	private static Node state(StatechartEditor editor, String name) {
		for (var contents = editor.getModel().eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && name.equals(node.getName())) {
				return node;
			}
		}
		throw new AssertionError("no state " + name);
	}

	/** Selects the state on the Tree tab, shows the Properties view and there the tab; the view's page. */
	private static TabbedPropertySheetPage showProperties(StatechartEditor editor, String state, String tab) throws Exception {
		editor.showDiagram(false);
		PropertySheet view = (PropertySheet) Ui.page().showView(IPageLayout.ID_PROP_SHEET, null, IWorkbenchPage.VIEW_VISIBLE);
		Ui.page().activate(editor);
		editor.getViewer().setSelection(new StructuredSelection(state(editor, state)), true);
		Ui.settle(300);
		TabbedPropertySheetPage sheet = assertInstanceOf(TabbedPropertySheetPage.class, view.getCurrentPage(), "the tabbed properties of the statechart");
		sheet.setSelectedTab(tab);
		Ui.settle(300);
		assertNotNull(sheet.getSelectedTab(), tab);
		assertEquals(tab, sheet.getSelectedTab().getId());
		return sheet;
	}

	@Test
	void closingTheEditorWhileThePropertiesShowAStateShowsNoError() throws Exception {
		StatechartEditor editor = openTheGoalie();
		showProperties(editor, "Stare", "org.kse.ui.tab.state");
		Ui.screenshot("newcomer-1-properties-of-a-state");
		Ui.page().closeEditor(editor, false);
		Ui.settle(500);
		assertTrue(logged.isEmpty(), () -> "closing the editor logged: " + errorsLogged());

		// and the same once the Advanced tab has been shown (its property table made and disposed)
		editor = openTheGoalie();
		showProperties(editor, "Stare", "org.kse.ui.tab.advanced");
		showProperties(editor, "Kick", "org.kse.ui.tab.state");
		Ui.page().closeEditor(editor, false);
		Ui.settle(500);
		Ui.screenshot("newcomer-2-editor-closed");
		assertTrue(logged.isEmpty(), () -> "closing the editor after the Advanced tab logged: " + errorsLogged());
		assertFalse(Arrays.stream(Ui.page().getEditorReferences()).anyMatch(reference -> "Goalie.stct".equals(reference.getName())), "the editor is closed");
	}

	/** The Goalie on its Diagram tab, the page ready. */
	private StatechartEditor openTheGoaliesDiagram() throws Exception {
		StatechartEditor editor = openTheGoalie();
		var diagram = editor.getDiagram();
		assertTrue(diagram.isAvailable(), String.valueOf(diagram.getProblem()));
		editor.showDiagram(true);
		assertTrue(Ui.waitUntil(() -> "ready".equals(diagram.evaluate("return document.body.dataset.kse")), 90_000), "the diagram page shows the model");
		return editor;
	}

	/** Presses the key with the modifiers once, as a person does, with the keyboard on the diagram. */
	private static void pressOnTheDiagram(StatechartEditor editor, char key, int... modifiers) {
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().forceActive();
		Ui.page().activate(editor);
		editor.getDiagram().getBrowser().setFocus();
		Ui.settle(500);
		assertTrue(editor.getDiagram().getBrowser().isFocusControl(), "the diagram has the keyboard");
		for (int modifier : modifiers) {
			key(SWT.KeyDown, modifier, '\0');
		}
		key(SWT.KeyDown, key, key);
		key(SWT.KeyUp, key, key);
		for (int index = modifiers.length - 1; index >= 0; index--) {
			key(SWT.KeyUp, modifiers[index], '\0');
		}
	}

	@Test
	void ctrlAltGPressedOnceOnTheDiagramGeneratesOnce() throws Exception {
		StatechartEditor editor = openTheGoaliesDiagram();

		// the command may be asked more than once for one press (SWT's Browser on GTK): what counts is what it does
		List<String> runs = new ArrayList<>();
		IJobChangeListener counter = new JobChangeAdapter() {
			@Override
			public void scheduled(IJobChangeEvent event) {
				if (event.getJob().getName().startsWith("Generating code")) {
					runs.add(event.getJob().getName());
				}
			}
		};
		Job.getJobManager().addJobChangeListener(counter);
		try {
			pressOnTheDiagram(editor, 'g', SWT.CTRL, SWT.ALT);
			// every copy of the key has arrived well within this
			Ui.waitUntil(() -> runs.size() > 1, 3_000);
			Ui.settle(1_000);
		} finally {
			Job.getJobManager().removeJobChangeListener(counter);
		}
		assertTrue(Ui.waitUntil(() -> Job.getJobManager().find(null).length == 0
				|| Arrays.stream(Job.getJobManager().find(null)).noneMatch(job -> job.getName().startsWith("Generating code")), 60_000), "the generation ends");
		Ui.screenshot("newcomer-3-generated-from-the-diagram");
		assertEquals(1, runs.size(), () -> "Ctrl+Alt+G pressed once generated " + runs.size() + " times: " + runs);
		assertTrue(project.getFolder("src/statecharts/Goalie").exists(), "the Goalie's code is generated");
		assertTrue(logged.isEmpty(), () -> "generating logged: " + errorsLogged());
	}

	@Test
	void ctrlZPressedOnceOnTheDiagramUndoesOneEdit() throws Exception {
		StatechartEditor editor = openTheGoaliesDiagram();
		var stack = editor.getEditingDomain().getCommandStack();
		List<String> renamed = List.of("Stare", "Kick", "Scan");
		for (String name : renamed) {
			Node state = state(editor, name);
			stack.execute(org.eclipse.emf.edit.command.SetCommand.create(editor.getEditingDomain(), state, state.eClass().getEStructuralFeature("name"),
					name + "Renamed"));
		}
		Ui.settle(500);
		pressOnTheDiagram(editor, 'z', SWT.CTRL);
		// every copy of the key has arrived well within this
		Ui.settle(2_000);
		List<String> undone = renamed.stream().filter(name -> editorHasState(editor, name)).toList();
		Ui.screenshot("newcomer-6-undone-on-the-diagram");
		assertEquals(List.of("Scan"), undone, "one press of Ctrl+Z takes back the last edit only");
		editor.doRevert();
	}

	private static boolean editorHasState(StatechartEditor editor, String name) {
		for (var contents = editor.getModel().eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && name.equals(node.getName())) {
				return true;
			}
		}
		return false;
	}

	private static void key(int type, int keyCode, char character) {
		Event event = new Event();
		event.type = type;
		event.keyCode = keyCode;
		event.character = character;
		assertTrue(Ui.display().post(event), "the display takes the key");
		Ui.settle(50);
	}

	@Test
	void newFormulaNamesTheBehaviourAfterTheFileAsAUserWrites() throws Exception {
		NewFormulaWizard wizard = new NewFormulaWizard();
		wizard.init(PlatformUI.getWorkbench(), new StructuredSelection(project.getFolder("models")));
		WizardDialog dialog = new WizardDialog(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell(), wizard);
		dialog.setBlockOnOpen(false);
		dialog.open();
		Text fileName = Ui.find(dialog.getShell(), Text.class).stream().filter(text -> text.getText().endsWith(".liveness")).findFirst()
				.orElseThrow(() -> new AssertionError("no file name field offering a .liveness file"));
		assertEquals("Behaviour.liveness", fileName.getText(), "new formulas are .liveness files");
		fileName.setText("keeper_liveness");
		Ui.settle(200);
		Ui.screenshotOf(dialog.getShell(), "newcomer-4-new-formula");
		Ui.press(Ui.button(dialog.getShell(), "Finish"));
		assertTrue(Ui.waitUntil(() -> dialog.getShell() == null || dialog.getShell().isDisposed(), 20_000), "the wizard finishes");

		IFile formula = project.getFile("models/keeper_liveness.liveness");
		assertTrue(formula.exists(), "the wizard adds .liveness to the name typed");
		String text;
		try (var in = formula.getContents()) {
			text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
		}
		assertTrue(text.lines().anyMatch(line -> line.startsWith("keeper = ")), () -> "the behaviour is keeper:\n" + text);
		var outcome = FormulaTransformation.run(text, URI.createURI(formula.getName()), null);
		assertEquals("keeper", outcome.model().getName(), "the model, so the generated code's folder, is keeper");
		assertInstanceOf(FormulaEditor.class, Ui.page().getActiveEditor(), "the new formulas open in the formula editor");

		assertEquals("goalie", NewFormulaWizard.behaviourName("Goalie.liveness"));
		assertEquals("keeperBall", NewFormulaWizard.behaviourName("KeeperBall.liveness"));
		assertEquals("keeper", NewFormulaWizard.behaviourName("Keeper formulas.txt"));
		assertEquals("ballKeeperV2", NewFormulaWizard.behaviourName("ball-keeper v2.liveness"));
		assertEquals("behaviour2v2", NewFormulaWizard.behaviourName("2v2.liveness"));
		assertEquals("behaviour", NewFormulaWizard.behaviourName("-.liveness"));
		assertEquals("liveness", NewFormulaWizard.behaviourName("liveness.liveness"), "a name that is only the kind stays");
		assertTrue(logged.isEmpty(), () -> "the wizard logged: " + errorsLogged());
	}

	private IFile file(IProject in, String path, String text) throws Exception {
		IFile file = in.getFile(path);
		var contents = new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8));
		if (file.exists()) {
			file.setContents(contents, true, false, null);
		} else {
			file.create(contents, true, null);
		}
		return file;
	}

	private static IEditorPart open(IFile file) throws Exception {
		// what a double click in the Project Explorer does
		return IDE.openEditor(Ui.page(), file);
	}

	@Test
	void formulaFilesOpenInTheFormulaEditorAndOtherTextFilesDoNot() throws Exception {
		assertInstanceOf(FormulaEditor.class, open(project.getFile("models/Goalie.liveness")), "the example's formulas");

		String original = "Keeper\nkeeper = Init.(Scan+ | Kick)+\n";
		IEditorPart keeper = open(file(project, "models/Keeper.txt", original));
		assertInstanceOf(FormulaEditor.class, keeper, "the original tool's formula file, in a KSE project");
		Ui.screenshot("newcomer-5-txt-formula-in-the-formula-editor");
		String commented = "// the keeper\n\nkeeper = Init.(Scan+ | Kick)+\n";
		assertInstanceOf(FormulaEditor.class, open(file(project, "models/Commented.txt", commented)), "formulas after a comment");

		IEditorPart notes = open(file(project, "models/notes.txt", "Ideas for the keeper:\nstay on the line, dive late.\n"));
		assertFalse(notes instanceof FormulaEditor, "notes stay in the text editor");
		IEditorPart cmake = open(file(project, "src/CMakeLists.txt", "cmake_minimum_required(VERSION 3.16)\nproject(robots CXX)\n"));
		assertFalse(cmake instanceof FormulaEditor, "a CMakeLists.txt stays in the text editor");

		IProject plain = ResourcesPlugin.getWorkspace().getRoot().getProject("NotKse");
		if (!plain.exists()) {
			plain.create(null);
		}
		plain.open(null);
		IEditorPart elsewhere = open(file(plain, "Keeper.txt", original));
		assertFalse(elsewhere instanceof FormulaEditor, "outside a KSE project a .txt stays in the text editor");

		// a choice made with Open With stays the user's
		IFile chosen = file(project, "models/Chosen.txt", original);
		IDE.setDefaultEditor(chosen, "org.eclipse.ui.DefaultTextEditor");
		assertFalse(open(chosen) instanceof FormulaEditor, "the editor the user chose for the file");
		assertTrue(logged.isEmpty(), () -> "opening the files logged: " + errorsLogged());
	}
}
