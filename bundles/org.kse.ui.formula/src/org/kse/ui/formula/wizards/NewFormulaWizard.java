package org.kse.ui.formula.wizards;

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

	/** Words of a file name that say what the file is rather than which behaviour it holds. */
	private static final java.util.regex.Pattern FILE_KIND = java.util.regex.Pattern.compile("(?i)[ ._-]*(liveness|formulas?)$");

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
				return new ByteArrayInputStream(TEMPLATE.formatted(behaviourName(getFileName())).getBytes(StandardCharsets.UTF_8));
			}
		};
		page.setTitle("Liveness formulas");
		page.setDescription("A behaviour as liveness formulas, to turn into a statechart.");
		page.setFileExtension("liveness");
		page.setFileName("Behaviour.liveness");
		addPage(page);
	}

	/**
	 * The behaviour's formula name for a file name, as the examples spell theirs: {@code Keeper.liveness},
	 * {@code keeper_liveness.liveness} and {@code Keeper formulas.txt} hold {@code keeper}; {@code
	 * ball-keeper v2} holds {@code ballKeeperV2}. It names the model, so the generated code's folder.
	 */
	public static String behaviourName(String fileName) {
		String name = fileName.strip();
		int dot = name.lastIndexOf('.');
		if (dot > 0) {
			name = name.substring(0, dot);
		}
		String rest = FILE_KIND.matcher(name).replaceFirst("");
		if (!rest.isEmpty()) {
			name = rest;
		}
		StringBuilder identifier = new StringBuilder();
		for (String word : name.split("[^A-Za-z0-9_]+")) {
			if (word.isEmpty()) {
				continue;
			}
			identifier.append(identifier.isEmpty() ? Character.toLowerCase(word.charAt(0)) : Character.toUpperCase(word.charAt(0)));
			identifier.append(word.substring(1));
		}
		if (identifier.isEmpty()) {
			return "behaviour";
		}
		// an ID starts with a letter or an underscore
		return Character.isDigit(identifier.charAt(0)) ? "behaviour" + identifier : identifier.toString();
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
