package org.kse.ui.messages;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.ui.handlers.HandlerUtil;

/** F3 in the message editor: to the declaration of the message or enum type at the cursor. */
public class OpenDeclarationHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) {
		if (HandlerUtil.getActiveEditor(event) instanceof ProtoEditor editor) {
			editor.openDeclarationAtCursor();
		}
		return null;
	}
}
