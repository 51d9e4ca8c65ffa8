package org.kse.diagram.server.operations;

import java.lang.reflect.ParameterizedType;
import java.util.Optional;

import org.eclipse.emf.common.command.Command;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.glsp.server.operations.Operation;
import org.eclipse.glsp.server.operations.OperationHandler;
import org.eclipse.glsp.server.types.GLSPServerException;
import org.kse.diagram.server.StatechartModelState;
import org.kse.model.statechart.Node;

import com.google.inject.Inject;

/**
 * An edit of the diagram as one command on the model's command stack. An edit the statechart
 * rules forbid is refused with a message that names the elements, and nothing changes.
 */
abstract class StatechartOperationHandler<O extends Operation> implements OperationHandler<O> {

	@Inject
	protected StatechartModelState state;

	@Override
	@SuppressWarnings("unchecked")
	public Class<O> getHandledOperationType() {
		return (Class<O>) ((ParameterizedType) getClass().getGenericSuperclass()).getActualTypeArguments()[0];
	}

	@Override
	public Optional<Command> createCommand(O operation) {
		if (state.getModel() == null) {
			throw refused("no model is open: the page asks for one first"); // an edit before requestModel failed on nulls
		}
		// the model is read where its owner edits it (a workbench's UI thread)
		return state.read(() -> {
			Command command = command(operation);
			if (command != null && !command.canExecute()) {
				throw refused("the edit cannot be applied here");
			}
			return Optional.ofNullable(command);
		});
	}

	/** The command of the operation, or null when it changes nothing. */
	protected abstract Command command(O operation);

	protected EObject element(String id) {
		EObject element = state.element(id);
		if (element == null) {
			throw refused("the diagram has no element " + id + " (it may have been removed meanwhile)");
		}
		return element;
	}

	protected Node state(String id) {
		if (element(id) instanceof Node node) {
			return node;
		}
		throw refused(id + " is not a state");
	}

	/** Farther than any drawing goes, near enough that sums of positions and sizes stay finite. */
	static final double FARTHEST = 1_000_000;

	/**
	 * A position or size a client sent, refused when it is not a finite number within
	 * {@link #FARTHEST}: an infinite one (JSON's 1e999) or one whose sums overflow made the
	 * layout unwritable, so the page got no more graphs and the notation file could not be saved.
	 */
	protected static double coordinate(double value) {
		if (!Double.isFinite(value) || Math.abs(value) > FARTHEST) {
			throw refused(value + " is not a position or size on the diagram (at most " + (long) FARTHEST + " either way)");
		}
		return value;
	}

	protected static GLSPServerException refused(String message) {
		return new GLSPServerException(message);
	}

	/** A state as the user knows it: "label (name)". */
	protected static String describe(Node node) {
		return node.getLabel() + " (" + node.getName() + ")";
	}
}
