/*
 * The KSE statechart diagram page. Opened as http://127.0.0.1:<port>/?token=<token>&model=<file>,
 * it connects to the GLSP server of the same host (ws://<host>/kse?token=<token>), opens the model
 * and wires the toolbar, the status line and the `window.kse` handle used by tests and hosts.
 *
 * This module only wires the page's parts: connection.ts (connect, reconnect, restore), startup.ts
 * (the first model shown, ready), page-state.ts (title, dirty mark, selection for the host),
 * toolbar.ts (the toolbar's actions, printing) and test-api.ts (`window.kse`).
 */
import 'reflect-metadata';

// GLSP's styles (it imports them) come first, then sprotty's for label editing, then the page's own (kse.css)
import '@eclipse-glsp/client';
import 'sprotty/css/edit-label.css';
import { ServerConnection } from './connection';
import { createKseDiagramContainer } from './di.config';
import { createBaseDiv, diagramPage } from './diagram-page';
import { setExportBaseName } from './export';
import { DIAGRAM_TYPE } from './model';
import { installMonitor, readMonitorParameters } from './monitor';
import { newClientId, readPageParameters } from './page';
import { followEditorState } from './page-state';
import { startPage } from './startup';
import { installTestApi } from './test-api';
import { installToolbar } from './toolbar';
import './kse.css';

const parameters = readPageParameters(window.location);
// opened to watch a running match: the diagram is only looked at (monitor.ts)
const monitor = readMonitorParameters(window.location);
const clientId = newClientId();
setExportBaseName(parameters.modelName);
document.title = `${parameters.modelName} – KSE`;
createBaseDiv(clientId);

const connection = new ServerConnection(parameters);
const container = createKseDiagramContainer(
    {
        clientId,
        diagramType: DIAGRAM_TYPE,
        sourceUri: parameters.model,
        glspClientProvider: () => connection.client,
        editMode: monitor ? 'readonly' : 'editable'
    },
    { popupOpenDelay: 500, popupCloseDelay: 300 }
);
const page = diagramPage(parameters, clientId, container);

followEditorState(page, connection);
const startup = startPage(page, connection);
const toolbar = installToolbar(page);
installTestApi(page, startup.ready, toolbar);
if (monitor) {
    window.kse.monitor = installMonitor(page, startup.ready, monitor);
}

connection.connect(page, startup.isShown);
