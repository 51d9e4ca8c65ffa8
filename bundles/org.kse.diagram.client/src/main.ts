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
import { installMonitorHub, readHubParameters } from './monitor-hub';
import { installReplay, isReplayedDiagram, readReplayParameters } from './replay';
import { installSimulation, isSimulation } from './simulation';
import { newClientId, readPageParameters } from './page';
import { followEditorState } from './page-state';
import { startPage } from './startup';
import { installTestApi, KseHandle } from './test-api';
import { installToolbar } from './toolbar';
import './kse.css';

// opened to replay a match log: the page shows the log, and no diagram of its own (replay.ts)
const replay = readReplayParameters(window.location);
// opened to pick a running match or to watch several robots: no diagram of its own (monitor-hub.ts)
const hub = readHubParameters(window.location);
if (replay) {
    window.kse = { replay: installReplay(replay) } as unknown as KseHandle;
} else if (hub) {
    window.kse = { monitorHub: installMonitorHub(hub) } as unknown as KseHandle;
} else {
    showDiagram();
}

/** The diagram page of one model (the page's usual self). */
function showDiagram(): void {
    const parameters = readPageParameters(window.location);
    // opened to watch a running match: the diagram is only looked at (monitor.ts)
    const monitor = readMonitorParameters(window.location);
    // a robot's statechart shown by a replay (replay.ts): only looked at as well
    const replayed = isReplayedDiagram(window.location);
    // run by the workbench's Simulation view, which draws its configurations (simulation.ts): only looked at too
    const simulated = isSimulation(window.location);
    if (replayed) {
        document.body.classList.add('kse-replayed');
    }
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
            editMode: monitor || replayed || simulated ? 'readonly' : 'editable'
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
    if (simulated) {
        window.kseSimulation = installSimulation(page, startup.ready);
    }

    connection.connect(page, startup.isShown);
}
