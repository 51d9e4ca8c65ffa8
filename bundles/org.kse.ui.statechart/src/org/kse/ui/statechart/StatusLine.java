package org.kse.ui.statechart;

import org.eclipse.jface.action.IStatusLineManager;
import org.eclipse.ui.IEditorSite;
import org.eclipse.ui.IViewSite;
import org.eclipse.ui.IWorkbenchPart;

/** A command's result in the status line of the part it was run from, where the user is looking. */
public final class StatusLine {

	private StatusLine() {
	}

	/** Shows {@code message} (as an error when {@code error}); a part already closed shows nothing. */
	public static void show(IWorkbenchPart part, String message, boolean error) {
		IStatusLineManager statusLine = manager(part);
		if (statusLine == null) {
			return;
		}
		if (error) {
			statusLine.setErrorMessage(message);
		} else {
			// an earlier error would hide the message
			statusLine.setErrorMessage(null);
			statusLine.setMessage(message);
		}
	}

	private static IStatusLineManager manager(IWorkbenchPart part) {
		if (part == null || part.getSite() == null || part.getSite().getPage() == null) {
			return null;
		}
		if (part.getSite() instanceof IViewSite view) {
			return view.getActionBars().getStatusLineManager();
		}
		if (part.getSite() instanceof IEditorSite editor) {
			return editor.getActionBars().getStatusLineManager();
		}
		return null;
	}
}
