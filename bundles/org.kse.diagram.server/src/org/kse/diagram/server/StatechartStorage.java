package org.kse.diagram.server;

import java.io.IOException;
import java.nio.file.Path;

import org.eclipse.glsp.server.actions.SaveModelAction;
import org.eclipse.glsp.server.features.core.model.RequestModelAction;
import org.eclipse.glsp.server.features.core.model.SourceModelStorage;
import org.eclipse.glsp.server.types.GLSPServerException;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.kse.model.StatechartResources;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Model;
import org.kse.notation.NotationFiles;

import com.google.inject.Inject;

/**
 * Opens the statechart a client names in {@code sourceUri} (only inside the served folder) with
 * its notation, and saves both atomically.
 */
public class StatechartStorage implements SourceModelStorage {

	@Inject
	private StatechartModelState state;

	@Inject
	private ServedFolder folder;

	@Override
	public void loadSourceModel(RequestModelAction action) {
		Path file;
		try {
			file = folder.resolve(action.getOptions().get("sourceUri"));
		} catch (IllegalArgumentException e) {
			throw new GLSPServerException(e.getMessage(), e);
		}
		try {
			EditingDomain domain = StatechartEdits.newDomain();
			Model model = StatechartResources.load(domain.getResourceSet(), file);
			NotationFiles.Opened opened = NotationFiles.open(file, model);
			state.open(file, model, domain, DiagramLayout.of(model, opened.notation()));
		} catch (IOException e) {
			throw new GLSPServerException("cannot open " + folder.root().relativize(file) + ": " + e.getMessage(), e);
		}
	}

	@Override
	public void saveSourceModel(SaveModelAction action) {
		try {
			StatechartResources.save(state.getModel(), state.getFile());
			NotationFiles.write(state.getFile(), state.getModel(), state.getLayout().toNotation(state.getModel()));
			state.saveIsDone();
		} catch (IOException e) {
			throw new GLSPServerException("cannot save " + state.getFile().getFileName() + ": " + e.getMessage(), e);
		}
	}
}
