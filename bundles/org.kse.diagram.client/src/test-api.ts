/*
 * `window.kse`: the page's handle for tests (the end-to-end tests drive the page through it) and
 * for hosts that embed the page.
 */
import { Action, SelectAction } from '@eclipse-glsp/client';
import { Container } from 'inversify';
import { DiagramPage } from './diagram-page';
import { exportSvg, svgToPng } from './export';
import { ElementJson, toJson } from './model-json';
import { MonitorHandle } from './monitor';
import { HubHandle } from './monitor-hub';
import { ReplayHandle } from './replay';
import { SimulationHandle } from './simulation';
import { StatusEntry, statusHistory } from './status-line';
import { Toolbar } from './toolbar';

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
    /** The live monitor, when the page was opened to watch a match (&monitor=…). */
    monitor?: MonitorHandle;
    /** The replay, when the page was opened to replay a match log (&replay=…); then it is the handle's only member. */
    replay?: ReplayHandle;
    /** The live monitor's picker or board, when the page was opened as one (&monitor=pick, &monitor=board); then it is the handle's only member. */
    monitorHub?: HubHandle;
}

declare global {
    interface Window {
        kse: KseHandle;
        /** The Simulation view's handle, when the page was opened by it (&simulation=1). */
        kseSimulation?: SimulationHandle;
    }
}

export function installTestApi(page: DiagramPage, ready: Promise<void>, toolbar: Toolbar): void {
    const { dispatcher, editorContext, selectionService } = page;
    window.kse = {
        ready,
        clientId: page.clientId,
        model: page.parameters.model,
        // resolved without a value: what the dispatcher resolves with may be the (cyclic) model
        dispatch: action => dispatcher.dispatch(action).then(() => undefined),
        request: action => dispatcher.request(action as Action & { requestId: string }).then(response => JSON.parse(JSON.stringify(response)) as Action),
        modelRoot: () => toJson(editorContext.modelRoot),
        exportSvg: (selected?: boolean) => exportSvg(page, selected),
        exportPng: async (selected?: boolean) => {
            const png = await svgToPng(await exportSvg(page, selected));
            return await new Promise<string>((resolve, reject) => {
                const reader = new FileReader();
                reader.onload = () => resolve(String(reader.result));
                reader.onerror = () => reject(reader.error);
                reader.readAsDataURL(png);
            });
        },
        run: toolbar.run,
        messages: () => statusHistory.slice(),
        isDirty: () => editorContext.isDirty,
        selection: () => selectionService.getSelectedElementIDs(),
        select: ids => dispatcher.dispatch(SelectAction.setSelection(ids)).then(() => undefined),
        container: page.container
    };
}
