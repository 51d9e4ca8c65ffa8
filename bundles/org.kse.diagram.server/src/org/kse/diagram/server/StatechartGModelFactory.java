package org.kse.diagram.server;

import org.eclipse.glsp.server.features.core.model.GModelFactory;

import com.google.inject.Inject;

/** Builds the session's graph from its statechart and notation (again after every change). */
public class StatechartGModelFactory implements GModelFactory {

	@Inject
	private StatechartModelState state;

	@Override
	public void createGModel() {
		state.updateRoot(StatechartGraph.of(state.getModel(), state.getNotation()));
	}
}
