package org.kse.diagram.server;

import java.nio.file.Path;

import org.eclipse.glsp.server.actions.ActionHandler;
import org.eclipse.glsp.server.di.DiagramModule;
import org.eclipse.glsp.server.di.MultiBinding;
import org.eclipse.glsp.server.features.directediting.LabelEditValidator;
import org.eclipse.glsp.server.features.popup.PopupModelFactory;
import org.eclipse.glsp.server.features.toolpalette.ToolPaletteItemProvider;
import org.eclipse.glsp.server.features.validation.ModelValidator;
import org.eclipse.glsp.server.gmodel.GModelCutOperationHandler;
import org.eclipse.glsp.server.operations.LayoutOperationHandler;
import org.eclipse.glsp.server.operations.OperationHandler;
import org.kse.diagram.server.operations.ArrangeHandler;
import org.kse.diagram.server.operations.ChangeBoundsHandler;
import org.kse.diagram.server.operations.ChangeContainerHandler;
import org.kse.diagram.server.operations.RoutingPointsHandler;
import org.kse.diagram.server.operations.ClipboardDataHandler;
import org.kse.diagram.server.operations.CreateStateHandler;
import org.kse.diagram.server.operations.CreateTransitionHandler;
import org.kse.diagram.server.operations.CutHandler;
import org.kse.diagram.server.operations.DeleteHandler;
import org.kse.diagram.server.operations.LabelEditHandler;
import org.kse.diagram.server.operations.LabelEdits;
import org.kse.diagram.server.operations.PasteHandler;
import org.eclipse.glsp.server.diagram.DiagramConfiguration;
import org.eclipse.glsp.server.features.core.model.GModelFactory;
import org.eclipse.glsp.server.features.core.model.SourceModelStorage;
import org.eclipse.glsp.server.model.GModelState;

/** The statechart diagram of a GLSP server that opens the models of one served folder. */
public class StatechartDiagramModule extends DiagramModule {

	private final ServedFolder folder;
	private final StatechartSources sources;

	/** Serves the statecharts of a folder, each session reading its own copy of the file. */
	public StatechartDiagramModule(Path servedFolder) {
		this(servedFolder, new FileSources());
	}

	/** Serves the statecharts of a folder, as {@code sources} hands them out. */
	public StatechartDiagramModule(Path servedFolder, StatechartSources sources) {
		this.folder = new ServedFolder(servedFolder);
		this.sources = sources;
	}

	@Override
	protected void configureBase() {
		super.configureBase();
		bind(ServedFolder.class).toInstance(folder);
		bind(StatechartSources.class).toInstance(sources);
		bind(StatechartModelState.class).in(com.google.inject.Singleton.class);
		bind(org.eclipse.glsp.server.features.core.model.ModelSubmissionHandler.class).to(StatechartSubmissions.class).in(com.google.inject.Singleton.class);
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

	@Override
	protected Class<? extends ToolPaletteItemProvider> bindToolPaletteItemProvider() {
		return StatechartPalette.class;
	}

	@Override
	protected Class<? extends PopupModelFactory> bindPopupModelFactory() {
		return StatechartPopups.class;
	}

	@Override
	protected Class<? extends ModelValidator> bindModelValidator() {
		return StatechartMarkers.class;
	}

	@Override
	protected Class<? extends LabelEditValidator> bindLabelEditValidator() {
		return LabelEdits.class;
	}

	@Override
	protected void configureActionHandlers(MultiBinding<ActionHandler> bindings) {
		super.configureActionHandlers(bindings);
		bindings.add(ClipboardDataHandler.class);
		bindings.add(ExternalChangeHandler.class);
		bindings.add(DiskChanges.FileChangedHandler.class);
		bindings.add(DiskChanges.ResolveHandler.class);
	}

	@Override
	protected void configureOperationHandlers(MultiBinding<OperationHandler<?>> bindings) {
		super.configureOperationHandlers(bindings);
		bindings.remove(LayoutOperationHandler.class);
		bindings.remove(GModelCutOperationHandler.class);
		bindings.add(CreateStateHandler.class);
		bindings.add(CreateTransitionHandler.class);
		bindings.add(ChangeBoundsHandler.class);
		bindings.add(ChangeContainerHandler.class);
		bindings.add(RoutingPointsHandler.class);
		bindings.add(DeleteHandler.class);
		bindings.add(LabelEditHandler.class);
		bindings.add(ArrangeHandler.class);
		bindings.add(CutHandler.class);
		bindings.add(PasteHandler.class);
	}
}
