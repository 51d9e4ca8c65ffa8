package org.kse.ui.statechart.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.wizard.WizardDialog;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.MethodOrderer.OrderAnnotation;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.ui.ModelFiles;
import org.kse.ui.statechart.ModelMarkers;
import org.kse.ui.wizards.NewProjectWizard;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * A team's project: created with the New KSE Project wizard and its examples, a model validated
 * (a broken guard is marked with the transition's label), labeled, and generated into the
 * project's source folder, connected through the Generate dialog the first time.
 */
@ExtendWith(UnexpectedDialogs.class)
@TestMethodOrder(OrderAnnotation.class)
class ModelWorkflowTest {

	private static IProject project;

	private static List<IMarker> problems(IFile file, int severity) throws CoreException {
		List<IMarker> found = new ArrayList<>();
		for (IMarker marker : file.findMarkers(ModelMarkers.MARKER, false, IResource.DEPTH_ZERO)) {
			if (marker.getAttribute(IMarker.SEVERITY, -1) == severity) {
				found.add(marker);
			}
		}
		return found;
	}

	/** The model's error markers now; -1 while they cannot be read. */
	private static int errors(IFile file) {
		try {
			return problems(file, IMarker.SEVERITY_ERROR).size();
		} catch (CoreException e) {
			return -1;
		}
	}

	@Test
	@Order(1)
	void theNewProjectWizardCreatesASourceTreeWithTheExamples() {
		Shell shell = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell();
		NewProjectWizard wizard = new NewProjectWizard();
		wizard.init(PlatformUI.getWorkbench(), StructuredSelection.EMPTY);
		WizardDialog dialog = new WizardDialog(shell, wizard);
		dialog.setBlockOnOpen(false);
		dialog.open();
		Text name = Ui.find(dialog.getShell(), Text.class).get(0);
		name.setText("Team");
		Ui.settle(200);
		Ui.screenshotOf(dialog.getShell(), "10-new-kse-project-wizard");
		Ui.press(Ui.button(dialog.getShell(), "Finish"));
		assertTrue(Ui.waitUntil(() -> dialog.getShell() == null || dialog.getShell().isDisposed(), 20_000), "the wizard finishes");

		project = ResourcesPlugin.getWorkspace().getRoot().getProject("Team");
		assertTrue(project.isOpen());
		for (String folder : List.of("models", "src/statecharts", "src/activities", "src/messages")) {
			assertTrue(project.getFolder(folder).exists(), folder);
		}
		for (String file : List.of("models/Goalie.liveness", "models/Goalie.stct", "models/Attacker.stct", "models/Defender.liveness",
				"src/activities/Kick/Kick.cpp", "src/activities/common/RobotIO.h")) {
			assertTrue(project.getFile(file).exists(), file);
		}
		assertEquals("/Team/src", ModelFiles.sourceFolder(project.getFile("models/Goalie.stct")).getFullPath().toString(),
				"the example models are connected to the project's source folder");
		Ui.screenshot("11-project-with-examples");
	}

	@Test
	@Order(2)
	void validateMarksABrokenGuardWithTheTransitionsLabel() throws Exception {
		IFile goalie = project.getFile("models/Goalie.stct");
		Ui.select(goalie);
		Ui.run("org.kse.ui.validate");
		assertTrue(Ui.waitUntil(Job::noneRunning, 20_000));
		assertEquals(List.of(), problems(goalie, IMarker.SEVERITY_ERROR), "the Goalie example is valid");

		Path file = Path.of(goalie.getLocationURI());
		String text = Files.readString(file);
		try {
			String broken = text.replaceFirst("ballfound\\(\\)>0", "ballfound()>");
			assertTrue(!broken.equals(text), "a guard to break");
			Files.writeString(file, broken);
			goalie.refreshLocal(IResource.DEPTH_ZERO, null);
			Ui.run("org.kse.ui.validate");
			assertTrue(Ui.waitUntil(() -> errors(goalie) > 0, 20_000), "the broken guard is marked");
			List<IMarker> errors = problems(goalie, IMarker.SEVERITY_ERROR);
			List<String> messages = errors.stream().map(marker -> marker.getAttribute(IMarker.MESSAGE, "")).toList();
			IMarker marker = errors.stream().filter(error -> error.getAttribute(IMarker.MESSAGE, "").contains("_TO_")).findFirst()
					.orElseThrow(() -> new AssertionError("no error names the transition: " + messages));
			assertNotNull(marker.getAttribute(ModelMarkers.ELEMENT, null), () -> "points at the model element: " + messages);
			Ui.page().showView(IPageLayout.ID_PROBLEM_VIEW);
			Ui.settle(1500);
			Ui.screenshot("12-validation-problem");
			// opening the problem (a double-click in the Problems view) selects the transition in the statechart editor
			var opened = org.eclipse.ui.ide.IDE.openEditor(Ui.page(), marker);
			var selected = ((org.eclipse.jface.viewers.IStructuredSelection) ((org.kse.ui.statechart.editor.StatechartEditor) opened).getViewer()
					.getSelection()).getFirstElement();
			assertTrue(selected instanceof org.kse.model.statechart.Transition transition
					&& marker.getAttribute(IMarker.MESSAGE, "").contains(transition.getName()), () -> "selected: " + selected);
			Ui.screenshot("12b-problem-opened");
			Ui.page().closeAllEditors(false);
		} finally {
			Files.writeString(file, text);
			goalie.refreshLocal(IResource.DEPTH_ZERO, null);
		}
		Ui.select(goalie);
		Ui.run("org.kse.ui.validate");
		assertTrue(Ui.waitUntil(() -> errors(goalie) == 0, 20_000), "fixed, the marker goes");
	}

	@Test
	@Order(3)
	void generateWritesTheStatechartAndKeepsTheActivities() throws Exception {
		IFile goalie = project.getFile("models/Goalie.stct");
		IFile kick = project.getFile("src/activities/Kick/Kick.cpp");
		String handWritten = Files.readString(Path.of(kick.getLocationURI()));
		Ui.select(goalie);
		Ui.run("org.kse.ui.generate");
		IFile statechart = project.getFile("src/statecharts/Goalie/Goalie.cpp");
		assertTrue(Ui.waitUntil(statechart::exists, 30_000), "src/statecharts/Goalie/Goalie.cpp generated");
		assertTrue(Ui.waitUntil(Job::noneRunning, 30_000));
		assertEquals(handWritten, Files.readString(Path.of(kick.getLocationURI())), "the hand-written Kick activity is kept");
		assertTrue(project.getFile("src/statecharts/Goalie/CMakeLists.txt").exists());
		assertTrue(Ui.waitUntil(() -> generationSummary() != null, 10_000), "a summary of the generation opens");
		Ui.screenshot("13-generated");
		generationSummary().close();
	}

	@Test
	@Order(4)
	void theFirstGenerationOfAModelAsksForItsSourceFolder() throws Exception {
		IFile attacker = project.getFile("models/Attacker.stct");
		attacker.setPersistentProperty(ModelFiles.SOURCE_FOLDER, null);
		Ui.select(attacker);
		Ui.Answered generateDialog = Ui.whenShown(shell -> Ui.offers(shell, "Generate"), dialog -> {
			Ui.screenshotOf(dialog, "14-generate-dialog");
			Text folder = Ui.find(dialog, Text.class).stream().filter(text -> text.getText().startsWith("/Team")).findFirst()
					.orElseThrow(() -> new AssertionError("no source folder field"));
			folder.setText("/Team/generated");
			Ui.press(Ui.button(dialog, "Generate"));
		});
		Ui.run("org.kse.ui.generate");
		generateDialog.check("Generate (asking for the folder)");
		IFile statechart = project.getFile("generated/statecharts/Attacker/Attacker.cpp");
		assertTrue(Ui.waitUntil(statechart::exists, 30_000), "generated into the chosen folder");
		assertEquals("/Team/generated", ModelFiles.sourceFolder(attacker).getFullPath().toString(), "and remembered");
		assertTrue(Ui.waitUntil(Job::noneRunning, 30_000));
		assertTrue(Ui.waitUntil(() -> generationSummary() != null, 10_000), "a summary of the generation opens");
		generationSummary().close();
	}

	@Test
	@Order(5)
	void labelRenumbersAndSavesTheModel() throws Exception {
		IFile defender = project.getFile("models/Defender.stct");
		Path file = Path.of(defender.getLocationURI());
		String before = Files.readString(file);
		Files.writeString(file, before.replace("label=\"0.2\"", "label=\"9.9\""));
		defender.refreshLocal(IResource.DEPTH_ZERO, null);
		Ui.select(defender);
		Ui.run("org.kse.ui.label");
		assertTrue(Ui.waitUntil(() -> {
			try {
				return Files.readString(file).equals(before);
			} catch (java.io.IOException e) {
				return false;
			}
		}, 20_000), "labeling gives the example its labels back");
	}

	@Test
	@Order(6)
	void editActivityOpensItsCppAndOpenFormulaItsFormulas() throws Exception {
		IFile goalie = project.getFile("models/Goalie.stct");
		Ui.select(goalie);
		Ui.Answered editActivity = Ui.whenShown(shell -> "Edit Activity".equals(shell.getText()), dialog -> {
			Ui.find(dialog, Text.class).get(0).setText("Kick");
			Ui.settle(300);
			Ui.screenshotOf(dialog, "15-edit-activity");
			Ui.press(Ui.button(dialog, "OK"));
		});
		Ui.run("org.kse.ui.editActivity");
		editActivity.check("Edit Activity");
		assertEquals("Kick.cpp", Ui.page().getActiveEditor().getEditorInput().getName(), "the activity's C++ is open");
		Ui.screenshot("16-activity-open");

		Ui.select(goalie);
		Ui.run("org.kse.ui.openFormula");
		assertEquals("Goalie.liveness", Ui.page().getActiveEditor().getEditorInput().getName());
		assertEquals("org.kse.ui.formula.editor", Ui.page().getActiveEditor().getSite().getId(), "the formula opens in the formula editor");
		Ui.page().closeAllEditors(false);
	}

	@Test
	@Order(7)
	void anExternalGeneratorFromThePreferencesGetsTheModelAndTheFolder() throws Exception {
		var preferences = org.kse.ui.preferences.KsePreferences.node();
		preferences.put(org.kse.ui.preferences.KsePreferences.GENERATOR, org.kse.ui.preferences.KsePreferences.EXTERNAL);
		preferences.put(org.kse.ui.preferences.KsePreferences.GENERATOR_COMMAND, "sh -c \"echo generated from {model} > '{folder}/external.txt'\"");
		try {
			IFile goalie = project.getFile("models/Goalie.stct");
			Ui.select(goalie);
			Ui.run("org.kse.ui.generate");
			IFile output = project.getFile("src/external.txt");
			assertTrue(Ui.waitUntil(output::exists, 30_000), "the external generator ran and the folder was refreshed");
			assertEquals("generated from " + Path.of(goalie.getLocationURI()), Files.readString(Path.of(output.getLocationURI())).strip());
			assertTrue(Ui.waitUntil(() -> generationSummary() != null, 10_000), "the summary shows what the generator said");
			generationSummary().close();
		} finally {
			preferences.remove(org.kse.ui.preferences.KsePreferences.GENERATOR);
			preferences.remove(org.kse.ui.preferences.KsePreferences.GENERATOR_COMMAND);
		}
	}

	@Test
	@Order(8)
	void theTreeEditorEditsAPropertyWithUndoRedoAndSave() throws Exception {
		IFile defender = project.getFile("models/Defender.stct");
		var part = org.eclipse.ui.ide.IDE.openEditor(Ui.page(), defender);
		var editor = (org.kse.ui.statechart.editor.StatechartEditor) part;
		var tree = editor.getViewer().getTree();
		var model = tree.getItem(0);
		assertTrue(model.getText().startsWith("Model Defender"), model.getText());
		assertTrue(model.getItem(0).getText().startsWith("0  defender : OR"), model.getItem(0).getText());
		assertTrue(model.getItem(model.getItemCount() - 1).getText().startsWith("Transitions ("));
		org.kse.model.statechart.Node init = null;
		for (var contents = editor.getModel().eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof org.kse.model.statechart.Node node && "Init".equals(node.getName())) {
				init = node;
			}
		}
		assertNotNull(init);
		editor.getViewer().setSelection(new StructuredSelection(init), true);
		Ui.page().showView(IPageLayout.ID_PROP_SHEET);
		Ui.page().activate(editor);
		var properties = editor.propertySource(init);
		properties.setPropertyValue("name", "Initialise");
		Ui.settle(300);
		assertEquals("Initialise", init.getName());
		assertTrue(editor.isDirty());
		assertTrue(shows(tree.getItems(), "Initialise"), "the tree shows the new name");
		Ui.screenshot("17-tree-editor-and-properties");

		var actions = editor.getEditorSite().getActionBars();
		actions.getGlobalActionHandler(org.eclipse.ui.actions.ActionFactory.UNDO.getId()).run();
		Ui.settle(200);
		assertEquals("Init", init.getName(), "undone");
		assertTrue(!editor.isDirty(), "back to the saved state");
		actions.getGlobalActionHandler(org.eclipse.ui.actions.ActionFactory.REDO.getId()).run();
		Ui.settle(200);
		assertEquals("Initialise", init.getName(), "redone");
		properties.setPropertyValue("type", 4); // the combo's index of a kind, as the Properties view sets it
		assertEquals(org.kse.model.NodeKind.values()[4].name(), init.getType());
		actions.getGlobalActionHandler(org.eclipse.ui.actions.ActionFactory.UNDO.getId()).run();
		editor.doSave(null);
		assertTrue(!editor.isDirty());
		String saved = Files.readString(Path.of(defender.getLocationURI()));
		assertTrue(saved.contains("name=\"Initialise\" label=\"0.2\" type=\"BASIC\""), "saved with the new name and the old kind");
		Ui.page().closeAllEditors(false);
	}

	@Test
	@Order(9)
	void aGuardIsEditedWithCompletionFromTheMessageCatalogAndCheckedWhileTyped() throws Exception {
		IFile goalie = project.getFile("models/Goalie.stct");
		var editor = (org.kse.ui.statechart.editor.StatechartEditor) org.eclipse.ui.ide.IDE.openEditor(Ui.page(), goalie);
		org.kse.model.statechart.Transition transition = editor.getModel().getTransitions().stream()
				.filter(t -> "0.2.2.2_TO_playing".equals(t.getName())).findFirst().orElseThrow();
		editor.getViewer().setSelection(new StructuredSelection(transition), true);
		var dialog = new org.kse.ui.statechart.editor.ExpressionDialog(editor.getSite().getShell(), transition.getName(), transition.getTE(),
				editor.catalog());
		dialog.setBlockOnOpen(false);
		dialog.open();
		try {
			var viewer = dialog.getViewer();
			var document = viewer.getDocument();
			document.set("[worldstate.State.GameStateMessage.player_s");
			viewer.getTextWidget().setFocus();
			viewer.setSelectedRange(document.getLength(), 0);
			var offered = new org.kse.ui.statechart.editor.ExpressionAssist(editor.catalog()).computeCompletionProposals(viewer, document.getLength());
			assertEquals(1, offered.length, "one field of GameStateMessage starts with 'player_s'");
			offered[0].apply(document);
			assertEquals("[worldstate.State.GameStateMessage.player_state()", document.get(), "the field is completed");
			assertTrue(dialog.getErrorMessage() != null, "unfinished, it is an error");
			Ui.screenshotOf(dialog.getShell(), "18-guard-completed");

			var proposals = new org.kse.ui.statechart.editor.ExpressionAssist(editor.catalog()).proposals("[worldstate.State.");
			assertTrue(proposals.stream().anyMatch(p -> p[0].equals("GameStateMessage")), "message types after topic.Kind.");
			assertTrue(new org.kse.ui.statechart.editor.ExpressionAssist(editor.catalog()).proposals("[behavior.").stream()
					.anyMatch(p -> p[0].equals("State")), "kinds after a topic");

			document.set("[worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING && behavior.State.HeadToBMessage.ballfound()>0]");
			assertEquals(null, dialog.getErrorMessage(), "a correct guard has no error");
			document.set("[worldstate.State.GameStateMessage.no_such_field()==1]");
			assertTrue(dialog.getErrorMessage() != null && dialog.getErrorMessage().startsWith("1:"), () -> "located: " + dialog.getErrorMessage());
			assertTrue(dialog.getErrorMessage().contains("no_such_field"), dialog.getErrorMessage());
			Ui.screenshotOf(dialog.getShell(), "19-guard-error-while-typing");
			document.set("[worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING && behavior.State.HeadToBMessage.ballfound()>0]");
			Ui.press(Ui.button(dialog.getShell(), "OK"));
		} finally {
			if (dialog.getShell() != null && !dialog.getShell().isDisposed()) {
				dialog.close();
			}
		}
		String before = transition.getTE();
		editor.propertySource(transition).setPropertyValue("TE", dialog.getValue());
		assertEquals(dialog.getValue(), transition.getTE());
		assertTrue(editor.isDirty());
		editor.getEditorSite().getActionBars().getGlobalActionHandler(org.eclipse.ui.actions.ActionFactory.UNDO.getId()).run();
		assertEquals(before, transition.getTE(), "the edit is undoable");
		Ui.page().closeAllEditors(false);
	}

	/** The window Generate opens when it ends; null until then. */
	private static Shell generationSummary() {
		return java.util.Arrays.stream(Ui.display().getShells()).filter(shell -> shell.isVisible() && "Generated Code".equals(shell.getText()))
				.findFirst().orElse(null);
	}

	private static boolean shows(org.eclipse.swt.widgets.TreeItem[] items, String text) {
		return java.util.Arrays.stream(items).anyMatch(item -> item.getText().contains(text) || shows(item.getItems(), text));
	}

	/** No KSE job is running or waiting. */
	private static final class Job {
		static boolean noneRunning() {
			return org.eclipse.core.runtime.jobs.Job.getJobManager().isIdle();
		}
	}
}
