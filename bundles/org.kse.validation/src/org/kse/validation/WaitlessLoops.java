package org.kse.validation;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.kse.expression.ExpressionParser;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/**
 * Loops the engine can go round without waiting for a message or a timer (docs/semantics.md):
 * cycles of transitions without a condition, followed through what entering a composite
 * starts (its START; every region of an AND) and through an END, which leaves the decision to
 * its composite's own transitions. A loop through a BASIC state waits only for the run of its
 * activity, so on a robot it runs the activity again as fast as it returns; a loop through no
 * BASIC state never waits at all.
 *
 * Linear in the size of the model (one strongly connected components pass, without recursion,
 * so that a deep or long model cannot overflow the stack).
 */
final class WaitlessLoops {

	/**
	 * A loop: its states in the order it goes round them (the first again at the end), the first
	 * transition on it without a condition (where a guard would go), and whether a BASIC state
	 * is on it.
	 */
	record Loop(List<Node> states, Transition transition, boolean runsActivities) {
	}

	private final List<Node> nodes = new ArrayList<>();
	private final Map<Node, Integer> index = new HashMap<>();
	private final Map<Transition, Integer> transitionOrder = new HashMap<>();
	// Graph vertices: 2i is "node i entered", 2i+1 "node i's own transitions tried" (the same
	// moment for a state that is not composite, so that vertex has no edges of its own).
	private int[][] edges;
	private Transition[][] edgeTransitions;
	private int[] edgeCount;

	private WaitlessLoops() {
	}

	static List<Loop> find(Model model, ExpressionParser.Session session) {
		WaitlessLoops graph = new WaitlessLoops();
		for (var it = model.eAllContents(); it.hasNext();) {
			if (it.next() instanceof Node node) {
				graph.index.put(node, graph.nodes.size());
				graph.nodes.add(node);
			}
		}
		graph.build(model, session);
		return graph.loops();
	}

	private int entered(Node node) {
		return 2 * index.get(node);
	}

	private int ownTransitions(Node node) {
		NodeKind kind = NodeKind.of(node);
		return kind != null && kind.isComposite() ? 2 * index.get(node) + 1 : entered(node);
	}

	private void build(Model model, ExpressionParser.Session session) {
		int vertices = 2 * nodes.size();
		edges = new int[vertices][];
		edgeTransitions = new Transition[vertices][];
		edgeCount = new int[vertices];
		for (Node node : nodes) {
			NodeKind kind = NodeKind.of(node);
			if (kind == NodeKind.OR) {
				for (Node child : node.getChildren()) {
					if (NodeKind.START.is(child)) {
						edge(entered(node), entered(child), null);
					} else if (NodeKind.END.is(child)) {
						edge(entered(child), ownTransitions(node), null);
					}
				}
				if (node.getFather_of() != null && NodeKind.AND.is(node.getFather_of())) {
					// a region whose inside cannot move leaves the decision to its AND state
					edge(ownTransitions(node), ownTransitions(node.getFather_of()), null);
				}
			} else if (kind == NodeKind.AND) {
				for (Node region : node.getChildren()) {
					if (NodeKind.OR.is(region)) {
						edge(entered(node), entered(region), null);
					}
				}
			}
		}
		for (Transition transition : model.getTransitions()) {
			transitionOrder.put(transition, transitionOrder.size());
			Node source = transition.getSource();
			Node target = transition.getTarget();
			if (source == null || target == null || !index.containsKey(source) || !index.containsKey(target) || NodeKind.END.is(source)
					|| NodeKind.START.is(target)) {
				continue;  // an END never steps; into START is an error of its own
			}
			if (waitsForNothing(transition.getTE(), session)) {
				edge(ownTransitions(source), entered(target), transition);
			}
		}
	}

	/** Without an event and a condition: it fires whenever its source is asked. */
	private static boolean waitsForNothing(String expression, ExpressionParser.Session session) {
		if (expression == null || expression.isBlank()) {
			return true;
		}
		ExpressionParser.Result parsed = session.parse(expression);
		return parsed.expression() != null && !parsed.hasErrors() && parsed.expression().getEvent() == null
				&& parsed.expression().getCondition() == null;
	}

	private void edge(int from, int to, Transition transition) {
		if (edges[from] == null) {
			edges[from] = new int[2];
			edgeTransitions[from] = new Transition[2];
		} else if (edgeCount[from] == edges[from].length) {
			edges[from] = Arrays.copyOf(edges[from], edgeCount[from] * 2);
			edgeTransitions[from] = Arrays.copyOf(edgeTransitions[from], edgeCount[from] * 2);
		}
		edges[from][edgeCount[from]] = to;
		edgeTransitions[from][edgeCount[from]++] = transition;
	}

	/** Where a guard goes: not on a START's transition if it can be helped, else the first in model order. */
	private boolean better(Transition candidate, Transition best) {
		boolean fromStart = NodeKind.START.is(candidate.getSource());
		boolean bestFromStart = NodeKind.START.is(best.getSource());
		if (fromStart != bestFromStart) {
			return bestFromStart;
		}
		return transitionOrder.get(candidate) < transitionOrder.get(best);
	}

	/** Tarjan's strongly connected components, iteratively; one loop described per component. */
	private List<Loop> loops() {
		int vertices = edges.length;
		int[] order = new int[vertices];
		int[] low = new int[vertices];
		int[] component = new int[vertices];
		Arrays.fill(order, -1);
		Arrays.fill(component, -1);
		boolean[] onStack = new boolean[vertices];
		int[] stack = new int[vertices];
		int stackSize = 0;
		int[] callVertex = new int[vertices];
		int[] callEdge = new int[vertices];
		int counter = 0;
		int components = 0;
		List<Loop> loops = new ArrayList<>();
		for (int root = 0; root < vertices; root++) {
			if (order[root] != -1) {
				continue;
			}
			int depth = 0;
			callVertex[0] = root;
			callEdge[0] = 0;
			order[root] = low[root] = counter++;
			stack[stackSize++] = root;
			onStack[root] = true;
			while (depth >= 0) {
				int v = callVertex[depth];
				if (callEdge[depth] < edgeCount[v]) {
					int w = edges[v][callEdge[depth]++];
					if (order[w] == -1) {
						order[w] = low[w] = counter++;
						stack[stackSize++] = w;
						onStack[w] = true;
						depth++;
						callVertex[depth] = w;
						callEdge[depth] = 0;
					} else if (onStack[w]) {
						low[v] = Math.min(low[v], order[w]);
					}
					continue;
				}
				if (low[v] == order[v]) {
					List<Integer> members = new ArrayList<>();
					int w;
					do {
						w = stack[--stackSize];
						onStack[w] = false;
						component[w] = components;
						members.add(w);
					} while (w != v);
					if (members.size() > 1 || hasEdge(v, v)) {
						loops.add(describe(members, component, components));
					}
					components++;
				}
				depth--;
				if (depth >= 0) {
					int parent = callVertex[depth];
					low[parent] = Math.min(low[parent], low[v]);
				}
			}
		}
		loops.sort((a, b) -> Integer.compare(index.get(a.states().get(0)), index.get(b.states().get(0))));
		return loops;
	}

	private boolean hasEdge(int from, int to) {
		for (int i = 0; i < edgeCount[from]; i++) {
			if (edges[from][i] == to) {
				return true;
			}
		}
		return false;
	}

	/**
	 * One way round the component: from the source of the transition a guard would go on, the
	 * shortest path back inside the component.
	 */
	private Loop describe(List<Integer> members, int[] component, int id) {
		int start = members.get(0);
		Transition first = null;
		for (int v : members) {
			for (int i = 0; i < edgeCount[v]; i++) {
				Transition transition = edgeTransitions[v][i];
				if (transition != null && component[edges[v][i]] == id && (first == null || better(transition, first))) {
					first = transition;
					start = v;
				}
			}
		}
		// along that transition, then breadth first back to start inside the component
		int next = start;
		for (int i = 0; i < edgeCount[start]; i++) {
			if (edgeTransitions[start][i] == first) {
				next = edges[start][i];
			}
		}
		Map<Integer, Integer> previous = new HashMap<>();
		previous.put(next, -1);
		ArrayDeque<Integer> queue = new ArrayDeque<>();
		queue.add(next);
		while (!queue.isEmpty() && !previous.containsKey(start)) {
			int v = queue.poll();
			for (int i = 0; i < edgeCount[v]; i++) {
				int w = edges[v][i];
				if (component[w] == id && !previous.containsKey(w)) {
					previous.put(w, v);
					queue.add(w);
				}
			}
		}
		List<Integer> path = new ArrayList<>();
		for (int v = start; v >= 0; v = previous.getOrDefault(v, -1)) {
			path.add(v);
			if (v == next) {
				break;
			}
		}
		path.add(start);
		Collections.reverse(path);
		List<Node> states = new ArrayList<>();
		boolean basic = false;
		for (int v : path) {
			Node node = nodes.get(v / 2);
			basic |= NodeKind.BASIC.is(node);
			states.add(node);
		}
		return new Loop(states, first, basic);
	}
}
