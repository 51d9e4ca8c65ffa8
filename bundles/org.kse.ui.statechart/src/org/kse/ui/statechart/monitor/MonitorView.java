package org.kse.ui.statechart.monitor;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import org.eclipse.core.resources.IFile;
import org.eclipse.swt.SWT;
import org.eclipse.swt.SWTError;
import org.eclipse.swt.browser.Browser;
import org.eclipse.swt.layout.FillLayout;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.ide.IDE;
import org.eclipse.ui.part.ViewPart;
import org.kse.diagram.server.websocket.RunningMatches;
import org.kse.ui.statechart.BehaviourModels;
import org.kse.ui.statechart.diagram.WorkspaceDiagramServer;
import org.kse.ui.statechart.editor.StatechartEditor;

/**
 * The Monitor view: robots of a running match side by side, each the live monitor page of the
 * diagram client (its statechart with the active states outlined, transitions flashing, its last
 * transitions listed, Pause) in an SWT Browser, served by the {@link WorkspaceDiagramServer} as the
 * statechart editor's Diagram tab is. A robot is drawn from its behaviour's model,
 * {@code <behaviour>.stct} found in the workspace's open projects, which is opened in a statechart
 * editor (not brought to the front): the workbench's diagram server serves only models open in
 * editors. A robot whose model is not in the workspace gets a message instead.
 * <p>
 * The page names the match by its process id; the server's relay looks its port and key up in
 * the discovery folder, so no key reaches the page.
 */
public final class MonitorView extends ViewPart {

	public static final String ID = "org.kse.ui.statechart.monitorView";

	private static final AtomicLong SECONDARY = new AtomicLong();

	/** A robot shown: its browser, or why it is not shown. */
	public record Tile(String robot, Browser browser, String problem) {
	}

	private Composite grid;
	private final List<Tile> tiles = new ArrayList<>();

	/** Opens a view of its own for {@code choice} (several matches may be watched at once). */
	public static MonitorView open(IWorkbenchPage page, MonitorDialog.Choice choice) throws PartInitException {
		MonitorView view = (MonitorView) page.showView(ID, Long.toString(SECONDARY.incrementAndGet()), IWorkbenchPage.VIEW_ACTIVATE);
		view.show(page, choice);
		// the diagrams need room (a diagram drawn in a sliver shows nothing): the view takes the window,
		// as a double click on its tab would; another double click gives the editors back
		page.setPartState(page.getReference(view), IWorkbenchPage.STATE_MAXIMIZED);
		return view;
	}

	@Override
	public void createPartControl(Composite parent) {
		grid = new Composite(parent, SWT.NONE);
		grid.setLayout(new GridLayout(1, true));
		Label hint = new Label(grid, SWT.WRAP);
		hint.setText("Choose robots of a running match with KSE > Monitor…");
	}

	/** Shows the chosen robots of the match, replacing what the view showed. */
	public void show(IWorkbenchPage page, MonitorDialog.Choice choice) {
		for (Control child : grid.getChildren()) {
			child.dispose();
		}
		tiles.clear();
		RunningMatches.Match match = choice.match();
		setPartName("Monitor: match " + match.pid());
		setContentDescription(choice.robots().size() + " robot" + (choice.robots().size() == 1 ? "" : "s") + " of match " + match.pid() + " (seed "
				+ match.seed() + ")");
		((GridLayout) grid.getLayout()).numColumns = (int) Math.ceil(Math.sqrt(choice.robots().size()));
		for (RunningMatches.Robot robot : choice.robots()) {
			Composite cell = new Composite(grid, SWT.BORDER);
			cell.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
			cell.setLayout(new FillLayout());
			tiles.add(tile(page, cell, match, robot));
		}
		grid.layout(true, true);
	}

	private static Tile tile(IWorkbenchPage page, Composite cell, RunningMatches.Match match, RunningMatches.Robot robot) {
		IFile model = BehaviourModels.find(robot.behaviour());
		if (model == null) {
			return message(cell, robot, robot.id() + " runs " + robot.behaviour() + ", and no open project of the workspace has a " + robot.behaviour()
					+ ".stct to draw it with: import the project whose statecharts built this kse-match.");
		}
		Browser browser = null;
		try {
			// the workbench's diagram server serves the models of open editors only
			IDE.openEditor(page, model, StatechartEditor.ID, false);
			String url = WorkspaceDiagramServer.page(Path.of(model.getLocationURI())) + "&match=" + match.pid() + "&robot=" + robot.id() + "&tile=1";
			browser = new Browser(cell, SWT.NONE);
			browser.setUrl(url);
			return new Tile(robot.id(), browser, null);
		} catch (SWTError | Exception e) {
			if (browser != null) {
				browser.dispose();
			}
			return message(cell, robot, robot.id() + " cannot be shown here: " + e.getMessage());
		}
	}

	private static Tile message(Composite cell, RunningMatches.Robot robot, String text) {
		Label label = new Label(cell, SWT.WRAP);
		label.setText(text);
		return new Tile(robot.id(), null, text);
	}

	/** The robots shown, in order. */
	public List<Tile> tiles() {
		return List.copyOf(tiles);
	}

	@Override
	public void dispose() {
		// closed while maximized: the rest of its stack (the Outline) would stay maximized, the
		// editors and the other views minimized
		IWorkbenchPage page = getSite().getPage();
		org.eclipse.ui.IWorkbenchPartReference reference = page.getReference(this);
		if (reference != null && page.getPartState(reference) == IWorkbenchPage.STATE_MAXIMIZED) {
			page.setPartState(reference, IWorkbenchPage.STATE_RESTORED);
		}
		super.dispose();
	}

	@Override
	public void setFocus() {
		grid.setFocus();
	}
}
