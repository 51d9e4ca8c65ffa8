package org.kse.ui.formula;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;

import org.eclipse.compare.CompareConfiguration;
import org.eclipse.compare.IEncodedStreamContentAccessor;
import org.eclipse.compare.ITypedElement;
import org.eclipse.compare.contentmergeviewer.TextMergeViewer;
import org.eclipse.compare.structuremergeviewer.DiffNode;
import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.dialogs.IDialogConstants;
import org.eclipse.jface.dialogs.IMessageProvider;
import org.eclipse.jface.dialogs.MessageDialog;
import org.eclipse.jface.dialogs.TitleAreaDialog;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.Point;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Label;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.swt.widgets.Table;
import org.eclipse.swt.widgets.TableColumn;
import org.eclipse.swt.widgets.TableItem;
import org.eclipse.ui.PartInitException;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.ide.IDE;
import org.kse.formula.StatechartToFormula;
import org.kse.model.StatechartResources;
import org.kse.ui.ModelFiles;

/**
 * The formula file as it is (left) against the formulas the statechart stands for (right), what
 * the formulas cannot say about the chart (state by state), and the button that writes the right
 * side into the file.
 */
final class UpdateFormulaDialog extends TitleAreaDialog {

	private final IFile model;
	private final IFile formula;
	private final String current;
	private final StatechartToFormula.Result recovered;

	UpdateFormulaDialog(Shell parent, IFile model, IFile formula, String current, StatechartToFormula.Result recovered) {
		super(parent);
		this.model = model;
		this.formula = formula;
		this.current = current;
		this.recovered = recovered;
		setShellStyle(getShellStyle() | SWT.RESIZE | SWT.MAX);
	}

	private boolean unchanged() {
		return normalized(current).equals(normalized(recovered.fileText()));
	}

	/** Line ends and trailing blanks are no change a user would want to see. */
	private static String normalized(String text) {
		return text.replace("\r\n", "\n").strip();
	}

	@Override
	protected void configureShell(Shell shell) {
		super.configureShell(shell);
		shell.setText(UpdateFormulaHandler.TITLE);
	}

	@Override
	protected Point getInitialSize() {
		return new Point(900, 640);
	}

	@Override
	protected Control createDialogArea(Composite parent) {
		Composite area = (Composite) super.createDialogArea(parent);
		setTitle(model.getName() + " \u2192 " + formula.getName());
		int problems = recovered.problems().size();
		if (unchanged() && problems == 0) {
			setMessage(formula.getName() + " already says what " + model.getName() + " does.", IMessageProvider.INFORMATION);
		} else if (unchanged()) {
			setMessage(formula.getName() + " already holds the closest formulas; " + parts(problems) + " of the statechart cannot be said by them (below).",
					IMessageProvider.WARNING);
		} else if (problems > 0) {
			setMessage("Left: " + formula.getName() + (formula.exists() ? " now" : " (new)") + "; right: the closest formulas to the statechart. "
					+ parts(problems) + " of the statechart cannot be said by formulas (below).", IMessageProvider.WARNING);
		} else {
			setMessage("Left: " + formula.getName() + (formula.exists() ? " now" : " (new)") + "; right: the formulas " + model.getName() + " stands for.");
		}
		Composite content = new Composite(area, SWT.NONE);
		GridDataFactory.fillDefaults().grab(true, true).applyTo(content);
		content.setLayout(new org.eclipse.swt.layout.GridLayout(1, false));

		CompareConfiguration configuration = new CompareConfiguration();
		configuration.setLeftLabel(formula.getName() + (formula.exists() ? "" : " (new)"));
		configuration.setRightLabel("From " + model.getName());
		configuration.setLeftEditable(false);
		configuration.setRightEditable(false);
		// the file on the left, as the dialog's message says, whatever the user's "swap sides" setting
		configuration.setProperty(CompareConfiguration.MIRRORED, Boolean.FALSE);
		TextMergeViewer viewer = new TextMergeViewer(content, SWT.BORDER, configuration);
		viewer.setInput(new DiffNode(new Text(formula.getName(), current), new Text(model.getName(), recovered.fileText())));
		GridDataFactory.fillDefaults().grab(true, true).hint(SWT.DEFAULT, 320).applyTo(viewer.getControl());
		viewer.getControl().addDisposeListener(event -> configuration.dispose());

		if (problems > 0) {
			Label heading = new Label(content, SWT.WRAP);
			heading.setText("Not said by the formulas (guards, timers, actions, shapes the transformation never makes):");
			GridDataFactory.fillDefaults().grab(true, false).applyTo(heading);
			Table table = new Table(content, SWT.BORDER | SWT.FULL_SELECTION | SWT.V_SCROLL);
			table.setHeaderVisible(true);
			for (String column : new String[] { "Label", "State", "What the formula cannot say" }) {
				new TableColumn(table, SWT.NONE).setText(column);
			}
			for (StatechartToFormula.Problem problem : recovered.problems()) {
				new TableItem(table, SWT.NONE).setText(new String[] { problem.label(), problem.name(), problem.message() });
			}
			for (TableColumn column : table.getColumns()) {
				column.pack();
			}
			GridDataFactory.fillDefaults().grab(true, false).hint(SWT.DEFAULT, 120).applyTo(table);
		}
		return area;
	}

	private static String parts(int count) {
		return count + (count == 1 ? " part" : " parts");
	}

	@Override
	protected void createButtonsForButtonBar(Composite parent) {
		createButton(parent, IDialogConstants.OK_ID, "Update " + formula.getName(), true).setEnabled(!unchanged());
		createButton(parent, IDialogConstants.CANCEL_ID, unchanged() ? IDialogConstants.CLOSE_LABEL : IDialogConstants.CANCEL_LABEL, false);
	}

	@Override
	protected void okPressed() {
		try {
			Charset charset = formula.exists() ? Charset.forName(formula.getCharset()) : StandardCharsets.UTF_8;
			StatechartResources.writeAtomically(ModelFiles.location(formula), recovered.fileText().getBytes(charset));
			formula.refreshLocal(IResource.DEPTH_ZERO, null);
		} catch (IOException | CoreException e) {
			MessageDialog.openError(getShell(), UpdateFormulaHandler.TITLE, "Cannot write " + formula.getFullPath() + ": " + e.getMessage());
			return;
		}
		super.okPressed();
		try {
			IDE.openEditor(PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage(), formula, FormulaEditor.ID);
		} catch (PartInitException e) {
			// written all the same; the user opens it from the explorer
		}
	}

	/** One side of the comparison. */
	private record Text(String name, String content) implements ITypedElement, IEncodedStreamContentAccessor {
		@Override
		public String getName() {
			return name;
		}

		@Override
		public Image getImage() {
			return null;
		}

		@Override
		public String getType() {
			return ITypedElement.TEXT_TYPE;
		}

		@Override
		public InputStream getContents() {
			return new ByteArrayInputStream(content.getBytes(StandardCharsets.UTF_8));
		}

		@Override
		public String getCharset() {
			return StandardCharsets.UTF_8.name();
		}
	}
}
