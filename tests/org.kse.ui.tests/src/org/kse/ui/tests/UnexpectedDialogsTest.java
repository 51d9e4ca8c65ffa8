package org.kse.ui.tests;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.testing.ui.Ui;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * The UI tests' guard against dialogs nobody expected ({@link UnexpectedDialogs}): an error
 * dialog fails the test that waits, a dialog that blocks the test is closed in bounded time,
 * each with its text and a screenshot, and a dialog the test expects is left to it.
 */
@ExtendWith(UnexpectedDialogs.class)
class UnexpectedDialogsTest {

	private static Shell workbench() {
		return PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell();
	}

	private static boolean open(String title) {
		return Arrays.stream(Ui.display().getShells()).anyMatch(shell -> !shell.isDisposed() && title.equals(shell.getText()));
	}

	@AfterEach
	void closeWhatIsLeft() {
		Arrays.stream(Ui.display().getShells()).filter(shell -> shell != workbench() && shell.getParent() != null && !shell.isDisposed())
				.forEach(Shell::close);
	}

	@Test
	void anErrorDialogFailsTheWaitingTestWithItsTextAndAScreenshot() {
		Ui.display().asyncExec(() -> MessageDialog.openError(workbench(), "Problem Occurred", "Cannot invoke dispose() because table is null"));
		long start = System.currentTimeMillis();
		AssertionError failure = assertThrows(AssertionError.class, () -> Ui.waitUntil(() -> false, 30_000));
		long took = System.currentTimeMillis() - start;
		assertTrue(failure.getMessage().contains("an error dialog") && failure.getMessage().contains("Problem Occurred")
				&& failure.getMessage().contains("because table is null"), failure.getMessage());
		assertTrue(took < 10_000, "the test fails at once, not at the end of its wait: " + took + " ms");
		assertFalse(open("Problem Occurred"), "the dialog is closed");
		Path shot = Path.of(failure.getMessage().replaceFirst("(?s).*closed; ([^)]*\\.png)\\).*", "$1"));
		assertTrue(Files.isRegularFile(shot), () -> "a screenshot of it: " + failure.getMessage());
	}

	@Test
	void aDialogThatBlocksTheTestIsClosedAndReported() {
		long start = System.currentTimeMillis();
		// the test's thread stops here as in a command that asks a question nobody answers
		boolean answer = MessageDialog.openQuestion(workbench(), "Replace Goalie.stct?", "Goalie.stct exists. Replace it?");
		long took = System.currentTimeMillis() - start;
		assertFalse(answer, "closed, not answered");
		assertTrue(took >= UnexpectedDialogs.BLOCKED_LIMIT && took < UnexpectedDialogs.BLOCKED_LIMIT + 10_000, "closed after " + took + " ms");
		AssertionError failure = assertThrows(AssertionError.class, () -> Ui.settle(100));
		assertTrue(failure.getMessage().contains("blocked the test") && failure.getMessage().contains("Replace Goalie.stct?")
				&& failure.getMessage().contains("Goalie.stct exists. Replace it?"), failure.getMessage());
	}

	@Test
	void aDialogTheTestExpectsIsLeftToIt() {
		Ui.expectDialog("Expected");
		MessageDialog dialog = new MessageDialog(workbench(), "Expected", null, "an error the test looks for", MessageDialog.ERROR, 0, "OK");
		dialog.setBlockOnOpen(false);
		dialog.open();
		assertTrue(Ui.waitUntil(() -> open("Expected"), 5_000), "the dialog opens");
		Ui.settle(1_000);
		assertTrue(open("Expected"), "the dialog the test expects stays open for it");
		Arrays.stream(Ui.display().getShells()).filter(shell -> "Expected".equals(shell.getText())).forEach(Shell::close);
		Ui.settle(200);
	}
}
