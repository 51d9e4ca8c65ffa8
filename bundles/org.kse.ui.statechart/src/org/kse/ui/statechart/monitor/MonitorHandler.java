package org.kse.ui.statechart.monitor;

import org.eclipse.core.commands.AbstractHandler;
import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.core.commands.ExecutionException;
import org.eclipse.jface.window.Window;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.handlers.HandlerUtil;

/** KSE > Monitor…: picks robots of a running match and shows them in a Monitor view. */
public final class MonitorHandler extends AbstractHandler {

	@Override
	public Object execute(ExecutionEvent event) throws ExecutionException {
		IWorkbenchWindow window = HandlerUtil.getActiveWorkbenchWindowChecked(event);
		MonitorDialog dialog = new MonitorDialog(window.getShell());
		if (dialog.open() != Window.OK || dialog.chosen() == null) {
			return null;
		}
		try {
			MonitorView.open(window.getActivePage(), dialog.chosen());
		} catch (PartInitException e) {
			throw new ExecutionException("cannot open the Monitor view: " + e.getMessage(), e);
		}
		return null;
	}
}
