package org.kse.scxml;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.kse.expression.ExpressionParser;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.Transition;
import org.kse.scxml.ScxmlImportReader.Element;

/**
 * An SCXML document written by another tool, mapped onto KSE's kinds of state: a {@code <state>}
 * with child states is an OR state whose START enters the initial child (its {@code initial}
 * attribute, its {@code <initial>} element, or its first child state, as SCXML says), an atomic
 * {@code <state>} is a BASIC state, a {@code <parallel>} an AND state whose regions are OR states
 * (an atomic or parallel child gets an OR state around it), a {@code <final>} the END state, and
 * {@code <scxml>} the root OR state. Each problem is added to the list given; the model is only
 * worth keeping when none is an error.
 */
final class ScxmlImportForeign {

	private static final StatechartFactory FACTORY = StatechartFactory.eINSTANCE;
	private static final Set<String> STATES = Set.of("state", "parallel", "final");
	private static final Set<String> SYSTEM_VARIABLES = Set.of("_event", "_sessionid", "_name", "_ioprocessors", "_x");
	/** A name in a condition, outside quotes or not (a quoted name is found too, which only makes the check stricter). */
	private static final Pattern IDENTIFIER = Pattern.compile("(?<![\\w.])[A-Za-z_]\\w*");

	private final List<ScxmlProblem> problems;
	private final Map<String, Element> ids = new HashMap<>();
	private final Map<Element, Node> nodes = new IdentityHashMap<>();
	/** Each state element's transitions, in document order, by state element. */
	private final Map<Element, List<Element>> transitions = new LinkedHashMap<>();
	private final List<Element> histories = new ArrayList<>();
	/** The names of the data model's variables, which a condition of another tool's may read. */
	private final Set<String> dataIds = new java.util.HashSet<>();
	private final Set<Element> targetedHistories = java.util.Collections.newSetFromMap(new IdentityHashMap<>());
	/** The SCXML element each state and transition comes from, to name it in the validator's problems. */
	private final Map<EObject, Element> origins = new IdentityHashMap<>();
	private final ExpressionParser.Session expressions;
	private Model model;

	/** {@code expressions}: the parses of the run, which the validation then reuses. */
	ScxmlImportForeign(List<ScxmlProblem> problems, ExpressionParser.Session expressions) {
		this.problems = problems;
		this.expressions = expressions;
	}

	/** The element of the document a state or transition of the model comes from; null for what the mapping added (a START, a region). */
	Element origin(EObject element) {
		return origins.get(element);
	}

	Model build(Element scxml, String fallbackName) {
		collectIds(scxml);
		model = FACTORY.createModel();
		String name = !blank(scxml.attribute("name")) ? scxml.attribute("name").trim() : blank(fallbackName) ? "Statechart" : fallbackName.trim();
		model.setName(name);
		Node root = node(scxml, NodeKind.OR, Character.toLowerCase(name.charAt(0)) + name.substring(1));
		model.getNodes().add(root);
		nodes.put(scxml, root);
		composite(scxml, root);
		connect();
		for (Element history : histories) {
			if (!targetedHistories.contains(history)) {
				warning(history, "left out: KSE has no history states (and no transition enters this one)");
			}
		}
		return model;
	}

	private void collectIds(Element root) {
		Deque<Element> work = new ArrayDeque<>(List.of(root));
		while (!work.isEmpty()) {
			Element element = work.pop();
			String id = element.attribute("id");
			if (element.is("data") && id != null) {
				dataIds.add(id);
			}
			if (element.isScxml() && id != null && (STATES.contains(element.name) || element.name.equals("history"))) {
				Element other = ids.putIfAbsent(id, element);
				if (other != null) {
					error(element, "the id '" + id + "' is also the id of " + other.describe() + "; ids name one state each");
				}
			}
			for (int i = element.children.size() - 1; i >= 0; i--) {
				work.push(element.children.get(i));
			}
		}
	}

	/** The children of {@code <scxml>} or of a compound {@code <state>}: its states, its START, its own transitions. */
	private void composite(Element element, Node node) {
		Element initial = null;
		List<Element> states = new ArrayList<>();
		Node end = null;
		// the START's transition goes before those of the states inside, as the export and the transformation write them
		int startTransition = model.getTransitions().size();
		for (Element child : element.children) {
			if (!child.isScxml()) {
				continue; // another tool's notes (Qt's editor geometry, say): nothing of the chart
			}
			switch (child.name) {
				case "state", "parallel" -> {
					node.getChildren().add(state(child));
					states.add(child);
				}
				case "final" -> {
					if (end == null) {
						end = finalState(child);
						node.getChildren().add(end);
					} else {
						// a KSE state has one END; every <final> of a state ends it alike
						nodes.put(child, end);
						finalContent(child);
					}
					states.add(child);
				}
				case "initial" -> {
					if (initial != null) {
						error(child, "a second <initial>: a state has one");
					}
					initial = initial == null ? child : initial;
				}
				case "transition" -> {
					if (element.is("scxml")) {
						error(child, "a transition of <scxml> itself, which SCXML does not have");
					} else {
						transitions.computeIfAbsent(element, key -> new ArrayList<>()).add(child);
					}
				}
				default -> other(element, child);
			}
		}
		if (states.isEmpty()) {
			error(element, "the document holds no state");
			return;
		}
		Node start = node(NodeKind.START, null);
		node.getChildren().add(0, start);
		Element first = initialTarget(element, initial, states.get(0));
		if (first != null && nodes.get(first) != null) {
			transition(start, nodes.get(first), null);
			model.getTransitions().move(startTransition, model.getTransitions().size() - 1);
		}
	}

	/** A child of a composite state: a {@code <parallel>}, a compound {@code <state>} or an atomic one. */
	private Node state(Element element) {
		if (element.name.equals("parallel")) {
			return parallel(element);
		}
		boolean compound = element.children.stream().anyMatch(child -> child.isScxml() && STATES.contains(child.name));
		if (compound) {
			Node or = node(element, NodeKind.OR, element.attribute("id"));
			nodes.put(element, or);
			composite(element, or);
			return or;
		}
		Node basic = node(element, NodeKind.BASIC, element.attribute("id"));
		nodes.put(element, basic);
		if (element.attribute("initial") != null) {
			error(element, "names an initial state ('" + element.attribute("initial") + "') but holds no state");
		}
		for (Element child : element.children) {
			if (!child.isScxml()) {
				continue;
			}
			if (child.name.equals("transition")) {
				transitions.computeIfAbsent(element, key -> new ArrayList<>()).add(child);
			} else if (child.name.equals("initial")) {
				error(child, "an <initial> in a state that holds no state");
			} else {
				other(element, child);
			}
		}
		return basic;
	}

	/** A {@code <parallel>}: an AND state whose regions are OR states; an atomic or parallel child is wrapped in one. */
	private Node parallel(Element element) {
		Node and = node(element, NodeKind.AND, element.attribute("id"));
		nodes.put(element, and);
		for (Element child : element.children) {
			if (!child.isScxml()) {
				continue;
			}
			switch (child.name) {
				case "state", "parallel" -> {
					Node inner = state(child);
					if (NodeKind.OR.is(inner)) {
						and.getChildren().add(inner);
					} else {
						// a region of its own around it, entering it at once
						Node region = node(NodeKind.OR, null);
						Node start = node(NodeKind.START, null);
						region.getChildren().add(start);
						region.getChildren().add(inner);
						and.getChildren().add(region);
						transition(start, inner, null);
					}
				}
				case "final" -> error(child, "a <final> in a <parallel>, which SCXML does not allow: each region ends in its own state");
				case "initial" -> error(child, "an <initial> in a <parallel>: a parallel state enters all its children");
				case "transition" -> transitions.computeIfAbsent(element, key -> new ArrayList<>()).add(child);
				default -> other(element, child);
			}
		}
		if (and.getChildren().isEmpty()) {
			error(element, "a <parallel> without child states: a KSE AND state holds at least one region");
		}
		return and;
	}

	private Node finalState(Element element) {
		Node end = node(element, NodeKind.END, null);
		nodes.put(element, end);
		finalContent(element);
		return end;
	}

	private void finalContent(Element element) {
		for (Element child : element.children) {
			if (!child.isScxml()) {
				continue;
			}
			if (child.name.equals("donedata")) {
				warning(child, "left out: a KSE END state passes no data to its parent");
			} else if (child.name.equals("transition")) {
				error(child, "a transition out of a <final>, which SCXML does not allow (nothing leaves an END state)");
			} else {
				other(element, child);
			}
		}
	}

	/** What a state may hold besides states and transitions: history, entry and exit content, invoke, data. */
	private void other(Element owner, Element child) {
		switch (child.name) {
			case "history" -> histories.add(child);
			case "onentry", "onexit" -> {
				if (child.children.stream().anyMatch(Element::isScxml)) {
					warning(child, "left out: KSE states run no " + (child.name.equals("onentry") ? "entry" : "exit")
							+ " actions (a BASIC state's activity runs when it is entered; a transition's actions when it fires)");
				}
			}
			case "invoke" -> warning(child, "left out: KSE invokes no services; a BASIC state's activity (C++ that runs when the state is entered) is how a KSE state works");
			case "datamodel" -> {
				if (child.children.stream().anyMatch(Element::isScxml)) {
					warning(child, "left out: a KSE statechart has no data model; its guards read the messages on the robot's blackboards");
				}
			}
			case "script" -> warning(child, "left out: KSE runs no scripts");
			default -> error(child, "<" + child.name + "> is not an SCXML element " + (owner.is("scxml") ? "of <scxml>" : "of a state") + " (a typo?)");
		}
	}

	/** The child a composite's START enters, or null (and an error) when SCXML names another. */
	private Element initialTarget(Element element, Element initial, Element firstChild) {
		String targets;
		Element named;
		if (element.attribute("initial") != null) {
			if (initial != null) {
				error(initial, "an <initial> element besides the initial attribute of " + element.describe() + "; SCXML allows one of them");
				return null;
			}
			targets = element.attribute("initial");
			named = element;
		} else if (initial != null) {
			List<Element> transitions = initial.children.stream().filter(child -> child.is("transition")).toList();
			if (transitions.size() != 1) {
				error(initial, "an <initial> holds one transition; this one holds " + transitions.size());
				return null;
			}
			Element transition = transitions.get(0);
			if (!blank(transition.attribute("event")) || !blank(transition.attribute("cond"))) {
				error(transition, "the transition of an <initial> has no event and no condition (SCXML)");
			}
			executableContent(transition);
			targets = transition.attribute("target");
			named = transition;
		} else {
			return firstChild;
		}
		List<String> idList = blank(targets) ? List.of() : List.of(targets.trim().split("\\s+"));
		if (idList.size() != 1) {
			error(named, "the initial state names " + idList.size() + " states" + (idList.isEmpty() ? "" : " ('" + targets.trim() + "')")
					+ "; a KSE START enters one child state (entering a parallel state enters all its regions)");
			return null;
		}
		Element target = ids.get(idList.get(0));
		if (target == null) {
			error(named, "the initial state '" + idList.get(0) + "' is no state of the document");
			return null;
		}
		if (target.name.equals("history")) {
			targetedHistories.add(target);
			error(named, "the initial state '" + idList.get(0) + "' is a history state, which KSE does not have");
			return null;
		}
		if (target.parent != element) {
			boolean inside = false;
			for (Element up = target.parent; up != null; up = up.parent) {
				inside |= up == element;
			}
			error(named, inside
					? "the initial state '" + idList.get(0) + "' is not a child but a deeper descendant: a KSE START enters a child state; name the child here and '"
							+ idList.get(0) + "' as the child's own initial state"
					: "the initial state '" + idList.get(0) + "' is not inside this state");
			return null;
		}
		return target;
	}

	/** One SCXML transition as KSE can take it: its target and its condition (null: none). */
	private record Candidate(Element element, Node target, String condition, boolean onEvent) {
	}

	/** The transitions, each state's in the order in which KSE tries them the way SCXML selects them. */
	private void connect() {
		for (Map.Entry<Element, List<Element>> entry : transitions.entrySet()) {
			Element source = entry.getKey();
			Node sourceNode = nodes.get(source);
			List<Candidate> eventless = new ArrayList<>();
			List<Candidate> onEvent = new ArrayList<>();
			for (Element transition : entry.getValue()) {
				Candidate candidate = candidate(source, sourceNode, transition);
				if (candidate != null) {
					(candidate.onEvent() ? onEvent : eventless).add(candidate);
				}
			}
			order(sourceNode, eventless, onEvent);
		}
	}

	private Candidate candidate(Element source, Node sourceNode, Element transition) {
		String targets = transition.attribute("target");
		if (blank(targets)) {
			error(transition, "a transition without a target (it would stay in its state); a KSE transition goes to a state:"
					+ " name one (its own state for a self-loop, which leaves and enters it again)");
			return null;
		}
		String[] idList = targets.trim().split("\\s+");
		if (idList.length > 1) {
			error(transition, "the transition enters " + idList.length + " states at once ('" + targets.trim()
					+ "'); a KSE transition enters one (entering a parallel state enters all its regions)");
			return null;
		}
		Element target = ids.get(idList[0]);
		if (target == null) {
			error(transition, "its target '" + idList[0] + "' is no state of the document");
			return null;
		}
		if (target.name.equals("history")) {
			targetedHistories.add(target);
			error(transition, "its target '" + idList[0] + "' is a history state: KSE has none (a KSE state is always entered at its START)");
			return null;
		}
		boolean onEvent = false;
		String event = transition.attribute("event");
		if (!blank(event)) {
			boolean done = event.trim().equals("done.state." + source.attribute("id")) && (NodeKind.OR.is(sourceNode) || NodeKind.AND.is(sourceNode));
			if (!done) {
				error(transition, "the event '" + event.trim() + "': KSE's engine raises no events (docs/semantics.md, rule 12), so the transition"
						+ " would never fire; a KSE transition fires when its condition on the robot's messages holds");
				return null;
			}
			// the state is done: KSE takes a composite's own transitions once its inside cannot move (its END reached)
			onEvent = true;
		}
		String condition = transition.attribute("cond");
		if (!blank(condition)) {
			String problem = conditionProblem(condition.trim());
			if (problem != null) {
				error(transition, "the condition '" + condition.trim() + "' is not a KSE condition (" + problem
						+ "); KSE's conditions read the robot's messages, as in [behavior.State.HeadToBMessage.ballfound()==1]");
				return null;
			}
		}
		executableContent(transition);
		Node targetNode = nodes.get(target);
		return targetNode == null ? null : new Candidate(transition, targetNode, blank(condition) ? null : condition.trim(), onEvent);
	}

	/**
	 * SCXML takes a state's first enabled eventless transition in document order, and its
	 * done.state transition only when none is; KSE tries the transitions with a condition
	 * first, the last created first, then those without in the order created. So the conditions
	 * are created in the reverse order, and a conditional transition behind one without a
	 * condition, which SCXML never takes, is left out.
	 */
	private void order(Node source, List<Candidate> eventless, List<Candidate> onEvent) {
		List<Candidate> byPriority = new ArrayList<>(eventless);
		byPriority.addAll(onEvent);
		List<Candidate> guarded = new ArrayList<>();
		List<Candidate> unguarded = new ArrayList<>();
		for (Candidate candidate : byPriority) {
			if (candidate.condition() == null) {
				unguarded.add(candidate);
			} else if (unguarded.isEmpty()) {
				guarded.add(candidate);
			} else {
				warning(candidate.element(), "left out: SCXML never takes it, as the transition without a condition before it ("
						+ unguarded.get(0).element().describe() + ") is always taken first");
			}
		}
		for (int i = guarded.size() - 1; i >= 0; i--) {
			transition(source, guarded.get(i).target(), "[" + guarded.get(i).condition() + "]", guarded.get(i).element());
		}
		for (Candidate candidate : unguarded) {
			transition(source, candidate.target(), null, candidate.element());
		}
	}

	private void executableContent(Element transition) {
		String content = transition.children.stream().filter(Element::isScxml).map(child -> "<" + child.name + ">").distinct()
				.collect(Collectors.joining(", "));
		if (!content.isEmpty()) {
			warning(transition, "its " + content + " left out: a KSE transition's actions are process_messages, publish_all, publish and"
					+ " TimeoutAction, written in its expression");
		}
	}

	/**
	 * Why a condition is not one of KSE's, or null when it is. KSE's grammar reads some
	 * ECMAScript too (a name, a call of a function): SCXML's In(), its system variables and the
	 * data model's variables are found first; then the grammar decides (and the validator, the
	 * topics, messages and fields it reads).
	 */
	private String conditionProblem(String condition) {
		Matcher names = IDENTIFIER.matcher(condition);
		while (names.find()) {
			String name = names.group();
			if (name.equals("In") && condition.substring(names.end()).stripLeading().startsWith("(")) {
				return "In() asks whether a state is active, which a KSE condition cannot";
			}
			if (SYSTEM_VARIABLES.contains(name)) {
				return "it reads SCXML's " + name + ", which KSE does not have";
			}
			if (dataIds.contains(name)) {
				return "it reads the data model's '" + name + "', which KSE does not have";
			}
		}
		// the grammar here, where the element's position is known; the messages it reads are the validator's
		for (Issue issue : expressions.parse("[" + condition + "]").issues()) {
			if (issue.getSeverity() == Severity.ERROR) {
				int line = issue.getLineNumber() == null ? 1 : issue.getLineNumber();
				int column = issue.getColumn() == null ? 1 : issue.getColumn();
				// the position within the condition, not within the bracketed expression
				return line + ":" + (line == 1 ? Math.max(column - 1, 1) : column) + ": " + issue.getMessage();
			}
		}
		return null;
	}

	private Node node(Element origin, NodeKind kind, String name) {
		Node node = node(kind, name);
		origins.put(node, origin);
		return node;
	}

	private Node node(NodeKind kind, String name) {
		Node node = FACTORY.createNode();
		node.setType(kind.name());
		node.setName(name);
		return node;
	}

	private void transition(Node source, Node target, String expression, Element origin) {
		transition(source, target, expression);
		origins.put(model.getTransitions().get(model.getTransitions().size() - 1), origin);
	}

	private void transition(Node source, Node target, String expression) {
		Transition transition = FACTORY.createTransition();
		transition.setSource(source);
		transition.setTarget(target);
		transition.setTE(expression);
		model.getTransitions().add(transition);
	}

	private void error(Element element, String message) {
		problems.add(ScxmlProblem.error(element.describe(), message));
	}

	private void warning(Element element, String message) {
		problems.add(ScxmlProblem.warning(element.describe(), message));
	}

	private static boolean blank(String text) {
		return text == null || text.isBlank();
	}
}
