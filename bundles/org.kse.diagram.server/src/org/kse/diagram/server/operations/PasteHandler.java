package org.kse.diagram.server.operations;

import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.common.command.CompoundCommand;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.glsp.graph.GPoint;
import org.eclipse.glsp.server.operations.PasteOperation;
import org.kse.diagram.server.BoundsCommand;
import org.kse.labeling.Copies;
import org.kse.model.NodeKind;
import org.kse.model.edit.StatechartEdits;
import org.kse.model.statechart.Node;
import org.kse.notation.Arrange;
import org.kse.notation.Bounds;

/**
 * Paste: the copied states go into the selected composite state (or beside the selected state,
 * or to the top of the model), relabelled there with their inner transitions and variables, and
 * drawn as they were, with the first pasted state where the mouse was (or a little off the original);
 * the composite that takes them grows to hold them.
 */
public class PasteHandler extends StatechartOperationHandler<PasteOperation> {

	@Override
	protected Command command(PasteOperation operation) {
		DiagramClipboard.Copy copy = operation.getClipboardData() == null ? null : DiagramClipboard.get(operation.getClipboardData().get(DiagramClipboard.FORMAT));
		if (copy == null) {
			throw refused("nothing to paste: copy states of a KSE diagram first");
		}
		List<String> selectedIds = DiagramClipboard.selectedIds(operation.getEditorContext());
		EObject selected = selectedIds.isEmpty() ? null : state.element(selectedIds.get(0));
		EObject owner = owner(selected);
		for (Node copied : copy.fragment().states()) {
			String refusal = StatechartEdits.refusal(owner, NodeKind.of(copied));
			if (refusal != null) {
				throw refused("cannot paste " + describe(copied) + " into " + describe((Node) owner) + ": " + refusal);
			}
		}
		Copies.Pasted pasted = Copies.prepare(copy.fragment(), state.getModel(), owner);
		Map<Node, Bounds> placed = new IdentityHashMap<>();
		Iterator<Bounds> bounds = copy.bounds().iterator();
		for (Node top : pasted.states()) {
			DiagramClipboard.walk(top, node -> placed.put(node, bounds.hasNext() ? bounds.next() : null));
		}
		placed.values().removeIf(java.util.Objects::isNull);
		offsetTopStates(pasted.states(), placed, owner, operation.getEditorContext() == null ? null : operation.getEditorContext().getLastMousePosition().orElse(null));
		placed.putAll(state.getLayout().grownToHold(owner, pasted.states().stream().map(placed::get).filter(java.util.Objects::nonNull).toList()));
		CompoundCommand paste = new CompoundCommand(CompoundCommand.MERGE_COMMAND_ALL, "Paste");
		paste.append(StatechartEdits.paste(state.getDomain(), state.getModel(), pasted));
		paste.append(new BoundsCommand("Place", state.getLayout(), placed));
		return paste;
	}

	/** A composite selected takes the paste; a simple state passes it to its parent. */
	private EObject owner(EObject selected) {
		return StatechartEdits.owner(state.getModel(), selected);
	}

	private void offsetTopStates(List<Node> tops, Map<Node, Bounds> placed, EObject owner, GPoint mouse) {
		if (tops.isEmpty() || placed.get(tops.get(0)) == null) {
			return;
		}
		Bounds first = placed.get(tops.get(0));
		double dx = 24;
		double dy = 24;
		if (mouse != null) {
			double[] origin = state.getLayout().absolute(owner);
			dx = coordinate(mouse.getX()) - origin[0] - first.x();
			dy = coordinate(mouse.getY()) - origin[1] - first.y();
		}
		for (Node top : tops) {
			Bounds b = placed.get(top);
			if (b != null) {
				double y = b.y() + dy;
				placed.put(top, new Bounds(Math.max(owner instanceof Node ? 4 : 0, b.x() + dx), owner instanceof Node ? Math.max(Arrange.HEADER, y) : Math.max(0, y),
						b.width(), b.height()));
			}
		}
	}
}
