package org.kse.testing;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.Transition;
import org.kse.model.statechart.Variable;

/**
 * Test helpers: a tiny builder for statecharts made in code, the legacy files of the
 * original tool, and ways to look into a model.
 */
public final class Models {

	public static final StatechartFactory FACTORY = StatechartFactory.eINSTANCE;

	/** The files saved by the original KSE (read only: never write there). */
	public static final Path LEGACY = Path.of(System.getProperty("kse.repository", "../.."), "tests", "data", "legacy-kse");

	private Models() {
	}

	// ------------------------------------------------------------------ building

	public static Model model(String name) {
		Model model = FACTORY.createModel();
		model.setName(name);
		return model;
	}

	/** A root state of the model. */
	public static Node root(Model model, String name, String label, String type) {
		Node node = newNode(name, label, type);
		model.getNodes().add(node);
		return node;
	}

	/** A child state of {@code parent}, appended in document order. */
	public static Node child(Node parent, String name, String label, String type) {
		Node node = newNode(name, label, type);
		parent.getChildren().add(node);
		return node;
	}

	public static Node newNode(String name, String label, String type) {
		Node node = FACTORY.createNode();
		node.setName(name);
		node.setLabel(label);
		node.setType(type);
		return node;
	}

	public static Transition transition(Model model, Node source, Node target) {
		return transition(model, source, target, null);
	}

	public static Transition transition(Model model, Node source, Node target, String expression) {
		Transition transition = FACTORY.createTransition();
		transition.setSource(source);
		transition.setTarget(target);
		transition.setTE(expression);
		if (source != null && target != null) {
			transition.setName(source.getName() + "_TO_" + target.getName());
		}
		model.getTransitions().add(transition);
		return transition;
	}

	public static Variable variable(Model model, String name, String type) {
		Variable variable = FACTORY.createVariable();
		variable.setName(name);
		variable.setType(type);
		model.getVariables().add(variable);
		return variable;
	}

	/**
	 * A correct, labeled model: {@code 0} OR "Main" holding {@code 0.1} START,
	 * {@code 0.2} BASIC "Work", {@code 0.3} END, with 0.1→0.2 and 0.2→0.3.
	 */
	public static Model simple() {
		Model model = model("Simple");
		Node root = root(model, "Main", "0", "OR");
		Node start = child(root, "0.1", "0.1", "START");
		Node work = child(root, "Work", "0.2", "BASIC");
		Node end = child(root, "0.3", "0.3", "END");
		transition(model, start, work);
		transition(model, work, end, "[behavior.State.HeadToBMessage.ballfound()>0]");
		return model;
	}

	// ------------------------------------------------------------------ legacy files

	/** Every .stct file under the legacy directory, sorted by path. */
	public static List<Path> legacyModels() {
		return legacyFiles(".stct");
	}

	public static List<Path> legacyFiles(String extension) {
		assertTrue(Files.isDirectory(LEGACY), () -> "legacy directory missing: " + LEGACY.toAbsolutePath());
		try (Stream<Path> files = Files.walk(LEGACY)) {
			List<Path> found = files.filter(Files::isRegularFile).filter(file -> file.getFileName().toString().endsWith(extension)).sorted()
					.toList();
			assertFalse(found.isEmpty(), () -> "no *" + extension + " under " + LEGACY.toAbsolutePath());
			return found;
		} catch (IOException e) {
			return fail(e);
		}
	}

	public static Path legacy(String relative) {
		Path file = LEGACY.resolve(relative);
		assertTrue(Files.isRegularFile(file), () -> "legacy file missing: " + file.toAbsolutePath());
		return file;
	}

	// ------------------------------------------------------------------ looking into models

	/** The states in a model, or inside a state (not the state itself), in document order (depth first). */
	public static List<Node> allNodes(org.eclipse.emf.ecore.EObject root) {
		List<Node> nodes = new ArrayList<>();
		root.eAllContents().forEachRemaining(element -> {
			if (element instanceof Node node) {
				nodes.add(node);
			}
		});
		return nodes;
	}

	public static Node byName(Model model, String name) {
		List<Node> found = allNodes(model).stream().filter(node -> name.equals(node.getName())).toList();
		assertTrue(found.size() == 1, () -> "expected one state named " + name + ", found " + found.size());
		return found.get(0);
	}

	/** The state is the ancestor or inside it. */
	public static boolean isInside(Node state, Node ancestor) {
		for (org.eclipse.emf.ecore.EObject each = state; each != null; each = each.eContainer()) {
			if (each == ancestor) {
				return true;
			}
		}
		return false;
	}

	public static Node byLabel(Model model, String label) {
		List<Node> found = allNodes(model).stream().filter(node -> label.equals(node.getLabel())).toList();
		assertTrue(found.size() == 1, () -> "expected one state labeled " + label + ", found " + found.size());
		return found.get(0);
	}

	public static boolean equal(Model a, Model b) {
		return new EcoreUtil.EqualityHelper().equals(a, b);
	}

	/** The labels of the children, in document order. */
	public static List<String> childLabels(Node parent) {
		return parent.getChildren().stream().map(Node::getLabel).toList();
	}

	public static String render(Diagnostic diagnostic) {
		StringBuilder text = new StringBuilder();
		for (Diagnostic child : diagnostic.getChildren()) {
			text.append('\n').append(child.getSeverity() == Diagnostic.ERROR ? "ERROR " : child.getSeverity() == Diagnostic.WARNING ? "WARNING " : "INFO ")
					.append(child.getCode()).append(' ').append(child.getMessage());
		}
		return text.length() == 0 ? "(no diagnostics)" : text.toString();
	}
}
