package org.kse.diagram.server;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.eclipse.glsp.server.actions.AbstractActionHandler;
import org.eclipse.glsp.server.actions.Action;
import org.eclipse.glsp.server.features.core.model.ModelSubmissionHandler;
import org.eclipse.glsp.server.types.GLSPServerException;
import org.kse.diagram.server.StatechartSources.DiskChange;

import com.google.inject.Inject;

/**
 * A file changed on disk by another program, as a page sees it: the source tells the session
 * ({@link FileChangedAction}); the session shows a model read again and tells its page
 * ({@link DiskChangeAction}), whose bar asks the user when there are unsaved edits; the user's
 * choice comes back as a {@link ResolveAction}.
 */
public final class DiskChanges {

	private DiskChanges() {
	}

	/** From the source to its session (never sent to the client): what happened to the file. */
	public static class FileChangedAction extends Action {
		public static final String KIND = "kseFileChanged";

		private DiskChange change;
		private String detail;

		public FileChangedAction() {
			super(KIND);
		}

		public FileChangedAction(DiskChange change, String detail) {
			this();
			this.change = change;
			this.detail = detail;
		}

		public DiskChange getChange() {
			return change;
		}

		public String getDetail() {
			return detail;
		}
	}

	/**
	 * To the page: {@code change} is {@code reloaded}, {@code conflict} (unsaved edits: ask),
	 * {@code unreadable} (ask; {@code detail} says why) or {@code kept}; {@code file} names it.
	 */
	public static class DiskChangeAction extends Action {
		public static final String KIND = "kseDiskChange";

		private String change;
		private String file;
		private String detail;

		public DiskChangeAction() {
			super(KIND);
		}

		public DiskChangeAction(DiskChange change, String file, String detail) {
			this();
			this.change = change.name().toLowerCase(Locale.ROOT);
			this.file = file;
			this.detail = detail;
		}

		public String getChange() {
			return change;
		}

		public String getFile() {
			return file;
		}

		public String getDetail() {
			return detail;
		}
	}

	/** From the page: the user's choice after a change on disk, to read the file again ({@code reload}) or to keep the edits. */
	public static class ResolveAction extends Action {
		public static final String KIND = "kseResolveDiskChange";

		private boolean reload;

		public ResolveAction() {
			super(KIND);
		}

		public boolean isReload() {
			return reload;
		}
	}

	/** Shows a model read again (with its layout, dirty state and markers) and tells the page. */
	public static class FileChangedHandler extends AbstractActionHandler<FileChangedAction> {

		@Inject
		private StatechartModelState state;

		@Inject
		private StatechartStorage storage;

		@Inject
		private ModelSubmissionHandler submissions;

		@Override
		protected List<Action> executeAction(FileChangedAction action) {
			if (state.getSource() == null || action.getChange() == null) {
				return none();
			}
			List<Action> answer = new ArrayList<>();
			if (action.getChange() == DiskChange.RELOADED) {
				storage.reopen();
				answer.addAll(submissions.submitModel());
			}
			answer.add(new DiskChangeAction(action.getChange(), state.getFile().getFileName().toString(), action.getDetail()));
			return answer;
		}
	}

	/** Carries out the user's choice; every page of the file learns it. */
	public static class ResolveHandler extends AbstractActionHandler<ResolveAction> {

		@Inject
		private StatechartModelState state;

		@Override
		protected List<Action> executeAction(ResolveAction action) {
			if (state.getSource() == null) {
				throw new GLSPServerException("no model is open");
			}
			if (!action.isReload()) {
				state.getSource().keepEdits();
				return none();
			}
			try {
				state.getSource().reload();
			} catch (IOException | RuntimeException e) {
				throw new GLSPServerException("cannot read " + state.getFile().getFileName() + " again: " + Reasons.of(e), e);
			}
			return none();
		}
	}
}
