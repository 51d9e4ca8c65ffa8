package org.kse.diagram.server;

import java.io.IOException;
import java.nio.file.Path;

import org.apache.logging.log4j.LogManager;
import org.apache.logging.log4j.Logger;
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

	private static final Logger LOG = LogManager.getLogger("org.kse.diagram");

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
			state.open(file, source, layoutOf(file, source));
			source.onSave(this::writeNotation);
			source.onDiskChange((change, detail) -> actions.dispatch(new DiskChanges.FileChangedAction(change, detail)).exceptionally(failure -> {
				// nobody waits for this action: its failure is said here or nowhere
				LOG.warn("showing a change of " + file.getFileName() + " on disk failed: " + Reasons.of(Reasons.unwrap(failure)));
				return null;
			}));
		} catch (IOException e) {
			String name = file.startsWith(folder.root()) ? folder.root().relativize(file).toString() : file.getFileName().toString();
			throw new GLSPServerException("cannot open " + name + ": " + e.getMessage(), e);
		}
	}

	/** Pages of one file share its layout, so that a move in one shows in the others. */
	private static DiagramLayout layoutOf(Path file, StatechartSources.Source source) {
		Model model = source.model();
		return source.shared(DiagramLayout.class, () -> DiagramLayout.of(model, NotationFiles.open(file, model).notation()));
	}

	/** Takes up the model its source holds now (read again from the file), with its layout. */
	public void reopen() {
		state.read(() -> {
			state.open(state.getFile(), state.getSource(), layoutOf(state.getFile(), state.getSource()));
			return null;
		});
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
