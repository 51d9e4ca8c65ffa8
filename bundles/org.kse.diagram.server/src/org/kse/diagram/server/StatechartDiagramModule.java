package org.kse.diagram.server;

import java.nio.file.Path;

import org.eclipse.glsp.server.di.DiagramModule;
import org.eclipse.glsp.server.diagram.DiagramConfiguration;
import org.eclipse.glsp.server.features.core.model.GModelFactory;
import org.eclipse.glsp.server.features.core.model.SourceModelStorage;
import org.eclipse.glsp.server.model.GModelState;

/** The statechart diagram of a GLSP server that opens the models of one served folder. */
public class StatechartDiagramModule extends DiagramModule {

	private final ServedFolder folder;

	public StatechartDiagramModule(Path servedFolder) {
		this.folder = new ServedFolder(servedFolder);
	}

	@Override
	protected void configureBase() {
		super.configureBase();
		bind(ServedFolder.class).toInstance(folder);
		bind(StatechartModelState.class).in(com.google.inject.Singleton.class);
	}

	@Override
	public String getDiagramType() {
		return StatechartDiagramConfiguration.DIAGRAM_TYPE;
	}

	@Override
	protected Class<? extends DiagramConfiguration> bindDiagramConfiguration() {
		return StatechartDiagramConfiguration.class;
	}

	@Override
	protected Class<? extends GModelState> bindGModelState() {
		return StatechartModelState.class;
	}

	@Override
	protected Class<? extends SourceModelStorage> bindSourceModelStorage() {
		return StatechartStorage.class;
	}

	@Override
	protected Class<? extends GModelFactory> bindGModelFactory() {
		return StatechartGModelFactory.class;
	}
}
