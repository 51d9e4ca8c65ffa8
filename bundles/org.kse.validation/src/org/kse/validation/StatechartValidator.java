package org.kse.validation;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;

import org.eclipse.emf.common.util.BasicDiagnostic;
import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.common.util.DiagnosticChain;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EDataType;
import org.eclipse.emf.ecore.EValidator;
import org.eclipse.emf.ecore.InternalEObject;
import org.eclipse.xtext.validation.Issue;
import org.kse.expression.ExpressionParser;
import org.kse.messages.MessageCatalog;
import org.kse.messages.StandardMessages;
import org.kse.model.NodeKind;
import org.kse.model.StatechartRules;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartPackage;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;

/**
 * The statechart rules of the original tool (docs/original-kse.md §5) as an EMF validator, so
 * that the headless tools and the editors report the same diagnostics. Each
 * diagnostic's data holds the offending element first; a transition-expression
 * problem also holds its {@link Issue}, whose offset counts inside the expression.
 */
public class StatechartValidator implements EValidator {

	public static final String DIAGNOSTIC_SOURCE = "org.kse.validation";

	public static final int ROOT = 1;
	public static final int AND_CHILDREN = 2;
	public static final int START_COUNT = 3;
	public static final int END_COUNT = 4;
	public static final int START_TARGET = 5;
	public static final int END_SOURCE = 6;
	public static final int SAME_PARENT = 7;
	public static final int EXPRESSION = 8;
	public static final int VARIABLE_NAME = 9;
	public static final int VARIABLE_TYPE = 10;
	public static final int NODE_TYPE = 11;
	public static final int DANGLING = 12;
	public static final int LEAF_CHILDREN = 13;
	public static final int DUPLICATE_LABEL = 14;
	public static final int MESSAGE = 15;
	public static final int EVENT = 16;
	public static final int DEPTH = 17;
	public static final int WAITLESS_LOOP = 18;

	/** KSE's limit on nesting, far above any behaviour (the Goalie nests 7 levels): the engine and the generated code recurse over it. */
	public static final int MAX_DEPTH = 1_000;

	/** Context key: the {@link MessageCatalog} to check messages against (the standard one when absent). */
	public static final Object CATALOG = MessageCatalog.class;
	/** Context key: the list of known topics (the standard Monas topics when absent). */
	public static final Object TOPICS = "org.kse.validation.topics";
	/**
	 * Context key: the {@link ExpressionParser.Session} that parses the transition expressions, so
	 * that whoever validates can reuse its parses (the generator does); one per validation when absent.
	 */
	public static final Object EXPRESSIONS = ExpressionParser.Session.class;

	private static final Pattern IDENTIFIER = Pattern.compile("[A-Za-z_]\\w*");
	private static final Pattern MESSAGE_TYPE = Pattern.compile("[A-Za-z_]\\w*\\.(Signal|State|Data)\\.[A-Za-z_]\\w*");

	@Override
	public boolean validate(EObject object, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return validate(object.eClass(), object, diagnostics, context);
	}

	@Override
	public boolean validate(EClass eClass, EObject object, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (diagnostics == null) {
			return true;
		}
		if (object instanceof Model model) {
			validateModel(model, diagnostics, context);
		} else if (object instanceof Node node) {
			validateNode(node, diagnostics, context);
		} else if (object instanceof Transition transition) {
			validateTransition(transition, diagnostics, context);
		} else if (object instanceof Variable variable) {
			validateVariable(variable, diagnostics, context);
		}
		return true;
	}

	private void validateModel(Model model, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (model.getNodes().size() != 1) {
			error(diagnostics, ROOT, model, "the model needs exactly one root state; it has " + model.getNodes().size());
		}
		if (!model.getNodes().isEmpty()) {
			String refusal = StatechartRules.rootRefusal(model.getNodes().get(0).getType());
			if (refusal != null) {
				error(diagnostics, ROOT, model.getNodes().get(0), refusal);
			}
		}
		for (var it = model.eAllContents(); it.hasNext();) {
			if (it.next() instanceof Node node && node.getChildren().isEmpty()) {
				int depth = 0;
				for (EObject level = node; level instanceof Node; level = level.eContainer()) {
					depth++;
				}
				if (depth > MAX_DEPTH) {
					error(diagnostics, DEPTH, node, "the state is nested " + depth + " levels deep; KSE's limit is " + MAX_DEPTH);
					return;
				}
			}
		}
		ExpressionParser.Session session = expressions(context);
		for (WaitlessLoops.Loop loop : WaitlessLoops.find(model, session == null ? ExpressionParser.session() : session)) {
			warning(diagnostics, WAITLESS_LOOP, loop.transition(), waitlessLoopMessage(loop));
		}
	}

	private static String waitlessLoopMessage(WaitlessLoops.Loop loop) {
		StringBuilder states = new StringBuilder();
		for (Node node : loop.states()) {
			states.append(states.isEmpty() ? "" : " -> ").append(Labels.describe(node));
		}
		if (!loop.runsActivities()) {
			return "the loop " + states + " runs no activity and waits for no message or timer: the engine goes round it without end"
					+ " (the simulator stops the robot); give one of its transitions a condition";
		}
		return "the loop " + states + " waits only for its activities' runs: on a robot it runs them again as soon as they return,"
				+ " in the simulator once per decision cycle. To poll, wait for a timer: give one of its transitions"
				+ " [TimeoutCheck(behavior)]/TimeoutAction.behavior.250, the transition into the loop /TimeoutAction.behavior.250,"
				+ " and the unguarded exits of the composites around it a condition (they are taken while the loop waits)";
	}

	private void validateNode(Node node, DiagnosticChain diagnostics, Map<Object, Object> context) {
		NodeKind kind = NodeKind.of(node);
		if (kind == null) {
			error(diagnostics, NODE_TYPE, node, (node.getType() == null ? "the state has no type" : "unknown state type '" + node.getType() + "'")
					+ ": use OR, AND, BASIC, START, END or CONDITION");
			return;
		}
		checkUniqueLabel(node, diagnostics, context);
		for (Variable variable : node.getVariables()) {
			if (variable.eIsProxy()) {
				error(diagnostics, DANGLING, node, "a variable of the state is in another document (" + ((InternalEObject) variable).eProxyURI()
						+ "), which KSE does not open: a model is one file");
			}
		}
		if (!kind.isComposite()) {
			if (!node.getChildren().isEmpty()) {
				error(diagnostics, LEAF_CHILDREN, node, StatechartRules.leafRefusal(kind));
			}
			return;
		}
		for (Node child : node.getChildren()) {
			NodeKind childKind = NodeKind.of(child);
			String refusal = childKind == null ? null : StatechartRules.holdRefusal(kind, childKind);
			if (refusal != null) {
				error(diagnostics, AND_CHILDREN, child, refusal);
			}
		}
		if (kind == NodeKind.OR) {
			String starts = StatechartRules.startCountRefusal(node.getChildren().stream().filter(NodeKind.START::is).count());
			if (starts != null) {
				error(diagnostics, START_COUNT, node, starts);
			}
			String ends = StatechartRules.endCountRefusal(node.getChildren().stream().filter(NodeKind.END::is).count());
			if (ends != null) {
				error(diagnostics, END_COUNT, node, ends);
			}
		}
	}

	@SuppressWarnings("unchecked")
	private void checkUniqueLabel(Node node, DiagnosticChain diagnostics, Map<Object, Object> context) {
		if (node.getLabel() == null || context == null) {
			return;
		}
		Map<String, Node> labels = (Map<String, Node>) context.computeIfAbsent(StatechartValidator.class, key -> new HashMap<String, Node>());
		Node other = labels.putIfAbsent(node.getLabel(), node);
		if (other != null && other != node) {
			warning(diagnostics, DUPLICATE_LABEL, node, "the label is also used by " + Labels.describe(other) + "; run Label to renumber");
		}
	}

	private void validateTransition(Transition transition, DiagnosticChain diagnostics, Map<Object, Object> context) {
		Node source = transition.getSource();
		Node target = transition.getTarget();
		if (source == null || target == null) {
			error(diagnostics, DANGLING, transition, "the transition has no " + (source == null ? "source" : "target") + " state");
		} else if (source.eIsProxy() || target.eIsProxy()) {
			Node outside = source.eIsProxy() ? source : target;
			error(diagnostics, DANGLING, transition, "the transition's " + (outside == source ? "source" : "target") + " is in another document ("
					+ ((InternalEObject) outside).eProxyURI() + "), which KSE does not open: a model is one file");
		} else {
			String into = StatechartRules.transitionRefusal(null, NodeKind.of(target));
			if (into != null) {
				error(diagnostics, START_TARGET, transition, into);
			}
			String outOf = StatechartRules.transitionRefusal(NodeKind.of(source), null);
			if (outOf != null) {
				error(diagnostics, END_SOURCE, transition, outOf);
			}
			if (source.getFather_of() != target.getFather_of()) {
				warning(diagnostics, SAME_PARENT, transition, "source and target should be in the same composite state");
			}
		}
		for (ExpressionChecks.Problem problem : ExpressionChecks.check(transition.getTE(), messageChecks(context), expressions(context))) {
			String message = "expression " + problem.line() + ":" + problem.column() + ": " + problem.message();
			if (problem.kind() == ExpressionChecks.Kind.SYNTAX) {
				diagnostics.add(new BasicDiagnostic(problem.error() ? Diagnostic.ERROR : Diagnostic.WARNING, DIAGNOSTIC_SOURCE, EXPRESSION,
						Labels.describe(transition) + ": " + message, new Object[] { transition, problem.issue() }));
			} else {
				error(diagnostics, problem.kind() == ExpressionChecks.Kind.UNSUPPORTED ? EVENT : MESSAGE, transition, message);
			}
		}
	}

	private static ExpressionParser.Session expressions(Map<Object, Object> context) {
		return context == null ? null : (ExpressionParser.Session) context.computeIfAbsent(EXPRESSIONS, key -> ExpressionParser.session());
	}

	@SuppressWarnings("unchecked")
	private static MessageChecks messageChecks(Map<Object, Object> context) {
		if (context == null) {
			return new MessageChecks(StandardMessages.catalog(), MessageCatalog.standardTopics());
		}
		return (MessageChecks) context.computeIfAbsent(MessageChecks.class, key -> {
			MessageCatalog catalog = context.get(CATALOG) instanceof MessageCatalog given ? given : StandardMessages.catalog();
			List<String> topics = context.get(TOPICS) instanceof List<?> given ? (List<String>) given : MessageCatalog.standardTopics();
			return new MessageChecks(catalog, topics);
		});
	}

	private void validateVariable(Variable variable, DiagnosticChain diagnostics, Map<Object, Object> context) {
		String name = variable.getName();
		if (name == null || !IDENTIFIER.matcher(name).matches()) {
			error(diagnostics, VARIABLE_NAME, variable, "a variable's name starts with a letter or '_' and holds only letters, digits and '_'");
		}
		String type = variable.getType();
		if (type == null || !MESSAGE_TYPE.matcher(type).matches()) {
			error(diagnostics, VARIABLE_TYPE, variable, "a variable's type is topic.Kind.Message with Kind Signal, State or Data, as in behavior.State.HeadToBMessage");
		} else {
			String[] parts = type.split("\\.");
			String problem = messageChecks(context).checkType(parts[0], parts[2]);
			if (problem != null) {
				error(diagnostics, MESSAGE, variable, problem);
			}
		}
	}

	private static void error(DiagnosticChain diagnostics, int code, EObject element, String message) {
		diagnostics.add(new BasicDiagnostic(Diagnostic.ERROR, DIAGNOSTIC_SOURCE, code, Labels.describe(element) + ": " + message, new Object[] { element }));
	}

	private static void warning(DiagnosticChain diagnostics, int code, EObject element, String message) {
		diagnostics.add(new BasicDiagnostic(Diagnostic.WARNING, DIAGNOSTIC_SOURCE, code, Labels.describe(element) + ": " + message, new Object[] { element }));
	}

	@Override
	public boolean validate(EDataType dataType, Object value, DiagnosticChain diagnostics, Map<Object, Object> context) {
		return true;
	}
}
