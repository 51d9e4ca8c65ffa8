package org.kse.ui.statechart.editor;

import java.util.List;

import org.eclipse.jface.dialogs.TitleAreaDialog;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.text.source.SourceViewer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;
import org.eclipse.swt.widgets.Control;
import org.eclipse.swt.widgets.Shell;
import org.kse.messages.MessageCatalog;
import org.kse.validation.ExpressionChecks;

/**
 * A transition's expression, {@code event[condition]/actions}, over several lines: checked while
 * typed against the grammar and the message catalog, with completion (Ctrl+Space) of topics,
 * kinds, message types, fields, helpers and actions.
 */
public class ExpressionDialog extends TitleAreaDialog {

	private final MessageCatalog catalog;
	private final String transition;
	private String value;
	private ExpressionField field;

	public ExpressionDialog(Shell shell, String transition, String value, MessageCatalog catalog) {
		super(shell);
		this.transition = transition;
		this.value = value == null ? "" : value;
		this.catalog = catalog;
		setShellStyle(getShellStyle() | SWT.RESIZE);
	}

	@Override
	protected Control createDialogArea(Composite parent) {
		setTitle("Transition expression of " + transition);
		setMessage("event[condition]/actions; Ctrl+Space completes topics, kinds, message types and fields.");
		Composite area = (Composite) super.createDialogArea(parent);
		field = new ExpressionField(area, SWT.BORDER, catalog, problems -> setErrorMessage(ExpressionField.summary(problems)));
		GridDataFactory.fillDefaults().grab(true, true).hint(560, 160).indent(8, 8).applyTo(field.getViewer().getControl());
		field.setText(value);
		return area;
	}

	/** What is wrong with the text now; shown as the dialog's error message. */
	public List<ExpressionChecks.Problem> check() {
		return field.check();
	}

	public SourceViewer getViewer() {
		return field.getViewer();
	}

	@Override
	protected void okPressed() {
		value = field.getText();
		super.okPressed();
	}

	public String getValue() {
		return value;
	}
}
