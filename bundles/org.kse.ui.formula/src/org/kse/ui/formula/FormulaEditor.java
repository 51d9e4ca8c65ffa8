package org.kse.ui.formula;

import org.eclipse.core.resources.IFile;
import org.eclipse.ui.editors.text.TextEditor;
import org.eclipse.ui.views.contentoutline.IContentOutlinePage;

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

	@Override
	protected void initializeKeyBindingScopes() {
		setKeyBindingScopes(new String[] { "org.kse.ui.formulaEditorScope" });
	}

	private FormulaOutline outline;

	@Override
	public <T> T getAdapter(Class<T> adapter) {
		if (adapter == IContentOutlinePage.class) {
			if (outline == null || outline.getControl() != null && outline.getControl().isDisposed()) {
				outline = new FormulaOutline(this);
			}
			return adapter.cast(outline);
		}
		return super.getAdapter(adapter);
	}

	/** Called after each check of the text (any thread): the outline follows the text. */
	void textChecked() {
		if (outline != null && getSite() != null) {
			getSite().getShell().getDisplay().asyncExec(() -> {
				if (outline != null) {
					outline.update();
				}
			});
		}
	}

	/** Go to the definition of the name at the cursor (F3). */
	public boolean openDefinitionAtCursor() {
		String text = getText();
		int offset = ((org.eclipse.jface.text.ITextSelection) getSelectionProvider().getSelection()).getOffset();
		int[] name = Definitions.wordAt(text, offset);
		Definitions.Definition definition = name == null ? null : Definitions.find(text, text.substring(name[0], name[1]));
		if (definition == null) {
			return false;
		}
		selectAndReveal(definition.offset(), definition.name().length());
		return true;
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
