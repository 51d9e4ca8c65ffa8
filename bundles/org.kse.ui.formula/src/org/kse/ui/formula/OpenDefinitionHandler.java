package org.kse.ui.formula;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.ui.handlers.HandlerUtil;

/** F3 in the formula editor: to the definition of the capability at the cursor. */
public class OpenDefinitionHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) {
		if (HandlerUtil.getActiveEditor(event) instanceof FormulaEditor editor) {
			editor.openDefinitionAtCursor();
		}
		return null;
	}
}
