package org.kse.ui.wizards;

import java.io.ByteArrayInputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

import org.eclipse.core.resources.IFile;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.ui.INewWizard;
import org.eclipse.ui.IWorkbench;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.dialogs.WizardNewFileCreationPage;
import org.eclipse.ui.ide.IDE;
import org.eclipse.jface.wizard.Wizard;
import org.kse.ui.formula.FormulaEditor;

/** New liveness formula file, started with a small correct behaviour to change. */
public class NewFormulaWizard extends Wizard implements INewWizard {

	static final String TEMPLATE = """
			// Liveness formulas: one per line; the first line's left side is the behaviour.
			// Capitalised names are activities, lower-case names are defined below.
			// Operators: . sequence, | choice, || parallel, * + ~ repetition, [x] option, (x) group.
			%s = Init.(playing | nonPlaying)+
			nonPlaying = NoPlay
			playing = Scan+ | ApproachBall+ | Kick
			""";

	private IWorkbench workbench;
	private IStructuredSelection selection;
	private WizardNewFileCreationPage page;

	@Override
	public void init(IWorkbench workbench, IStructuredSelection selection) {
		this.workbench = workbench;
		this.selection = selection;
		setWindowTitle("New Formula");
		setNeedsProgressMonitor(true);
	}

	@Override
	public void addPages() {
		page = new WizardNewFileCreationPage("formula", selection) {
			@Override
			protected InputStream getInitialContents() {
				String behaviour = getFileName().replaceFirst("\\\\.[^.]*$", "");
				String root = behaviour.isEmpty() ? "behaviour" : Character.toLowerCase(behaviour.charAt(0)) + behaviour.substring(1).replaceAll("[^A-Za-z0-9_]", "_");
				return new ByteArrayInputStream(TEMPLATE.formatted(root).getBytes(StandardCharsets.UTF_8));
			}
		};
		page.setTitle("Liveness formulas");
		page.setDescription("A behaviour as liveness formulas, to turn into a statechart.");
		page.setFileExtension("liveness");
		page.setFileName("Behaviour.liveness");
		addPage(page);
	}

	@Override
	public boolean performFinish() {
		IFile file = page.createNewFile();
		if (file == null) {
			return false;
		}
		try {
			IDE.openEditor(workbench.getActiveWorkbenchWindow().getActivePage(), file, FormulaEditor.ID);
		} catch (PartInitException e) {
			page.setErrorMessage("created, but cannot open: " + e.getMessage());
		}
		return true;
	}
}
