package org.kse.ui.statechart.editor;

import org.kse.model.edit.StatechartEdits;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.jface.util.LocalSelectionTransfer;
import org.eclipse.jface.viewers.IStructuredSelection;
import org.eclipse.jface.viewers.ViewerDropAdapter;
import org.eclipse.swt.dnd.DND;
import org.eclipse.swt.dnd.DragSourceAdapter;
import org.eclipse.swt.dnd.DragSourceEvent;
import org.eclipse.swt.dnd.Transfer;
import org.eclipse.swt.dnd.TransferData;
import org.kse.model.statechart.Node;

/** Dragging states in the statechart editor's tree onto another state (or the model) moves them there, as one command. */
final class StructureDragAndDrop {

	private StructureDragAndDrop() {
	}

	static void install(StatechartEditor editor) {
		var viewer = editor.getViewer();
		Transfer[] transfers = { LocalSelectionTransfer.getTransfer() };
		viewer.addDragSupport(DND.DROP_MOVE, transfers, new DragSourceAdapter() {
			@Override
			public void dragStart(DragSourceEvent event) {
				List<Node> states = states(viewer.getStructuredSelection());
				event.doit = !states.isEmpty() && states.size() == viewer.getStructuredSelection().size();
				LocalSelectionTransfer.getTransfer().setSelection(viewer.getSelection());
			}

			@Override
			public void dragFinished(DragSourceEvent event) {
				LocalSelectionTransfer.getTransfer().setSelection(null);
			}
		});
		viewer.addDropSupport(DND.DROP_MOVE, transfers, new ViewerDropAdapter(viewer) {
			@Override
			public boolean validateDrop(Object target, int operation, TransferData type) {
				return getCurrentLocation() == LOCATION_ON && move(target).canExecute();
			}

			@Override
			public boolean performDrop(Object data) {
				var command = move(getCurrentTarget());
				editor.execute(command);
				return true;
			}

			private org.eclipse.emf.common.command.Command move(Object target) {
				var dragged = LocalSelectionTransfer.getTransfer().getSelection();
				List<Node> states = dragged instanceof IStructuredSelection structured ? states(structured) : List.of();
				return StatechartEdits.move(editor.getEditingDomain(), editor.getModel(), states, target);
			}
		});
	}

	private static List<Node> states(IStructuredSelection selection) {
		List<Node> states = new ArrayList<>();
		selection.forEach(each -> {
			if (each instanceof Node node) {
				states.add(node);
			}
		});
		return states;
	}
}
