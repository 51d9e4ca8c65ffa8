/*
 * What users of diagram editors expect beyond GLSP's defaults: dragging a state into another
 * composite reparents it, the keyboard nudges, zooms, fits and finds, a right click opens a menu.
 */
import {
    ChangeBoundsTool,
    DeleteElementContextMenuItemProvider,
    FeatureModule,
    GLSPContextMenuMouseListener,
    InvokeCopyPasteAction,
    InvokeCopyPasteActionHandler,
    TYPES,
    bindAsService,
    configureActionHandler
} from '@eclipse-glsp/client';
import { KseClipboardService, KseContextMenu, KseContextMenuMouseListener, KseCopyPasteMenuItems, KseMenuItems } from './context-menu';
import { FindBox } from './find';
import { KseKeyListener, Nudger } from './keys';
import { KseChangeBoundsTool } from './reparent';

export const kseInteractionModule = new FeatureModule(
    (bind, unbind, isBound, rebind) => {
        const context = { bind, unbind, isBound, rebind };

        rebind(ChangeBoundsTool).to(KseChangeBoundsTool).inSingletonScope();

        bind(Nudger).toSelf().inSingletonScope();
        bind(FindBox).toSelf().inSingletonScope();
        bindAsService(context, TYPES.KeyListener, KseKeyListener);

        rebind(GLSPContextMenuMouseListener).to(KseContextMenuMouseListener).inSingletonScope();
        bind(TYPES.IContextMenuService).to(KseContextMenu).inSingletonScope();
        bindAsService(context, TYPES.IContextMenuItemProvider, DeleteElementContextMenuItemProvider);
        bindAsService(context, TYPES.IContextMenuItemProvider, KseCopyPasteMenuItems);
        bindAsService(context, TYPES.IContextMenuItemProvider, KseMenuItems);
        configureActionHandler(context, InvokeCopyPasteAction.KIND, InvokeCopyPasteActionHandler);
        rebind(TYPES.IAsyncClipboardService).to(KseClipboardService).inSingletonScope();
    },
    { featureId: Symbol('kseInteraction') }
);
