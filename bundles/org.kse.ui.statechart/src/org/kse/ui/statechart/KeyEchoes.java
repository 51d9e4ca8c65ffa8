package org.kse.ui.statechart;

import org.eclipse.core.commands.ExecutionEvent;
import org.eclipse.swt.widgets.Event;

/**
 * One key press on the diagram reaches the workbench's key bindings up to three times: the
 * diagram is an SWT Browser, and WebKitGTK hands a key the page did not use back to GTK, where
 * SWT takes it for a new press. The copies keep the press's
 * time stamp, so a handler that asks here first runs once per press, as the user meant.
 */
public final class KeyEchoes {

	private static String lastCommand;
	private static int lastTime;
	private static int lastKey;
	private static int lastModifiers;

	private KeyEchoes() {
	}

	/** Whether the command was triggered by a key press that has already triggered it. */
	public static boolean isEcho(ExecutionEvent event) {
		return isEcho(event.getCommand() == null ? "" : event.getCommand().getId(), event.getTrigger() instanceof Event key ? key : null);
	}

	/** Whether this event, which asks for the command (an action's id), is a key press that has already asked for it. */
	public static synchronized boolean isEcho(String command, Event key) {
		if (key == null || key.keyCode == 0 || key.time == 0) {
			return false; // a menu, a toolbar or a program: every call is meant
		}
		boolean echo = command.equals(lastCommand) && key.time == lastTime && key.keyCode == lastKey && key.stateMask == lastModifiers;
		lastCommand = command;
		lastTime = key.time;
		lastKey = key.keyCode;
		lastModifiers = key.stateMask;
		return echo;
	}
}
