package org.kse.ui.messages;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.runtime.IPath;
import org.eclipse.jface.text.IDocument;
import org.kse.messages.ProtoProblem;
import org.kse.ui.text.ProblemMarkers;
import org.kse.ui.text.TextChecker;

/**
 * Checks the editor's text when it opens and whenever typing pauses (and when another {@code .proto} file of its
 * folder changes on disk) and shows what is wrong as problem markers on the file: the file's own
 * problems and what linking it with its folder's files and the standard messages finds (unknown
 * types, imports not found, duplicate names). Another file's problems stay on that file.
 */
class ProtoChecker extends TextChecker {

	static final String MARKER = "org.kse.ui.messages.messageProblem";

	private final ProtoEditor editor;
	/** How long the last check took, read, linked and marked, in nanoseconds (the UI tests print it). */
	volatile long lastCheckNanos;

	ProtoChecker(ProtoEditor editor) {
		this.editor = editor;
	}

	/**
	 * One check at a time: the reconciler's thread and a change on disk may both ask, and the
	 * markers of the later check must win.
	 */
	@Override
	protected synchronized void check(IDocument document) {
		IFile file = editor.getFile();
		long start = System.nanoTime();
		String text = document.get();
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
		List<ProblemMarkers.Problem> problems = new ArrayList<>();
		linked.problems().forEach(problem -> problems.add(problem(problem, IMarker.SEVERITY_ERROR, linked.positions(), textLength)));
		linked.replacements().forEach(note -> problems.add(problem(note, IMarker.SEVERITY_INFO, linked.positions(), textLength)));
		ProblemMarkers.replace(file, MARKER, problems);
	}

	private static ProblemMarkers.Problem problem(ProtoProblem problem, int severity, LinkedProto.Positions positions, int textLength) {
		int[] range = positions.problemRange(positions.offset(problem.line(), problem.column()));
		return new ProblemMarkers.Problem(problem.message(), severity, problem.line(), problem.column(), Math.min(range[0], textLength),
				Math.min(textLength, range[1]));
	}

	/** Where a workspace file is on disk; null for a file outside the file system (a virtual one). */
	static Path locationOf(IFile file) {
		IPath location = file == null ? null : file.getLocation();
		return location == null ? null : location.toPath();
	}
}
