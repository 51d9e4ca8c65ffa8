package org.kse.ui.statechart;

import java.nio.file.Path;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.IPath;
import org.eclipse.jface.dialogs.Dialog;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.layout.GridLayoutFactory;
import org.eclipse.swt.SWT;
import org.eclipse.swt.custom.ScrolledComposite;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Link;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.IWorkbenchWindow;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;

/**
 * What a generation did, shown when it ends: the headline (written, unchanged, activities kept),
 * warnings, and a link for each file written that opens it in an editor. The window does not block
 * the workbench, so the user can open files and keep working; a new generation's summary replaces it.
 */
final class GenerationSummary extends Dialog {

	static final String TITLE = "Generated Code";
	private static final int SHOWN_LINKS = 200;

	private static GenerationSummary shown;

	private final String headline;
	private final List<String> details;
	private final List<Path> written;
	private final IWorkbenchWindow window;

	private GenerationSummary(IWorkbenchWindow window, String headline, List<String> details, List<Path> written) {
		super(window.getShell());
		this.window = window;
		this.headline = headline;
		this.details = details;
		this.written = written;
		setShellStyle((getShellStyle() & ~SWT.APPLICATION_MODAL) | SWT.MODELESS | SWT.RESIZE);
		setBlockOnOpen(false);
	}

	/** Opens the summary in the workbench window, closing an earlier one. */
	static void open(String headline, List<String> details, List<Path> written) {
		var window = PlatformUI.getWorkbench().getActiveWorkbenchWindow();
		if (window == null && PlatformUI.getWorkbench().getWorkbenchWindowCount() > 0) {
			window = PlatformUI.getWorkbench().getWorkbenchWindows()[0];
		}
		if (window == null) {
			return;
		}
		if (shown != null) {
			shown.close();
		}
		shown = new GenerationSummary(window, headline, details, written);
		shown.open();
	}

	@Override
	protected void configureShell(Shell shell) {
		super.configureShell(shell);
		shell.setText(TITLE);
	}

	@Override
	protected Control createDialogArea(Composite parent) {
		Composite area = (Composite) super.createDialogArea(parent);
		Label summary = new Label(area, SWT.WRAP);
		summary.setText(headline.replace("&", "&&"));
		GridDataFactory.fillDefaults().grab(true, false).hint(520, SWT.DEFAULT).applyTo(summary);
		for (String detail : details) {
			Label line = new Label(area, SWT.WRAP);
			line.setText(detail.replace("&", "&&"));
			GridDataFactory.fillDefaults().grab(true, false).hint(520, SWT.DEFAULT).applyTo(line);
		}
		if (!written.isEmpty()) {
			new Label(area, SWT.NONE).setText("Files written (click to open):");
			ScrolledComposite scroller = new ScrolledComposite(area, SWT.V_SCROLL | SWT.BORDER);
			GridDataFactory.fillDefaults().grab(true, true).hint(520, Math.min(240, 22 * written.size() + 8)).applyTo(scroller);
			Composite links = new Composite(scroller, SWT.NONE);
			GridLayoutFactory.swtDefaults().applyTo(links);
			for (Path file : written.stream().limit(SHOWN_LINKS).toList()) {
				IFile workspaceFile = workspaceFile(file);
				Link link = new Link(links, SWT.NONE);
				String shownName = workspaceFile != null ? workspaceFile.getFullPath().toString() : file.toString();
				link.setText(workspaceFile != null ? "<a href=\"" + shownName + "\">" + shownName + "</a>" : shownName);
				link.addListener(SWT.Selection, event -> openInEditor(event.text));
			}
			if (written.size() > SHOWN_LINKS) {
				new Label(links, SWT.NONE).setText("\u2026 and " + (written.size() - SHOWN_LINKS) + " more");
			}
			scroller.setContent(links);
			scroller.setExpandHorizontal(true);
			scroller.setExpandVertical(true);
			scroller.setMinSize(links.computeSize(SWT.DEFAULT, SWT.DEFAULT));
		}
		return area;
	}

	@Override
	protected void createButtonsForButtonBar(Composite parent) {
		createButton(parent, IDialogConstants.CLOSE_ID, IDialogConstants.CLOSE_LABEL, true);
	}

	@Override
	protected void buttonPressed(int buttonId) {
		close();
	}

	@Override
	public boolean close() {
		if (shown == this) {
			shown = null;
		}
		return super.close();
	}

	private static IFile workspaceFile(Path file) {
		IFile[] files = ResourcesPlugin.getWorkspace().getRoot().findFilesForLocationURI(file.toUri());
		return files.length == 0 ? null : files[0];
	}

	private void openInEditor(String workspacePath) {
		IFile file = ResourcesPlugin.getWorkspace().getRoot().getFile(IPath.fromPortableString(workspacePath));
		IWorkbenchPage page = window.getActivePage();
		if (page == null) {
			return;
		}
		try {
			IDE.openEditor(page, file, true);
		} catch (PartInitException e) {
			org.eclipse.jface.dialogs.MessageDialog.openError(getShell(), TITLE, "Cannot open " + workspacePath + ": " + e.getMessage());
		}
	}
}
