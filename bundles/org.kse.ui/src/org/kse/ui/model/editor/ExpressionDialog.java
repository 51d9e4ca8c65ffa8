package org.kse.ui.model.editor;

import java.util.List;

import org.eclipse.jface.dialogs.TitleAreaDialog;
import org.eclipse.jface.layout.GridDataFactory;
import org.eclipse.jface.text.Document;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.contentassist.ContentAssistant;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.jface.text.source.SourceViewer;
import org.eclipse.jface.text.source.SourceViewerConfiguration;
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
	private SourceViewer viewer;
	private ContentAssistant assistant;

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
		viewer = new SourceViewer(area, null, SWT.BORDER | SWT.MULTI | SWT.V_SCROLL | SWT.H_SCROLL);
		GridDataFactory.fillDefaults().grab(true, true).hint(560, 160).indent(8, 8).applyTo(viewer.getControl());
		viewer.getTextWidget().setFont(org.eclipse.jface.resource.JFaceResources.getTextFont());
		assistant = new ContentAssistant();
		assistant.setContentAssistProcessor(new ExpressionAssist(catalog), IDocument.DEFAULT_CONTENT_TYPE);
		assistant.enableAutoActivation(true);
		assistant.setAutoActivationDelay(200);
		assistant.enableAutoInsert(true);
		viewer.configure(new SourceViewerConfiguration() {
			@Override
			public org.eclipse.jface.text.contentassist.IContentAssistant getContentAssistant(ISourceViewer sourceViewer) {
				return assistant;
			}
		});
		viewer.setDocument(new Document(value));
		viewer.getTextWidget().addListener(SWT.KeyDown, event -> {
			if (event.keyCode == ' ' && (event.stateMask & SWT.CTRL) != 0) {
				viewer.doOperation(ISourceViewer.CONTENTASSIST_PROPOSALS);
				event.doit = false;
			}
		});
		viewer.getDocument().addDocumentListener(new org.eclipse.jface.text.IDocumentListener() {
			@Override
			public void documentAboutToBeChanged(org.eclipse.jface.text.DocumentEvent event) {
			}

			@Override
			public void documentChanged(org.eclipse.jface.text.DocumentEvent event) {
				check();
			}
		});
		check();
		return area;
	}

	/** What is wrong with the text now; shown as the dialog's error message. */
	public List<ExpressionChecks.Problem> check() {
		List<ExpressionChecks.Problem> problems = ExpressionChecks.check(viewer.getDocument().get(), catalog);
		ExpressionChecks.Problem first = problems.stream().filter(ExpressionChecks.Problem::error).findFirst().orElse(null);
		setErrorMessage(first == null ? null : first + (problems.size() > 1 ? " (and " + (problems.size() - 1) + " more)" : ""));
		return problems;
	}

	public SourceViewer getViewer() {
		return viewer;
	}

	@Override
	protected void okPressed() {
		value = viewer.getDocument().get();
		super.okPressed();
	}

	public String getValue() {
		return value;
	}
}
