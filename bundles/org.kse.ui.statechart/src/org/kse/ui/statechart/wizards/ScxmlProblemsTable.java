package org.kse.ui.statechart.wizards;

import java.util.List;

import org.eclipse.swt.SWT;
import org.eclipse.swt.layout.GridData;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.TableItem;
import org.kse.scxml.ScxmlProblem;

/**
 * The SCXML wizards' list of problems: one row per problem, with its severity, the file, the
 * element (an SCXML element with its line:column, or a KSE state by label and name) and the message.
 */
final class ScxmlProblemsTable {

	/** One problem of one file. */
	record Row(String file, ScxmlProblem problem) {
	}

	private final Table table;

	ScxmlProblemsTable(Composite parent) {
		table = new Table(parent, SWT.BORDER | SWT.FULL_SELECTION | SWT.V_SCROLL | SWT.H_SCROLL);
		table.setHeaderVisible(true);
		table.setLinesVisible(true);
		GridData layout = new GridData(SWT.FILL, SWT.FILL, true, true, 3, 1);
		layout.heightHint = 160;
		table.setLayoutData(layout);
		for (String[] column : new String[][] { { "", "70" }, { "File", "130" }, { "Element", "220" }, { "Problem", "600" } }) {
			TableColumn tableColumn = new TableColumn(table, SWT.LEFT);
			tableColumn.setText(column[0]);
			tableColumn.setWidth(Integer.parseInt(column[1]));
		}
		table.setToolTipText("What the SCXML cannot carry over; an error means that nothing is written");
	}

	void show(List<Row> rows) {
		table.removeAll();
		Display display = table.getDisplay();
		for (Row row : rows) {
			TableItem item = new TableItem(table, SWT.NONE);
			boolean error = row.problem().isError();
			item.setText(new String[] { error ? "Error" : "Warning", row.file(), row.problem().element(), row.problem().message() });
			item.setForeground(0, display.getSystemColor(error ? SWT.COLOR_DARK_RED : SWT.COLOR_DARK_YELLOW));
		}
		table.setVisible(true);
	}

	Table table() {
		return table;
	}
}
