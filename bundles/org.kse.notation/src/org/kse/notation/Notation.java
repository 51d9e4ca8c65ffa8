package org.kse.notation;

import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import org.eclipse.emf.ecore.EObject;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;

/**
 * Where the states of one statechart are drawn, kept beside the model so that the model file
 * stays as the original tool wrote it. An entry is keyed by the state's path in the model file
 * ({@code //@nodes.0/@Children.1}, as the original's GMF notation referred to states) and keeps
 * the state's label and name, by which it is found again when the file's order has changed.
 */
public final class Notation {

	/** One state's place: its path in the model file, its label and name when it was placed, and its bounds. */
	public record Entry(String element, String label, String name, Bounds bounds) {
	}

	private final Map<String, Entry> entries = new LinkedHashMap<>();

	/** The path of a state in its model file, as XMI writes references to it. */
	public static String path(Node node) {
		StringBuilder path = new StringBuilder();
		EObject current = node;
		while (current instanceof Node each) {
			EObject container = each.eContainer();
			if (container instanceof Node parent) {
				path.insert(0, "/@Children." + parent.getChildren().indexOf(each));
			} else if (container instanceof Model model) {
				path.insert(0, "//@nodes." + model.getNodes().indexOf(each));
			} else {
				path.insert(0, "//?");
			}
			current = container;
		}
		return path.toString();
	}

	public void put(Node node, Bounds bounds) {
		String element = path(node);
		entries.put(element, new Entry(element, node.getLabel(), node.getName(), bounds));
	}

	void put(Entry entry) {
		entries.put(entry.element(), entry);
	}

	/**
	 * The bounds of a state: the entry at its path when that entry has its label or its name, else
	 * the one entry with both its label and its name; null when the state was never placed.
	 */
	public Bounds get(Node node) {
		Entry atPath = entries.get(path(node));
		if (atPath != null && (Objects.equals(atPath.label(), node.getLabel()) || Objects.equals(atPath.name(), node.getName()))) {
			return atPath.bounds();
		}
		List<Entry> same = entries.values().stream()
				.filter(entry -> Objects.equals(entry.label(), node.getLabel()) && Objects.equals(entry.name(), node.getName())).toList();
		return same.size() == 1 ? same.get(0).bounds() : null;
	}

	/** Every state of the model has bounds. */
	public boolean covers(Model model) {
		for (var contents = model.eAllContents(); contents.hasNext();) {
			if (contents.next() instanceof Node node && get(node) == null) {
				return false;
			}
		}
		return true;
	}

	public Collection<Entry> entries() {
		return Collections.unmodifiableCollection(entries.values());
	}

	public int size() {
		return entries.size();
	}
}
