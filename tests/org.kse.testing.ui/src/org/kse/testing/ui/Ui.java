package org.kse.testing.ui;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.BooleanSupplier;

import org.eclipse.core.resources.IResource;
import org.eclipse.jface.viewers.StructuredSelection;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Button;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IPageLayout;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.handlers.IHandlerService;
import org.eclipse.ui.navigator.CommonNavigator;

/** What the UI tests share: finding and pressing controls, selecting and running commands, waiting while the workbench runs, and screenshots a person can look at. */
public final class Ui {

	private Ui() {
	}

	public static IWorkbenchPage page() {
		return PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
	}

	/** The controls of a type in a window or composite, the root included, depth first. */
	public static <T extends Control> List<T> find(Control root, Class<T> type) {
		List<T> found = new ArrayList<>();
		if (type.isInstance(root)) {
			found.add(type.cast(root));
		}
		if (root instanceof Composite composite) {
			for (Control child : composite.getChildren()) {
				found.addAll(find(child, type));
			}
		}
		return found;
	}

	public static Button button(Shell shell, String label) {
		return find(shell, Button.class).stream().filter(button -> button.getText().replace("&", "").equals(label))
				.findFirst().orElseThrow(() -> new AssertionError("no button " + label + " in " + shell.getText()));
	}

	/** A click on a button. */
	public static void press(Button button) {
		button.notifyListeners(SWT.Selection, null);
	}

	public static void press(Shell shell, String label) {
		press(button(shell, label));
	}

	/** Selects a resource in the Project Explorer, so that commands work on it as a user's click would. */
	public static void select(IResource resource) throws Exception {
		var explorer = (CommonNavigator) page().showView(IPageLayout.ID_PROJECT_EXPLORER);
		explorer.selectReveal(new StructuredSelection(resource));
		page().activate(explorer);
		settle(300);
	}

	/**
	 * The example model {@code examples/<example>/<example>.stct}, fresh, as a file of the project
	 * {@code project} (created and opened when needed) at {@code folder}'s location (null: in the workspace).
	 */
	public static org.eclipse.core.resources.IFile exampleModel(String project, Path folder, String example) throws Exception {
		var workspace = org.eclipse.core.resources.ResourcesPlugin.getWorkspace();
		var holder = workspace.getRoot().getProject(project);
		if (!holder.exists()) {
			var description = workspace.newProjectDescription(project);
			if (folder != null) {
				description.setLocationURI(folder.toUri());
			}
			holder.create(description, null);
		}
		holder.open(null);
		var file = holder.getFile(example + ".stct");
		byte[] model = Files.readAllBytes(Path.of(System.getProperty("kse.examples"), example, example + ".stct"));
		if (file.exists()) {
			file.setContents(new java.io.ByteArrayInputStream(model), IResource.FORCE, null);
		} else {
			file.create(new java.io.ByteArrayInputStream(model), true, null);
		}
		return file;
	}

	public static void run(String command) throws Exception {
		PlatformUI.getWorkbench().getService(IHandlerService.class).executeCommand(command, null);
	}

	public static Display display() {
		return PlatformUI.getWorkbench().getDisplay();
	}

	/**
	 * Runs the event loop until the condition holds; false after {@code millis}. A dialog that no
	 * test expected, seen meanwhile, fails the test at once ({@link UnexpectedDialogs}).
	 */
	public static boolean waitUntil(BooleanSupplier condition, long millis) {
		long end = System.currentTimeMillis() + millis;
		Display display = display();
		UnexpectedDialogs.install(display);
		while (System.currentTimeMillis() < end) {
			UnexpectedDialogs.lastWaitTurn = System.currentTimeMillis();
			UnexpectedDialogs.failIfAny();
			if (condition.getAsBoolean()) {
				return true;
			}
			if (!display.readAndDispatch()) {
				try {
					Thread.sleep(5);
				} catch (InterruptedException e) {
					Thread.currentThread().interrupt();
					return false;
				}
			}
		}
		return condition.getAsBoolean();
	}

	/** The test is about to show a window with this title on purpose (until it ends): it is not an unexpected dialog. */
	public static void expectDialog(String title) {
		UnexpectedDialogs.expect(title);
	}

	/** What {@link #whenShown} did: whether it answered a dialog, and how that failed if it did. */
	public static final class Answered {
		public volatile boolean done;
		public volatile Throwable failure;

		/** Throws what went wrong while answering the dialog, or that none was shown. */
		public void check(String what) {
			if (failure != null) {
				throw new AssertionError("answering the " + what + " dialog failed", failure);
			}
			if (!done) {
				throw new AssertionError("no " + what + " dialog was shown");
			}
		}
	}

	/**
	 * Answers the next visible window that {@code which} picks with {@code answer}, looking every
	 * 100 ms for 20 s: a dialog opened by a command may show late on a loaded machine. A failing
	 * answer closes the dialogs, so the command returns and the test can report it.
	 */
	public static Answered whenShown(java.util.function.Predicate<Shell> which, java.util.function.Consumer<Shell> answer) {
		Answered answered = new Answered();
		long deadline = System.currentTimeMillis() + 20_000;
		Runnable[] look = new Runnable[1];
		look[0] = () -> {
			for (Shell shell : display().getShells()) {
				if (shell.isVisible() && which.test(shell)) {
					try {
						answer.accept(shell);
						answered.done = true;
					} catch (Throwable e) {
						answered.failure = e;
						for (Shell dialog : display().getShells()) {
							if (dialog.getParent() != null && !dialog.isDisposed()) {
								dialog.close();
							}
						}
					}
					return;
				}
			}
			if (System.currentTimeMillis() < deadline) {
				display().timerExec(100, look[0]);
			}
		};
		display().timerExec(100, look[0]);
		return answered;
	}

	/** Whether a window offers a button with this label (mnemonics ignored). */
	public static boolean offers(Shell shell, String label) {
		return find(shell, Button.class).stream().anyMatch(button -> label.equals(button.getText().replace("&", "")));
	}

	/** Lets the workbench paint what changed. */
	public static void settle(long millis) {
		waitUntil(() -> false, millis);
	}

	/** The workbench window as a PNG under target/screenshots (system property kse.screenshots). */
	public static Path screenshot(String name) {
		return screenshotOf(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell(), name);
	}

	/** A window (a dialog, the workbench) as a PNG under target/screenshots. */
	public static Path screenshotOf(Shell shell, String name) {
		// a window just opened is mapped and painted only after the event loop has run a while
		shell.moveAbove(null);
		shell.update();
		settle(500);
		Display display = display();
		Rectangle bounds = shell.getBounds();
		Image image = new Image(display, bounds.width, bounds.height);
		GC gc = new GC(display);
		try {
			gc.copyArea(image, bounds.x, bounds.y);
			Path folder = Path.of(System.getProperty("kse.screenshots", "target/screenshots"));
			Files.createDirectories(folder);
			Path file = folder.resolve(name + ".png");
			ImageLoader loader = new ImageLoader();
			loader.data = new org.eclipse.swt.graphics.ImageData[] { image.getImageData() };
			loader.save(file.toString(), SWT.IMAGE_PNG);
			return file;
		} catch (IOException e) {
			throw new AssertionError("cannot save the screenshot " + name, e);
		} finally {
			gc.dispose();
			image.dispose();
		}
	}
}
