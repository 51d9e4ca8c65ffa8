package org.kse.ui.statechart;

import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.kse.labeling.Labeler;
import org.kse.model.StatechartResources;
import org.kse.ui.ModelFiles;

/**
 * "Label": renumbers the states (the original's "Labeling Diagram") and saves the model
 * atomically; an open editor of the model shows the result (it reloads the file).
 */
public class LabelHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) {
		List<IFile> files = ModelFiles.of(event);
		if (!files.isEmpty() && !org.kse.ui.statechart.KeyEchoes.isEcho(event)) {
			ModelJob.schedule("Labeling", files, true, (file, model, progress) -> {
				Labeler.label(model);
				progress.worked(5);
				StatechartResources.save(model, ModelFiles.location(file));
				file.refreshLocal(IResource.DEPTH_ZERO, progress.split(5));
			});
		}
		return null;
	}
}
