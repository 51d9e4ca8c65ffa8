package org.kse.ui.messages;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IWorkspace;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.ILog;
import org.eclipse.core.runtime.IPath;
import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IRegion;
import org.eclipse.jface.text.reconciler.DirtyRegion;
import org.eclipse.jface.text.reconciler.IReconcilingStrategy;
import org.eclipse.jface.text.reconciler.IReconcilingStrategyExtension;
import org.kse.messages.ProtoProblem;

/**
 * Checks the editor's text whenever typing pauses (and when another {@code .proto} file of its
 * folder changes on disk) and shows what is wrong as problem markers on the file: the file's own
 * problems and what linking it with its folder's files and the standard messages finds (unknown
 * types, imports not found, duplicate names). Another file's problems stay on that file.
 */
class ProtoChecker implements IReconcilingStrategy, IReconcilingStrategyExtension {

	static final String MARKER = "org.kse.ui.messages.messageProblem";

	private final ProtoEditor editor;
	private IDocument document;
	/** How long the last check took, read, linked and marked, in nanoseconds (the UI tests print it). */
	volatile long lastCheckNanos;

	ProtoChecker(ProtoEditor editor) {
		this.editor = editor;
	}

	@Override
	public void setDocument(IDocument document) {
		this.document = document;
	}

	@Override
	public void reconcile(DirtyRegion dirtyRegion, IRegion subRegion) {
		check();
	}

	@Override
	public void reconcile(IRegion partition) {
		check();
	}

	/** The reconciler's first run, once the editor has its text: a file opens with its problems shown. */
	@Override
	public void initialReconcile() {
		check();
	}

	@Override
	public void setProgressMonitor(IProgressMonitor monitor) {
		// a check takes milliseconds: nothing to cancel
	}

	/**
	 * One check at a time: the reconciler's thread and a change on disk may both ask, and the
	 * markers of the later check must win.
	 */
	synchronized void check() {
		IDocument current = document;
		IFile file = editor.getFile();
		if (current == null) {
			return;
		}
		long start = System.nanoTime();
		String text = current.get();
		Path location = locationOf(file);
		LinkedProto linked = location == null ? null : LinkedProto.of(location, text);
		if (linked != null) {
			show(file, linked, text.length());
		}
		lastCheckNanos = System.nanoTime() - start;
		editor.textChecked(linked == null ? null : linked.file());
	}

	/** Replaces the file's message markers by these problems. */
	private static void show(IFile file, LinkedProto linked, int textLength) {
		List<ProtoProblem> problems = linked.problems();
		List<ProtoProblem> notes = linked.replacements();
		try {
			file.getWorkspace().run(monitor -> {
				if (!file.exists()) {
					return;
				}
				file.deleteMarkers(MARKER, false, 0);
				for (ProtoProblem problem : problems) {
					file.createMarker(MARKER, attributes(problem, IMarker.SEVERITY_ERROR, linked.positions(), textLength));
				}
				for (ProtoProblem note : notes) {
					file.createMarker(MARKER, attributes(note, IMarker.SEVERITY_INFO, linked.positions(), textLength));
				}
			}, file, IWorkspace.AVOID_UPDATE, null);
		} catch (CoreException e) {
			ILog.of(ProtoChecker.class).error("cannot show the problems of " + file.getFullPath(), e);
		}
	}

	/** All attributes at once: a reader never sees a marker half made. */
	private static Map<String, Object> attributes(ProtoProblem problem, int severity, LinkedProto.Positions positions, int textLength) {
		int[] range = positions.problemRange(positions.offset(problem.line(), problem.column()));
		int start = Math.min(range[0], textLength);
		int end = Math.min(textLength, range[1]);
		Map<String, Object> attributes = new HashMap<>();
		attributes.put(IMarker.MESSAGE, problem.message());
		attributes.put(IMarker.SEVERITY, severity);
		attributes.put(IMarker.LINE_NUMBER, problem.line());
		attributes.put(IMarker.CHAR_START, start);
		attributes.put(IMarker.CHAR_END, end);
		attributes.put(IMarker.LOCATION, "line " + problem.line() + ", column " + problem.column());
		return attributes;
	}

	/** Where a workspace file is on disk; null for a file outside the file system (a virtual one). */
	static Path locationOf(IFile file) {
		IPath location = file == null ? null : file.getLocation();
		return location == null ? null : location.toPath();
	}
}
