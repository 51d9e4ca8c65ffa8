/*
 * The KSE statechart diagram page. Opened as http://127.0.0.1:<port>/?token=<token>&model=<file>,
 * it connects to the GLSP server of the same host (ws://<host>/kse?token=<token>), opens the model
 * and wires the toolbar, the status line and the `window.kse` handle used by tests and hosts.
 */
import 'reflect-metadata';

import {
    Action,
    BaseJsonrpcGLSPClient,
    DiagramLoader,
    EditorContextService,
    FitToScreenAction,
    GLSPActionDispatcher,
    GLSPClient,
    GChildElement,
    GEdge,
    GModelElement,
    GModelRoot,
    IGridManager,
    LayoutOperation,
    RedoAction,
    RequestExportSvgAction,
    SaveModelAction,
    SelectAction,
    SelectionService,
    SetViewportAction,
    TYPES,
    UndoAction,
    createWebSocketConnection,
    isBoundsAware,
    isViewport,
    wrap
} from '@eclipse-glsp/client';
import 'sprotty/css/edit-label.css';
import { Container } from 'inversify';
import { createKseDiagramContainer } from './di.config';
import { Focus, download, pngFileName, setExportBaseName, standaloneSvg, svgFileName, svgToPng } from './export';
import { DIAGRAM_TYPE } from './model';
import { ElementJson, toJson } from './model-json';
import { newClientId, readPageParameters } from './page';
import { StatusEntry, onStatus, report, statusHistory } from './status-line';
import { showGridPressed } from './toolbar-sync';
import { fitStatesAction, zoomAction } from './viewport';
import { openingViewportAction } from './readable-viewport';
import './kse.css';

export interface KseHandle {
    /** Resolved when the first model is shown. */
    ready: Promise<void>;
    /** The GLSP client id (also the id of the diagram's base div). */
    clientId: string;
    /** The model file the page edits (relative to the served folder). */
    model: string;
    /** Sends any GLSP action through the action dispatcher. */
    dispatch(action: Action): Promise<void>;
    /** Sends a request action and resolves with its response. */
    request(action: Action & { requestId: string }): Promise<Action>;
    /** The current client model as plain JSON. */
    modelRoot(): ElementJson;
    /** The diagram (or, with `selected`, the one selected composite state) as a standalone SVG document. */
    exportSvg(selected?: boolean): Promise<string>;
    /** The diagram (or, with `selected`, the one selected composite state) as a PNG (a data: URL). */
    exportPng(selected?: boolean): Promise<string>;
    /** Runs a toolbar action by its data-action name. */
    run(action: string): Promise<void>;
    /** Status and messages reported so far. */
    messages(): StatusEntry[];
    /** Whether the model has unsaved changes. */
    isDirty(): boolean;
    /** The ids of the selected elements (model element paths; a label's id ends in #name or #expression). */
    selection(): string[];
    /** Selects exactly these elements (and reveals nothing else). */
    select(ids: string[]): Promise<void>;
    /** The dependency injection container (for debugging). */
    container: Container;
}

declare global {
    interface Window {
        kse: KseHandle;
        /**
         * Set by a host that embeds the page (the KSE workbench, through an SWT BrowserFunction):
         * told the selected ids, as a JSON array, whenever the selection changes.
         */
        kseHostSelection?: (idsJson: string) => unknown;
        /**
         * Set by a host that embeds the page: called when the page lost its connection, answers the
         * address to open the page anew at (on a server it started again if the old one is gone,
         * maybe on another port), or null when it cannot.
         */
        kseHostReconnect?: () => unknown;
    }
}

const parameters = readPageParameters(window.location);
const clientId = newClientId();
setExportBaseName(parameters.modelName);
document.title = `${parameters.modelName} – KSE`;

// the base div of the diagram has the client id as its id (GLSP renders into the element with that id)
const host = document.getElementById('kse-diagram');
if (!host) {
    throw new Error('the page has no #kse-diagram element');
}
const baseDiv = document.createElement('div');
baseDiv.id = clientId;
baseDiv.className = 'kse-base';
host.appendChild(baseDiv);

let resolveClient: (client: GLSPClient) => void = () => undefined;
const clientPromise = new Promise<GLSPClient>(resolve => (resolveClient = resolve));

const container = createKseDiagramContainer(
    { clientId, diagramType: DIAGRAM_TYPE, sourceUri: parameters.model, glspClientProvider: () => clientPromise },
    { popupOpenDelay: 500, popupCloseDelay: 300 }
);
const dispatcher = container.get(GLSPActionDispatcher);
const editorContext = container.get(EditorContextService);
const selectionService = container.get(SelectionService);

selectionService.onSelectionChanged(() => {
    const ids = selectionService.getSelectedElementIDs();
    document.body.dataset.kseSelection = ids.join(' ');
    if (typeof window.kseHostSelection === 'function') {
        window.kseHostSelection(JSON.stringify(ids));
    }
});

let resolveReady: () => void = () => undefined;
const ready = new Promise<void>(resolve => (resolveReady = resolve));
let shown = false;
let revision = 0;

function nextFrame(): Promise<void> {
    return new Promise(resolve => requestAnimationFrame(() => resolve()));
}

editorContext.onModelRootChanged(root => {
    if (root.type === 'NONE' || root.id === 'EMPTY') {
        return;
    }
    revision++;
    const current = revision;
    void nextFrame().then(async () => {
        await nextFrame();
        document.body.dataset.kseRevision = String(current);
        if (!shown) {
            shown = true;
            const restore = takeRestore();
            if (restore) {
                await dispatcher.dispatch(SetViewportAction.create(root.id, { scroll: restore.scroll, zoom: restore.zoom }, { animate: false }));
                await dispatcher.dispatch(SelectAction.setSelection(restore.selection));
            } else {
                const canvas = diagramSvg()?.getBoundingClientRect() ?? { width: window.innerWidth, height: window.innerHeight };
                await dispatcher.dispatch(openingViewportAction(root, canvas) ?? fitAction(1, false));
            }
            await nextFrame();
            await nextFrame();
            document.body.dataset.kse = 'ready';
            document.body.dataset.kseConnection = restore ? 'reconnected' : 'open';
            report({ kind: 'connection', severity: 'NONE', message: '' });
            if (restore) {
                report({ kind: 'status', severity: 'OK', message: 'Reconnected to the diagram server' }, 4000);
            }
            resolveReady();
        }
    });
});

editorContext.onDirtyStateChanged(change => {
    if (!change.isDirty && change.reason === 'save') {
        report({ kind: 'status', severity: 'OK', message: `Saved ${parameters.model}` }, 4000);
    }
    document.title = `${parameters.modelName}${change.isDirty ? ' *' : ''} – KSE`;
    document.body.dataset.kseDirty = String(change.isDirty);
    document.querySelector('[data-action="save"]')?.classList.toggle('kse-dirty', change.isDirty);
});

function fitAction(maxZoom: number, animate: boolean): FitToScreenAction {
    return fitStatesAction(editorContext.modelRoot, maxZoom, animate);
}

function diagramSvg(): SVGSVGElement | null {
    return document.getElementById(clientId)?.querySelector('svg') ?? null;
}

function focusDiagram(): void {
    const svg = diagramSvg();
    if (svg && typeof (svg as unknown as HTMLElement).focus === 'function') {
        (svg as unknown as HTMLElement).focus({ preventScroll: true });
    }
}

/**
 * The one selected composite (OR or AND) state: where it lies in diagram coordinates (children
 * are placed relative to their parent) and the transitions between its insides; undefined when
 * the selection is not a single composite. Ids are model paths: an inside's id extends its owner's.
 */
function selectedComposite(): Focus | undefined {
    const selected = selectionService.getSelectedElements();
    if (selected.length !== 1 || !['state:or', 'state:and'].includes(selected[0].type)) {
        return undefined;
    }
    const composite = selected[0] as unknown as GModelElement;
    if (!isBoundsAware(composite)) {
        return undefined;
    }
    const area = { ...composite.bounds };
    let parent = (composite as unknown as GChildElement).parent as GModelElement | undefined;
    while (parent && !(parent instanceof GModelRoot)) {
        if (isBoundsAware(parent)) {
            area.x += parent.bounds.x;
            area.y += parent.bounds.y;
        }
        parent = (parent as unknown as GChildElement).parent as GModelElement | undefined;
    }
    const within = (id: string | undefined) => id !== undefined && id.startsWith(composite.id + '/');
    const innerTransitions = Array.from(composite.root.index.all())
        .filter(element => element instanceof GEdge && within(element.sourceId) && within(element.targetId))
        .map(element => element.id);
    return { area, id: composite.id, innerTransitions };
}

/** The diagram as a standalone SVG; with `selected`, only the selected composite when there is one. */
async function exportSvg(selected = false): Promise<string> {
    const focus = selected ? selectedComposite() : undefined;
    const response = await dispatcher.request(RequestExportSvgAction.create());
    return standaloneSvg(response.svg, focus);
}

function zoomBy(factor: number): Promise<void> {
    const action = zoomAction(editorContext.modelRoot, factor);
    return action ? dispatcher.dispatch(action) : Promise.resolve();
}

function gridManager(): IGridManager | undefined {
    return container.isBound(TYPES.IGridManager) ? container.get<IGridManager>(TYPES.IGridManager) : undefined;
}

function updateGridButton(): void {
    showGridPressed(gridManager()?.isGridVisible ?? false);
}

async function printDiagram(): Promise<void> {
    const holder = document.getElementById('kse-print');
    if (holder) {
        const svg = await exportSvg();
        const parsed = new DOMParser().parseFromString(svg, 'image/svg+xml').documentElement;
        holder.replaceChildren(document.importNode(parsed, true));
        document.body.classList.add('kse-printing');
    }
    window.print();
}

window.addEventListener('afterprint', () => {
    document.body.classList.remove('kse-printing');
    document.getElementById('kse-print')?.replaceChildren();
});

function failed(what: string): (error: unknown) => void {
    return error => {
        const message = error instanceof Error ? error.message : String(error);
        report({ kind: 'status', severity: 'ERROR', message: `${what} failed: ${message}` });
    };
}

const toolbarActions: Record<string, () => Promise<void>> = {
    save: () => dispatcher.dispatch(SaveModelAction.create()),
    undo: () => dispatcher.dispatch(UndoAction.create()),
    redo: () => dispatcher.dispatch(RedoAction.create()),
    layout: () => dispatcher.dispatch(LayoutOperation.create()),
    fit: () => dispatcher.dispatch(fitAction(2, true)),
    'zoom-in': () => zoomBy(1.25),
    'zoom-out': () => zoomBy(0.8),
    grid: async () => {
        gridManager()?.toggleGridVisible();
        updateGridButton();
    },
    'export-svg': async () => {
        const svg = await exportSvg(true);
        download(svgFileName(), new Blob([svg], { type: 'image/svg+xml;charset=utf-8' }));
    },
    'export-png': async () => {
        const png = await svgToPng(await exportSvg(true));
        download(pngFileName(), png);
    },
    print: () => printDiagram()
};

async function run(action: string): Promise<void> {
    const perform = toolbarActions[action];
    if (!perform) {
        throw new Error(`unknown toolbar action: ${action}`);
    }
    await perform();
}

for (const button of Array.from(document.querySelectorAll<HTMLButtonElement>('#kse-toolbar [data-action]'))) {
    const action = button.dataset.action ?? '';
    // keep the keyboard focus on the diagram, so that its shortcuts go on working after a click
    button.addEventListener('mousedown', event => event.preventDefault());
    button.addEventListener('click', () => {
        run(action)
            .catch(failed(button.title || action))
            .finally(() => {
                if (action !== 'print') {
                    focusDiagram();
                }
            });
    });
}

window.kse = {
    ready,
    clientId,
    model: parameters.model,
    // resolved without a value: what the dispatcher resolves with may be the (cyclic) model
    dispatch: action => dispatcher.dispatch(action).then(() => undefined),
    request: action => dispatcher.request(action as Action & { requestId: string }).then(response => JSON.parse(JSON.stringify(response)) as Action),
    modelRoot: () => toJson(editorContext.modelRoot),
    exportSvg,
    exportPng: async (selected?: boolean) => {
        const png = await svgToPng(await exportSvg(selected));
        return await new Promise<string>((resolve, reject) => {
            const reader = new FileReader();
            reader.onload = () => resolve(String(reader.result));
            reader.onerror = () => reject(reader.error);
            reader.readAsDataURL(png);
        });
    },
    run,
    messages: () => statusHistory.slice(),
    isDirty: () => editorContext.isDirty,
    selection: () => selectionService.getSelectedElementIDs(),
    select: ids => dispatcher.dispatch(SelectAction.setSelection(ids)).then(() => undefined),
    container
};

// connection: one WebSocket to the server that served the page
function connect(): void {
    if (!parameters.model) {
        report({ kind: 'connection', severity: 'ERROR', message: 'No model given: open the page with ?token=…&model=<file>.stct' });
        document.body.dataset.kse = 'error';
        return;
    }
    if (!window.location.host) {
        report({ kind: 'connection', severity: 'ERROR', message: 'The page must be served by the KSE diagram server (http://127.0.0.1:<port>/).' });
        document.body.dataset.kse = 'error';
        return;
    }
    report({ kind: 'connection', severity: 'INFO', message: `Connecting to the diagram server for ${parameters.model}…` });
    const socket = new WebSocket(parameters.socketUrl);
    let opened = false;
    socket.addEventListener('open', () => {
        opened = true;
        const connection = createWebSocketConnection(wrap(socket));
        resolveClient(new BaseJsonrpcGLSPClient({ id: 'kse', connectionProvider: connection }));
        container
            .get(DiagramLoader)
            .load()
            .catch(error => {
                failed('Opening the diagram')(error);
                document.body.dataset.kse = 'error';
            });
    });
    socket.addEventListener('close', event => {
        if (event.code === MESSAGE_TOO_BIG) {
            // the server refused a message of this page as too large: reconnecting would only send it again
            report({
                kind: 'connection',
                severity: 'ERROR',
                message: `The diagram is too large for the diagram server (${event.reason || 'a message of this page exceeded its limit'}).`
            });
            document.body.dataset.kseConnection = 'closed';
            document.body.dataset.kse = 'error';
            return;
        }
        if (opened && shown) {
            void reconnect();
            return;
        }
        const reason = event.reason ? `: ${event.reason}` : '';
        report({ kind: 'connection', severity: 'ERROR', message: `Cannot connect to the diagram server (${event.code}${reason}).` });
        document.body.dataset.kseConnection = 'closed';
        document.body.dataset.kse = 'error';
    });
}

/** The WebSocket close code of a message larger than the receiver takes (RFC 6455). */
const MESSAGE_TOO_BIG = 1009;

/** What a page that reopens after a dropped connection restores, kept for this tab only. */
interface Restore {
    scroll: { x: number; y: number };
    zoom: number;
    selection: string[];
}

const restoreKey = `kse-restore:${parameters.model}`;
/** How a host hands the page what to restore (a reopened page's origin may differ, so its session storage too). */
const RESTORE_HASH = '#kse-restore=';

function sleep(milliseconds: number): Promise<void> {
    return new Promise(resolve => setTimeout(resolve, milliseconds));
}

/**
 * A dropped connection (the server's machine slept, a proxy closed an idle socket, the network
 * blinked): the server keeps the model with its unsaved edits and its undo history, so the page
 * waits until the server answers again and opens the model anew, where the user left it. A
 * server that no longer knows the token was restarted: what it held is gone, and the page says so.
 */
async function reconnect(): Promise<void> {
    document.body.dataset.kseConnection = 'reconnecting';
    report({ kind: 'connection', severity: 'WARNING', message: 'Connection to the diagram server lost: reconnecting…' });
    const root = editorContext.modelRoot as GModelRoot;
    const restore: Restore = {
        scroll: isViewport(root) ? { ...root.scroll } : { x: 0, y: 0 },
        zoom: isViewport(root) ? root.zoom : 1,
        selection: selectionService.getSelectedElementIDs()
    };
    if (typeof window.kseHostReconnect === 'function') {
        reopenAt(window.kseHostReconnect(), restore);
        return;
    }
    for (let attempt = 0; ; attempt++) {
        await sleep(Math.min(5000, 250 * 2 ** attempt));
        try {
            const answer = await fetch(`/models?token=${encodeURIComponent(parameters.token)}`, { cache: 'no-store' });
            if (answer.ok) {
                break;
            }
            if (answer.status === 403) {
                document.body.dataset.kseConnection = 'closed';
                report({
                    kind: 'connection',
                    severity: 'ERROR',
                    message: 'The diagram server was restarted: open the address it printed (edits not saved before it stopped are gone).'
                });
                return;
            }
        } catch {
            // the server is not back yet
        }
    }
    sessionStorage.setItem(restoreKey, JSON.stringify(restore));
    reopening = true;
    window.location.reload();
}

/**
 * Opens the page anew at the address its host gave, with what to restore in the address's fragment
 * (the new page's origin may differ, and with it its session storage).
 */
function reopenAt(address: unknown, restore: Restore): void {
    if (typeof address !== 'string') {
        document.body.dataset.kseConnection = 'closed';
        report({ kind: 'connection', severity: 'ERROR', message: 'The diagram server cannot be reached: close and reopen the editor (its model keeps your edits).' });
        return;
    }
    const target = new URL(address, window.location.href);
    target.hash = RESTORE_HASH.slice(1) + encodeURIComponent(JSON.stringify(restore));
    reopening = true;
    const sameDocument = target.origin + target.pathname + target.search === window.location.origin + window.location.pathname + window.location.search;
    window.location.href = target.toString();
    if (sameDocument) {
        window.location.reload(); // a change of the fragment alone does not load the page
    }
}

/** True while the page reloads itself to reconnect (no question about unsaved edits then: the server keeps them). */
let reopening = false;

/** The viewport and selection of the page before its connection dropped, once. */
function takeRestore(): Restore | undefined {
    const fromHost = window.location.hash.startsWith(RESTORE_HASH) ? decodeURIComponent(window.location.hash.slice(RESTORE_HASH.length)) : null;
    if (fromHost !== null) {
        history.replaceState(null, '', window.location.pathname + window.location.search);
    }
    const saved = fromHost ?? sessionStorage.getItem(restoreKey);
    sessionStorage.removeItem(restoreKey);
    try {
        return saved ? (JSON.parse(saved) as Restore) : undefined;
    } catch {
        return undefined;
    }
}

// a server error before the first model (e.g. "cannot open …") marks the page as failed
onStatus(entry => {
    if (!shown && entry.kind === 'message' && (entry.severity === 'ERROR' || entry.severity === 'FATAL')) {
        document.body.dataset.kse = 'error';
    }
});

// Closing or leaving a page with unsaved edits asks first; in the workbench its editor asks instead.
window.addEventListener('beforeunload', event => {
    if (editorContext.isDirty && !reopening && typeof window.kseHostSelection !== 'function') {
        event.preventDefault();
        event.returnValue = '';
    }
});

updateGridButton();
connect();
