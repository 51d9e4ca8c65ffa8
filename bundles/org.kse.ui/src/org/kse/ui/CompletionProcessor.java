package org.kse.ui;

import org.eclipse.jface.text.ITextViewer;
import org.eclipse.jface.text.contentassist.CompletionProposal;
import org.eclipse.jface.text.contentassist.ICompletionProposal;
import org.eclipse.jface.text.contentassist.IContentAssistProcessor;
import org.eclipse.jface.text.contentassist.IContextInformation;
import org.eclipse.jface.text.contentassist.IContextInformationValidator;

/** What KSE's completions share: proposals that replace the typed prefix, and no context information. */
public abstract class CompletionProcessor implements IContentAssistProcessor {

	/** {@code text} in place of the {@code prefix} typed before {@code offset}, shown as "text  (what)". */
	protected static ICompletionProposal proposal(String text, String prefix, int offset, String what) {
		return new CompletionProposal(text, offset - prefix.length(), prefix.length(), text.length(), null, text + "  (" + what + ")", null, null);
	}

	@Override
	public IContextInformation[] computeContextInformation(ITextViewer viewer, int offset) {
		return null;
	}

	@Override
	public char[] getContextInformationAutoActivationCharacters() {
		return null;
	}

	@Override
	public String getErrorMessage() {
		return null;
	}

	@Override
	public IContextInformationValidator getContextInformationValidator() {
		return null;
	}
}
