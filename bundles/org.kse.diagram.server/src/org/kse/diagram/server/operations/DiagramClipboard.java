package org.kse.diagram.server.operations;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.UUID;

import org.eclipse.emf.ecore.EObject;
import org.kse.diagram.server.DiagramLayout;
import org.kse.labeling.Copies;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.notation.Bounds;

/**
 * Copied states of every diagram of this server, so that a copy can be pasted into another
 * model. The client's clipboard carries only the copy's key; the copy keeps the states' bounds
 * in the order a walk over the copied trees meets them, which is the order of the pasted trees.
 */
final class DiagramClipboard {

	static final String FORMAT = "application/x-kse-states";

	record Copy(Copies.Fragment fragment, List<Bounds> bounds, String description) {
	}

	private static final int KEPT = 32;
	private static final Map<String, Copy> COPIES = new LinkedHashMap<>(KEPT, 0.75f, true) {
		private static final long serialVersionUID = 1L;

		@Override
		protected boolean removeEldestEntry(Map.Entry<String, Copy> eldest) {
			return size() > KEPT;
		}
	};

	private DiagramClipboard() {
	}

	/** Copies the states and returns the copy's key. */
	static synchronized String copy(Model model, Collection<Node> selected, DiagramLayout layout) {
		Copies.Fragment fragment = Copies.copy(model, selected);
		List<Node> topMost = selected.stream().filter(node -> !insideAny(node, selected)).distinct().toList();
		List<Bounds> bounds = new ArrayList<>();
		for (Node node : topMost) {
			walk(node, each -> bounds.add(layout.get(each)));
		}
		String description = topMost.stream().map(node -> node.getLabel() + " (" + node.getName() + ")").reduce((a, b) -> a + ", " + b).orElse("");
		String key = UUID.randomUUID().toString();
		COPIES.put(key, new Copy(fragment, bounds, description));
		return key;
	}

	static synchronized Copy get(String key) {
		return key == null ? null : COPIES.get(key);
	}

	/**
	 * The ids selected in the page, none when a client sent no editor context or no selection
	 * (the page always sends both; without this, such a message failed with a NullPointerException).
	 */
	static List<String> selectedIds(org.eclipse.glsp.server.types.EditorContext context) {
		return context == null || context.getSelectedElementIds() == null ? List.of()
				: context.getSelectedElementIds().stream().filter(java.util.Objects::nonNull).toList();
	}

	static void walk(Node node, java.util.function.Consumer<Node> visitor) {
		visitor.accept(node);
		for (Node child : node.getChildren()) {
			walk(child, visitor);
		}
	}

	private static boolean insideAny(Node node, Collection<Node> selected) {
		for (EObject container = node.eContainer(); container != null; container = container.eContainer()) {
			if (selected.contains(container)) {
				return true;
			}
		}
		return false;
	}
}
