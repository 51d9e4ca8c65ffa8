/*
 * The dependency injection container of the diagram: GLSP's default and standalone modules (select,
 * move, resize, delete, palette, label editing, undo/redo keys, copy/paste, zoom/scroll, grid,
 * helper lines, markers, hover popups, SVG export) plus the statechart's model elements and views.
 */
import {
    ConsoleLogger,
    ExportSvgAction,
    ExportSvgKeyListener,
    FeatureModule,
    GlspEditLabelUI,
    GLSPModelSource,
    GlspHoverMouseListener,
    IDiagramOptions,
    LogLevel,
    MessageAction,
    SetEditValidationResultAction,
    STANDALONE_MODULES,
    ShowGridAction,
    StatusAction,
    TYPES,
    ViewerOptions,
    alignFeature,
    bindAsService,
    bindOrRebind,
    configureActionHandler,
    configureDefaultModelElements,
    configureModelElement,
    createDiagramOptionsModule,
    editLabelFeature,
    edgeLayoutFeature,
    gridModule,
    helperLineModule,
    initializeDiagramContainer,
    standaloneExportModule,
    statusModule
} from '@eclipse-glsp/client';
import { Container } from 'inversify';
import { DISK_CHANGE, DiskChangeHandler } from './disk-changes';
import { KseExportSvgActionHandler } from './export';
import { KseHoverMouseListener } from './hover';
import { kseInteractionModule } from './interaction';
import { KseEditLabelUI, LateEditValidationResults } from './label-editing';
import { KseModelSource } from './model-source';
import {
    BasicStateNode,
    EXPRESSION_LABEL,
    ExpressionLabel,
    NAME_LABEL,
    NameLabel,
    STATE_PREFIX,
    StateNode,
    TRANSITION,
    TransitionEdge
} from './model';
import { ANY_STATE, KseModelRegistry, KseViewRegistry } from './registries';
import { StatusLineHandler } from './status-line';
import { GridButtonSync } from './toolbar-sync';
import { ExpressionLabelView, NameLabelView, StateView, TransitionView } from './views';

export const kseDiagramModule = new FeatureModule(
    (bind, unbind, isBound, rebind) => {
        const context = { bind, unbind, isBound, rebind };
        bindOrRebind(context, TYPES.ILogger).to(ConsoleLogger).inSingletonScope();
        bindOrRebind(context, TYPES.LogLevel).toConstantValue(LogLevel.warn);

        configureDefaultModelElements(context);
        // every kind the server's rule book names is a StateNode drawn by StateView (registries.ts);
        // a BASIC state edits its name on a double click, so it has its own, registered first
        bindOrRebind(context, TYPES.SModelRegistry).to(KseModelRegistry).inSingletonScope();
        bindOrRebind(context, TYPES.ViewRegistry).to(KseViewRegistry).inSingletonScope();
        configureModelElement(context, STATE_PREFIX + 'basic', BasicStateNode, StateView);
        configureModelElement(context, ANY_STATE, StateNode, StateView);
        configureModelElement(context, NAME_LABEL, NameLabel, NameLabelView, { enable: [editLabelFeature], disable: [alignFeature] });
        // placed by the server's layout (its top-left corner), neither along the edge nor aligned by the client
        configureModelElement(context, EXPRESSION_LABEL, ExpressionLabel, ExpressionLabelView, {
            enable: [editLabelFeature],
            disable: [alignFeature, edgeLayoutFeature]
        });
        configureModelElement(context, TRANSITION, TransitionEdge, TransitionView);

        // the page's status line shows GLSP's status and messages (instead of the overlay in the diagram)
        bind(StatusLineHandler).toSelf().inSingletonScope();
        configureActionHandler(context, StatusAction.KIND, StatusLineHandler);
        configureActionHandler(context, MessageAction.KIND, StatusLineHandler);

        // the toolbar's Grid button follows the grid (which the tool palette can switch too)
        bind(GridButtonSync).toSelf().inSingletonScope();
        configureActionHandler(context, ShowGridAction.KIND, GridButtonSync);

        // the model's file changed on disk: reloaded, or the user is asked (a bar over the diagram)
        bind(DiskChangeHandler).toSelf().inSingletonScope();
        configureActionHandler(context, DISK_CHANGE, DiskChangeHandler);

        // SVG export: saved as <model>.svg; Ctrl+Shift+E exports too
        bind(KseExportSvgActionHandler).toSelf().inSingletonScope();
        configureActionHandler(context, ExportSvgAction.KIND, KseExportSvgActionHandler);
        bindAsService(context, TYPES.KeyListener, ExportSvgKeyListener);

        // expressions are edited whole, in a text area
        rebind(GlspEditLabelUI).to(KseEditLabelUI).inSingletonScope();
        bind(LateEditValidationResults).toSelf().inSingletonScope();
        configureActionHandler(context, SetEditValidationResultAction.KIND, LateEditValidationResults);

        // compound operations carry only what the server handles
        rebind(GLSPModelSource).to(KseModelSource).inSingletonScope();

        // popups of transitions open at the mouse
        rebind(GlspHoverMouseListener).to(KseHoverMouseListener).inSingletonScope();
    },
    { featureId: Symbol('kseDiagram') }
);

export function createKseDiagramContainer(options: IDiagramOptions, viewerOptions?: Partial<ViewerOptions>): Container {
    const standalone = STANDALONE_MODULES.filter(module => module !== standaloneExportModule);
    return initializeDiagramContainer(
        new Container(),
        createDiagramOptionsModule(options, viewerOptions),
        helperLineModule,
        gridModule,
        kseDiagramModule,
        kseInteractionModule,
        { add: standalone, remove: statusModule }
    );
}
