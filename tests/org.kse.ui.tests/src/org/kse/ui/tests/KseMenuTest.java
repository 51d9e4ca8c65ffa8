package org.kse.ui.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Event;
import org.eclipse.swt.widgets.Menu;
import org.eclipse.swt.widgets.MenuItem;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.PlatformUI;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.kse.testing.ui.UnexpectedDialogs;

/**
 * The KSE menu as a user opens it: three bundles fill it (the workbench's groups, the formula
 * editor's Transform and Open Formula, the statechart editor's commands), in the order of the
 * pipeline, each command once, with its key.
 */
@ExtendWith(UnexpectedDialogs.class)
class KseMenuTest {

	@Test
	void theKseMenuListsThePipelineInOrder() {
		Shell window = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell();
		MenuItem kse = Arrays.stream(window.getMenuBar().getItems()).filter(item -> "KSE".equals(item.getText().replace("&", ""))).findFirst()
				.orElse(null);
		assertNotNull(kse, "a KSE menu in the menu bar");
		Menu menu = kse.getMenu();
		// the workbench fills a menu when it is about to show
		menu.notifyListeners(SWT.Show, new Event());
		try {
			assertEquals(List.of("Transform to Statechart\tCtrl+Alt+T", "-", "Validate\tCtrl+Alt+V", "Label\tCtrl+Alt+L", "Generate Code\tCtrl+Alt+G",
					"Generate Code Into...", "-", "Edit Activity...", "Open Formula", "Update Formula from Statechart...", "-", "Monitor...", "Simulate"), entries(menu));
		} finally {
			menu.notifyListeners(SWT.Hide, new Event());
		}
	}

	private static List<String> entries(Menu menu) {
		List<String> entries = new ArrayList<>();
		for (MenuItem item : menu.getItems()) {
			if ((item.getStyle() & SWT.SEPARATOR) != 0) {
				// a separator shows only between entries
				if (!entries.isEmpty() && !entries.get(entries.size() - 1).equals("-")) {
					entries.add("-");
				}
			} else {
				entries.add(item.getText().replace("&", ""));
			}
		}
		if (!entries.isEmpty() && entries.get(entries.size() - 1).equals("-")) {
			entries.remove(entries.size() - 1);
		}
		return entries;
	}
}
