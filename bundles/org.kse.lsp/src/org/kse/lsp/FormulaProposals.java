package org.kse.lsp;

import java.util.LinkedHashSet;
import java.util.Set;

import org.eclipse.xtext.Assignment;
import org.eclipse.xtext.GrammarUtil;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IIdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.kse.liveness.Formulas;
import org.kse.liveness.liveness.FormulaFile;
import org.kse.liveness.liveness.Reference;

/**
 * Completion in formulas: the grammar's operators and brackets (Xtext's keywords), and where a
 * name goes, the names of the file. A name in a formula is plain text in the grammar (one defined
 * nowhere is an activity), so Xtext alone would propose none.
 */
public class FormulaProposals extends IdeContentProposalProvider {

	@Override
	protected void _createProposals(Assignment assignment, ContentAssistContext context, IIdeContentProposalAcceptor acceptor) {
		String rule = GrammarUtil.containingParserRule(assignment).getName();
		if (!"name".equals(assignment.getFeature()) || !(context.getRootModel() instanceof FormulaFile file)) {
			super._createProposals(assignment, context, acceptor);
			return;
		}
		Set<String> defined = Formulas.capabilities(file).keySet();
		Set<String> used = new LinkedHashSet<>();
		for (Reference reference : Formulas.references(file)) {
			if (reference.getName() != null && !reference.getName().equals(context.getPrefix())) {
				used.add(reference.getName());
			}
		}
		if (rule.equals("Reference")) {
			defined.forEach(name -> propose(name, "capability", context, acceptor));
			used.stream().filter(name -> !defined.contains(name)).forEach(name -> propose(name, "activity", context, acceptor));
		} else if (rule.equals("Formula")) {
			// a formula's left side: the names that are used and not defined yet
			used.stream().filter(name -> !defined.contains(name)).forEach(name -> propose(name, "used, not defined yet", context, acceptor));
		}
	}

	private void propose(String name, String description, ContentAssistContext context, IIdeContentProposalAcceptor acceptor) {
		ContentAssistEntry entry = getProposalCreator().createProposal(name, context, ContentAssistEntry.KIND_REFERENCE, it -> it.setDescription(description));
		if (entry != null) {
			acceptor.accept(entry, getProposalPriorities().getDefaultPriority(entry) + 100);
		}
	}
}
