package org.kse.ui.statechart.monitor;

import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.jface.dialogs.TitleAreaDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.layout.GridLayout;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Tree;
import org.eclipse.swt.widgets.TreeItem;
import org.kse.diagram.server.websocket.RunningMatches;

/**
 * KSE > Monitor…: the matches running with {@code kse-match --monitor} on this machine (from the
 * discovery folder, as {@code kse serve}'s picker lists them), each with its robots and their
 * behaviours. The robots ticked, of one match, are what {@link #chosen()} returns.
 */
public final class MonitorDialog extends TitleAreaDialog {

	public static final String TITLE = "Monitor a Running Match";

	/** What was chosen: a match and some of its robots. */
	public record Choice(RunningMatches.Match match, List<RunningMatches.Robot> robots) {
	}

	private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss").withZone(ZoneId.systemDefault());

	private Tree tree;
	private Choice chosen;

	public MonitorDialog(Shell parent) {
		super(parent);
		setShellStyle(getShellStyle() | SWT.RESIZE);
	}

	@Override
	protected void configureShell(Shell shell) {
		super.configureShell(shell);
		shell.setText(TITLE);
	}

	@Override
	protected Control createDialogArea(Composite parent) {
		Composite area = (Composite) super.createDialogArea(parent);
		setTitle("Watch robots of a running match");
		Composite body = new Composite(area, SWT.NONE);
		body.setLayoutData(new GridData(SWT.FILL, SWT.FILL, true, true));
		body.setLayout(new GridLayout(1, false));
		tree = new Tree(body, SWT.CHECK | SWT.BORDER | SWT.V_SCROLL);
		GridData size = new GridData(SWT.FILL, SWT.FILL, true, true);
		size.heightHint = 260;
		size.widthHint = 460;
		tree.setLayoutData(size);
		tree.addListener(SWT.Selection, event -> {
			if (event.detail == SWT.CHECK && event.item instanceof TreeItem item) {
				// a match's box ticks its robots; robots of two matches cannot be watched together
				if (item.getParentItem() == null) {
					for (TreeItem robot : item.getItems()) {
						robot.setChecked(item.getChecked());
					}
				}
				TreeItem match = item.getParentItem() == null ? item : item.getParentItem();
				if (item.getChecked()) {
					for (TreeItem other : tree.getItems()) {
						if (other != match) {
							other.setChecked(false);
							for (TreeItem robot : other.getItems()) {
								robot.setChecked(false);
							}
						}
					}
				}
				update();
			}
		});
		Button refresh = new Button(body, SWT.PUSH);
		refresh.setText("&Refresh");
		refresh.addListener(SWT.Selection, event -> fill());
		fill();
		return area;
	}

	@Override
	protected void createButtonsForButtonBar(Composite parent) {
		createButton(parent, IDialogConstants.OK_ID, "&Watch", true);
		createButton(parent, IDialogConstants.CANCEL_ID, IDialogConstants.CANCEL_LABEL, false);
		update();
	}

	/** Lists the running matches anew. */
	public void fill() {
		tree.removeAll();
		List<RunningMatches.Match> matches = RunningMatches.list();
		for (RunningMatches.Match match : matches) {
			TreeItem item = new TreeItem(tree, SWT.NONE);
			item.setText("Match " + match.pid() + " · seed " + match.seed() + " · started " + TIME.format(match.started()));
			item.setData(match);
			for (RunningMatches.Robot robot : match.robots()) {
				TreeItem child = new TreeItem(item, SWT.NONE);
				child.setText(robot.id() + "   " + robot.behaviour());
				child.setData(robot);
			}
			item.setExpanded(true);
		}
		if (matches.isEmpty()) {
			setMessage("No match is running with a monitor on this machine. Start one with kse-match --monitor, then Refresh.");
		} else {
			setMessage("Tick the robots to watch (of one match); each is shown with its behaviour's statechart from the workspace.");
		}
		update();
	}

	/** The tree (for tests). */
	public Tree tree() {
		return tree;
	}

	private void update() {
		chosen = null;
		if (tree != null) {
			for (TreeItem match : tree.getItems()) {
				List<RunningMatches.Robot> robots = new ArrayList<>();
				for (TreeItem robot : match.getItems()) {
					if (robot.getChecked()) {
						robots.add((RunningMatches.Robot) robot.getData());
					}
				}
				if (!robots.isEmpty()) {
					chosen = new Choice((RunningMatches.Match) match.getData(), List.copyOf(robots));
				}
			}
		}
		Button ok = getButton(IDialogConstants.OK_ID);
		if (ok != null) {
			ok.setEnabled(chosen != null);
		}
	}

	/** The match and robots ticked when Watch was pressed; null when none. */
	public Choice chosen() {
		return chosen;
	}
}
