package org.kse.ui.formula;

import java.util.List;

import org.eclipse.jface.viewers.ColumnLabelProvider;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.TreeViewer;
import org.eclipse.swt.graphics.Color;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.ui.views.contentoutline.ContentOutlinePage;
import org.kse.ui.text.OutlineContent;

/** The Outline of a formula file: its capabilities in file order; a click selects the definition. */
class FormulaOutline extends ContentOutlinePage {

	private final FormulaEditor editor;

	FormulaOutline(FormulaEditor editor) {
		this.editor = editor;
	}

	@Override
	public void createControl(Composite parent) {
		super.createControl(parent);
		TreeViewer viewer = getTreeViewer();
		viewer.setContentProvider(new OutlineContent(definition -> List.of()));
		viewer.setLabelProvider(new ColumnLabelProvider() {
			@Override
			public String getText(Object element) {
				Definitions.Definition definition = (Definitions.Definition) element;
				String expression = definition.expression().length() > 60 ? definition.expression().substring(0, 57) + "..." : definition.expression();
				return definition.name() + " = " + expression;
			}

			@Override
			public Color getForeground(Object element) {
				return FormulaScanner.CAPABILITY;
			}
		});
		viewer.addSelectionChangedListener(event -> {
			if (event.getSelection() instanceof IStructuredSelection selection && selection.getFirstElement() instanceof Definitions.Definition definition) {
				editor.selectAndReveal(definition.offset(), definition.name().length());
			}
		});
		update();
	}

	/** Shows the definitions of the editor's text as it is now. */
	void update() {
		TreeViewer viewer = getTreeViewer();
		if (viewer == null || viewer.getControl().isDisposed()) {
			return;
		}
		List<Definitions.Definition> definitions = Definitions.of(editor.getText());
		viewer.setInput(definitions);
	}
}
