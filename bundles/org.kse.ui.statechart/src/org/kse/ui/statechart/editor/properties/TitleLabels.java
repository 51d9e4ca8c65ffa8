package org.kse.ui.statechart.editor.properties;

import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.LabelProvider;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.ui.statechart.editor.StatechartEditor;

/** The title of the Properties view for the statechart editor's selection: what it is and how the tree names it. */
public class TitleLabels extends LabelProvider {

	@Override
	public String getText(Object element) {
		Object first = element instanceof IStructuredSelection selection ? selection.getFirstElement() : element;
		if (first instanceof Node) {
			return "State " + StatechartEditor.label(first);
		}
		if (first instanceof Transition) {
			return "Transition " + StatechartEditor.label(first);
		}
		if (first instanceof Model model) {
			return "Model " + model.getName();
		}
		return first == null ? "" : StatechartEditor.label(first);
	}
}
