/*
 * The page's connection: one WebSocket to the server that served the page, over which the GLSP
 * client talks to the diagram server. A connection that drops after the diagram was shown is made
 * again, and the page opens anew where the user left it (viewport and selection restored).
 */
import { BaseJsonrpcGLSPClient, DiagramLoader, GLSPClient, GModelRoot, createWebSocketConnection, isViewport, wrap } from '@eclipse-glsp/client';
import { DiagramPage } from './diagram-page';
import { PageParameters } from './page';
import { failed, report } from './status-line';

declare global {
    interface Window {
        /**
         * Set by a host that embeds the page: called when the page lost its connection, answers the
         * address to open the page anew at (on a server it started again if the old one is gone,
         * maybe on another port), or null when it cannot.
         */
        kseHostReconnect?: () => unknown;
    }
}

/** The WebSocket close code of a message larger than the receiver takes (RFC 6455). */
const MESSAGE_TOO_BIG = 1009;

/** What a page that reopens after a dropped connection restores, kept for this tab only. */
export interface Restore {
    scroll: { x: number; y: number };
    zoom: number;
    selection: string[];
}

/** How a host hands the page what to restore (a reopened page's origin may differ, so its session storage too). */
const RESTORE_HASH = '#kse-restore=';

function sleep(milliseconds: number): Promise<void> {
    return new Promise(resolve => setTimeout(resolve, milliseconds));
}

export class ServerConnection {
    /** The GLSP client, once the WebSocket is open (what the diagram container's glspClientProvider answers). */
    readonly client: Promise<GLSPClient>;
    protected resolveClient: (client: GLSPClient) => void = () => undefined;
    protected readonly restoreKey: string;
    /** True while the page reloads itself to reconnect (no question about unsaved edits then: the server keeps them). */
    protected reopening = false;

    constructor(protected readonly parameters: PageParameters) {
        this.client = new Promise<GLSPClient>(resolve => (this.resolveClient = resolve));
        this.restoreKey = `kse-restore:${parameters.model}`;
    }

    get isReopening(): boolean {
        return this.reopening;
    }

    /** Connects and opens the diagram; `shown` tells whether the first model was shown (only then a dropped connection is made again). */
    connect(page: DiagramPage, shown: () => boolean): void {
        const parameters = this.parameters;
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
            this.resolveClient(new BaseJsonrpcGLSPClient({ id: 'kse', connectionProvider: connection }));
            page.container
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
            if (opened && shown()) {
                void this.reconnect(page);
                return;
            }
            const reason = event.reason ? `: ${event.reason}` : '';
            report({ kind: 'connection', severity: 'ERROR', message: `Cannot connect to the diagram server (${event.code}${reason}).` });
            document.body.dataset.kseConnection = 'closed';
            document.body.dataset.kse = 'error';
        });
    }

    /**
     * A dropped connection (the server's machine slept, a proxy closed an idle socket, the network
     * blinked): the server keeps the model with its unsaved edits and its undo history, so the page
     * waits until the server answers again and opens the model anew, where the user left it. A
     * server that no longer knows the token was restarted: what it held is gone, and the page says so.
     */
    protected async reconnect(page: DiagramPage): Promise<void> {
        document.body.dataset.kseConnection = 'reconnecting';
        report({ kind: 'connection', severity: 'WARNING', message: 'Connection to the diagram server lost: reconnecting…' });
        const root = page.editorContext.modelRoot as GModelRoot;
        const restore: Restore = {
            scroll: isViewport(root) ? { ...root.scroll } : { x: 0, y: 0 },
            zoom: isViewport(root) ? root.zoom : 1,
            selection: page.selectionService.getSelectedElementIDs()
        };
        if (typeof window.kseHostReconnect === 'function') {
            this.reopenAt(window.kseHostReconnect(), restore);
            return;
        }
        for (let attempt = 0; ; attempt++) {
            await sleep(Math.min(5000, 250 * 2 ** attempt));
            try {
                const answer = await fetch(`/models?token=${encodeURIComponent(this.parameters.token)}`, { cache: 'no-store' });
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
        sessionStorage.setItem(this.restoreKey, JSON.stringify(restore));
        this.reopening = true;
        window.location.reload();
    }

    /**
     * Opens the page anew at the address its host gave, with what to restore in the address's fragment
     * (the new page's origin may differ, and with it its session storage).
     */
    protected reopenAt(address: unknown, restore: Restore): void {
        if (typeof address !== 'string') {
            document.body.dataset.kseConnection = 'closed';
            report({ kind: 'connection', severity: 'ERROR', message: 'The diagram server cannot be reached: close and reopen the editor (its model keeps your edits).' });
            return;
        }
        const target = new URL(address, window.location.href);
        target.hash = RESTORE_HASH.slice(1) + encodeURIComponent(JSON.stringify(restore));
        this.reopening = true;
        const sameDocument = target.origin + target.pathname + target.search === window.location.origin + window.location.pathname + window.location.search;
        window.location.href = target.toString();
        if (sameDocument) {
            window.location.reload(); // a change of the fragment alone does not load the page
        }
    }

    /** The viewport and selection of the page before its connection dropped, once. */
    takeRestore(): Restore | undefined {
        const fromHost = window.location.hash.startsWith(RESTORE_HASH) ? decodeURIComponent(window.location.hash.slice(RESTORE_HASH.length)) : null;
        if (fromHost !== null) {
            history.replaceState(null, '', window.location.pathname + window.location.search);
        }
        const saved = fromHost ?? sessionStorage.getItem(this.restoreKey);
        sessionStorage.removeItem(this.restoreKey);
        try {
            return saved ? (JSON.parse(saved) as Restore) : undefined;
        } catch {
            return undefined;
        }
    }
}
