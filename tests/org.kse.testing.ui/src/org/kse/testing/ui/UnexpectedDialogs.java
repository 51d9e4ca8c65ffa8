package org.kse.testing.ui;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.WeakHashMap;

import org.eclipse.jface.dialogs.ErrorDialog;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Link;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Text;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * A modal window that no test asked for would hold the UI thread until surefire kills the run, and
 * an error dialog would go unseen. While the event loop runs, this looks at the open windows: an
 * error dialog (the system's error icon) that the test did not name with {@link #expect(String)},
 * or any modal window open while the test has not come back to its wait ({@link Ui#waitUntil}) for
 * {@link #BLOCKED_LIMIT} ms (nobody answers it), is screenshot, closed and reported; the test fails
 * with its text at its next wait or when it ends (this extension).
 */
public final class UnexpectedDialogs implements BeforeEachCallback, AfterEachCallback {

	/** Tests answer their dialogs from a timer within a second or two; a dialog waiting this long is nobody's. */
	public static final long BLOCKED_LIMIT = 15_000;
	private static final int INTERVAL = 250;

	private static final Set<String> expected = new HashSet<>();
	/** When each modal window was first seen. */
	private static final Map<Shell, Long> seen = new WeakHashMap<>();
	private static final List<String> found = new ArrayList<>();
	private static boolean installed;
	private static boolean reporting;
	private static int shots;
	/**
	 * When the test last went round its wait ({@link Ui#waitUntil}): a dialog whose own event loop
	 * holds the test (opened by the test's code or by an event dispatched in its wait) stops it.
	 */
	static long lastWaitTurn = System.currentTimeMillis();

	/** Watches the display's windows from now on (once). */
	public static void install(Display display) {
		if (installed) {
			return;
		}
		installed = true;
		display.timerExec(INTERVAL, new Runnable() {
			@Override
			public void run() {
				try {
					look(display);
				} finally {
					if (!display.isDisposed()) {
						display.timerExec(INTERVAL, this);
					}
				}
			}
		});
	}

	/** A window with this title is the test's own until the test ends. */
	public static void expect(String title) {
		expected.add(title);
	}

	/** Fails the test with the windows found since the last call. */
	public static void failIfAny() {
		if (!found.isEmpty() && !reporting) {
			String message = String.join("\n", found);
			found.clear();
			throw new AssertionError(message);
		}
	}

	@Override
	public void beforeEach(ExtensionContext context) {
		install(Ui.display());
		expected.clear();
		found.clear();
	}

	@Override
	public void afterEach(ExtensionContext context) {
		expected.clear();
		failIfAny();
	}

	private static void look(Display display) {
		if (reporting) {
			return;
		}
		long now = System.currentTimeMillis();
		for (Shell shell : display.getShells()) {
			if (shell.isDisposed() || !shell.isVisible() || (shell.getStyle() & (SWT.APPLICATION_MODAL | SWT.PRIMARY_MODAL | SWT.SYSTEM_MODAL)) == 0) {
				continue;
			}
			long blocked = now - Math.max(seen.computeIfAbsent(shell, opened -> now), lastWaitTurn);
			if (showsAnError(shell) && !expected.contains(shell.getText())) {
				report(shell, "an error dialog appeared");
			} else if (blocked >= BLOCKED_LIMIT) {
				report(shell, "a dialog blocked the test for " + blocked / 1000 + " s");
			}
		}
	}

	private static boolean showsAnError(Shell shell) {
		if (shell.getData() instanceof ErrorDialog) {
			return true;
		}
		Image error = shell.getDisplay().getSystemImage(SWT.ICON_ERROR);
		return Ui.find(shell, Label.class).stream().anyMatch(label -> label.getImage() != null && label.getImage() == error);
	}

	private static void report(Shell shell, String what) {
		reporting = true;
		try {
			String text = text(shell);
			String shot;
			try {
				shot = Ui.screenshotOf(shell, "unexpected-dialog-" + ++shots).toString();
			} catch (RuntimeException | AssertionError e) {
				shot = "no screenshot: " + e.getMessage();
			}
			if (!shell.isDisposed()) {
				shell.close();
			}
			seen.remove(shell);
			found.add(what + " (closed; " + shot + "): " + text);
		} finally {
			reporting = false;
		}
	}

	/** The window's title and what it says, as a person would read it. */
	private static String text(Shell shell) {
		List<String> parts = new ArrayList<>();
		parts.add("\"" + shell.getText() + "\"");
		Ui.find(shell, Label.class).stream().map(Label::getText).filter(text -> !text.isBlank()).forEach(parts::add);
		Ui.find(shell, Link.class).stream().map(Link::getText).filter(text -> !text.isBlank()).forEach(parts::add);
		Ui.find(shell, Text.class).stream().map(Text::getText).filter(text -> !text.isBlank()).forEach(parts::add);
		List<String> buttons = Ui.find(shell, Button.class).stream().map(Button::getText).filter(text -> !text.isBlank()).toList();
		if (!buttons.isEmpty()) {
			parts.add("buttons " + buttons);
		}
		String all = String.join(" | ", parts);
		return all.length() > 2000 ? all.substring(0, 2000) + "..." : all;
	}
}
