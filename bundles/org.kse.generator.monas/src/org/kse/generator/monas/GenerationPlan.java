package org.kse.generator.monas;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

import org.eclipse.emf.common.util.TreeIterator;
import org.eclipse.emf.ecore.EObject;
import org.kse.expression.ExpressionParser;
import org.kse.expression.transitionExpression.Action;
import org.kse.expression.transitionExpression.Condition;
import org.kse.expression.transitionExpression.TransitionExpression;
import org.kse.messages.MessageCatalog;
import org.kse.messages.StandardMessages;
import org.kse.model.NodeKind;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.validation.Labels;

/**
 * Every name the generated code uses, decided once per model so that the templates
 * stay simple and the output is deterministic: the statechart class, one variable per
 * state, the activity of each BASIC state, and the classes of each transition.
 */
public final class GenerationPlan {

	/** A transition with its parsed expression and the C++ classes that carry it. */
	public record PlannedTransition(String name, Node source, Node target, String expression, Condition condition,
			List<Action> action, String conditionClass, String actionClass, String namespace) {
	}

	private final String modelName;
	private final String className;
	private final Node root;
	private final List<Node> nodes = new ArrayList<>();
	private final Map<Node, String> variables = new HashMap<>();
	private final Map<String, Node> activities = new LinkedHashMap<>();
	private final List<PlannedTransition> transitions = new ArrayList<>();
	private final List<String> problems = new ArrayList<>();

	private final MessageCatalog catalog;
	private final TreeMessages tree;

	private GenerationPlan(Model model, MessageCatalog catalog, TreeMessages tree, ExpressionParser.Session expressions) {
		this.catalog = catalog;
		this.tree = tree;
		this.modelName = model.getName() == null ? model.getNodes().get(0).getName() : model.getName();
		this.className = CppNames.identifier(modelName);
		this.root = model.getNodes().get(0);
		checkFileName("model (" + modelName + ")", className);
		Set<String> used = new HashSet<>();
		Map<String, Node> activityByFolder = new HashMap<>();
		add(root, used, activityByFolder);
		for (TreeIterator<EObject> it = root.eAllContents(); it.hasNext();) {
			if (it.next() instanceof Node node) {
				add(node, used, activityByFolder);
			}
		}
		String namespace = "kse_statechart_" + className;
		// Keys in lower case: two class files that differ only in case are one file on Windows and macOS.
		Set<String> classes = new HashSet<>();
		for (Transition transition : model.getTransitions()) {
			String te = transition.getTE();
			ExpressionParser.Result parsed = expressions.parse(te);
			TransitionExpression expression = parsed.expression();
			Condition condition = expression == null ? null : expression.getCondition();
			List<Action> actions = expression == null || expression.getActions().isEmpty() ? null : List.copyOf(expression.getActions());
			String base = CppNames.shortened(CppNames.label(transition.getSource().getLabel()) + "_TO_" + CppNames.label(transition.getTarget().getLabel()));
			String unique = base;
			for (int k = 2; !classes.add(unique.toLowerCase(Locale.ROOT)); k++) {
				unique = base + "_" + k;
			}
			transitions.add(new PlannedTransition(transition.getName() == null ? unique : transition.getName(), transition.getSource(),
					transition.getTarget(), te, condition, actions, "TrCond_" + unique, "TrAction_" + unique, namespace));
		}
	}

	private void add(Node node, Set<String> used, Map<String, Node> activityByFolder) {
		nodes.add(node);
		String base = "Node_" + CppNames.label(node.getLabel());
		String variable = base;
		for (int k = 2; !used.add(variable); k++) {
			variable = base + "_" + k;
		}
		variables.put(node, variable);
		if (NodeKind.BASIC.is(node)) {
			String activity = activityName(node);
			Node first = activities.putIfAbsent(activity, node);
			if (first != null) {
				if (!Objects.equals(first.getName(), node.getName())) {
					problems.add(Labels.describe(node) + ": its activity and that of " + Labels.describe(first) + " both become the C++ class '"
							+ activity + "' (only letters, digits and '_' are kept); rename one of them");
				}
				return;
			}
			Node sameFolder = activityByFolder.putIfAbsent(activity.toLowerCase(Locale.ROOT), node);
			if (sameFolder != null) {
				problems.add(Labels.describe(node) + ": its activity '" + activity + "' and '" + activityName(sameFolder) + "' of "
						+ Labels.describe(sameFolder) + " differ only in case, so their folders under activities/ are one folder on Windows and macOS; rename one of them");
			} else if (activity.equals(className)) {
				problems.add(Labels.describe(node) + ": its activity '" + activity + "' has the name of the statechart's C++ class; rename the activity or the model");
			}
			checkFileName(Labels.describe(node), activity);
		}
	}

	/** A name that becomes a file name must leave room for the longest suffix KSE adds (".cpp", and an atomic write's temporary name). */
	private void checkFileName(String element, String name) {
		if (name.length() > CppNames.MAX_NAME_LENGTH) {
			problems.add(element + ": the name is " + name.length() + " characters long; KSE's limit is " + CppNames.MAX_NAME_LENGTH
					+ " because it becomes a file name");
		}
	}

	/**
	 * What makes the model impossible to generate although it validates: names that become the same
	 * C++ name or the same file on a case-insensitive disk, names too long for a file. Each names
	 * the elements involved, worded like a validation diagnostic.
	 */
	public List<String> problems() {
		return List.copyOf(problems);
	}

	public static GenerationPlan of(Model model) {
		return of(model, StandardMessages.catalog(), TreeMessages.NONE);
	}

	public static GenerationPlan of(Model model, MessageCatalog catalog, TreeMessages tree) {
		return of(model, catalog, tree, ExpressionParser.session());
	}

	/**
	 * With the session the model was validated with, so that each expression is parsed once
	 * per run; the conditions and actions planned are that session's, shared by the
	 * transitions of one text (the templates only read them).
	 */
	public static GenerationPlan of(Model model, MessageCatalog catalog, TreeMessages tree, ExpressionParser.Session expressions) {
		return new GenerationPlan(model, catalog, tree, expressions);
	}

	/** The source tree's own .proto files, as the generated CMake builds them. */
	public TreeMessages tree() {
		return tree;
	}

	/**
	 * Headers of the user's message types among {@code messages}: {@code <File>.pb.h} of
	 * each type not in the standard set (the standard set comes with kse/messages/all.h). A
	 * standard type that the tree defines again is the runtime's in C++ (see {@link TreeMessages}).
	 */
	public List<String> userHeaders(java.util.Collection<String> messages) {
		java.util.TreeSet<String> headers = new java.util.TreeSet<>();
		for (String message : messages) {
			catalog.message(message).filter(type -> !tree.replaced().contains(type.fullName())).ifPresent(type -> {
				String file = type.file() == null ? "" : type.file().toString().replace('\\', '/');
				if (!StandardMessages.isStandard(type.file()) && file.endsWith(".proto")) {
					headers.add(file.substring(0, file.length() - ".proto".length()) + ".pb.h");
				}
			});
		}
		return List.copyOf(headers);
	}

	public String modelName() {
		return modelName;
	}

	public String className() {
		return className;
	}

	public Node root() {
		return root;
	}

	/** Every state, parents before children (label order for a labeled model). */
	public List<Node> nodes() {
		return nodes;
	}

	public List<PlannedTransition> transitions() {
		return transitions;
	}

	public String variable(Node node) {
		return variables.get(node);
	}

	/** The engine's name of a state, as the original generator wrote it: Node_ and the name, or the label with '_' for dots. */
	public String stateName(Node node) {
		String name = node.getName();
		boolean namedByLabel = name == null || name.isEmpty() || name.equals(node.getLabel());
		return "Node_" + (namedByLabel ? CppNames.label(node.getLabel()) : name);
	}

	/** The activity a BASIC state runs: its name as a C++ identifier. */
	public String activityName(Node node) {
		return CppNames.identifier(node.getName() == null ? "Activity_" + CppNames.label(node.getLabel()) : node.getName());
	}

	/** Activity name → the first BASIC state that runs it. */
	public Map<String, Node> activities() {
		return activities;
	}
}
