package org.kse.lsp;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.SymbolKind;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.server.Document;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Issue;
import org.kse.liveness.FormulaLoader;
import org.kse.liveness.Formulas;
import org.kse.liveness.ide.LivenessIdeSetup;
import org.kse.liveness.liveness.Formula;
import org.kse.liveness.liveness.FormulaFile;
import org.kse.liveness.liveness.LivenessPackage;
import org.kse.liveness.liveness.Reference;

import com.google.inject.Injector;

/**
 * Formula files ({@code .liveness}, and the original tool's {@code .txt}): the problems
 * {@code kse transform} reports, completion of operators and names, and for a name its meaning
 * (hover) and the formula that defines it (go to definition; a name defined again means its last
 * definition), each formula a symbol.
 */
final class FormulaLanguage implements DocumentLanguage {

	private static final class Holder {
		static final Injector INJECTOR = create();

		private static Injector create() {
			FormulaLoader.injector(); // registers the language with EMF first
			return new LivenessIdeSetup().createInjector();
		}
	}

	@Override
	public List<Diagnostic> diagnostics(String uri, Document document) {
		List<Diagnostic> diagnostics = new ArrayList<>();
		for (Issue issue : FormulaLoader.load(document.getContents(), URI.createURI(uri)).issues()) {
			if (issue.getSeverity() == Severity.ERROR || issue.getSeverity() == Severity.WARNING) {
				diagnostics.add(Protocol.diagnostic(range(document, issue), issue.getMessage(), issue.getSeverity() == Severity.ERROR));
			}
		}
		return diagnostics;
	}

	private static Range range(Document document, Issue issue) {
		if (issue.getOffset() != null) {
			int length = issue.getLength() == null ? 0 : issue.getLength();
			return Protocol.range(document, issue.getOffset(), issue.getOffset() + length);
		}
		int line = issue.getLineNumber() == null ? 1 : issue.getLineNumber();
		int column = issue.getColumn() == null ? 1 : issue.getColumn();
		int offset = document.getOffSet(new org.eclipse.lsp4j.Position(line - 1, column - 1));
		return Protocol.range(document, offset, offset);
	}

	@Override
	public List<CompletionItem> completion(String uri, Document document, int offset) {
		FormulaProposals provider = Holder.INJECTOR.getInstance(FormulaProposals.class);
		List<CompletionItem> items = new ArrayList<>();
		for (ContentAssistEntry entry : XtextProposals.at(Holder.INJECTOR, provider, named(uri), document.getContents(), offset)) {
			int prefix = entry.getPrefix() == null ? 0 : entry.getPrefix().length();
			items.add(Protocol.item(entry, Protocol.range(document, offset - prefix, offset), entry.getProposal()));
		}
		return items;
	}

	/** The URI the language's resource needs: a formula file's extension, whatever the client calls it. */
	private static URI named(String uri) {
		URI parsed = URI.createURI(uri);
		return List.of("liveness", "txt").contains(parsed.fileExtension()) ? parsed : parsed.appendFileExtension("liveness");
	}

	@Override
	public Hover hover(String uri, Document document, int offset) {
		FormulaFile file = FormulaLoader.load(document.getContents(), URI.createURI(uri)).file();
		String name = nameAt(file, offset);
		if (name == null) {
			return null;
		}
		Map<String, Formula> capabilities = Formulas.capabilities(file);
		Formula definition = capabilities.get(name);
		StringBuilder text = new StringBuilder();
		if (definition == null) {
			text.append("activity **").append(name).append("**: no formula defines it, so it is a BASIC state that runs the activity ")
					.append(name);
		} else {
			Formula root = Formulas.root(file);
			text.append(root != null && name.equals(root.getName()) ? "root capability **" : "capability **").append(name).append("**");
			long definitions = file.getFormulas().stream().filter(formula -> name.equals(formula.getName())).count();
			if (definitions > 1) {
				text.append(" (defined ").append(definitions).append(" times: the last definition counts)");
			}
			INode node = NodeModelUtils.getNode(definition);
			text.append(", line ").append(node.getStartLine()).append("\n\n```\n").append(NodeModelUtils.getTokenText(node)).append("\n```");
		}
		return new Hover(new MarkupContent(MarkupKind.MARKDOWN, text.toString()));
	}

	@Override
	public List<Location> definition(String uri, Document document, int offset) {
		FormulaFile file = FormulaLoader.load(document.getContents(), URI.createURI(uri)).file();
		String name = nameAt(file, offset);
		Formula definition = name == null ? null : Formulas.capabilities(file).get(name);
		if (definition == null) {
			return List.of();
		}
		return List.of(new Location(uri, nameRange(document, definition)));
	}

	@Override
	public List<DocumentSymbol> symbols(String uri, Document document) {
		FormulaFile file = FormulaLoader.load(document.getContents(), URI.createURI(uri)).file();
		List<DocumentSymbol> symbols = new ArrayList<>();
		if (file == null) {
			return symbols;
		}
		for (Formula formula : file.getFormulas()) {
			INode node = NodeModelUtils.getNode(formula);
			if (formula.getName() == null || node == null) {
				continue;
			}
			Range whole = Protocol.range(document, node.getOffset(), node.getEndOffset());
			String expression = formula.getExpression() == null ? "" : NodeModelUtils.getTokenText(NodeModelUtils.getNode(formula.getExpression()));
			symbols.add(new DocumentSymbol(formula.getName(), SymbolKind.Function, whole, nameRange(document, formula), expression));
		}
		return symbols;
	}

	private static Range nameRange(Document document, Formula formula) {
		List<INode> nodes = NodeModelUtils.findNodesForFeature(formula, LivenessPackage.Literals.FORMULA__NAME);
		INode node = nodes.isEmpty() ? NodeModelUtils.getNode(formula) : nodes.get(0);
		return Protocol.range(document, node.getOffset(), node.getEndOffset());
	}

	/** The name of the capability or activity written at the offset (or just before it), or null. */
	private static String nameAt(FormulaFile file, int offset) {
		INode rootNode = file == null ? null : NodeModelUtils.getNode(file);
		if (rootNode == null) {
			return null;
		}
		for (int at : new int[] { offset, offset - 1 }) {
			ILeafNode leaf = at < 0 ? null : NodeModelUtils.findLeafNodeAtOffset(rootNode.getRootNode(), at);
			if (leaf == null || leaf.isHidden()) {
				continue;
			}
			EObject element = NodeModelUtils.findActualSemanticObjectFor(leaf);
			if (element instanceof Reference reference && leaf.getText().equals(reference.getName())) {
				return reference.getName();
			}
			if (element instanceof Formula formula && leaf.getText().equals(formula.getName())
					&& NodeModelUtils.findNodesForFeature(formula, LivenessPackage.Literals.FORMULA__NAME).contains(leaf)) {
				return formula.getName();
			}
		}
		return null;
	}
}
