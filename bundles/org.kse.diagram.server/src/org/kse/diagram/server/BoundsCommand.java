package org.kse.diagram.server;

import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.Map;

import org.eclipse.emf.common.command.AbstractCommand;
import org.kse.model.statechart.Node;
import org.kse.notation.Bounds;

/** Moves and resizes states on the diagram, as one undoable step on the model's command stack. */
public final class BoundsCommand extends AbstractCommand {

	private final DiagramLayout layout;
	private final Map<Node, Bounds> after;
	private final Map<Node, Bounds> before = new IdentityHashMap<>();

	public BoundsCommand(String label, DiagramLayout layout, Map<Node, Bounds> after) {
		super(label);
		this.layout = layout;
		this.after = new LinkedHashMap<>(after);
	}

	@Override
	protected boolean prepare() {
		return !after.isEmpty();
	}

	@Override
	public void execute() {
		before.clear();
		after.forEach((node, bounds) -> before.put(node, layout.put(node, bounds)));
	}

	@Override
	public void undo() {
		before.forEach(layout::put);
	}

	@Override
	public void redo() {
		after.forEach(layout::put);
	}
}
