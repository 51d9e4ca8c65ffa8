package org.kse.ui.formula;

import org.eclipse.jface.text.IRegion;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.Region;
import org.eclipse.jface.text.hyperlink.AbstractHyperlinkDetector;
import org.eclipse.jface.text.hyperlink.IHyperlink;
import org.kse.ui.text.Jump;

/** Ctrl+click (or F3 through the editor's action) on a capability goes to its definition. */
class FormulaHyperlinks extends AbstractHyperlinkDetector {

	private final FormulaEditor editor;

	FormulaHyperlinks(FormulaEditor editor) {
		this.editor = editor;
	}

	@Override
	public IHyperlink[] detectHyperlinks(ITextViewer viewer, IRegion region, boolean canShowMultipleHyperlinks) {
		String text = viewer.getDocument().get();
		int[] name = Definitions.wordAt(text, region.getOffset());
		if (name == null) {
			return null;
		}
		int start = name[0];
		int end = name[1];
		Definitions.Definition definition = Definitions.find(text, text.substring(start, end));
		if (definition == null || definition.offset() == start) {
			return null;
		}
		return new IHyperlink[] { new Jump(new Region(start, end - start), "Definition", "Go to the definition of " + definition.name(),
				() -> editor.selectAndReveal(definition.offset(), definition.name().length())) };
	}
}
