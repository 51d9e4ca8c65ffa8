package org.kse.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.wizard.WizardDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.views.properties.PropertySheet;
import org.eclipse.ui.views.properties.tabbed.TabbedPropertySheetPage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Transition;
import org.kse.ui.formula.FormulaEditor;
import org.kse.ui.statechart.ModelMarkers;
import org.kse.ui.statechart.editor.StatechartEditor;
import org.kse.ui.statechart.editor.properties.TransitionSection;
import org.kse.ui.formula.wizards.NewFormulaWizard;
import org.kse.ui.wizards.NewProjectWizard;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * The whole path of the manual's tutorial on one project, as a user takes it: a new KSE project,
 * a new formula file with the Goalie typed in, an error marker that comes and goes, Transform,
 * the model opened, a guard written in the Properties view with completion, Validate, Generate
 * into the project (the Generate dialog asks for the folder), and the generated files found.
 * Every step leaves a screenshot in target/screenshots (40-…).
 */
@ExtendWith(UnexpectedDialogs.class)
class EndToEndTest {

	private static final List<String> GOALIE = List.of("goalie = Init.(playing | nonPlaying)+", "nonPlaying = NoPlay .[GoToPosition+]",
			"playing = Scan+ | ApproachBall+ | Kick | followBall", "followBall = Stare+.[SpecialAction]");
	private static final String GUARD = "[worldstate.State.GameStateMessage.player_state()==PLAYER_PLAYING]";

	private static int errors(IFile file, String type) {
		try {
			return (int) Arrays.stream(file.findMarkers(type, false, IResource.DEPTH_ZERO))
					.filter(marker -> marker.getAttribute(IMarker.SEVERITY, -1) == IMarker.SEVERITY_ERROR).count();
		} catch (CoreException e) {
			return -1;
		}
	}

	private static Shell openWizard(org.eclipse.jface.wizard.IWizard wizard) {
		WizardDialog dialog = new WizardDialog(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell(), wizard);
		dialog.setBlockOnOpen(false);
		dialog.open();
		return dialog.getShell();
	}

	@Test
	void fromANewProjectToGeneratedCode() throws Exception {
		Path log = org.eclipse.core.runtime.Platform.getLogFileLocation().toPath();
		long logBefore = Files.exists(log) ? Files.size(log) : 0;
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 860);
		// 1. a new KSE project, without the examples
		Shell projectWizard = openWizard(init(new NewProjectWizard()));
		Ui.find(projectWizard, Text.class).get(0).setText("Behaviours");
		Ui.find(projectWizard, Button.class).stream().filter(button -> (button.getStyle() & SWT.CHECK) != 0 && button.getText().contains("example"))
				.forEach(button -> {
					button.setSelection(false);
					button.notifyListeners(SWT.Selection, null);
				});
		Ui.press(projectWizard, "Finish");
		assertTrue(Ui.waitUntil(projectWizard::isDisposed, 20_000), "the project wizard finishes");
		IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject("Behaviours");
		assertTrue(project.getFolder("src/activities").exists() && !project.getFile("models/Goalie.stct").exists(), "an empty KSE project");
		Ui.screenshot("40-new-project");

		// 2. a new formula file, the Goalie typed into it line by line
		Ui.select(project.getFolder("models"));
		Shell formulaWizard = openWizard(init(new NewFormulaWizard()));
		Text fileName = Ui.find(formulaWizard, Text.class).stream().filter(text -> text.getText().endsWith(".liveness")).findFirst()
				.orElseThrow(() -> new AssertionError("no file name field"));
		fileName.setText("Goalie.liveness");
		Ui.screenshotOf(formulaWizard, "41-new-formula-wizard");
		Ui.press(formulaWizard, "Finish");
		assertTrue(Ui.waitUntil(formulaWizard::isDisposed, 20_000), "the formula wizard finishes");
		IFile formula = project.getFile("models/Goalie.liveness");
		FormulaEditor editor = assertInstanceOf(FormulaEditor.class, Ui.page().getActiveEditor(), "the new formula is open");
		IDocument document = editor.getDocumentProvider().getDocument(editor.getEditorInput());
		document.set("");
		for (String line : GOALIE) {
			document.replace(document.getLength(), 0, line + "\n");
			Ui.settle(100);
		}
		editor.doSave(null);
		assertTrue(Ui.waitUntil(() -> errors(formula, "org.kse.ui.formulaProblem") == 0, 10_000), "the Goalie formulas have no error");
		Ui.screenshot("42-goalie-typed");

		// 3. a mistake is marked while typing and unmarked when fixed
		int end = document.getLength();
		document.replace(end, 0, "special = Kick.Dive | Stand\n");
		assertTrue(Ui.waitUntil(() -> errors(formula, "org.kse.ui.formulaProblem") > 0, 10_000), "mixed operators are marked");
		Ui.screenshot("43-formula-error-marker");
		document.replace(end, document.getLength() - end, "");
		assertTrue(Ui.waitUntil(() -> errors(formula, "org.kse.ui.formulaProblem") == 0, 10_000), "the marker goes when fixed");
		editor.doSave(null);

		// 4. Transform to Statechart
		Ui.page().activate(editor);
		Ui.run("org.kse.ui.transform");
		IFile model = project.getFile("models/Goalie.stct");
		assertTrue(Ui.waitUntil(model::exists, 30_000), "Goalie.stct written next to the formulas");
		assertTrue(Ui.waitUntil(() -> Job.getJobManager().isIdle(), 30_000));

		// 5. the model opened by Transform; a guard written in the Properties view, with completion
		StatechartEditor statechart = assertInstanceOf(StatechartEditor.class, Ui.page().getActiveEditor(), "Transform opens the model");
		Transition toPlaying = statechart.getModel().getTransitions().stream()
				.filter(t -> NodeKind.CONDITION.is(t.getSource()) && "playing".equals(t.getTarget().getName())).findFirst()
				.orElseThrow(() -> new AssertionError("no choice of 'playing' in the transformed model"));
		Ui.screenshot("44-model-open");
		PropertySheet properties = (PropertySheet) Ui.page().showView(IPageLayout.ID_PROP_SHEET, null, IWorkbenchPage.VIEW_VISIBLE);
		Ui.page().activate(statechart);
		statechart.getViewer().setSelection(new StructuredSelection(toPlaying), true);
		Ui.settle(300);
		TabbedPropertySheetPage sheet = (TabbedPropertySheetPage) properties.getCurrentPage();
		sheet.setSelectedTab("org.kse.ui.tab.transition");
		Ui.settle(300);
		TransitionSection section = Arrays.stream(sheet.getCurrentTab().getSections()).filter(TransitionSection.class::isInstance)
				.map(TransitionSection.class::cast).findFirst().orElseThrow();
		var viewer = section.getExpression().getViewer();
		var guard = viewer.getDocument();
		viewer.getTextWidget().setFocus();
		guard.set("[worldstate.State.GameStateMessage.player_st");
		viewer.setSelectedRange(guard.getLength(), 0);
		viewer.doOperation(ISourceViewer.CONTENTASSIST_PROPOSALS);
		assertTrue(Ui.waitUntil(() -> guard.get().endsWith("player_state()"), 5000), () -> "completed: " + guard.get());
		guard.replace(guard.getLength(), 0, "==PLAYER_PLAYING]");
		assertEquals(GUARD, guard.get());
		assertEquals(List.of(), section.getExpression().problems(), "the guard is correct");
		Ui.screenshot("45-guard-with-completion");
		assertTrue(toPlaying.getTE() == null || toPlaying.getTE().isEmpty(), "nothing is set while typing");
		// Save with the cursor still in the field: the guard typed is saved
		statechart.doSave(null);
		assertEquals(GUARD, toPlaying.getTE(), "the guard is set in the model");
		assertTrue(!statechart.isDirty(), "and saved");

		// 6. Validate
		Ui.select(model);
		Ui.run("org.kse.ui.validate");
		assertTrue(Ui.waitUntil(() -> Job.getJobManager().isIdle(), 30_000));
		assertEquals(0, errors(model, ModelMarkers.MARKER), "the model is valid");
		Ui.page().showView(IPageLayout.ID_PROBLEM_VIEW);
		Ui.screenshot("46-validated");

		// 7. Generate: the first time, the dialog asks for the source folder
		Ui.select(model);
		Ui.Answered generateDialog = Ui.whenShown(shell -> Ui.offers(shell, "Generate"), dialog -> {
			Ui.screenshotOf(dialog, "47-generate-dialog");
			Ui.press(dialog, "Generate");
		});
		// a summary left open by an earlier test would be found first, then replaced by this run's
		Arrays.stream(Ui.display().getShells()).filter(shell -> "Generated Code".equals(shell.getText())).forEach(Shell::close);
		Ui.run("org.kse.ui.generate");
		generateDialog.check("Generate");
		assertTrue(Ui.waitUntil(() -> project.getFolder("src/statecharts").exists() && Job.getJobManager().isIdle(), 30_000));
		assertTrue(Ui.waitUntil(() -> project.getFile("src/activities/Scan/Scan.cpp").exists(), 30_000), "activity skeletons generated");
		Shell[] summary = new Shell[1];
		assertTrue(Ui.waitUntil(() -> (summary[0] = Arrays.stream(Ui.display().getShells())
				.filter(shell -> shell.isVisible() && "Generated Code".equals(shell.getText())).findFirst().orElse(null)) != null, 10_000),
				"a summary of the generation opens");
		Ui.screenshotOf(summary[0], "47b-generation-summary");
		summary[0].close();

		// 8. the generated files, in the project
		Path statecharts = Path.of(project.getFolder("src/statecharts").getLocationURI());
		List<Path> charts;
		try (Stream<Path> listed = Files.list(statecharts)) {
			charts = listed.toList();
		}
		assertEquals(1, charts.size(), () -> "one statechart: " + charts);
		String name = charts.get(0).getFileName().toString();
		for (String part : List.of(name + ".h", name + ".cpp", "CMakeLists.txt")) {
			assertTrue(Files.exists(charts.get(0).resolve(part)), part);
		}
		for (String activity : List.of("Init", "NoPlay", "GoToPosition", "Scan", "ApproachBall", "Kick", "Stare", "SpecialAction")) {
			assertTrue(project.getFile("src/activities/" + activity + "/" + activity + ".cpp").exists(), activity);
		}
		assertTrue(containsGuard(charts.get(0)), "the guard written in the Properties view is in the generated C++");
		IFile generated = project.getFile("src/statecharts/" + name + "/" + name + ".cpp");
		assertTrue(generated.exists(), "the workspace sees the generated files");
		Ui.select(generated);
		IDE.openEditor(Ui.page(), generated);
		Ui.screenshot("48-generated-files");
		Ui.page().closeAllEditors(false);
		// the Error Log a user would open afterwards: nothing written to .metadata/.log on the way
		byte[] all = Files.exists(log) ? Files.readAllBytes(log) : new byte[0];
		String logged = all.length > logBefore ? new String(all, (int) logBefore, all.length - (int) logBefore, java.nio.charset.StandardCharsets.UTF_8) : "";
		assertEquals("", logged, "the tutorial wrote to " + log);
	}

	private static boolean containsGuard(Path folder) throws IOException {
		try (Stream<Path> files = Files.walk(folder)) {
			return files.filter(Files::isRegularFile).anyMatch(file -> {
				try {
					return Files.readString(file).contains("PLAYER_PLAYING");
				} catch (IOException e) {
					return false;
				}
			});
		}
	}

	private static <W extends org.eclipse.ui.IWorkbenchWizard> W init(W wizard) {
		var selection = Ui.page().getSelection();
		wizard.init(PlatformUI.getWorkbench(), selection instanceof StructuredSelection structured ? structured : StructuredSelection.EMPTY);
		return wizard;
	}
}
