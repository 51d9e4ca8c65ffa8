package org.kse.ui.statechart.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.jface.wizard.IWizard;
import org.eclipse.jface.wizard.WizardDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableItem;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.MethodOrderer.OrderAnnotation;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;
import org.kse.ui.statechart.wizards.ExportScxmlWizard;
import org.kse.ui.statechart.wizards.ImportScxmlWizard;

/**
 * File > Export... > KSE > Statechart as SCXML and File > Import... > KSE > SCXML statechart:
 * the selected Goalie exported into a folder; a statechart the export refuses listed with its
 * problems and nothing written; a chart of another tool imported and opened in the editor; an
 * event-driven chart's errors listed per element with line:column and nothing imported; a chart
 * with parts left out imported on the second Finish; an existing model overwritten only when
 * the user says so.
 */
@ExtendWith(UnexpectedDialogs.class)
@TestMethodOrder(OrderAnnotation.class)
class ScxmlWizardsTest {

	private static final String PROJECT = "ScxmlTeam";
	private static final Path FIXTURES = Path.of(System.getProperty("kse.repository", "../.."), "tests", "org.kse.scxml.tests", "data", "import");
	private static Path outside;

	private WizardDialog dialog;

	@AfterEach
	void closeTheWizard() {
		if (dialog != null && dialog.getShell() != null && !dialog.getShell().isDisposed()) {
			dialog.close();
		}
		Ui.page().closeAllEditors(false);
	}

	private WizardDialog open(IWizard wizard) {
		Shell shell = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell();
		dialog = new WizardDialog(shell, wizard);
		dialog.setBlockOnOpen(false);
		dialog.open();
		Ui.settle(200);
		return dialog;
	}

	private boolean closed() {
		return dialog.getShell() == null || dialog.getShell().isDisposed();
	}

	/** The wizard's list of problems: the table with a Problem column. */
	private Table problems() {
		return Ui.find(dialog.getShell(), Table.class).stream().filter(table -> table.getColumnCount() == 4).findFirst()
				.orElseThrow(() -> new AssertionError("no list of problems"));
	}

	private static List<String> rows(Table table) {
		return Arrays.stream(table.getItems()).map(item -> item.getText(0) + " | " + item.getText(2) + " | " + item.getText(3)).toList();
	}

	private Text field(int index) {
		// the page's own fields: editable, one line (the dialog's message area is a read-only text)
		return Ui.find(dialog.getShell(), Text.class).stream().filter(text -> (text.getStyle() & SWT.READ_ONLY) == 0 && (text.getStyle() & SWT.MULTI) == 0)
				.toList().get(index);
	}

	@Test
	@Order(1)
	void theSelectedGoalieIsExportedIntoTheChosenFolder() throws Exception {
		IFile goalie = Ui.exampleModel(PROJECT, null, "Goalie");
		outside = Files.createTempDirectory("kse-scxml-export");
		ExportScxmlWizard wizard = new ExportScxmlWizard();
		wizard.init(PlatformUI.getWorkbench(), new StructuredSelection(goalie));
		open(wizard);

		Table models = Ui.find(dialog.getShell(), Table.class).stream().filter(table -> (table.getStyle() & SWT.CHECK) != 0).findFirst().orElseThrow();
		List<String> checked = Arrays.stream(models.getItems()).filter(TableItem::getChecked).map(TableItem::getText).toList();
		assertEquals(List.of(PROJECT + "/Goalie.stct"), checked, "the selection, checked");
		field(0).setText(outside.toString());
		Ui.screenshotOf(dialog.getShell(), "40-export-scxml-wizard");
		Ui.press(dialog.getShell(), "Finish");

		assertTrue(Ui.waitUntil(this::closed, 30_000), "the wizard finishes");
		String scxml = Files.readString(outside.resolve("Goalie.scxml"), StandardCharsets.UTF_8);
		assertTrue(scxml.contains("<scxml") && scxml.contains("kse:export=\"1\"") && scxml.contains("name=\"Goalie\""), scxml.substring(0, Math.min(400, scxml.length())));
	}

	@Test
	@Order(2)
	void aStatechartTheExportRefusesIsListedWithItsProblemsAndNothingIsWritten() throws Exception {
		IProject project = Ui.exampleModel(PROJECT, null, "Goalie").getProject();
		IFile withVariable = project.getFile("WithVariable.stct");
		String goalie = Files.readString(Path.of(project.getFile("Goalie.stct").getLocationURI()));
		String text = goalie.replace("</statechart:Model>", "  <variables name=\"ball\" type=\"behavior.State.HeadToBMessage\"/>\n</statechart:Model>");
		if (withVariable.exists()) {
			withVariable.delete(true, null);
		}
		withVariable.create(text.getBytes(StandardCharsets.US_ASCII), IResource.FORCE, null);
		ExportScxmlWizard wizard = new ExportScxmlWizard();
		wizard.init(PlatformUI.getWorkbench(), new StructuredSelection(withVariable));
		open(wizard);
		field(0).setText(outside.toString());

		Ui.press(dialog.getShell(), "Finish");
		assertTrue(Ui.waitUntil(() -> problems().getItemCount() > 0, 30_000), "the problems are listed");

		assertFalse(closed(), "the wizard stays open");
		assertTrue(rows(problems()).stream().anyMatch(row -> row.startsWith("Error | ") && row.contains("ball")), rows(problems()).toString());
		assertTrue(String.valueOf(dialog.getCurrentPage().getErrorMessage()).contains("nothing was written"), dialog.getCurrentPage().getErrorMessage());
		assertFalse(Files.exists(outside.resolve("WithVariable.scxml")), "nothing written");
		Ui.screenshotOf(dialog.getShell(), "41-export-scxml-refused");
	}

	@Test
	@Order(3)
	void aChartOfAnotherToolIsImportedIntoTheSelectedProjectAndOpened() throws Exception {
		IProject project = Ui.exampleModel(PROJECT, null, "Goalie").getProject();
		ImportScxmlWizard wizard = new ImportScxmlWizard();
		wizard.init(PlatformUI.getWorkbench(), new StructuredSelection(project));
		open(wizard);
		assertEquals("/" + PROJECT, field(1).getText(), "the selected project");

		field(0).setText(FIXTURES.resolve("TrafficLight.scxml").toString());
		assertEquals("TrafficLight.stct", field(2).getText(), "the model's file named after the chart");
		Ui.screenshotOf(dialog.getShell(), "42-import-scxml-wizard");
		Ui.press(dialog.getShell(), "Finish");

		assertTrue(Ui.waitUntil(this::closed, 30_000), () -> "the wizard finishes: " + rows(problems()));
		IFile model = project.getFile("TrafficLight.stct");
		assertTrue(model.exists());
		assertTrue(Files.readString(Path.of(model.getLocationURI())).contains("name=\"Crossing\" label=\"0.2\" type=\"AND\""));
		assertTrue(Ui.waitUntil(() -> Ui.page().getActiveEditor() != null && "TrafficLight.stct".equals(Ui.page().getActiveEditor().getEditorInput().getName()), 20_000),
				"opened in the statechart editor");
		Ui.settle(1500);
		Ui.screenshot("43-imported-statechart");
	}

	@Test
	@Order(4)
	void anEventDrivenChartsErrorsAreListedPerElementAndNothingIsImported() throws Exception {
		IProject project = Ui.exampleModel(PROJECT, null, "Goalie").getProject();
		ImportScxmlWizard wizard = new ImportScxmlWizard();
		wizard.init(PlatformUI.getWorkbench(), new StructuredSelection(project));
		open(wizard);
		field(0).setText(FIXTURES.resolve("EventDriven.scxml").toString());

		Ui.press(dialog.getShell(), "Finish");
		assertTrue(Ui.waitUntil(() -> problems().getItemCount() > 0, 30_000), "the problems are listed");

		assertFalse(closed(), "the wizard stays open");
		List<String> rows = rows(problems());
		assertEquals(8, rows.size(), rows.toString());
		assertTrue(rows.get(1).startsWith("Error | <transition event=\"start\" target=\"Running\"> at 9:53 | the event 'start'"), rows.toString());
		assertTrue(String.valueOf(dialog.getCurrentPage().getErrorMessage()).contains("6 errors"), dialog.getCurrentPage().getErrorMessage());
		assertFalse(project.getFile("EventDriven.stct").exists(), "nothing imported");
		Ui.screenshotOf(dialog.getShell(), "44-import-scxml-errors");
	}

	@Test
	@Order(5)
	void partsLeftOutAreShownFirstAndAnExistingModelIsOverwrittenOnlyWhenTheUserSaysSo() throws Exception {
		IProject project = Ui.exampleModel(PROJECT, null, "Goalie").getProject();
		IFile model = project.getFile("SideEffects.stct");
		model.create("not yet a model".getBytes(StandardCharsets.US_ASCII), IResource.FORCE, null);
		ImportScxmlWizard wizard = new ImportScxmlWizard();
		wizard.init(PlatformUI.getWorkbench(), new StructuredSelection(model));
		open(wizard);
		field(0).setText(FIXTURES.resolve("SideEffects.scxml").toString());

		Ui.press(dialog.getShell(), "Finish");
		assertTrue(Ui.waitUntil(() -> problems().getItemCount() > 0, 30_000), "the parts left out are listed");
		assertFalse(closed(), "the first Finish shows them");
		assertEquals(5, problems().getItemCount(), rows(problems()).toString());
		assertTrue(String.valueOf(dialog.getCurrentPage().getMessage()).contains("Press Finish again"), dialog.getCurrentPage().getMessage());
		Ui.screenshotOf(dialog.getShell(), "45-import-scxml-left-out");

		Ui.expectDialog("Overwrite Statechart");
		Ui.Answered no = Ui.whenShown(shell -> "Overwrite Statechart".equals(shell.getText()), shell -> Ui.press(shell, "No"));
		Ui.press(dialog.getShell(), "Finish");
		no.check("Overwrite (no)");
		assertFalse(closed(), "not overwritten: the wizard stays");
		assertEquals("not yet a model", Files.readString(Path.of(model.getLocationURI())));

		Ui.Answered yes = Ui.whenShown(shell -> "Overwrite Statechart".equals(shell.getText()), shell -> Ui.press(shell, "Yes"));
		Ui.press(dialog.getShell(), "Finish");
		yes.check("Overwrite (yes)");
		assertTrue(Ui.waitUntil(this::closed, 30_000), "imported");
		assertTrue(Files.readString(Path.of(model.getLocationURI())).contains("name=\"Wait\""), "the imported statechart");
	}
}
