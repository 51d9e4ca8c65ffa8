// Large statecharts for the scale tests and the browser benchmark, made as a user makes them: a
// liveness formula turned into a statechart by `kse transform` (a valid model, without a notation
// file: the diagram server arranges it with ELK when it is first opened).
import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { repository, servedFolder } from './harness.mjs';

/**
 * A behaviour that chooses among `capabilities`, each a choice of `activities` repeated
 * activities: nested OR states as real behaviours have, about 4 states per activity.
 */
export function choiceFormula(name, capabilities, activities) {
    const lines = [name, `${name.toLowerCase()} = Init.(${Array.from({ length: capabilities }, (_, c) => `cap${c}`).join(' | ')})+`];
    for (let c = 0; c < capabilities; c++) {
        lines.push(`cap${c} = ${Array.from({ length: activities }, (_, a) => `Act${c}_${a}+`).join(' | ')}`);
    }
    return lines.join('\n') + '\n';
}

/** Writes `<name>.stct` into the served folder from choiceFormula; returns its path relative to the folder and its state count. */
export function generatedModel(name, capabilities, activities) {
    const formula = path.join(servedFolder(), `${name}.formula.txt`);
    const model = path.join(servedFolder(), `${name}.stct`);
    writeFileSync(formula, choiceFormula(name, capabilities, activities));
    execFileSync(path.join(repository, 'kse'), ['transform', '-q', formula, '-o', model], { stdio: ['ignore', 'ignore', 'inherit'] });
    return { model: `${name}.stct`, states: stateCount(readFileSync(model, 'utf8')) };
}

/** How many states a .stct file declares. */
export function stateCount(xml) {
    return (xml.match(/<(?:nodes|Children)\b/g) ?? []).length;
}
