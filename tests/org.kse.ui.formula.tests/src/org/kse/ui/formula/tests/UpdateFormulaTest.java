package org.kse.ui.formula.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.emf.common.util.URI;
import org.eclipse.swt.custom.StyledText;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableItem;
import org.eclipse.swt.widgets.Text;
import org.eclipse.ui.PlatformUI;
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
import org.kse.model.statechart.Transition;
import org.kse.transform.FormulaTransformation;
import org.kse.ui.formula.FormulaEditor;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * KSE > Update Formula from Statechart, as a user meets it: a chart edited after its
 * transformation, the formula file against the recovered formulas in a compare viewer, what the
 * formulas cannot say listed by state, the file written when accepted and opened in the formula
 * editor, and nothing to update the second time.
 */
@ExtendWith(UnexpectedDialogs.class)
@TestMethodOrder(OrderAnnotation.class)
class UpdateFormulaTest {

	private static final String TITLE = "Update Formula from Statechart";
	private static final String WRITTEN = "keeper = Wait.Scan.Kick\n";
	private static IProject project;
	private static IFile formula;
	private static IFile chart;

	@BeforeAll
	static void aChartTransformedFromItsFormulaThenEditedInTheDiagram() throws CoreException, IOException {
		project = ResourcesPlugin.getWorkspace().getRoot().getProject("Recovered");
		if (!project.exists()) {
			project.create(null);
		}
		project.open(null);
		formula = project.getFile("Keeper.liveness");
		formula.create(new ByteArrayInputStream(WRITTEN.getBytes(StandardCharsets.UTF_8)), true, null);
		Model model = FormulaTransformation.run(WRITTEN, URI.createURI("Keeper.liveness"), null).model();
		assertNotNull(model);
		// the user renamed a state in the diagram and guarded the kick
		node(model, "Scan").setName("Search");
		Transition toKick = model.getTransitions().stream().filter(transition -> "Kick".equals(transition.getTarget().getName())).findFirst()
				.orElseThrow();
		toKick.setTE("[ballSeen(behavior)]");
		chart = project.getFile("Keeper.stct");
		StatechartResources.save(model, java.nio.file.Path.of(chart.getLocationURI()));
		project.refreshLocal(IResource.DEPTH_INFINITE, null);
		PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell().setSize(1280, 800);
	}

	@AfterAll
	static void closeEditors() {
		Ui.page().closeAllEditors(false);
	}

	private static Node node(Model model, String name) {
		var contents = model.eAllContents();
		while (contents.hasNext()) {
			if (contents.next() instanceof Node node && name.equals(node.getName())) {
				return node;
			}
		}
		throw new AssertionError("no state " + name);
	}

	/** The texts of the compare viewer's sides, left to right as the user sees them. */
	private static List<String> sides(Shell dialog) {
		return Ui.find(dialog, StyledText.class).stream().filter(text -> text.isVisible() && !text.getText().isEmpty())
				.sorted(java.util.Comparator.comparingInt(text -> text.toDisplay(0, 0).x)).map(StyledText::getText)
				.map(text -> text.replace("\r\n", "\n")).toList();
	}

	private static String message(Shell dialog) {
		return String.join("\n", Ui.find(dialog, Text.class).stream().map(Text::getText).toList());
	}

	@Test
	@Order(1)
	void theFormulaFileAndTheRecoveredFormulasAreComparedAndTheFileIsUpdated() throws Exception {
		Ui.select(chart);
		List<String> sides = new java.util.ArrayList<>();
		List<List<String>> problems = new java.util.ArrayList<>();
		Ui.Answered answered = Ui.whenShown(shell -> TITLE.equals(shell.getText()), dialog -> {
			Ui.settle(300);
			Ui.screenshotOf(dialog, "20-update-formula");
			sides.addAll(sides(dialog));
			for (TableItem item : Ui.find(dialog, Table.class).get(0).getItems()) {
				problems.add(List.of(item.getText(0), item.getText(1), item.getText(2)));
			}
			Ui.press(Ui.button(dialog, "Update Keeper.liveness"));
		});
		Ui.run("org.kse.ui.updateFormula");
		answered.check(TITLE);

		assertEquals(List.of(WRITTEN, "keeper = Wait.Search.Kick\n"), sides, "left the file as it is, right the formulas of the edited chart");
		assertEquals(1, problems.size(), "one thing the formula cannot say: " + problems);
		assertEquals(List.of("0.3", "Search"), problems.get(0).subList(0, 2), "named by the state's label and name");
		assertTrue(problems.get(0).get(2).contains("[ballSeen(behavior)]"), problems.get(0).get(2));
		assertEquals("keeper = Wait.Search.Kick\n", Files.readString(java.nio.file.Path.of(formula.getLocationURI())), "written into the file");
		assertTrue(Ui.waitUntil(() -> Ui.page().getActiveEditor() instanceof FormulaEditor, 10_000), "the formula editor shows the file");
		FormulaEditor editor = assertInstanceOf(FormulaEditor.class, Ui.page().getActiveEditor());
		assertEquals("Keeper.liveness", editor.getEditorInput().getName());
		assertEquals("keeper = Wait.Search.Kick\n", editor.getDocumentProvider().getDocument(editor.getEditorInput()).get());
		Ui.settle(500);
		Ui.screenshot("21-formula-updated");
	}

	@Test
	@Order(2)
	void aSecondUpdateHasNothingToWrite() throws Exception {
		Ui.select(chart);
		boolean[] updateEnabled = { true };
		String[] message = new String[1];
		Ui.Answered answered = Ui.whenShown(shell -> TITLE.equals(shell.getText()), dialog -> {
			Ui.settle(200);
			updateEnabled[0] = Ui.button(dialog, "Update Keeper.liveness").isEnabled();
			message[0] = message(dialog);
			Ui.press(Ui.button(dialog, "Close"));
		});
		Ui.run("org.kse.ui.updateFormula");
		answered.check(TITLE);

		assertFalse(updateEnabled[0], "nothing to update");
		assertTrue(message[0].contains("Keeper.liveness already holds the closest formulas"), message[0]);
	}
}
