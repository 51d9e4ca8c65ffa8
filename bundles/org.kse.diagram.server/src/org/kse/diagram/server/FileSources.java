package org.kse.diagram.server;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
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
 * command stack with one layout, one page at a time ({@link Source#access}). A change in one page
 * is shown in the others, and no save can overwrite a change it has not seen. A model with unsaved
 * edits stays open when its last page closes, until the server stops, so that a page that lost
 * its connection finds them again; one without is let go, and read anew from its file by the next
 * page.
 * <p>
 * The files held are compared with the disk every {@link #WATCH_MILLIS} ms: a file that another
 * program changed is read again when nobody has unsaved edits, and otherwise its pages ask the
 * user ({@link DiskChange}). Polling the modification time is what every file system supports
 * (a WatchService misses changes on network and some container file systems).
 */
public final class FileSources implements StatechartSources {

	private static final Logger LOG = LogManager.getLogger("org.kse.diagram");

	/** How often the files held are compared with the disk. */
	public static final long WATCH_MILLIS = 1000;

	private static final ScheduledExecutorService WATCHER = Executors.newSingleThreadScheduledExecutor(runnable -> {
		Thread thread = new Thread(runnable, "kse-diagram-files");
		thread.setDaemon(true);
		return thread;
	});

	private final Map<Path, Shared> open = new HashMap<>();
	private ScheduledFuture<?> watching;

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
		if (watching == null) {
			watching = WATCHER.scheduleWithFixedDelay(this::checkFiles, WATCH_MILLIS, WATCH_MILLIS, TimeUnit.MILLISECONDS);
		}
		return shared.page();
	}

	/** How many pages have the file open now (for tests and the log). */
	public synchronized int pages(Path file) {
		Shared shared = open.get(file);
		return shared == null ? 0 : shared.pages;
	}

	/**
	 * Compares every file held with the disk and handles what another program changed: read again
	 * when nobody has unsaved edits, else the pages are asked, once per change. The watcher calls
	 * it every {@link #WATCH_MILLIS} ms; tests call it directly.
	 */
	public void checkFiles() {
		List<Shared> held;
		synchronized (this) {
			held = new ArrayList<>(open.values());
		}
		for (Shared shared : held) {
			try {
				shared.check();
			} catch (RuntimeException unexpected) {
				// the watcher runs on: one file's trouble must not stop it for the others
				LOG.warn("checking " + shared.file.getFileName() + " on disk failed: " + Reasons.of(unexpected));
			}
		}
	}

	private synchronized void closed(Shared shared) {
		shared.pages--;
		if (shared.pages == 0 && !shared.isDirty()) {
			open.remove(shared.file, shared);
		} else if (shared.pages == 0) {
			LOG.info("kept the unsaved edits of " + shared.file.getFileName() + " for a page that reconnects");
		}
		if (open.isEmpty() && watching != null) {
			watching.cancel(false);
			watching = null;
		}
	}

	/** The file's modification time and size, or "missing": what tells that the file changed. */
	private static String stamp(Path file) {
		try {
			BasicFileAttributes attributes = Files.readAttributes(file, BasicFileAttributes.class);
			return attributes.lastModifiedTime().toString() + " " + attributes.size();
		} catch (IOException gone) {
			return "missing";
		}
	}

	/** A change on disk the pages were told of and nobody has decided on yet. */
	private record Waiting(String stamp, DiskChange change, String detail) {
	}

	/**
	 * One file's model, command stack and layout, what each page registered to run after a save,
	 * and whom to tell of changes on disk. Its monitor guards the model: every page reads and
	 * edits it through {@link Source#access}.
	 */
	private final class Shared {
		final Path file;
		volatile EditingDomain domain;
		volatile Model model;
		final Map<Class<?>, Object> attachments = new HashMap<>();
		final List<NotationWriter> afterSave = new ArrayList<>();
		final List<DiskListener> listeners = new ArrayList<>();
		/** The file as it was when read or last saved. */
		String loaded;
		Waiting waiting;
		int pages;

		Shared(Path file) throws IOException {
			this.file = file;
			read();
		}

		/** Reads the file into a domain of its own: what was read before, its layout and its undo history are dropped. */
		private void read() throws IOException {
			String stamp = stamp(file); // taken first: a change made while reading is seen by the next check
			EditingDomain fresh = StatechartEdits.newDomain();
			Model read;
			try {
				read = StatechartResources.load(fresh.getResourceSet(), file);
			} catch (NoSuchFileException gone) {
				throw new IOException("the file is gone", gone);
			}
			domain = fresh;
			model = read;
			attachments.clear();
			loaded = stamp;
			waiting = null;
		}

		boolean isDirty() {
			return ((BasicCommandStack) domain.getCommandStack()).isSaveNeeded();
		}

		boolean changedOnDisk() {
			return !stamp(file).equals(loaded);
		}

		/** One look at the disk; see {@link FileSources#checkFiles()}. */
		void check() {
			DiskChange change;
			String detail = null;
			List<DiskListener> told;
			synchronized (this) {
				String now = stamp(file);
				if (now.equals(loaded) || (waiting != null && waiting.stamp().equals(now))) {
					return;
				}
				if (isDirty()) {
					change = DiskChange.CONFLICT;
					LOG.info(file.getFileName() + " was changed on disk while it has unsaved edits: its pages ask what to keep");
				} else {
					try {
						read();
						change = DiskChange.RELOADED;
						LOG.info("read " + file.getFileName() + " again: another program changed it");
					} catch (IOException | RuntimeException unreadable) {
						change = DiskChange.UNREADABLE;
						detail = Reasons.of(unreadable);
						LOG.warn(file.getFileName() + " was changed on disk and cannot be read: " + detail);
					}
				}
				waiting = change == DiskChange.RELOADED ? null : new Waiting(now, change, detail);
				told = new ArrayList<>(listeners);
			}
			tell(told, change, detail);
		}

		/** Tells pages outside the monitor: a page answers on its own session's thread, which may be waiting for it. */
		void tell(List<DiskListener> told, DiskChange change, String detail) {
			for (DiskListener listener : told) {
				listener.changed(change, detail);
			}
		}

		Source page() {
			return new Source() {
				private NotationWriter registered;
				private DiskListener listening;

				@Override
				public Model model() {
					return model;
				}

				@Override
				public EditingDomain domain() {
					return domain;
				}

				@Override
				public <T> T access(Supplier<T> access) {
					synchronized (Shared.this) {
						return access.get();
					}
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
							throw new IOException(file.getFileName() + " was changed on disk by another program since it was read; "
									+ "choose Reload to see that version (your unsaved edits are dropped) or Keep mine to overwrite it");
						}
						StatechartResources.save(model, file);
						loaded = stamp(file);
						waiting = null;
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
				public void onDiskChange(DiskListener listener) {
					Waiting undecided;
					synchronized (Shared.this) {
						listeners.remove(listening);
						listening = listener;
						listeners.add(listener);
						undecided = waiting;
					}
					if (undecided != null) {
						listener.changed(undecided.change(), undecided.detail());
					}
				}

				@Override
				public void reload() throws IOException {
					List<DiskListener> told;
					synchronized (Shared.this) {
						read();
						told = new ArrayList<>(listeners);
					}
					LOG.info("read " + file.getFileName() + " again: a page chose its version on disk");
					tell(told, DiskChange.RELOADED, null);
				}

				@Override
				public void keepEdits() {
					List<DiskListener> told;
					synchronized (Shared.this) {
						loaded = stamp(file);
						waiting = null;
						told = new ArrayList<>(listeners);
					}
					tell(told, DiskChange.KEPT, null);
				}

				@Override
				public void close() {
					synchronized (Shared.this) {
						afterSave.remove(registered);
						listeners.remove(listening);
					}
					closed(Shared.this);
				}
			};
		}
	}
}
