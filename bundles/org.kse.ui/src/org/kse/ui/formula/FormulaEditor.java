package org.kse.ui.formula;

import org.eclipse.core.resources.IFile;
import org.eclipse.ui.editors.text.TextEditor;

/**
 * The text editor of liveness formulas: colours, problems while typing, content assist
 * (Xtext's IDE services for the grammar, the file's names for references).
 */
public class FormulaEditor extends TextEditor {

	public static final String ID = "org.kse.ui.formula.editor";

	@Override
	protected void initializeEditor() {
		super.initializeEditor();
		setSourceViewerConfiguration(new FormulaViewerConfiguration(this, getPreferenceStore()));
	}

	/** The workspace file being edited, or null for a file outside the workspace. */
	public IFile getFile() {
		return getEditorInput() == null ? null : getEditorInput().getAdapter(IFile.class);
	}

	/** The text as it is in the editor now, saved or not. */
	public String getText() {
		return getDocumentProvider().getDocument(getEditorInput()).get();
	}
}
