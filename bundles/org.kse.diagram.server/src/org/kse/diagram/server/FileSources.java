package org.kse.diagram.server;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

import org.apache.logging.log4j.LogManager;
import org.apache.logging.log4j.Logger;
import org.eclipse.emf.common.command.BasicCommandStack;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.kse.model.StatechartResources;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Model;

/**
 * Statecharts read from their files and shared by every page of a file ({@code kse serve}): two
 * tabs, or a page and the one that replaced it after a dropped connection, edit one model on one
 * command stack with one layout. A change in one page is shown in the others, and no save can
 * overwrite a change it has not seen. A model with unsaved edits stays open when its last page
 * closes, until the server stops, so that a page that lost its connection finds them again; one
 * without is let go, and read anew from its file by the next page (another program may have
 * changed it meanwhile).
 */
public final class FileSources implements StatechartSources {

	private static final Logger LOG = LogManager.getLogger("org.kse.diagram");

	private final Map<Path, Shared> open = new HashMap<>();

	@Override
	public synchronized Source open(Path file) throws IOException {
		Shared shared = open.get(file);
		if (shared != null && shared.pages == 0 && !shared.isDirty() && shared.changedOnDisk()) {
			open.remove(file);
			shared = null;
		}
		if (shared == null) {
			shared = new Shared(file);
			open.put(file, shared);
		}
		shared.pages++;
		return shared.page();
	}

	/** How many pages have the file open now (for tests and the log). */
	public synchronized int pages(Path file) {
		Shared shared = open.get(file);
		return shared == null ? 0 : shared.pages;
	}

	private synchronized void closed(Shared shared) {
		shared.pages--;
		if (shared.pages == 0 && !shared.isDirty()) {
			open.remove(shared.file, shared);
		} else if (shared.pages == 0) {
			LOG.info("kept the unsaved edits of " + shared.file.getFileName() + " for a page that reconnects");
		}
	}

	/** One file's model, command stack and layout, and what each page registered to run after a save. */
	private final class Shared {
		final Path file;
		final EditingDomain domain = StatechartEdits.newDomain();
		final Model model;
		final Map<Class<?>, Object> attachments = new HashMap<>();
		final List<NotationWriter> afterSave = new ArrayList<>();
		FileTime loaded;
		int pages;

		Shared(Path file) throws IOException {
			this.file = file;
			this.model = StatechartResources.load(domain.getResourceSet(), file);
			this.loaded = modified();
		}

		boolean isDirty() {
			return ((BasicCommandStack) domain.getCommandStack()).isSaveNeeded();
		}

		boolean changedOnDisk() {
			try {
				return !modified().equals(loaded);
			} catch (IOException gone) {
				return true;
			}
		}

		FileTime modified() throws IOException {
			return Files.getLastModifiedTime(file);
		}

		Source page() {
			return new Source() {
				private NotationWriter registered;

				@Override
				public Model model() {
					return model;
				}

				@Override
				public EditingDomain domain() {
					return domain;
				}

				@Override
				@SuppressWarnings("unchecked")
				public <T> T shared(Class<T> kind, Supplier<T> create) {
					synchronized (Shared.this) {
						return (T) attachments.computeIfAbsent(kind, key -> create.get());
					}
				}

				@Override
				public void save(NotationWriter notation) throws IOException {
					List<NotationWriter> others;
					synchronized (Shared.this) {
						if (changedOnDisk()) {
							throw new IOException(file.getFileName() + " was changed on disk by another program since it was opened; "
									+ "close every page of it and open it again to see that version, or copy your edits first");
						}
						StatechartResources.save(model, file);
						loaded = modified();
						notation.write();
						others = new ArrayList<>(afterSave);
						others.remove(registered);
					}
					for (NotationWriter other : others) {
						other.write();
					}
				}

				@Override
				public void onSave(NotationWriter notation) {
					synchronized (Shared.this) {
						registered = notation;
						afterSave.add(notation);
					}
				}

				@Override
				public void close() {
					synchronized (Shared.this) {
						afterSave.remove(registered);
					}
					closed(Shared.this);
				}
			};
		}
	}
}
