/*
 * The simulation's diagram: the page opened with `&simulation=1` by the workbench's Simulation
 * view shows the statechart read-only; the view runs the statechart on the C++ engine (a simulator
 * program, org.kse.simulation) and, after every command, tells the page what to draw through
 * `window.kseSimulation.show(activeLabels, takenTransitionIndexes)` (SWT Browser.execute). The
 * page keeps no state of the simulation: it draws the configuration it was told last.
 *
 * The active states are outlined and the transitions the last command took marked as the live
 * monitor does (highlight.ts): here a user looks at one step at a time, so the marks stay until
 * the next command instead of fading.
 *
 * `body[data-kse-simulation]` counts the configurations drawn; `window.kseSimulation` also lets
 * tests read what the diagram shows.
 */
import { ModifyCSSFeedbackAction } from '@eclipse-glsp/client';
import { DiagramPage } from './diagram-page';
import { CSS_ACTIVE, CSS_FIRED, cssChanges, emptyMapping, Mapping, mappingOf } from './highlight';
import './simulation.css';

export interface SimulationHandle {
    /** Draws this configuration: the states' labels (as the engine names them) and the transitions' model indexes. */
    show(activeLabels: string[], takenTransitionIndexes: number[]): Promise<void>;
    /** The labels of the states outlined on the diagram (read from the drawn SVG: what a user sees), sorted. */
    drawnActiveLabels(): string[];
    /** The model indexes of the transitions marked as just taken on the diagram, ascending. */
    drawnTakenIndexes(): number[];
    /** Labels the view named that the diagram does not have (a model edited since the simulator was built). */
    unknownLabels(): string[];
}

/** Whether the page was opened by the Simulation view (&simulation=1). */
export function isSimulation(location: Location): boolean {
    return new URLSearchParams(location.search).get('simulation') === '1';
}

const TRANSITION_PREFIX = '//@transitions.';

export function installSimulation(page: DiagramPage, ready: Promise<void>): SimulationHandle {
    const { dispatcher, editorContext } = page;
    document.body.classList.add('kse-simulated');
    let mapping: Mapping = emptyMapping();
    let labelOf = new Map<string, string>();
    // what the view said last, and what the diagram shows
    let wantedLabels: string[] = [];
    let wantedTaken: number[] = [];
    let drawnActive = new Set<string>();
    let drawnFired = new Set<string>();
    let unknown: string[] = [];
    let drawn = 0;
    let drawing: Promise<void> = Promise.resolve();

    function remap(): void {
        mapping = mappingOf(editorContext.modelRoot);
        labelOf = new Map([...mapping.stateByLabel].map(([label, id]) => [id, label]));
    }

    async function draw(): Promise<void> {
        const active = new Set<string>();
        unknown = [];
        for (const label of wantedLabels) {
            const id = mapping.stateByLabel.get(label);
            if (id) {
                active.add(id);
            } else {
                unknown.push(label);
            }
        }
        const fired = new Set<string>();
        for (const index of wantedTaken) {
            const id = TRANSITION_PREFIX + String(index);
            if (mapping.transitions.has(id)) {
                fired.add(id);
            }
        }
        const actions: ModifyCSSFeedbackAction[] = [...cssChanges(drawnActive, active, CSS_ACTIVE), ...cssChanges(drawnFired, fired, CSS_FIRED)];
        drawnActive = active;
        drawnFired = fired;
        if (actions.length > 0) {
            await dispatcher.dispatchAll(actions);
        }
        // the diagram draws what it was sent in its next animation frame
        await new Promise<void>(resolve => requestAnimationFrame(() => requestAnimationFrame(() => resolve())));
        drawn++;
        document.body.dataset.kseSimulation = String(drawn);
    }

    // a model shown anew (the file changed on disk, a reconnection) has lost the classes: draw everything again
    editorContext.onModelRootChanged(root => {
        if (root.type === 'NONE' || root.id === 'EMPTY') {
            return;
        }
        remap();
        drawnActive = new Set();
        drawnFired = new Set();
        drawing = drawing.then(draw);
    });

    const shown = ready.then(remap);

    function drawnIds(css: string): string[] {
        return Array.from(document.querySelectorAll(`#kse-diagram g.${css}[data-id]`)).map(element => element.getAttribute('data-id') ?? '');
    }

    return {
        show(activeLabels: string[], takenTransitionIndexes: number[]): Promise<void> {
            wantedLabels = activeLabels.filter(label => typeof label === 'string');
            wantedTaken = takenTransitionIndexes.filter(index => Number.isInteger(index));
            // calls before the first model is shown draw once it is; calls in a row draw in order
            drawing = drawing.then(() => shown).then(draw);
            return drawing;
        },
        drawnActiveLabels: () =>
            drawnIds(CSS_ACTIVE)
                .map(id => labelOf.get(id) ?? id)
                .sort(),
        drawnTakenIndexes: () =>
            drawnIds(CSS_FIRED)
                .filter(id => id.startsWith(TRANSITION_PREFIX))
                .map(id => Number(id.slice(TRANSITION_PREFIX.length)))
                .sort((a, b) => a - b),
        unknownLabels: () => unknown.slice()
    };
}
