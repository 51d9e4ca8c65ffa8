package org.kse.ui.statechart.editor;

import java.util.List;
import java.util.function.Consumer;

import org.eclipse.jface.text.Document;
import org.eclipse.jface.text.DocumentEvent;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IDocumentListener;
import org.eclipse.jface.text.contentassist.ContentAssistant;
import org.eclipse.jface.text.contentassist.IContentAssistant;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.jface.text.source.SourceViewer;
import org.eclipse.jface.text.source.SourceViewerConfiguration;
import org.eclipse.swt.SWT;
import org.eclipse.swt.widgets.Composite;
import org.kse.messages.MessageCatalog;
import org.kse.validation.ExpressionChecks;

/**
 * The editing field of a transition expression, for the expression dialog and the Properties
 * view alike: several lines, completion on Ctrl+Space (and after '.', '[', '/'), and the text
 * checked against the grammar and the message catalog at every change.
 */
public final class ExpressionField {

	private final SourceViewer viewer;
	private final ContentAssistant assistant = new ContentAssistant();
	private MessageCatalog catalog;
	private ExpressionAssist assist;
	private List<ExpressionChecks.Problem> problems = List.of();
	private final Consumer<List<ExpressionChecks.Problem>> onCheck;

	/** @param onCheck told the problems of the text after every change */
	public ExpressionField(Composite parent, int style, MessageCatalog catalog, Consumer<List<ExpressionChecks.Problem>> onCheck) {
		this.catalog = catalog;
		this.onCheck = onCheck;
		viewer = new SourceViewer(parent, null, style | SWT.MULTI | SWT.V_SCROLL | SWT.H_SCROLL);
		viewer.getTextWidget().setFont(org.eclipse.jface.resource.JFaceResources.getTextFont());
		assist = new ExpressionAssist(catalog);
		assistant.setContentAssistProcessor(assist, IDocument.DEFAULT_CONTENT_TYPE);
		assistant.enableAutoActivation(true);
		assistant.setAutoActivationDelay(200);
		assistant.enableAutoInsert(true);
		viewer.configure(new SourceViewerConfiguration() {
			@Override
			public IContentAssistant getContentAssistant(ISourceViewer sourceViewer) {
				return assistant;
			}
		});
		viewer.setDocument(new Document(""));
		viewer.getTextWidget().addListener(SWT.KeyDown, event -> {
			if (event.keyCode == ' ' && (event.stateMask & SWT.CTRL) != 0) {
				viewer.doOperation(ISourceViewer.CONTENTASSIST_PROPOSALS);
				event.doit = false;
			}
		});
		viewer.getDocument().addDocumentListener(new IDocumentListener() {
			@Override
			public void documentAboutToBeChanged(DocumentEvent event) {
			}

			@Override
			public void documentChanged(DocumentEvent event) {
				check();
			}
		});
	}

	/** Runs at every change of the text, typed or set. */
	public void onChange(Runnable listener) {
		viewer.getDocument().addDocumentListener(new IDocumentListener() {
			@Override
			public void documentAboutToBeChanged(DocumentEvent event) {
			}

			@Override
			public void documentChanged(DocumentEvent event) {
				listener.run();
			}
		});
	}

	/** The catalog changes when the model is connected to another source folder. */
	public void setCatalog(MessageCatalog catalog) {
		if (catalog != this.catalog) {
			this.catalog = catalog;
			assist = new ExpressionAssist(catalog);
			assistant.setContentAssistProcessor(assist, IDocument.DEFAULT_CONTENT_TYPE);
		}
	}

	public void setText(String text) {
		String value = text == null ? "" : text;
		if (!value.equals(getText())) {
			viewer.getDocument().set(value);
		} else {
			check();
		}
	}

	public String getText() {
		return viewer.getDocument().get();
	}

	public List<ExpressionChecks.Problem> check() {
		problems = ExpressionChecks.check(getText(), catalog);
		onCheck.accept(problems);
		return problems;
	}

	public List<ExpressionChecks.Problem> problems() {
		return problems;
	}

	/** The first error, and how many problems follow it, in a line; null when there is none. */
	public static String summary(List<ExpressionChecks.Problem> problems) {
		ExpressionChecks.Problem first = problems.stream().filter(ExpressionChecks.Problem::error).findFirst().orElse(null);
		return first == null ? null : first + (problems.size() > 1 ? " (and " + (problems.size() - 1) + " more)" : "");
	}

	public SourceViewer getViewer() {
		return viewer;
	}

	public ExpressionAssist getAssist() {
		return assist;
	}
}
