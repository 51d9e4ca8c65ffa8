package org.kse.ui.messages;

import org.eclipse.jface.preference.IPreferenceStore;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.hyperlink.IHyperlinkDetector;
import org.eclipse.jface.text.presentation.IPresentationReconciler;
import org.eclipse.jface.text.presentation.PresentationReconciler;
import org.eclipse.jface.text.reconciler.IReconciler;
import org.eclipse.jface.text.reconciler.MonoReconciler;
import org.eclipse.jface.text.rules.DefaultDamagerRepairer;
import org.eclipse.jface.text.source.ISourceViewer;
import org.eclipse.swt.SWT;
import org.eclipse.ui.editors.text.TextSourceViewerConfiguration;

class ProtoViewerConfiguration extends TextSourceViewerConfiguration {

	/** Milliseconds of quiet typing before the text is checked again, as in the formula editor. */
	static final int CHECK_DELAY = 250;

	private final ProtoEditor editor;

	ProtoViewerConfiguration(ProtoEditor editor, IPreferenceStore preferences) {
		super(preferences);
		this.editor = editor;
	}

	@Override
	public String getConfiguredDocumentPartitioning(ISourceViewer sourceViewer) {
		return ProtoScanner.PARTITIONING;
	}

	@Override
	public String[] getConfiguredContentTypes(ISourceViewer sourceViewer) {
		return new String[] { IDocument.DEFAULT_CONTENT_TYPE, ProtoScanner.COMMENT_PARTITION, ProtoScanner.STRING_PARTITION };
	}

	@Override
	public IPresentationReconciler getPresentationReconciler(ISourceViewer sourceViewer) {
		PresentationReconciler reconciler = new PresentationReconciler();
		reconciler.setDocumentPartitioning(ProtoScanner.PARTITIONING);
		colour(reconciler, new DefaultDamagerRepairer(new ProtoScanner()), IDocument.DEFAULT_CONTENT_TYPE);
		colour(reconciler, new DefaultDamagerRepairer(ProtoScanner.whole(ProtoScanner.COMMENT, SWT.ITALIC)), ProtoScanner.COMMENT_PARTITION);
		colour(reconciler, new DefaultDamagerRepairer(ProtoScanner.whole(ProtoScanner.STRING, SWT.NORMAL)), ProtoScanner.STRING_PARTITION);
		return reconciler;
	}

	private static void colour(PresentationReconciler reconciler, DefaultDamagerRepairer colours, String partition) {
		reconciler.setDamager(colours, partition);
		reconciler.setRepairer(colours, partition);
	}

	@Override
	public IReconciler getReconciler(ISourceViewer sourceViewer) {
		MonoReconciler reconciler = new MonoReconciler(editor.checker(), false);
		reconciler.setDelay(CHECK_DELAY);
		return reconciler;
	}

	@Override
	public IHyperlinkDetector[] getHyperlinkDetectors(ISourceViewer sourceViewer) {
		return new IHyperlinkDetector[] { new ProtoHyperlinks(editor) };
	}
}
