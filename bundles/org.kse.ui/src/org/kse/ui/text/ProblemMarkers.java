package org.kse.ui.text;

import java.util.List;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IWorkspace;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.ILog;

/** The problems a text editor's check found, as markers on its file (Problems view, ruler, squiggles). */
public final class ProblemMarkers {

	/**
	 * One problem: {@code start} and {@code end} are character offsets in the text, {@code line} and
	 * {@code column} count from 1; {@code severity} is an {@link IMarker} severity.
	 */
	public record Problem(String message, int severity, int line, int column, int start, int end) {
	}

	private ProblemMarkers() {
	}

	/** Replaces the markers of this type on the file by these problems, in one workspace operation. */
	public static void replace(IFile file, String type, List<Problem> problems) {
		try {
			file.getWorkspace().run(monitor -> {
				if (!file.exists()) {
					return;
				}
				file.deleteMarkers(type, false, 0);
				for (Problem problem : problems) {
					// all attributes at once: a reader never sees a marker half made
					file.createMarker(type, Map.of(IMarker.MESSAGE, problem.message(), IMarker.SEVERITY, problem.severity(), IMarker.LINE_NUMBER,
							problem.line(), IMarker.CHAR_START, problem.start(), IMarker.CHAR_END, problem.end(), IMarker.LOCATION,
							"line " + problem.line() + ", column " + problem.column()));
				}
			}, file, IWorkspace.AVOID_UPDATE, null);
		} catch (CoreException e) {
			ILog.of(ProblemMarkers.class).error("cannot show the problems of " + file.getFullPath(), e);
		}
	}
}
