package org.kse.ui.statechart;

import java.util.List;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.jobs.IJobChangeEvent;
import org.eclipse.core.runtime.jobs.JobChangeAdapter;
import org.eclipse.swt.widgets.Display;
import org.eclipse.ui.IWorkbenchPart;
import org.eclipse.ui.handlers.HandlerUtil;
import org.kse.ui.ModelFiles;

/**
 * "Validate": the rules of the original tool and the message catalog; the problems in the Problems
 * view, and how many there are (or that there are none) in the status line.
 */
public class ValidateHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) {
		List<IFile> files = ModelFiles.of(event);
		if (files.isEmpty() || org.kse.ui.statechart.KeyEchoes.isEcho(event)) {
			return null;
		}
		IWorkbenchPart part = HandlerUtil.getActivePart(event);
		Display display = Display.getCurrent();
		ModelJob.schedule("Validating", files, false, (file, model, progress) -> ModelMarkers.validate(file, model), new JobChangeAdapter() {
			@Override
			public void done(IJobChangeEvent done) {
				if (done.getResult().isOK()) {
					display.asyncExec(() -> {
						int[] counts = problems(files);
						StatusLine.show(part, summary(files, counts), counts[0] > 0);
					});
				}
			}
		});
		return null;
	}

	/** {errors, warnings} the files are marked with now, unreadable files included. */
	static int[] problems(List<IFile> files) {
		int[] counts = new int[2];
		for (IFile file : files) {
			try {
				for (IMarker marker : file.findMarkers(ModelMarkers.MARKER, false, IResource.DEPTH_ZERO)) {
					int severity = marker.getAttribute(IMarker.SEVERITY, -1);
					if (severity == IMarker.SEVERITY_ERROR) {
						counts[0]++;
					} else if (severity == IMarker.SEVERITY_WARNING) {
						counts[1]++;
					}
				}
			} catch (CoreException e) {
				// a file deleted meanwhile has no problems to count
			}
		}
		return counts;
	}

	static String summary(List<IFile> files, int[] counts) {
		String what = files.size() == 1 ? files.get(0).getName() : files.size() + " statecharts";
		if (counts[0] == 0 && counts[1] == 0) {
			return "Validated " + what + ": no problems.";
		}
		return "Validated " + what + ": " + count(counts[0], "error") + ", " + count(counts[1], "warning") + " (see the Problems view).";
	}

	private static String count(int count, String noun) {
		return count + " " + noun + (count == 1 ? "" : "s");
	}
}
