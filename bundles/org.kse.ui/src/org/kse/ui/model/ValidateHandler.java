package org.kse.ui.model;

import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;

/** "Validate": the rules of the original tool and the message catalog; the results in the Problems view. */
public class ValidateHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) {
		List<IFile> files = ModelFiles.of(event);
		if (!files.isEmpty()) {
			ModelJob.schedule("Validating", files, false, (file, model, progress) -> ModelMarkers.validate(file, model));
		}
		return null;
	}
}
