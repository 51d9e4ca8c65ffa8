package org.kse.diagram.server;

import java.util.HashMap;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.glsp.server.features.core.model.GModelFactory;

import com.google.inject.Inject;

/** Builds the session's graph from its statechart and layout (again after every change). */
public class StatechartGModelFactory implements GModelFactory {

	@Inject
	private StatechartModelState state;

	@Override
	public void createGModel() {
		Map<String, EObject> ids = new HashMap<>();
		state.updateRoot(StatechartGraph.of(state.getModel(), state.getLayout()::get, ids));
		state.index(ids);
	}
}
