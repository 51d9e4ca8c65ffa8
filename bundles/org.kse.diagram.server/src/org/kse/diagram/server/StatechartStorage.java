package org.kse.diagram.server;

import java.io.IOException;
import java.nio.file.Path;

import org.eclipse.glsp.server.actions.SaveModelAction;
import org.eclipse.glsp.server.features.core.model.RequestModelAction;
import org.eclipse.glsp.server.features.core.model.SourceModelStorage;
import org.eclipse.glsp.server.types.GLSPServerException;
import org.kse.model.statechart.Model;
import org.kse.notation.NotationFiles;

import com.google.inject.Inject;

/**
 * Opens the statechart a client names in {@code sourceUri} (only inside the served folder) with
 * its notation (from the {@link StatechartSources} bound: a file, or an editor's model), and
 * saves both atomically.
 */
public class StatechartStorage implements SourceModelStorage {

	@Inject
	private StatechartModelState state;

	@Inject
	private ServedFolder folder;

	@Inject
	private StatechartSources sources;

	@Inject
	private org.eclipse.glsp.server.actions.ActionDispatcher actions;

	@Override
	public void loadSourceModel(RequestModelAction action) {
		Path file;
		try {
			file = sources.locate(action.getOptions().get("sourceUri"), folder);
		} catch (IllegalArgumentException e) {
			throw new GLSPServerException(e.getMessage(), e);
		}
		try {
			if (state.getSource() != null) {
				state.getSource().close(); // a page that asks again gives up what it had
			}
			StatechartSources.Source source = sources.open(file);
			Model model = source.model();
			// pages of one file share its layout, so that a move in one shows in the others
			DiagramLayout layout = source.shared(DiagramLayout.class, () -> DiagramLayout.of(model, NotationFiles.open(file, model).notation()));
			state.open(file, source, layout);
			source.onSave(this::writeNotation);
		} catch (IOException e) {
			String name = file.startsWith(folder.root()) ? folder.root().relativize(file).toString() : file.getFileName().toString();
			throw new GLSPServerException("cannot open " + name + ": " + e.getMessage(), e);
		}
	}

	@Override
	public void saveSourceModel(SaveModelAction action) {
		if (state.getSource() == null) {
			throw new GLSPServerException("no model is open to save"); // not a NullPointerException
		}
		try {
			state.getSource().save(this::writeNotation);
			state.saveIsDone();
		} catch (IOException e) {
			throw new GLSPServerException("cannot save " + state.getFile().getFileName() + ": " + e.getMessage(), e);
		}
	}

	/** Writes the notation as part of a save, made here or by the editor that holds the model (then the page learns it is saved). */
	private void writeNotation() throws IOException {
		NotationFiles.write(state.getFile(), state.getModel(), state.getLayout().toNotation(state.getModel()));
		actions.dispatch(new org.eclipse.glsp.server.actions.SetDirtyStateAction(false, org.eclipse.glsp.server.actions.SetDirtyStateAction.Reason.SAVE));
	}
}
