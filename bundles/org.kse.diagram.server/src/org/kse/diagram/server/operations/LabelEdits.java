package org.kse.diagram.server.operations;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.glsp.graph.GModelElement;
import org.eclipse.glsp.server.features.directediting.LabelEditValidator;
import org.eclipse.glsp.server.features.directediting.ValidationStatus;
import org.kse.diagram.server.StatechartModelState;
import org.kse.messages.MessageCatalog;
import org.kse.messages.StandardMessages;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.validation.ExpressionChecks;

import com.google.inject.Inject;

/**
 * What may be typed into a label, checked while it is typed and again when it is applied: a
 * state's name is not empty (an activity's is a C++ class name), an expression passes the same
 * checks as in the properties view.
 */
public class LabelEdits implements LabelEditValidator {

	private static final MessageCatalog CATALOG = StandardMessages.catalog();

	@Inject
	private StatechartModelState state;

	@Override
	public ValidationStatus validate(String text, GModelElement label) {
		String problem = problem(state, label.getId(), text);
		return problem == null ? ValidationStatus.ok() : ValidationStatus.error(problem);
	}

	/** Why the text cannot go into the label, or null. */
	static String problem(StatechartModelState state, String labelId, String text) {
		if (text == null) {
			return "the edit has no text";
		}
		// refused here, not only when the model is saved: until then every save failed, for every page of the model
		for (int i = 0; i < text.length(); i++) {
			char c = text.charAt(i);
			if (Character.isHighSurrogate(c) && i + 1 < text.length() && Character.isLowSurrogate(text.charAt(i + 1))) {
				i++;
			} else if (!(c == '\t' || c == '\n' || c == '\r' || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD))) {
				return "the text holds the character U+" + String.format("%04X", (int) c) + ", which a model file cannot hold";
			}
		}
		EObject element = state.element(labelId);
		if (element instanceof Node node) {
			String name = text.strip();
			if (NodeKind.CONDITION.is(node)) {
				return "a CONDITION state has no name to edit";
			}
			if (name.isEmpty()) {
				return "a state needs a name";
			}
			if (NodeKind.BASIC.is(node) && !name.matches("[A-Za-z_][A-Za-z0-9_]*")) {
				return "an activity's name is its C++ class name: letters, digits and _, not starting with a digit";
			}
			if (name.contains("\n")) {
				return "a name is one line";
			}
			return null;
		}
		if (element instanceof Transition) {
			List<ExpressionChecks.Problem> problems = ExpressionChecks.check(text.strip(), CATALOG);
			return problems.stream().filter(ExpressionChecks.Problem::error).findFirst().map(ExpressionChecks.Problem::toString).orElse(null);
		}
		return labelId + " is not a name or an expression";
	}
}
