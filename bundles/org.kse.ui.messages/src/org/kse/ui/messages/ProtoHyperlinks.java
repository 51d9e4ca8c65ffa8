package org.kse.ui.messages;

import org.eclipse.jface.text.IRegion;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.Region;
import org.eclipse.jface.text.hyperlink.AbstractHyperlinkDetector;
import org.eclipse.jface.text.hyperlink.IHyperlink;
import org.kse.ui.text.Jump;

/** Ctrl+click on a field's type name goes to the declaration of that message or enum. */
public class ProtoHyperlinks extends AbstractHyperlinkDetector {

	private final ProtoEditor editor;

	public ProtoHyperlinks(ProtoEditor editor) {
		this.editor = editor;
	}

	@Override
	public IHyperlink[] detectHyperlinks(ITextViewer viewer, IRegion region, boolean canShowMultipleHyperlinks) {
		ProtoEditor.TypeAt at = editor.typeAt(viewer.getDocument().get(), region.getOffset());
		if (at == null || at.declaration().isEmpty()) {
			return null;
		}
		LinkedProto.Declaration declaration = at.declaration().get();
		return new IHyperlink[] { new Jump(new Region(at.start(), at.end() - at.start()), "Declaration",
				"Go to the declaration of " + declaration.type().fullName(), () -> editor.open(declaration)) };
	}
}
