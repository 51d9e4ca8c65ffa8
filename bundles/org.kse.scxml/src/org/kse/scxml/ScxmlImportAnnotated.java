package org.kse.scxml;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.Transition;
import org.kse.scxml.ScxmlImportReader.Element;

/**
 * A document the export wrote ({@code kse:export="1"}), rebuilt from its {@code kse:} annotations
 * (ADR 0038): each element with a {@code kse:type} is a state, each {@code <kse:connector>} a
 * CONDITION connector, in document order; each transition with a {@code kse:order} is a KSE
 * transition (a path through connectors is several SCXML transitions with one order: one KSE
 * transition), and the model's transitions are in that order. Everything else is the export's
 * machinery for SCXML processors, and is skipped.
 */
final class ScxmlImportAnnotated {

	private static final StatechartFactory FACTORY = StatechartFactory.eINSTANCE;

	private final List<ScxmlProblem> problems;
	private final Map<Element, Node> nodes = new IdentityHashMap<>();
	private final Map<String, Element> ids = new HashMap<>();
	private final Map<String, Node> labels = new HashMap<>();
	/** Transition elements (SCXML's and the connectors' kse:transition) with the state they leave. */
	private final List<Map.Entry<Element, Node>> pending = new ArrayList<>();

	private ScxmlImportAnnotated(List<ScxmlProblem> problems) {
		this.problems = problems;
	}

	static Model build(Element scxml, List<ScxmlProblem> problems) {
		return new ScxmlImportAnnotated(problems).build(scxml);
	}

	private Model build(Element scxml) {
		Model model = FACTORY.createModel();
		model.setName(scxml.attribute("name"));
		walk(scxml, null, model);
		if (model.getNodes().isEmpty()) {
			problems.add(ScxmlProblem.error(scxml.describe(), "the document says the export wrote it (kse:export=\"1\") but holds no state with a kse:type"));
			return model;
		}
		TreeMap<Integer, Transition> byOrder = new TreeMap<>();
		for (Map.Entry<Element, Node> entry : pending) {
			transition(entry.getKey(), entry.getValue(), byOrder);
		}
		model.getTransitions().addAll(byOrder.values());
		return model;
	}

	private void walk(Element element, Node owner, Model model) {
		for (Element child : element.children) {
			if (child.attribute("id") != null) {
				ids.putIfAbsent(child.attribute("id"), child);
			}
			boolean connector = child.isKse("connector");
			if (connector || child.isScxml() && child.kse.containsKey("type")) {
				NodeKind kind = connector ? NodeKind.CONDITION : NodeKind.of(child.kse.get("type"));
				if (kind == null) {
					problems.add(ScxmlProblem.error(child.describe(), "kse:type '" + child.kse.get("type") + "' is not a kind of KSE state (OR, AND, BASIC, START, END)"));
					continue;
				}
				Node node = FACTORY.createNode();
				node.setType(kind.name());
				node.setLabel(child.kse.get("label"));
				node.setName(child.kse.get("name"));
				node.setActivity(child.kse.get("activity"));
				if (owner == null) {
					model.getNodes().add(node);
				} else {
					owner.getChildren().add(node);
				}
				nodes.put(child, node);
				if (node.getLabel() != null) {
					labels.putIfAbsent(node.getLabel(), node);
				}
				walk(child, node, model);
			} else if ((child.is("transition") && child.kse.containsKey("order")) || child.isKse("transition")) {
				if (owner == null) {
					problems.add(ScxmlProblem.error(child.describe(), "a transition of KSE's outside every state with a kse:type"));
				} else {
					pending.add(Map.entry(child, owner));
				}
			} else {
				walk(child, owner, model);
			}
		}
	}

	private void transition(Element element, Node source, TreeMap<Integer, Transition> byOrder) {
		int order;
		try {
			order = Integer.parseInt(String.valueOf(element.kse.get("order")).trim());
		} catch (NumberFormatException e) {
			problems.add(ScxmlProblem.error(element.describe(), "kse:order '" + element.kse.get("order") + "' is not a number"));
			return;
		}
		if (byOrder.containsKey(order)) {
			return; // another path of the same transition through its connectors
		}
		Node target = target(element);
		if (target == null) {
			return;
		}
		Transition transition = FACTORY.createTransition();
		transition.setSource(source);
		transition.setTarget(target);
		transition.setName(element.kse.get("name"));
		transition.setTE(element.kse.get("expression"));
		byOrder.put(order, transition);
	}

	/** The KSE state a transition enters: a connector's by label, a path's first connector, else the state of its SCXML target. */
	private Node target(Element element) {
		String label = element.isKse("transition") ? element.kse.get("target")
				: element.kse.get("chain") != null && !element.kse.get("chain").isBlank() ? element.kse.get("chain").trim().split("\\s+")[0] : null;
		if (label != null) {
			Node node = labels.get(label);
			if (node == null) {
				problems.add(ScxmlProblem.error(element.describe(), "its target '" + label + "' is the label of no state or connector"));
			}
			return node;
		}
		String id = element.attribute("target");
		Element target = id == null ? null : ids.get(id.trim());
		while (target != null && !nodes.containsKey(target)) {
			target = target.parent;
		}
		if (target == null) {
			problems.add(ScxmlProblem.error(element.describe(), "its target '" + id + "' is no state of KSE's in the document"));
			return null;
		}
		return nodes.get(target);
	}
}
