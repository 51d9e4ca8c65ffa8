package org.kse.diagram.server;

import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Supplier;

import org.eclipse.emf.edit.domain.EditingDomain;
import org.kse.model.statechart.Model;

/**
 * Where a diagram session gets the statechart of a file. {@code kse serve} reads the file for each
 * session ({@link FileSources}); the workbench hands out the model that its editor of the file
 * holds, so that the diagram, the tree and the Properties view edit one model on one command
 * stack, on the workbench's UI thread.
 */
public interface StatechartSources {

	/** The statechart of {@code file} (as {@link #locate} found it). */
	Source open(Path file) throws IOException;

	/**
	 * The file a client asks for: by default a {@code .stct} inside the served folder, anything
	 * else refused with an {@link IllegalArgumentException} that says why.
	 */
	default Path locate(String requested, ServedFolder folder) {
		return folder.resolve(requested);
	}

	/** Writes a diagram's notation file next to its model. */
	@FunctionalInterface
	interface NotationWriter {
		void write() throws IOException;
	}

	/** What happened to the file under a model while pages show it. */
	enum DiskChange {
		/** Another program changed the file and nobody had unsaved edits: the model was read again. */
		RELOADED,
		/** Another program changed the file while the model has unsaved edits: the user chooses. */
		CONFLICT,
		/** The file was changed but cannot be read (or is gone): the model is kept, the user chooses. */
		UNREADABLE,
		/** A page chose to keep the edits: the next save overwrites the file. */
		KEPT
	}

	/** Told of a change on disk; {@code detail} says why the file cannot be read (null otherwise). */
	@FunctionalInterface
	interface DiskListener {
		void changed(DiskChange change, String detail);
	}

	/** One opened statechart. */
	interface Source {

		Model model();

		/** The domain whose command stack takes the diagram's edits (and holds its undo and redo). */
		EditingDomain domain();

		/**
		 * Runs {@code access} where the model may be read and changed, and returns its result. A
		 * workbench runs it on its UI thread; a file source runs it where it is called.
		 */
		default <T> T access(Supplier<T> access) {
			return access.get();
		}

		/**
		 * Saves the model and, through {@code notation}, the diagram's notation file. A source
		 * whose owner saves on its own (an editor) saves as its owner does, which runs what
		 * {@link #onSave} registered.
		 */
		void save(NotationWriter notation) throws IOException;

		/**
		 * What every page of this statechart shares besides the model (its layout): made once by
		 * {@code create} where pages share the model, made for each page otherwise.
		 */
		default <T> T shared(Class<T> kind, Supplier<T> create) {
			return create.get();
		}

		/** Registers what runs after every save of the owner's (say, the tree's Save), until {@link #close()}. */
		default void onSave(NotationWriter notation) {
		}

		/**
		 * Registers what a page is told when another program changes the file, until
		 * {@link #close()}; told at once of a change still waiting for a choice. A source whose owner
		 * watches the file itself (an editor) tells nothing.
		 */
		default void onDiskChange(DiskListener listener) {
		}

		/** The user's choice after a change on disk: the unsaved edits are dropped and the file read again, for every page. */
		default void reload() throws IOException {
			throw new IOException("the editor that holds this model reads it again");
		}

		/** The user's choice after a change on disk: the edits are kept, and the next save overwrites the file. */
		default void keepEdits() {
		}

		/** The session ends. */
		default void close() {
		}
	}
}
