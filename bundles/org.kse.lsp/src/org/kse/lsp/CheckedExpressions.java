package org.kse.lsp;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.kse.messages.MessageCatalog;
import org.kse.validation.ExpressionChecks;

/**
 * The problems of expressions already checked against a catalog: a statechart is checked again at
 * every change, and only the expressions that changed need parsing again (a model's transitions
 * also share many texts). Forgotten when the catalog changes, and beyond a bound, the oldest first.
 */
final class CheckedExpressions {

	private static final int KEPT = 20_000;

	private MessageCatalog catalog;
	private final Map<String, List<ExpressionChecks.Problem>> problems = new LinkedHashMap<>(256, 0.75f, true) {
		@Override
		protected boolean removeEldestEntry(Map.Entry<String, List<ExpressionChecks.Problem>> eldest) {
			return size() > KEPT;
		}
	};

	synchronized List<ExpressionChecks.Problem> problems(String expression, MessageCatalog against) {
		if (against != catalog) {
			problems.clear();
			catalog = against;
		}
		return problems.computeIfAbsent(expression, text -> List.copyOf(ExpressionChecks.check(text, against)));
	}
}
