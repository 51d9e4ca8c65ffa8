package org.kse.ui.formula;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.ILog;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IEditorPart;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.handlers.HandlerUtil;
import org.eclipse.ui.ide.IDE;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.transform.FormulaTransformation;

/**
 * "Transform to Statechart": the formulas of the active editor become {@code <name>.stct} next to
 * the formula file, which then opens. Formulas with errors are reported (line and column) before
 * anything is asked. An existing model with edits the formulas cannot reproduce is never replaced
 * without listing them; writing {@code <name>-from-formula.stct} beside it is what Enter does.
 */
public class TransformHandler extends AbstractHandler {

	static final String TITLE = "Transform to Statechart";
	/** The suffix of the model written beside one that has edits of its own. */
	public static final String BESIDE_SUFFIX = "-from-formula";
	private static final int SHOWN_EDITS = 8;

	@Override
	public Object execute(ExecutionEvent event) {
		IEditorPart part = HandlerUtil.getActiveEditor(event);
		if (!(part instanceof FormulaEditor editor) || editor.getFile() == null) {
			return null;
		}
		Shell shell = editor.getSite().getShell();
		IFile formula = editor.getFile();
		String text = editor.getText();
		FormulaTransformation.Outcome outcome;
		try {
			outcome = transformed(formula, text);
			if (outcome == null) {
				return null;
			}
		} catch (InvocationTargetException e) {
			ILog.of(TransformHandler.class).error("transforming " + formula.getFullPath() + " failed", e.getCause());
			MessageDialog.openError(shell, TITLE, "The formulas of " + formula.getName() + " could not be transformed: " + e.getCause().getMessage());
			return null;
		}
		if (outcome.model() == null) {
			reportErrors(editor, outcome.issues());
			return null;
		}
		IFile target = chooseTarget(shell, FormulaTransformer.modelOf(formula), outcome.model());
		if (target == null) {
			return null;
		}
		try {
			FormulaTransformer.write(outcome.model(), target);
			IDE.openEditor(editor.getSite().getPage(), target, true);
		} catch (IOException | CoreException e) {
			MessageDialog.openError(shell, TITLE, "Cannot write " + target.getFullPath() + ": " + e.getMessage());
		}
		return null;
	}

	/**
	 * Parses and transforms off the UI thread, with a busy cursor (and a progress dialog if it takes
	 * long), the formula's problems shown as markers; null when cancelled there.
	 */
	private static FormulaTransformation.Outcome transformed(IFile formula, String text) throws InvocationTargetException {
		FormulaTransformation.Outcome[] outcome = new FormulaTransformation.Outcome[1];
		try {
			PlatformUI.getWorkbench().getProgressService().busyCursorWhile(monitor -> {
				try {
					outcome[0] = FormulaTransformer.outcome(formula, text, monitor);
					if (monitor.isCanceled()) {
						throw new InterruptedException();
					}
				} catch (RuntimeException e) {
					throw new InvocationTargetException(e);
				} finally {
					monitor.done();
				}
			});
		} catch (InterruptedException cancelled) {
			return null;
		}
		return outcome[0];
	}

	/** One message that says where the first error is, with the cursor put there. */
	private static void reportErrors(FormulaEditor editor, List<Issue> issues) {
		List<Issue> errors = issues.stream().filter(issue -> issue.getSeverity() == Severity.ERROR).toList();
		String file = editor.getFile().getName();
		if (errors.isEmpty()) {
			MessageDialog.openError(editor.getSite().getShell(), TITLE, file + " holds no formula to transform.");
			return;
		}
		Issue first = errors.get(0);
		if (first.getOffset() != null) {
			editor.selectAndReveal(first.getOffset(), first.getLength() == null ? 0 : first.getLength());
		}
		String more = errors.size() == 1 ? "" : "\n\n" + (errors.size() - 1) + (errors.size() == 2 ? " more error is" : " more errors are")
				+ " listed in the Problems view.";
		MessageDialog.openError(editor.getSite().getShell(), TITLE, shown(file + ", line " + first.getLineNumber() + ", column " + first.getColumn()
				+ ": " + first.getMessage() + "\n\nNothing was transformed." + more));
	}

	/**
	 * Where the statechart goes: the model file itself when it does not exist or holds nothing the
	 * formulas cannot reproduce; otherwise what the user chooses after reading what would be lost
	 * (null: cancelled). Asked by Transform and by the New Statechart from Formulas wizard.
	 */
	public static IFile chooseTarget(Shell shell, IFile model, Model fresh) {
		if (!model.exists()) {
			return model;
		}
		// edits still in an open editor count too: they are saved first (the user is asked)
		if (!IDE.saveAllEditors(new IResource[] { model }, true)) {
			return null;
		}
		IFile beside = besideOf(model);
		String reason;
		try {
			List<String> lost = HandEdits.lostBy(StatechartResources.load(java.nio.file.Path.of(model.getLocationURI())), fresh);
			if (lost.isEmpty()) {
				return model;
			}
			StringBuilder list = new StringBuilder();
			lost.stream().limit(SHOWN_EDITS).forEach(edit -> list.append("\n  \u2022 ").append(edit));
			if (lost.size() > SHOWN_EDITS) {
				list.append("\n  \u2026 and ").append(lost.size() - SHOWN_EDITS).append(" more");
			}
			reason = model.getName() + " has edits these formulas cannot reproduce. Replacing it loses "
					+ (lost.size() == 1 ? "this one:" : "these " + lost.size() + ":") + list;
		} catch (IOException e) {
			reason = model.getName() + " cannot be read (" + e.getMessage() + "), so what replacing it loses is unknown.";
		}
		String question = reason + "\n\nWrite the new statechart beside it as " + beside.getName()
				+ (beside.exists() ? " (replacing that file)" : "") + ", or replace " + model.getName() + "?";
		MessageDialog dialog = new MessageDialog(shell, TITLE, null, shown(question), MessageDialog.WARNING, 0, "Write " + beside.getName(),
				"Replace " + model.getName(), "Cancel");
		return switch (dialog.open()) {
			case 0 -> beside;
			case 1 -> model;
			default -> null;
		};
	}

	/** A dialog's label takes '&' for a mnemonic: the guards' "&&" must show as written. */
	private static String shown(String message) {
		return message.replace("&", "&&");
	}

	/** {@code Goalie-from-formula.stct} for {@code Goalie.stct}. */
	public static IFile besideOf(IFile model) {
		String name = model.getFullPath().removeFileExtension().lastSegment();
		return model.getParent().getFile(org.eclipse.core.runtime.Path.fromPortableString(name + BESIDE_SUFFIX + "." + model.getFileExtension()));
	}
}
