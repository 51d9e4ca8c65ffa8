package org.kse.diagram.server;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.common.util.Diagnostic;
import org.eclipse.glsp.graph.GModelElement;
import org.eclipse.glsp.server.features.validation.Marker;
import org.eclipse.glsp.server.features.validation.MarkerKind;
import org.eclipse.glsp.server.features.validation.ModelValidator;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;
import org.kse.notation.Notation;
import org.kse.validation.ModelValidation;

import com.google.inject.Inject;

/** The KSE rules checked on the whole model after each edit; each problem marks its state or transition. */
public class StatechartMarkers implements ModelValidator {

	@Inject
	private StatechartModelState state;

	@Override
	public List<Marker> validate(List<GModelElement> elements, String reason) {
		// live validation runs on a thread of its own, while the model's owner may be editing it
		return state.read(this::markers);
	}

	private List<Marker> markers() {
		List<Marker> markers = new ArrayList<>();
		if (state.getModel() == null) {
			return markers;
		}
		for (Diagnostic diagnostic : ModelValidation.validate(state.getModel()).getChildren()) {
			String kind = diagnostic.getSeverity() == Diagnostic.ERROR ? MarkerKind.ERROR
					: diagnostic.getSeverity() == Diagnostic.WARNING ? MarkerKind.WARNING : MarkerKind.INFO;
			String id = StatechartGraph.ROOT;
			if (!diagnostic.getData().isEmpty()) {
				Object element = diagnostic.getData().get(0);
				if (element instanceof Node node) {
					id = Notation.path(node);
				} else if (element instanceof Transition transition) {
					id = "//@transitions." + state.getModel().getTransitions().indexOf(transition);
				}
			}
			markers.add(new Marker(diagnostic.getMessage(), diagnostic.getMessage(), id, kind));
		}
		return markers;
	}
}
