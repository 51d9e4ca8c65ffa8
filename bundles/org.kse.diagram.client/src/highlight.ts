/*
 * What the live monitor (monitor.ts) and the replay (replay.ts) share to show a robot's statechart
 * at work: how the engine's names of states and transitions map to the diagram's element ids, and
 * the CSS feedback (GLSP's, as the drop feedback of reparent.ts) that outlines the active states
 * and flashes fired transitions. Both draw by difference: only the elements whose class changes
 * are named in the actions, so that a redraw costs what changed, not the size of the chart.
 */
import { ModifyCSSFeedbackAction } from '@eclipse-glsp/client';

export const CSS_ACTIVE = 'kse-active';
export const CSS_FIRED = 'kse-fired';

/** A diagram element as the GLSP client model has it, or as its plain JSON copy (window.kse.modelRoot()). */
export interface ElementLike {
    readonly type: string;
    readonly id: string;
    readonly args?: Readonly<Record<string, unknown>>;
    readonly children?: readonly ElementLike[];
}

/** The element ids a robot's runtime names map to. */
export interface Mapping {
    /** A state's model label ("0.2.2.5", the monitor's names) → its id. */
    stateByLabel: Map<string, string>;
    /** A state's engine name ("Node_goalie", "Node_0_2_2_5", the match log's names) → its id. */
    stateByEngineName: Map<string, string>;
    /** How many states the diagram has. */
    states: number;
    /** The transitions' ids (//@transitions.N: N is the index of the engine's Definition::Transitions()). */
    transitions: Set<string>;
    /** A transition's id → its expression ("guard / actions"). */
    expressionOf: Map<string, string>;
}

export function emptyMapping(): Mapping {
    return { stateByLabel: new Map(), stateByEngineName: new Map(), states: 0, transitions: new Set(), expressionOf: new Map() };
}

function stringArg(element: ElementLike, name: string): string {
    const value = element.args?.[name];
    return typeof value === 'string' ? value : '';
}

/** A transition's id: the model's path of it (its labels' ids add #expression or #name). */
const TRANSITION_ID = /^\/\/@transitions\.\d+$/;

/**
 * The engine's name of a state, by the generator's rule (GenerationPlan.stateName, CppNames.label):
 * Node_ and its name, or, when it has none or its name is its label, its label with '_' for each
 * character that is not an ASCII letter, digit or '_' ("unlabeled" without a label).
 */
export function engineStateName(label: string, name: string): string {
    const byLabel = name === '' || name === label;
    return 'Node_' + (byLabel ? (label === '' ? 'unlabeled' : label.replace(/[^A-Za-z0-9_]/g, '_')) : name);
}

export function mappingOf(root: ElementLike): Mapping {
    const mapping = emptyMapping();
    const visit = (element: ElementLike): void => {
        if (element.type.startsWith('state:')) {
            mapping.states++;
            const label = stringArg(element, 'label');
            if (label) {
                mapping.stateByLabel.set(label, element.id);
            }
            mapping.stateByEngineName.set(engineStateName(label, stringArg(element, 'name')), element.id);
        } else if (TRANSITION_ID.test(element.id)) {
            mapping.transitions.add(element.id);
            mapping.expressionOf.set(element.id, stringArg(element, 'expression'));
        }
        for (const child of element.children ?? []) {
            visit(child);
        }
    };
    visit(root);
    return mapping;
}

/** The actions that take the class `css` off the elements drawn with it and put it on those that should have it. */
export function cssChanges(before: ReadonlySet<string>, after: ReadonlySet<string>, css: string): ModifyCSSFeedbackAction[] {
    const actions: ModifyCSSFeedbackAction[] = [];
    const gone = [...before].filter(id => !after.has(id));
    const come = [...after].filter(id => !before.has(id));
    if (gone.length > 0) {
        actions.push(ModifyCSSFeedbackAction.create({ elements: gone, remove: [css] }));
    }
    if (come.length > 0) {
        actions.push(ModifyCSSFeedbackAction.create({ elements: come, add: [css] }));
    }
    return actions;
}
