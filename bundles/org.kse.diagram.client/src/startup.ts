/*
 * The page's start-up until its first model is shown: then the diagram opens where the user left it
 * before a dropped connection (viewport and selection restored), else at a readable viewport, and
 * the page is ready (body data-kse="ready", window.kse.ready). Every model shown after that counts
 * in data-kse-revision; a server error before the first model marks the page as failed.
 *
 * Not a GLSP IDiagramStartup (postModelInitialization): GLSP calls that hook one after another with
 * its own start-up services (after the tool palette's request to the server, for one), so the page
 * would be ready later than two frames after its first model, and an error in it would only be logged.
 */
import { GModelRoot, SelectAction, SetViewportAction } from '@eclipse-glsp/client';
import { ServerConnection } from './connection';
import { DiagramPage, diagramSvg } from './diagram-page';
import { openingViewportAction } from './readable-viewport';
import { onStatus, report } from './status-line';
import { fitStatesAction } from './viewport';

export interface Startup {
    /** Resolved when the first model is shown. */
    ready: Promise<void>;
    /** Whether the first model was shown. */
    isShown(): boolean;
}

function nextFrame(): Promise<void> {
    return new Promise(resolve => requestAnimationFrame(() => resolve()));
}

export function startPage(page: DiagramPage, connection: ServerConnection): Startup {
    const { dispatcher, editorContext } = page;
    let resolveReady: () => void = () => undefined;
    const ready = new Promise<void>(resolve => (resolveReady = resolve));
    let shown = false;
    let revision = 0;

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
                await showFirst(root);
            }
        });
    });

    async function showFirst(root: Readonly<GModelRoot>): Promise<void> {
        const restore = connection.takeRestore();
        if (restore) {
            await dispatcher.dispatch(SetViewportAction.create(root.id, { scroll: restore.scroll, zoom: restore.zoom }, { animate: false }));
            await dispatcher.dispatch(SelectAction.setSelection(restore.selection));
        } else {
            const canvas = diagramSvg(page.clientId)?.getBoundingClientRect() ?? { width: window.innerWidth, height: window.innerHeight };
            await dispatcher.dispatch(openingViewportAction(root, canvas) ?? fitStatesAction(editorContext.modelRoot, 1, false));
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

    // a server error before the first model (e.g. "cannot open …") marks the page as failed
    onStatus(entry => {
        if (!shown && entry.kind === 'message' && (entry.severity === 'ERROR' || entry.severity === 'FATAL')) {
            document.body.dataset.kse = 'error';
        }
    });

    return { ready, isShown: () => shown };
}
