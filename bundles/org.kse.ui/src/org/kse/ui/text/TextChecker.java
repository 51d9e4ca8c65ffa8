package org.kse.ui.text;

import org.eclipse.core.runtime.IProgressMonitor;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.IRegion;
import org.eclipse.jface.text.reconciler.DirtyRegion;
import org.eclipse.jface.text.reconciler.IReconcilingStrategy;
import org.eclipse.jface.text.reconciler.IReconcilingStrategyExtension;

/**
 * What KSE's text editors check whenever typing pauses: the whole text at once, and also when
 * the file opens (JFace's reconciler checks at once only a strategy with the extension).
 */
public abstract class TextChecker implements IReconcilingStrategy, IReconcilingStrategyExtension {

	private volatile IDocument document;

	/** Checks the text as it is now and shows what is wrong (any thread but the UI's). */
	protected abstract void check(IDocument document);

	/** Checks again now, as when typing paused; nothing before the editor has its text. */
	public void check() {
		IDocument current = document;
		if (current != null) {
			check(current);
		}
	}

	@Override
	public void setDocument(IDocument document) {
		this.document = document;
	}

	@Override
	public void reconcile(DirtyRegion dirtyRegion, IRegion subRegion) {
		check();
	}

	@Override
	public void reconcile(IRegion partition) {
		check();
	}

	@Override
	public void initialReconcile() {
		check();
	}

	@Override
	public void setProgressMonitor(IProgressMonitor monitor) {
		// a check takes milliseconds: nothing to cancel
	}
}
