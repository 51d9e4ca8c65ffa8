package org.kse.scxml;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

import org.kse.expression.ExpressionParser;
import org.kse.expression.transitionExpression.Action;
import org.kse.expression.transitionExpression.Publish;
import org.kse.expression.transitionExpression.TimeoutAction;
import org.kse.expression.transitionExpression.TransitionExpression;
import org.kse.messages.MessageCatalog;
import org.kse.messages.StandardMessages;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.scxml.ScxmlExportGuards.Guard;
import org.kse.scxml.ScxmlExportGuards.Unfaithful;

/**
 * A KSE statechart as a W3C SCXML document that an SCXML processor (ECMAScript data model) runs
 * with the transitions the Monas engine takes, in the same order (docs/semantics.md; the mapping
 * is docs/adr/0038-scxml-mapping.md). What has no faithful SCXML form is refused per element: the
 * result then has no document and one error per element.
 */
public final class ScxmlExport {

	public static final String SCXML_NAMESPACE = "http://www.w3.org/2005/07/scxml";
	public static final String KSE_NAMESPACE = "http://kse/scxml/1.0";

	/** The document ({@code null} when refused) and the problems, errors first by model order. */
	public record Result(String scxml, List<ScxmlProblem> problems) {
		public Result {
			problems = problems.stream().distinct().toList();
		}

		public boolean refused() {
			return scxml == null;
		}
	}

	public static Result export(Model model) {
		return export(model, StandardMessages.catalog());
	}

	/** With the catalog whose enums give the constants in guards their values. */
	public static Result export(Model model, MessageCatalog catalog) {
		return new ScxmlExport(model, catalog).run();
	}

	/** One KSE transition with what the export made of it. */
	private record Planned(Transition transition, int order, Guard guard, String actions, Node board) {
	}

	private final Model model;
	private final MessageCatalog catalog;
	private final List<ScxmlProblem> problems = new ArrayList<>();
	private final Map<Node, String> ids = new HashMap<>();
	private final Set<String> usedIds = new HashSet<>(Set.of("kse"));
	private final Map<Transition, Planned> planned = new LinkedHashMap<>();
	private final Map<Node, List<Transition>> leaving = new HashMap<>();
	private final Map<String, Set<String>> subscriptions = new LinkedHashMap<>();
	private final Set<List<String>> timers = new LinkedHashSet<>();
	private final StringBuilder out = new StringBuilder();
	private int chains;

	private ScxmlExport(Model model, MessageCatalog catalog) {
		this.model = model;
		this.catalog = catalog;
	}

	private Result run() {
		if (model.getNodes().size() != 1) {
			problems.add(ScxmlProblem.error(modelElement(), "the model has " + model.getNodes().size()
					+ " top-level states; a statechart has one root (an OR state)"));
			return new Result(null, problems);
		}
		Node root = model.getNodes().get(0);
		if (!NodeKind.OR.is(root)) {
			problems.add(ScxmlProblem.error(describe(root), "the root is " + root.getType() + "; it must be an OR state"));
			return new Result(null, problems);
		}
		if (!model.getVariables().isEmpty()) {
			model.getVariables().forEach(v -> problems.add(ScxmlProblem.error("variable '" + v.getName() + "'",
					"variables have no SCXML form in the export (and no meaning in the engine); remove them")));
		}
		checkNodes(root);
		planTransitions();
		checkAndStates(root);
		if (problems.stream().anyMatch(ScxmlProblem::isError)) {
			return new Result(null, problems);
		}
		assignIds(root);
		write(root);
		if (problems.stream().anyMatch(ScxmlProblem::isError)) {
			return new Result(null, problems);
		}
		return new Result(out.toString(), problems);
	}

	// ------------------------------------------------------------ checks and plan

	private void checkNodes(Node node) {
		NodeKind kind = NodeKind.of(node.getType());
		if (kind == null) {
			problems.add(ScxmlProblem.error(describe(node), "'" + node.getType() + "' is not a kind of state"));
			return;
		}
		if (!node.getVariables().isEmpty()) {
			problems.add(ScxmlProblem.error(describe(node), "its variables have no SCXML form in the export"));
		}
		if (kind == NodeKind.OR) {
			long starts = node.getChildren().stream().filter(NodeKind.START::is).count();
			if (starts != 1) {
				problems.add(ScxmlProblem.error(describe(node), "an OR state needs exactly one START to be entered at (it has " + starts + ")"));
			}
		}
		if (kind == NodeKind.AND) {
			for (Node child : node.getChildren()) {
				if (!NodeKind.OR.is(child)) {
					problems.add(ScxmlProblem.error(describe(child), "a child of an AND state must be an OR state (a region)"));
				}
			}
			if (node.getChildren().isEmpty()) {
				problems.add(ScxmlProblem.error(describe(node), "an AND state without regions has no SCXML form (<parallel> needs a child to be entered)"));
			}
		}
		if ((kind == NodeKind.BASIC || kind == NodeKind.START || kind == NodeKind.END || kind == NodeKind.CONDITION)
				&& !node.getChildren().isEmpty()) {
			problems.add(ScxmlProblem.error(describe(node), "a " + kind + " state with children has no SCXML form"));
		}
		for (Node child : node.getChildren()) {
			checkNodes(child);
		}
	}

	private void planTransitions() {
		ExpressionParser.Session expressions = ExpressionParser.session();
		List<Transition> all = model.getTransitions();
		for (int i = 0; i < all.size(); i++) {
			Transition t = all.get(i);
			if (t.getSource() == null || t.getTarget() == null) {
				problems.add(ScxmlProblem.error(describe(t), "the transition has no " + (t.getSource() == null ? "source" : "target")));
				continue;
			}
			if (NodeKind.START.is(t.getTarget())) {
				problems.add(ScxmlProblem.error(describe(t), "it enters a START state, which the engine refuses"));
				continue;
			}
			if (NodeKind.END.is(t.getSource())) {
				problems.add(ScxmlProblem.error(describe(t), "it leaves an END state, which never steps"));
				continue;
			}
			if (t.getSource().eContainer() instanceof Model || t.getTarget().eContainer() instanceof Model) {
				problems.add(ScxmlProblem.error(describe(t), "it leaves or enters the root, which the engine refuses"));
				continue;
			}
			ExpressionParser.Result parsed = expressions.parse(t.getTE());
			if (parsed.hasErrors()) {
				problems.add(ScxmlProblem.error(describe(t), "its expression '" + t.getTE() + "' does not parse: "
						+ parsed.issues().get(0).getMessage()));
				continue;
			}
			TransitionExpression te = parsed.expression();
			if (te != null && te.getEvent() != null) {
				problems.add(ScxmlProblem.error(describe(t), "the event '" + te.getEvent().getName()
						+ "' is never raised by the engine (rule 12), so the transition has no faithful SCXML form; remove the event"));
				continue;
			}
			Node board = region(lca(t.getSource(), t.getTarget()));
			Guard guard = null;
			String actions = "";
			try {
				if (te != null && te.getCondition() != null) {
					guard = ScxmlExportGuards.condition(te.getCondition(), catalog);
					for (ScxmlExportGuards.Read read : guard.reads()) {
						subscriptions.computeIfAbsent(board.getLabel(), k -> new LinkedHashSet<>()).add(read.topic());
					}
				}
				if (te != null) {
					actions = ScxmlExportGuards.actions(te.getActions(), board.getLabel());
					for (Action action : te.getActions()) {
						if (action instanceof TimeoutAction timeout) {
							timers.add(List.of(board.getLabel(), timeout.getTopic()));
						}
					}
				}
			} catch (Unfaithful e) {
				problems.add(ScxmlProblem.error(describe(t), e.getMessage()));
				continue;
			}
			planned.put(t, new Planned(t, i, guard, actions, board));
			leaving.computeIfAbsent(t.getSource(), k -> new ArrayList<>()).add(t);
		}
	}

	/**
	 * SCXML evaluates the transitions of an AND state and of the states around one once for each
	 * region that cannot move, and also while another region moves; the engine evaluates them
	 * once, and only when no region moved. The same for guards of a later region: SCXML evaluates
	 * them before an earlier region's action, the engine after. Refused where that shows.
	 */
	private void checkAndStates(Node node) {
		for (Node child : node.getChildren()) {
			checkAndStates(child);
		}
		if (!NodeKind.AND.is(node)) {
			return;
		}
		for (Node around = node; around != null; around = parent(around)) {
			for (Transition t : ordered(around)) {
				Planned p = planned.get(t);
				if (p != null && p.guard() != null && ScxmlExportGuards.hasSideEffects(p.guard())) {
					problems.add(ScxmlProblem.error(describe(t), "its guard changes a blackboard (a TimeoutCheck refreshes it, a Signal read consumes it) and it leaves "
							+ (around == node ? "an AND state" : "a state around the AND state " + describe(node))
							+ "; SCXML would evaluate it once per region and also while a region moves, the engine only when no region moves"));
				}
			}
		}
		List<Node> regions = node.getChildren();
		for (int l = 1; l < regions.size(); l++) {
			Node later = regions.get(l);
			for (Transition t : transitionsInside(later)) {
				Planned p = planned.get(t);
				if (p == null || p.guard() == null || !p.guard().checksTimeouts()) {
					continue;
				}
				Transition publisher = publisherSeenInTheSameStep(node, regions.subList(0, l), later, t);
				if (publisher != null) {
					problems.add(ScxmlProblem.error(describe(t), "its TimeoutCheck refreshes the blackboard of " + describe(later)
							+ " in a step where " + describe(publisher) + " in an earlier region of " + describe(node)
							+ " may publish on a topic that blackboard reads; SCXML evaluates the guard before that action runs, the engine after"));
				}
			}
		}
	}

	/**
	 * A transition of an earlier region whose publish can change what the TimeoutCheck guard of
	 * {@code guarded} reads or leaves refreshed, or {@code null}. SCXML runs the guard (read, then
	 * process its blackboard) before the publish, the engine after; that shows only when (a) the
	 * publish reaches the guard's blackboard, at once (the same blackboard) or through its inbox (a
	 * topic a guard of that blackboard reads: processed by the engine's refresh, by SCXML's next
	 * one, and read in between), and (b) both can happen in one step.
	 */
	private Transition publisherSeenInTheSameStep(Node and, List<Node> earlierRegions, Node later, Transition guarded) {
		String board = planned.get(guarded).board().getLabel();
		Set<String> read = subscriptions.getOrDefault(board, Set.of());
		for (Node earlier : earlierRegions) {
			for (Transition t : transitionsInside(earlier)) {
				boolean reaches = planned.get(t).board().getLabel().equals(board)
						? !publishedTopics(t).isEmpty()
						: publishedTopics(t).stream().anyMatch(read::contains);
				if (reaches && !(firesOnlyInTheFirstStep(t, earlier, and) && !triedInTheFirstStep(guarded, later))) {
					return t;
				}
			}
		}
		return null;
	}

	/** The topics the transition's actions publish on (a TimeoutAction publishes its TimeoutMsg). */
	private static Set<String> publishedTopics(Transition t) {
		ExpressionParser.Result parsed = ExpressionParser.parse(t.getTE());
		Set<String> topics = new LinkedHashSet<>();
		if (parsed.expression() != null) {
			for (Action action : parsed.expression().getActions()) {
				if (action instanceof Publish publish) {
					topics.add(publish.getTopic());
				} else if (action instanceof TimeoutAction timeout) {
					topics.add(timeout.getTopic());
				}
			}
		}
		return topics;
	}

	/**
	 * Whether {@code t} can fire only in the first step of {@code region} after {@code and} is
	 * entered: it leaves the region's START, which an unguarded transition to a state always
	 * leaves then (rule 4), and the region cannot still be running from an earlier entry (it has
	 * no activity of its own, or nothing leaves the AND state, so it is entered once).
	 */
	private boolean firesOnlyInTheFirstStep(Transition t, Node region, Node and) {
		Node start = t.getSource();
		if (!NodeKind.START.is(start) || parent(start) != region) {
			return false;
		}
		boolean alwaysLeft = leaving.getOrDefault(start, List.of()).stream()
				.anyMatch(s -> planned.get(s).guard() == null && !NodeKind.CONDITION.is(s.getTarget()));
		boolean neverRunning = !hasOwnActivity(region) || planned.keySet().stream().noneMatch(s -> leaves(s, and));
		return alwaysLeft && neverRunning;
	}

	/** Whether the transition may be tried in the region's first step: the region's START (and the connectors after it) or the region itself. */
	private static boolean triedInTheFirstStep(Transition t, Node region) {
		Node source = t.getSource();
		return source == region || NodeKind.CONDITION.is(source) || NodeKind.START.is(source) && parent(source) == region;
	}

	private static boolean hasOwnActivity(Node region) {
		return hasOwnActivity(region, region);
	}

	private static boolean hasOwnActivity(Node node, Node region) {
		for (Node child : node.getChildren()) {
			if (NodeKind.BASIC.is(child) || !isRegion(child) && hasOwnActivity(child, region)) {
				return true;
			}
		}
		return false;
	}

	/** Rule 6: whether firing the transition leaves {@code node} (it leaves an ancestor-or-self of the source below the lca). */
	private static boolean leaves(Transition t, Node node) {
		Node lca = lca(t.getSource(), t.getTarget());
		for (Node y = node; y != null; y = parent(y)) {
			if (y != lca && isInside(y, lca) && isInside(t.getSource(), y)) {
				return true;
			}
		}
		return false;
	}

	private List<Transition> transitionsInside(Node node) {
		List<Transition> result = new ArrayList<>();
		for (Transition t : planned.keySet()) {
			if (isInside(t.getSource(), node)) {
				result.add(t);
			}
		}
		return result;
	}

	// ------------------------------------------------------------ structure

	private static Node parent(Node node) {
		return node.eContainer() instanceof Node parent ? parent : null;
	}

	private static boolean isInside(Node node, Node ancestor) {
		for (Node n = node; n != null; n = parent(n)) {
			if (n == ancestor) {
				return true;
			}
		}
		return false;
	}

	private static boolean isRegion(Node node) {
		Node parent = parent(node);
		return parent == null || NodeKind.AND.is(parent);
	}

	/** The region a state belongs to: the nearest region around it (a region is its own). */
	private static Node region(Node node) {
		Node n = node;
		while (!isRegion(n)) {
			n = parent(n);
		}
		return n;
	}

	private static int depth(Node node) {
		int depth = 0;
		for (Node n = parent(node); n != null; n = parent(n)) {
			depth++;
		}
		return depth;
	}

	/** The engine's lowest common ancestor: of the two parents, then above any AND state. */
	private static Node lca(Node source, Node target) {
		Node a = parent(source);
		Node b = parent(target);
		while (depth(a) > depth(b)) {
			a = parent(a);
		}
		while (depth(b) > depth(a)) {
			b = parent(b);
		}
		while (a != b) {
			a = parent(a);
			b = parent(b);
		}
		while (NodeKind.AND.is(a)) {
			a = parent(a);
		}
		return a;
	}

	/** Rule 4: those with a condition first, the last created first; then the others in creation order. */
	private List<Transition> ordered(Node source) {
		List<Transition> all = leaving.getOrDefault(source, List.of());
		List<Transition> guarded = new ArrayList<>();
		List<Transition> unguarded = new ArrayList<>();
		for (Transition t : all) {
			(planned.get(t).guard() != null ? guarded : unguarded).add(t);
		}
		List<Transition> result = new ArrayList<>(guarded.reversed());
		result.addAll(unguarded);
		return result;
	}

	/** The regions whose running stops the state's own transitions (rule 2, rule 3). */
	private static List<String> blockingRegions(Node source) {
		List<String> labels = new ArrayList<>();
		if (NodeKind.AND.is(source)) {
			source.getChildren().forEach(region -> labels.add(region.getLabel()));
		}
		for (Node n = source; n != null; n = parent(n)) {
			if (isRegion(n)) {
				labels.add(n.getLabel());
			}
		}
		return labels;
	}

	// ------------------------------------------------------------ ids

	private void assignIds(Node node) {
		if (!NodeKind.CONDITION.is(node)) {
			String base = ncName(node.getName() == null || node.getName().isEmpty() ? node.getLabel() : node.getName());
			String id = base;
			for (int k = 2; !usedIds.add(id); k++) {
				id = base + "_" + k;
			}
			ids.put(node, id);
		}
		for (Node child : node.getChildren()) {
			assignIds(child);
		}
	}

	static String ncName(String text) {
		StringBuilder id = new StringBuilder();
		String source = text == null ? "" : text;
		for (int i = 0; i < source.length(); i++) {
			char c = source.charAt(i);
			boolean ok = c < 0x80 && (Character.isLetterOrDigit(c) || c == '.' || c == '-' || c == '_');
			id.append(ok ? c : '_');
		}
		if (id.isEmpty() || !(Character.isLetter(id.charAt(0)) || id.charAt(0) == '_')) {
			id.insert(0, "s_");
		}
		return id.toString();
	}

	// ------------------------------------------------------------ writing

	private void write(Node root) {
		out.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
		out.append("<!-- written by kse export-scxml: the mapping is KSE's docs/adr/0038-scxml-mapping.md -->\n");
		out.append("<scxml xmlns=\"").append(SCXML_NAMESPACE).append("\" xmlns:kse=\"").append(KSE_NAMESPACE)
				.append("\" version=\"1.0\" datamodel=\"ecmascript\" initial=\"kse\"");
		attribute("name", model.getName() == null ? "" : model.getName());
		out.append(" kse:export=\"1\">\n");
		out.append("  <datamodel>\n");
		out.append("    <data id=\"kse_in\" expr=\"''\"/>\n");
		out.append("    <data id=\"kse_done\" expr=\"0\"/>\n");
		out.append("  </datamodel>\n");
		StringBuilder script = new StringBuilder(ScxmlExportRuntime.SCRIPT);
		script.append("kse.subscriptions = {");
		script.append(subscriptions.entrySet().stream()
				.map(e -> ScxmlExportGuards.quote(e.getKey()) + ": ["
						+ e.getValue().stream().map(ScxmlExportGuards::quote).collect(Collectors.joining(", ")) + "]")
				.collect(Collectors.joining(", ")));
		script.append("};\nkse.timers = [");
		script.append(timers.stream().map(t -> "[" + ScxmlExportGuards.quote(t.get(0)) + ", " + ScxmlExportGuards.quote(t.get(1)) + "]")
				.collect(Collectors.joining(", ")));
		script.append("];\n");
		out.append("  <script>").append(text(script.toString())).append("  </script>\n");
		out.append("  <state id=\"kse\">\n");
		out.append("    <onentry><script>kse.start();</script><log label=\"kse.out\" expr=\"kse.flush()\"/></onentry>\n");
		out.append("    <transition event=\"done.activity\"><log label=\"kse.event\" expr=\"_event.name\"/>"
				+ "<script>kse.activityDone(_event.name.substring(14));</script></transition>\n");
		out.append("    <transition event=\"kse.wake\"><log label=\"kse.event\" expr=\"_event.name\"/></transition>\n");
		writeNode(root, "    ");
		out.append("  </state>\n");
		out.append("</scxml>\n");
	}

	private void writeNode(Node node, String indent) {
		NodeKind kind = NodeKind.of(node.getType());
		if (kind == NodeKind.CONDITION) {
			writeConnector(node, indent);
			return;
		}
		String element = switch (kind) {
			case AND -> "parallel";
			case END -> "final";
			default -> "state";
		};
		out.append(indent).append('<').append(element);
		attribute("id", ids.get(node));
		if (kind == NodeKind.OR) {
			node.getChildren().stream().filter(NodeKind.START::is).findFirst().ifPresent(start -> attribute("initial", ids.get(start)));
		}
		kseAttributes(node, kind.name());
		if (kind == NodeKind.BASIC && node.getActivity() != null) {
			attribute("kse:activity", node.getActivity());
		}
		out.append(">\n");
		String inner = indent + "  ";
		out.append(inner).append("<onentry><log label=\"kse.enter\" expr=\"").append(attr(ScxmlExportGuards.quote(node.getLabel() == null ? "" : node.getLabel())))
				.append("\"/>");
		if (kind == NodeKind.BASIC) {
			out.append("<script>").append(text("kse.enterBasic(" + ScxmlExportGuards.quote(region(node).getLabel()) + ", "
					+ ScxmlExportGuards.quote(activityName(node)) + ", " + ScxmlExportGuards.quote(node.getLabel()) + ");"))
					.append("</script><log label=\"kse.out\" expr=\"kse.flush()\"/>");
		}
		out.append("</onentry>\n");
		if (kind != NodeKind.END) {
			for (Transition t : ordered(node)) {
				writeTransition(node, t, inner);
			}
		}
		for (Node child : node.getChildren()) {
			writeNode(child, inner);
		}
		out.append(indent).append("</").append(element).append(">\n");
	}

	/** The engine's name of a BASIC state's activity: its name as a C++ identifier (GenerationPlan). */
	static String activityName(Node node) {
		String name = node.getName() == null ? "Activity_" + node.getLabel().replace('.', '_') : node.getName();
		StringBuilder id = new StringBuilder();
		for (char c : name.toCharArray()) {
			if (c < 0x80 && (Character.isLetterOrDigit(c) || c == '_')) {
				id.append(c);
			}
		}
		if (id.isEmpty() || Character.isDigit(id.charAt(0))) {
			id.insert(0, '_');
		}
		return id.toString();
	}

	private void writeConnector(Node connector, String indent) {
		out.append(indent).append("<kse:connector");
		attribute("kse:label", connector.getLabel());
		attribute("kse:name", connector.getName());
		out.append(">\n");
		for (Transition t : leaving.getOrDefault(connector, List.of())) {
			out.append(indent).append("  <kse:transition");
			attribute("kse:name", t.getName());
			attribute("kse:order", Integer.toString(planned.get(t).order()));
			attribute("kse:target", t.getTarget().getLabel());
			attribute("kse:expression", t.getTE());
			out.append("/>\n");
		}
		out.append(indent).append("</kse:connector>\n");
	}

	/** One KSE transition leaving a state: one SCXML transition, or one per complete path of its connector chain. */
	private void writeTransition(Node source, Transition t, String indent) {
		Planned first = planned.get(t);
		String idle = "kse.idle([" + blockingRegions(source).stream().map(ScxmlExportGuards::quote).collect(Collectors.joining(",")) + "])";
		if (!NodeKind.CONDITION.is(t.getTarget())) {
			String cond = first.guard() == null ? idle : idle + " && " + first.guard().js(first.board().getLabel());
			writeScxmlTransition(t, List.of(t), cond, null, indent);
			return;
		}
		List<List<Transition>> paths = new ArrayList<>();
		try {
			collectPaths(new ArrayList<>(List.of(t)), paths);
		} catch (Unfaithful e) {
			problems.add(ScxmlProblem.error(describe(t), e.getMessage()));
			return;
		}
		if (paths.isEmpty()) {
			writeScxmlTransitionDead(t, indent);
			return;
		}
		String chain = "c" + chains++;
		StringBuilder decide = new StringBuilder("function(){");
		decideTree(List.of(t), paths, 0, decide);
		decide.append("return -1;}");
		for (int k = 0; k < paths.size(); k++) {
			String cond = k == 0 ? idle + " && kse.choose('" + chain + "'," + decide + ") == 0" : idle + " && kse.chosen['" + chain + "'] == " + k;
			List<Transition> path = paths.get(k);
			String labels = path.subList(0, path.size() - 1).stream().map(s -> s.getTarget().getLabel()).collect(Collectors.joining(" "));
			writeScxmlTransition(t, path, cond, labels, indent);
		}
	}

	/** Every complete path from {@code prefix} (whose last segment enters a connector) to a state, in the engine's order. */
	private void collectPaths(List<Transition> prefix, List<List<Transition>> paths) throws Unfaithful {
		Transition last = prefix.get(prefix.size() - 1);
		Node connector = last.getTarget();
		if (!NodeKind.CONDITION.is(connector)) {
			checkChainLevels(prefix);
			paths.add(List.copyOf(prefix));
			return;
		}
		for (Transition next : ordered(connector)) {
			if (prefix.stream().anyMatch(s -> s.getSource() == next.getTarget() || s.getTarget() == next.getTarget() && NodeKind.CONDITION.is(next.getTarget()))) {
				throw new Unfaithful("its connector chain goes round a loop of connectors (" + describe(next) + "), which has no SCXML form");
			}
			prefix.add(next);
			collectPaths(prefix, paths);
			prefix.remove(prefix.size() - 1);
		}
	}

	/** The chain fires as one SCXML transition from the first source to the last target: faithful only when every segment leaves and enters at one level. */
	private void checkChainLevels(List<Transition> path) throws Unfaithful {
		Node first = path.get(0).getSource();
		Node last = path.get(path.size() - 1).getTarget();
		Node level = lca(first, last);
		for (Transition segment : path) {
			if (lca(segment.getSource(), segment.getTarget()) != level) {
				throw new Unfaithful("its connector chain passes " + describe(segment) + " at another level than the chain's ends "
						+ describe(first) + " and " + describe(last) + "; the engine leaves and enters the states between, one SCXML transition cannot");
			}
		}
	}

	/** The engine's evaluation of a chain (rule 5): each segment's guard once, depth first, the first complete path wins. */
	private void decideTree(List<Transition> prefix, List<List<Transition>> paths, int depth, StringBuilder js) {
		Transition segment = prefix.get(prefix.size() - 1);
		Planned p = planned.get(segment);
		String guard = p.guard() == null ? "true" : p.guard().js(p.board().getLabel());
		js.append("if(").append(guard).append("){");
		if (!NodeKind.CONDITION.is(segment.getTarget())) {
			for (int k = 0; k < paths.size(); k++) {
				if (paths.get(k).equals(prefix)) {
					js.append("return ").append(k).append(';');
				}
			}
		} else {
			for (Transition next : ordered(segment.getTarget())) {
				List<Transition> longer = new ArrayList<>(prefix);
				longer.add(next);
				if (paths.stream().anyMatch(path -> path.size() >= longer.size() && path.subList(0, longer.size()).equals(longer))) {
					decideTree(longer, paths, depth + 1, js);
				}
			}
		}
		js.append('}');
	}

	private void writeScxmlTransition(Transition t, List<Transition> path, String cond, String chain, String indent) {
		Planned first = planned.get(t);
		Node target = path.get(path.size() - 1).getTarget();
		out.append(indent).append("<transition");
		attribute("target", ids.get(target));
		attribute("cond", cond);
		attribute("kse:name", t.getName());
		attribute("kse:order", Integer.toString(first.order()));
		if (chain != null) {
			attribute("kse:chain", chain);
		}
		attribute("kse:expression", t.getTE());
		out.append(">\n");
		String taken = t.getSource().getLabel() + " -> "
				+ path.stream().map(s -> s.getTarget().getLabel()).collect(Collectors.joining(" -> "));
		out.append(indent).append("  <log label=\"kse.taken\" expr=\"").append(attr(ScxmlExportGuards.quote(taken))).append("\"/>\n");
		StringBuilder actions = new StringBuilder();
		for (Transition segment : path) {
			actions.append(planned.get(segment).actions());
		}
		if (!actions.isEmpty()) {
			out.append(indent).append("  <script>").append(text(actions.toString())).append("</script>\n");
			out.append(indent).append("  <log label=\"kse.out\" expr=\"kse.flush()\"/>\n");
		}
		out.append(indent).append("</transition>\n");
	}

	private void writeScxmlTransitionDead(Transition t, String indent) {
		out.append(indent).append("<transition");
		attribute("target", ids.get(t.getSource()));
		attribute("cond", "false");
		attribute("kse:name", t.getName());
		attribute("kse:order", Integer.toString(planned.get(t).order()));
		attribute("kse:chain", t.getTarget().getLabel());
		attribute("kse:expression", t.getTE());
		out.append("/>\n");
	}

	private void kseAttributes(Node node, String type) {
		attribute("kse:type", type);
		attribute("kse:label", node.getLabel());
		attribute("kse:name", node.getName());
	}

	private void attribute(String name, String value) {
		if (value != null) {
			out.append(' ').append(name).append("=\"").append(attr(value)).append('"');
		}
	}

	private static String attr(String value) {
		StringBuilder escaped = new StringBuilder();
		for (char c : value.toCharArray()) {
			switch (c) {
				case '&' -> escaped.append("&amp;");
				case '<' -> escaped.append("&lt;");
				case '>' -> escaped.append("&gt;");
				case '"' -> escaped.append("&quot;");
				case '\n' -> escaped.append("&#10;");
				case '\r' -> escaped.append("&#13;");
				case '\t' -> escaped.append("&#9;");
				default -> escaped.append(c);
			}
		}
		return escaped.toString();
	}

	private static String text(String value) {
		return value.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
	}

	// ------------------------------------------------------------ names of elements in problems

	private String modelElement() {
		return "model '" + (model.getName() == null ? "" : model.getName()) + "'";
	}

	/** {@code label 'name'}, as the brief of every problem names a state. */
	static String describe(Node node) {
		return (node.getLabel() == null ? "(no label)" : node.getLabel()) + " '" + (node.getName() == null ? "" : node.getName()) + "'";
	}

	/** {@code source->target 'name'}. */
	static String describe(Transition t) {
		String source = t.getSource() == null ? "?" : t.getSource().getLabel();
		String target = t.getTarget() == null ? "?" : t.getTarget().getLabel();
		return source + "->" + target + " '" + (t.getName() == null ? "" : t.getName()) + "'";
	}
}
