package org.kse.model.edit;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.common.command.CompoundCommand;
import org.eclipse.emf.common.command.UnexecutableCommand;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.edit.command.AddCommand;
import org.eclipse.emf.edit.command.DeleteCommand;
import org.eclipse.emf.edit.command.RemoveCommand;
import org.eclipse.emf.common.command.BasicCommandStack;
import org.eclipse.emf.edit.domain.AdapterFactoryEditingDomain;
import org.eclipse.emf.edit.domain.EditingDomain;
import org.eclipse.emf.edit.provider.ComposedAdapterFactory;
import org.eclipse.emf.edit.provider.ReflectiveItemProviderAdapterFactory;
import org.eclipse.emf.edit.provider.resource.ResourceItemProviderAdapterFactory;
import org.kse.labeling.Copies;
import org.kse.model.NodeKind;
import org.kse.model.StatechartRules;
import org.kse.model.StatechartResources;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.StatechartFactory;
import org.kse.model.statechart.StatechartPackage.Literals;
import org.kse.model.statechart.Transition;

/**
 * The structure edits of statecharts as commands, shared by the tree and diagram editors: add a state or a transition, delete
 * states with what they hold and every transition that touches them, move states into another
 * state. Each is one command, so one Undo takes it back whole.
 */
public final class StatechartEdits {

	/** An editing domain for statecharts: reflective item providers, a command stack and a resource set of its own (that reads .stct files in and out of OSGi). */
	public static AdapterFactoryEditingDomain newDomain() {
		ComposedAdapterFactory adapters = new ComposedAdapterFactory(ComposedAdapterFactory.Descriptor.Registry.INSTANCE);
		adapters.addAdapterFactory(new ResourceItemProviderAdapterFactory());
		adapters.addAdapterFactory(new ReflectiveItemProviderAdapterFactory());
		return new AdapterFactoryEditingDomain(adapters, new BasicCommandStack(), StatechartResources.newResourceSet());
	}

	private StatechartEdits() {
	}

	/**
	 * A new state of the given kind: inside the selected state when that is composite (or the
	 * root), next to it otherwise, and a root of the model when the model is selected. It gets the
	 * next free label of its parent; a BASIC state is called NewActivity, the others by their label.
	 */
	public static Command newState(EditingDomain domain, Model model, Object selected, NodeKind kind) {
		EObject owner = owner(model, selected);
		return labelled(add(domain, model, owner, createState(model, owner, kind)), "New " + kind.name() + " State");
	}

	/**
	 * A new state of the given kind for {@code owner} (a state, or the model for a top-level
	 * state), not yet added: it has the next free label of the owner's children; a BASIC state is
	 * called NewActivity (NewActivity2, … when taken), the others by their label.
	 */
	public static Node createState(Model model, EObject owner, NodeKind kind) {
		List<Node> siblings = owner instanceof Node parent ? parent.getChildren() : model.getNodes();
		Node state = StatechartFactory.eINSTANCE.createNode();
		state.setType(kind.name());
		String prefix = owner instanceof Node parent ? parent.getLabel() + "." : "";
		int number = owner instanceof Node ? siblings.size() + 1 : siblings.size();
		while (labelTaken(siblings, prefix + number)) {
			number++;
		}
		state.setLabel(prefix + number);
		if (kind == NodeKind.BASIC) {
			String name = "NewActivity";
			for (int suffix = 2; nameTaken(siblings, name); suffix++) {
				name = "NewActivity" + suffix;
			}
			state.setName(name);
			state.setActivity("");
		} else {
			state.setName(state.getLabel());
		}
		return state;
	}

	/** Adds a state to {@code owner}: a state's children, or the model's top-level states. */
	public static Command add(EditingDomain domain, Model model, EObject owner, Node state) {
		EReference feature = owner instanceof Node ? Literals.NODE__CHILDREN : Literals.MODEL__NODES;
		return AddCommand.create(domain, owner instanceof Node ? owner : model, feature, state);
	}

	/**
	 * Why a state of this kind cannot go into {@code owner} (a state, or the model), or null when
	 * it can ({@link StatechartRules#holdRefusal}); the top of a model takes any state.
	 */
	public static String refusal(EObject owner, NodeKind kind) {
		if (!(owner instanceof Node parent)) {
			return null;
		}
		NodeKind parentKind = NodeKind.of(parent);
		if (parentKind == null) {
			return "a state of unknown type '" + parent.getType() + "' cannot hold other states";
		}
		return StatechartRules.holdRefusal(parentKind, kind);
	}

	/**
	 * Where a state added or pasted with {@code selected} selected goes: into a selected composite
	 * (or the root), else beside the selected state; into the model when nothing is selected.
	 */
	public static EObject owner(Model model, Object selected) {
		if (selected instanceof Node node) {
			NodeKind kind = NodeKind.of(node);
			boolean composite = kind != null && kind.isComposite() || node.eContainer() instanceof Model;
			if (composite) {
				return node;
			}
			return node.eContainer() == null ? model : node.eContainer();
		}
		return model;
	}

	private static boolean labelTaken(List<Node> siblings, String label) {
		return siblings.stream().anyMatch(each -> label.equals(each.getLabel()));
	}

	private static boolean nameTaken(List<Node> siblings, String name) {
		return siblings.stream().anyMatch(each -> name.equals(each.getName()));
	}

	/** A transition from the first selected state to the second, or from a lone selected state to itself. */
	public static Command newTransition(EditingDomain domain, Model model, List<Node> selected) {
		if (selected.isEmpty() || selected.size() > 2) {
			return UnexecutableCommand.INSTANCE;
		}
		return newTransition(domain, model, selected.get(0), selected.get(selected.size() - 1));
	}

	/** A transition with an empty expression, named after its states as Label names it. */
	public static Command newTransition(EditingDomain domain, Model model, Node source, Node target) {
		Transition transition = StatechartFactory.eINSTANCE.createTransition();
		transition.setSource(source);
		transition.setTarget(target);
		transition.setName(source.getName() + "_TO_" + target.getName());
		transition.setTE("");
		return labelled(AddCommand.create(domain, model, Literals.MODEL__TRANSITIONS, transition), "New Transition");
	}

	/** Deletes the selected states (with everything inside them) and transitions, and every transition that touches a deleted state. */
	public static Command delete(EditingDomain domain, Model model, Collection<?> selected) {
		Set<EObject> doomed = new LinkedHashSet<>();
		Set<Node> states = new LinkedHashSet<>();
		for (Object each : selected) {
			if (each instanceof Node node) {
				doomed.add(node);
				states.add(node);
				node.eAllContents().forEachRemaining(inner -> {
					if (inner instanceof Node child) {
						states.add(child);
					}
				});
			} else if (each instanceof Transition transition) {
				doomed.add(transition);
			}
		}
		// a state inside another deleted state goes with it
		doomed.removeIf(each -> each instanceof Node node && hasAncestorIn(node, doomed));
		for (Transition transition : model.getTransitions()) {
			if (states.contains(transition.getSource()) || states.contains(transition.getTarget())) {
				doomed.add(transition);
			}
		}
		if (doomed.isEmpty()) {
			return UnexecutableCommand.INSTANCE;
		}
		return labelled(DeleteCommand.create(domain, new ArrayList<>(doomed)), "Delete");
	}

	private static boolean hasAncestorIn(Node node, Set<EObject> set) {
		for (EObject container = node.eContainer(); container != null; container = container.eContainer()) {
			if (set.contains(container)) {
				return true;
			}
		}
		return false;
	}

	/**
	 * Moves states into another state (or to the top of the model): not into themselves or a
	 * state inside them, and only where they are not already.
	 */
	public static Command move(EditingDomain domain, Model model, List<Node> states, Object target) {
		EObject owner = target instanceof Node node ? node : target instanceof Model ? model : null;
		if (owner == null || states.isEmpty()) {
			return UnexecutableCommand.INSTANCE;
		}
		CompoundCommand move = new CompoundCommand(states.size() == 1 ? "Move State" : "Move States");
		for (Node state : states) {
			if (state == owner || state.eContainer() == owner || (owner instanceof Node node && hasAncestorIn(node, Set.of(state)))) {
				return UnexecutableCommand.INSTANCE;
			}
			move.append(RemoveCommand.create(domain, state.eContainer(), state.eContainingFeature(), state));
			move.append(AddCommand.create(domain, owner, owner instanceof Node ? Literals.NODE__CHILDREN : Literals.MODEL__NODES, state));
		}
		return move;
	}

	/**
	 * Pastes copied states into the selected composite state (or next to the selected state, or at
	 * the top of the model), relabelled there, with their inner transitions and variables.
	 */
	public static Command paste(EditingDomain domain, Model model, Copies.Fragment fragment, Object selected) {
		return pasteInto(domain, model, fragment, owner(model, selected));
	}

	/** Pastes copied states into {@code owner} (a state, or the model for top-level states). */
	public static Command pasteInto(EditingDomain domain, Model model, Copies.Fragment fragment, EObject owner) {
		if (fragment == null) {
			return UnexecutableCommand.INSTANCE;
		}
		return paste(domain, model, Copies.prepare(fragment, model, owner));
	}

	/** Adds what {@link Copies#prepare} made for one paste: the states to their container, their transitions and new variables to the model. */
	public static Command paste(EditingDomain domain, Model model, Copies.Pasted pasted) {
		EObject owner = pasted.container();
		CompoundCommand paste = new CompoundCommand(CompoundCommand.LAST_COMMAND_ALL, "Paste");
		if (!pasted.variables().isEmpty()) {
			paste.append(AddCommand.create(domain, model, Literals.MODEL__VARIABLES, pasted.variables()));
		}
		if (!pasted.transitions().isEmpty()) {
			paste.append(AddCommand.create(domain, model, Literals.MODEL__TRANSITIONS, pasted.transitions()));
		}
		// the states last: what a command affects is selected, and that should be the pasted states
		paste.append(AddCommand.create(domain, owner instanceof Node ? owner : model, owner instanceof Node ? Literals.NODE__CHILDREN : Literals.MODEL__NODES,
				pasted.states()));
		return paste;
	}

	private static Command labelled(Command command, String label) {
		CompoundCommand compound = new CompoundCommand(label);
		compound.append(command);
		return compound;
	}
}
