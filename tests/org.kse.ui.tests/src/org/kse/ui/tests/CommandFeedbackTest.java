package org.kse.ui.tests;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Function;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.jobs.Job;
import org.eclipse.jface.dialogs.ProgressMonitorDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.CLabel;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Link;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer.OrderAnnotation;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.ui.formula.FormulaEditor;
import org.kse.ui.ModelFiles;
import org.kse.ui.statechart.editor.StatechartEditor;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * Each command answers where the user looks: a broken formula is reported once, with its line and
 * column, before any question; Transform opens what it wrote and never replaces a curated model
 * without listing what would be lost (writing beside it is the default); Validate says in the
 * status line that there are no problems; Generate opens a summary whose links open the files.
 * Screenshots: target/screenshots/60-….
 */
@TestMethodOrder(OrderAnnotation.class)
@ExtendWith(UnexpectedDialogs.class)
class CommandFeedbackTest {

	private static final String SUMMARY_TITLE = "Generated Code";
	private static final String TRANSFORM_TITLE = "Transform to Statechart";
	private static IProject project;

	/** A dialog as the user saw it: its title and all its text. */
	private record Seen(String title, String text, String defaultButton) {
	}

	@BeforeAll
	static void createProject() throws Exception {
		project = ResourcesPlugin.getWorkspace().getRoot().getProject("Feedback");
		if (!project.exists()) {
			project.create(null);
		}
		project.open(null);
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 860);
	}

	@AfterAll
	static void closeAll() {
		closeSummaries();
		Ui.page().closeAllEditors(false);
	}

	private static IFile write(String name, byte[] content) throws Exception {
		IFile file = project.getFile(name);
		if (file.exists()) {
			file.setContents(new ByteArrayInputStream(content), IResource.FORCE, null);
		} else {
			file.create(new ByteArrayInputStream(content), true, null);
		}
		return file;
	}

	private static byte[] example(String name) throws Exception {
		return Files.readAllBytes(Path.of(System.getProperty("kse.examples"), "Goalie", name));
	}

	private static FormulaEditor openFormula(IFile formula) throws Exception {
		FormulaEditor editor = assertInstanceOf(FormulaEditor.class, IDE.openEditor(Ui.page(), formula, FormulaEditor.ID));
		Ui.page().activate(editor);
		Ui.settle(300);
		return editor;
	}

	/**
	 * Runs a command and answers each dialog it opens meanwhile: {@code answer} gets the dialog and
	 * returns the label of the button to press (null: the default button, as Enter would). Returns the
	 * dialogs seen, in order.
	 */
	private static List<Seen> runAnswering(String command, String screenshot, Function<Seen, String> answer) throws Exception {
		Ui.expectDialog(TRANSFORM_TITLE);
		List<Seen> seen = new ArrayList<>();
		List<Shell> answered = new ArrayList<>();
		Throwable[] failure = new Throwable[1];
		boolean[] running = { true };
		Runnable[] watch = new Runnable[1];
		watch[0] = () -> {
			if (!running[0]) {
				return;
			}
			try {
				for (Shell shell : Ui.display().getShells()) {
					// a progress dialog (a slow first transform) is no question to answer
					if (!shell.isDisposed() && shell.isVisible() && shell.getParent() != null && !answered.contains(shell)
							&& !SUMMARY_TITLE.equals(shell.getText()) && !(shell.getData() instanceof ProgressMonitorDialog)) {
						answered.add(shell);
						Button preset = shell.getDefaultButton();
						Seen dialog = new Seen(shell.getText(), String.join("\n", Ui.find(shell, Label.class).stream().map(Label::getText).toList()),
								preset == null ? null : preset.getText().replace("&", ""));
						seen.add(dialog);
						Ui.screenshotOf(shell, screenshot + "-" + seen.size());
						String label = answer.apply(dialog);
						Ui.press(label == null ? preset : Ui.button(shell, label));
					}
				}
			} catch (Throwable e) {
				failure[0] = e;
				Arrays.stream(Ui.display().getShells()).filter(shell -> shell.getParent() != null).forEach(Shell::close);
				return;
			}
			Ui.display().timerExec(100, watch[0]);
		};
		Ui.display().timerExec(100, watch[0]);
		try {
			Ui.run(command);
		} finally {
			running[0] = false;
		}
		if (failure[0] != null) {
			throw new AssertionError("answering the dialogs of " + command + " failed", failure[0]);
		}
		return seen;
	}

	/** The visible dialogs other than the generation summary: a job's error dialog would be one. */
	private static List<String> openDialogs() {
		return Arrays.stream(Ui.display().getShells())
				.filter(shell -> shell.isVisible() && shell.getParent() != null && !SUMMARY_TITLE.equals(shell.getText())).map(Shell::getText)
				.toList();
	}

	private static void idle() {
		assertTrue(Ui.waitUntil(() -> Job.getJobManager().isIdle(), 30_000), "the command's work finishes");
		Ui.settle(500);
	}

	private static String statusLine() {
		return String.join(" | ", Ui.find(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell(), CLabel.class).stream()
				.map(CLabel::getText).filter(text -> text != null && !text.isEmpty()).toList());
	}

	private static Shell summary() {
		return Arrays.stream(Ui.display().getShells()).filter(shell -> shell.isVisible() && SUMMARY_TITLE.equals(shell.getText())).findFirst()
				.orElse(null);
	}

	private static void closeSummaries() {
		Arrays.stream(Ui.display().getShells()).filter(shell -> SUMMARY_TITLE.equals(shell.getText())).forEach(Shell::close);
	}

	@Test
	@Order(1)
	void aBrokenFormulaIsReportedOnceWithLineAndColumnBeforeAnyQuestion() throws Exception {
		// a model exists already: the old Transform asked about replacing it before reading the formulas
		byte[] curated = example("Goalie.stct");
		IFile model = write("Broken.stct", curated);
		IFile formula = write("Broken.liveness", "broken = Init.(Scan | Kick\nother = Stare\n".getBytes(StandardCharsets.UTF_8));
		openFormula(formula);

		List<Seen> seen = runAnswering("org.kse.ui.transform", "60-broken-formula", dialog -> null);
		idle();

		assertEquals(1, seen.size(), () -> "one message, no question before it: " + seen);
		Seen message = seen.get(0);
		assertEquals(TRANSFORM_TITLE, message.title());
		assertTrue(message.text().contains("Broken.liveness, line "), message::text);
		assertTrue(message.text().matches("(?s).*line \\d+, column \\d+: .*"), message::text);
		assertTrue(message.text().contains("Nothing was transformed"), message::text);
		assertTrue(!message.text().contains("Replace"), "nothing is asked: " + message.text());
		assertEquals(List.of(), openDialogs(), "no job-error dialog afterwards");
		assertArrayEquals(curated, Files.readAllBytes(Path.of(model.getLocationURI())), "the model is untouched");
		assertTrue(!project.getFile("Broken-from-formula.stct").exists());
		Ui.page().closeAllEditors(false);
	}

	@Test
	@Order(2)
	void transformOfTheCuratedGoalieListsItsGuardsAndWritesBesideItByDefault() throws Exception {
		byte[] curated = example("Goalie.stct");
		IFile model = write("Goalie.stct", curated);
		IFile formula = write("Goalie.liveness", example("Goalie.liveness"));
		openFormula(formula);

		List<Seen> seen = runAnswering("org.kse.ui.transform", "61-transform-curated", dialog -> null);
		idle();

		assertEquals(1, seen.size(), () -> "one question: " + seen);
		Seen question = seen.get(0);
		assertEquals("Write Goalie-from-formula.stct", question.defaultButton(), "writing beside the model is what Enter does");
		assertTrue(question.text().contains("the guard or action of") && question.text().contains("PLAYER_PLAYING"),
				() -> "the curated guards are listed: " + question.text());
		assertTrue(question.text().contains("Replace") || question.text().contains("replace"), question::text);
		assertArrayEquals(curated, Files.readAllBytes(Path.of(model.getLocationURI())), "the curated Goalie is kept as it is");
		IFile beside = project.getFile("Goalie-from-formula.stct");
		assertTrue(beside.exists(), "the transformed statechart is written beside it");
		IEditorPart active = Ui.page().getActiveEditor();
		assertInstanceOf(StatechartEditor.class, active, "the new model opens");
		assertEquals("Goalie-from-formula.stct", active.getEditorInput().getName());
		Ui.screenshot("62-transformed-beside");

		// answering Replace replaces it, and the model opens
		openFormula(formula);
		List<Seen> again = runAnswering("org.kse.ui.transform", "63-transform-replace", dialog -> "Replace Goalie.stct");
		idle();
		assertEquals(1, again.size(), () -> "asked again: " + again);
		assertTrue(!Arrays.equals(curated, Files.readAllBytes(Path.of(model.getLocationURI()))), "replaced as chosen");
		assertEquals("Goalie.stct", Ui.page().getActiveEditor().getEditorInput().getName(), "the replaced model is open");
		Ui.page().closeAllEditors(false);
	}

	@Test
	@Order(3)
	void transformOfAModelWithoutHandEditsReplacesItWithoutAskingAndOpensIt() throws Exception {
		IFile formula = write("Keeper.liveness", example("Goalie.liveness"));
		IFile model = project.getFile("Keeper.stct");
		openFormula(formula);
		assertEquals(List.of(), runAnswering("org.kse.ui.transform", "64-transform-new", dialog -> "Cancel"), "a new model: nothing to ask");
		idle();
		assertTrue(model.exists());
		assertEquals("Keeper.stct", Ui.page().getActiveEditor().getEditorInput().getName(), "the new model opens");

		// transformed again: the model holds nothing the formulas cannot reproduce, so nothing is lost
		openFormula(formula);
		assertEquals(List.of(), runAnswering("org.kse.ui.transform", "65-transform-again", dialog -> "Cancel"), "nothing lost: nothing to ask");
		idle();
		assertTrue(!project.getFile("Keeper-from-formula.stct").exists());
		assertEquals("Keeper.stct", Ui.page().getActiveEditor().getEditorInput().getName());
		Ui.page().closeAllEditors(false);
	}

	@Test
	@Order(4)
	void validateSaysInTheStatusLineThatThereAreNoProblemsOrHowMany() throws Exception {
		IFile goalie = write("Goalie.stct", example("Goalie.stct"));
		Ui.select(goalie);
		Ui.run("org.kse.ui.validate");
		assertTrue(Ui.waitUntil(() -> statusLine().contains("Validated Goalie.stct: no problems."), 30_000),
				() -> "the status line says so: " + statusLine());
		Ui.screenshot("66-validated-no-problems");

		String text = new String(example("Goalie.stct"), StandardCharsets.UTF_8);
		String broken = text.replaceFirst("ballfound\\(\\)>0", "ballfound()>");
		assertTrue(!broken.equals(text), "a guard to break");
		write("Goalie.stct", broken.getBytes(StandardCharsets.UTF_8));
		Ui.select(goalie);
		Ui.run("org.kse.ui.validate");
		assertTrue(Ui.waitUntil(() -> statusLine().matches(".*Validated Goalie.stct: [1-9]\\d* errors?, .*Problems view.*"), 30_000),
				() -> "the status line counts the errors: " + statusLine());
		Ui.screenshot("67-validated-with-errors");
		write("Goalie.stct", example("Goalie.stct"));
	}

	@Test
	@Order(5)
	void generateOpensASummaryWhoseLinksOpenTheWrittenFiles() throws Exception {
		closeSummaries();
		IFile goalie = write("Goalie.stct", example("Goalie.stct"));
		if (!project.getFolder("src").exists()) {
			project.getFolder("src").create(true, true, null);
		}
		ModelFiles.remember(goalie, project.getFolder("src"), false);
		Ui.select(goalie);
		Ui.run("org.kse.ui.generate");
		assertTrue(Ui.waitUntil(() -> summary() != null, 30_000), "a summary opens when the generation ends");
		Shell summary = summary();
		String text = String.join("\n", Ui.find(summary, Label.class).stream().map(Label::getText).toList());
		assertTrue(text.matches("(?s).*[1-9]\\d* written, \\d+ unchanged, \\d+ activities kept.*"), text);
		Ui.screenshotOf(summary, "68-generation-summary");
		List<Link> links = Ui.find(summary, Link.class);
		Link statechart = links.stream().filter(link -> link.getText().contains("/Feedback/src/statecharts/Goalie/Goalie.cpp")).findFirst()
				.orElseThrow(() -> new AssertionError("no link to Goalie.cpp: " + links.stream().map(Link::getText).toList()));
		assertTrue(links.stream().anyMatch(link -> link.getText().contains("/Feedback/src/activities/Kick/Kick.cpp")), "the new activities too");
		Event click = new Event();
		click.text = "/Feedback/src/statecharts/Goalie/Goalie.cpp";
		statechart.notifyListeners(SWT.Selection, click);
		Ui.settle(300);
		assertNotNull(Ui.page().getActiveEditor());
		assertEquals("Goalie.cpp", Ui.page().getActiveEditor().getEditorInput().getName(), "the link opens the file in an editor");
		Ui.screenshot("69-generated-file-opened");

		// again: nothing new to write, the hand-written activities kept; the new summary replaces the old
		Ui.select(goalie);
		Ui.run("org.kse.ui.generate");
		assertTrue(Ui.waitUntil(() -> summary() != null && summary() != summary, 30_000), "a new summary");
		Shell second = summary();
		String secondText = String.join("\n", Ui.find(second, Label.class).stream().map(Label::getText).toList());
		assertTrue(secondText.matches("(?s).*0 written, [1-9]\\d* unchanged, [1-9]\\d* activities kept.*"), secondText);
		assertTrue(secondText.contains("Kick"), () -> "the kept activities are named: " + secondText);
		assertEquals(1, Arrays.stream(Ui.display().getShells()).filter(shell -> shell.isVisible() && SUMMARY_TITLE.equals(shell.getText())).count(),
				"one summary at a time");
		Ui.screenshotOf(second, "70-generation-summary-again");
		Ui.press(second, "Close");
		assertTrue(second.isDisposed());
		Ui.page().closeAllEditors(false);
	}

	@Test
	@Order(6)
	void aGenerationThatFailsSaysWhyInTheSummaryNotInAJobErrorDialog() throws Exception {
		closeSummaries();
		IFile goalie = write("Goalie.stct", new String(example("Goalie.stct"), StandardCharsets.UTF_8)
				.replaceFirst("ballfound\\(\\)>0", "ballfound()>").getBytes(StandardCharsets.UTF_8));
		Ui.select(goalie);
		Ui.run("org.kse.ui.generate");
		assertTrue(Ui.waitUntil(() -> summary() != null, 30_000), "the summary says what happened");
		String text = String.join("\n", Ui.find(summary(), Label.class).stream().map(Label::getText).toList());
		assertTrue(text.contains("nothing was generated"), text);
		idle();
		assertEquals(List.of(), openDialogs(), "no job-error dialog");
		Ui.screenshotOf(summary(), "71-generation-failed");
		closeSummaries();
		write("Goalie.stct", example("Goalie.stct"));
	}

	@Test
	@Order(7)
	void newStatechartFromFormulasAsksAsTransformDoesAndKeepsTheCuratedGoalie() throws Exception {
		byte[] curated = example("Goalie.stct");
		IFile model = write("Goalie.stct", curated);
		IFile formula = write("Goalie.liveness", example("Goalie.liveness"));
		IFile beside = project.getFile("Goalie-from-formula.stct");
		if (beside.exists()) {
			beside.delete(true, null);
		}
		var wizard = new org.kse.ui.formula.wizards.NewStatechartFromFormulaWizard();
		wizard.init(PlatformUI.getWorkbench(), new org.eclipse.jface.viewers.StructuredSelection(formula));
		var dialog = new org.eclipse.jface.wizard.WizardDialog(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell(), wizard);
		dialog.setBlockOnOpen(false);
		dialog.open();
		Ui.expectDialog(TRANSFORM_TITLE);
		String[] asked = new String[2];
		Ui.Answered question = Ui.whenShown(shell -> TRANSFORM_TITLE.equals(shell.getText()), shown -> {
			asked[0] = String.join("\n", Ui.find(shown, Label.class).stream().map(Label::getText).toList());
			asked[1] = shown.getDefaultButton() == null ? null : shown.getDefaultButton().getText().replace("&", "");
			Ui.screenshotOf(shown, "64-wizard-asks");
			Ui.press(shown.getDefaultButton());
		});
		Ui.press(dialog.getShell(), "Finish");
		question.check("replace-or-write-beside (New Statechart from Formulas)");
		assertTrue(Ui.waitUntil(() -> dialog.getShell() == null || dialog.getShell().isDisposed(), 30_000), "the wizard closes");
		assertEquals("Write Goalie-from-formula.stct", asked[1], "writing beside the model is what Enter does");
		assertTrue(asked[0].contains("PLAYER_PLAYING"), () -> "the hand-written guards are listed: " + asked[0]);
		assertArrayEquals(curated, Files.readAllBytes(Path.of(model.getLocationURI())), "the curated Goalie is kept as it is");
		assertTrue(beside.exists(), "the statechart from the formulas is written beside it");
	}
}
