// `kse diagram` and the diagram editor draw from one notation style (org.kse.notation's
// notation-style.json): the Goalie drawn both ways has, state by state, the same kind, shape,
// colours, stroke, corner radius, size, caption and label in the same font, and the same
// transitions in the same line, arrow head and font. The command's SVG is shown in the same
// browser, so both are compared as the browser computes them (colours as rgb(), sizes in px).
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { after, afterEach, before, test } from 'node:test';
import { closePages, copyGoalie, flatten, launch, modelRoot, openModel, repository, screenshotter, servedFolder, states } from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

/** Where each part is in `kse diagram`'s SVG (its classes) and in the editor's visible diagram. */
const PICTURE = {
    states: 'svg > g.state',
    shape: ':scope > .shape',
    centre: ':scope > .centre',
    caption: ':scope > .caption',
    label: ':scope > .label',
    transitions: 'svg > g.transition',
    line: '.line',
    expression: '.expression',
    arrow: 'marker#arrow > path'
};
const EDITOR = {
    states: '#kse-diagram g.kse-state',
    shape: ':scope > .kse-shape',
    centre: ':scope > .kse-end-centre',
    caption: ':scope > .kse-name, :scope > .kse-caption > .kse-name',
    label: ':scope > .kse-hierarchical-label',
    transitions: '#kse-diagram g.kse-transition',
    line: '.kse-line',
    expression: '.kse-expression',
    arrow: '#kse-diagram g.kse-transition .kse-arrow'
};

/**
 * The drawing as the browser computes it (colours rgb(), lengths px): per state its kind, shape
 * (element, fill, stroke, stroke width and dashes, corner radius, size), END's centre, caption and
 * label (text, font size, family, weight, colour); per transition its line and expression; the
 * arrow head. A state is known by its hierarchical label: the SVG's data-label, or `labels` by id.
 */
function drawing(page, parts, labels) {
    return page.evaluate(
        ([parts, labels]) => {
            const text = element =>
                element && {
                    text: element.textContent,
                    fontSize: getComputedStyle(element).fontSize,
                    fontFamily: getComputedStyle(element).fontFamily,
                    fontWeight: getComputedStyle(element).fontWeight,
                    colour: getComputedStyle(element).fill
                };
            // to the half pixel: the SVG writes one decimal
            const length = (element, name) => Math.round(Number(element.getAttribute(name)) * 2) / 2;
            const shapeOf = shape => {
                if (!shape) {
                    return undefined;
                }
                const style = getComputedStyle(shape);
                const round = shape.tagName === 'circle';
                return {
                    element: shape.tagName,
                    fill: style.fill,
                    stroke: style.stroke,
                    strokeWidth: style.strokeWidth,
                    dash: style.strokeDasharray,
                    cornerRadius: round ? undefined : style.rx,
                    size: round ? `r ${length(shape, 'r')}` : `${length(shape, 'width')} x ${length(shape, 'height')}`
                };
            };
            const lineOf = line => line && { colour: getComputedStyle(line).stroke, width: getComputedStyle(line).strokeWidth };
            const states = [...document.querySelectorAll(parts.states)].map(group => {
                const centre = group.querySelector(parts.centre);
                return {
                    state: labels ? labels[group.dataset.id] : group.dataset.label,
                    kind: group.dataset.kind ?? group.classList[1],
                    shape: shapeOf(group.querySelector(parts.shape)),
                    centre: centre && { fill: getComputedStyle(centre).fill, size: `r ${length(centre, 'r')}` },
                    caption: text(group.querySelector(parts.caption)),
                    label: text(group.querySelector(parts.label))
                };
            });
            const arrow = document.querySelector(parts.arrow);
            return {
                states,
                transitions: [...document.querySelectorAll(parts.transitions)].map(group => ({
                    line: lineOf(group.querySelector(parts.line)),
                    expression: text(group.querySelector(parts.expression))
                })),
                arrow: arrow && { d: arrow.getAttribute('d'), fill: getComputedStyle(arrow).fill, stroke: getComputedStyle(arrow).stroke, strokeWidth: getComputedStyle(arrow).strokeWidth }
            };
        },
        [parts, labels]
    );
}

/** Every difference between two values, as "path: kse diagram … ≠ editor …" lines. */
function differences(picture, editor, where) {
    if (picture !== null && editor !== null && typeof picture === 'object' && typeof editor === 'object') {
        const keys = [...new Set([...Object.keys(picture), ...Object.keys(editor)])];
        return keys.flatMap(key => differences(picture[key], editor[key], `${where}.${key}`));
    }
    return JSON.stringify(picture) === JSON.stringify(editor) ? [] : [`${where}: kse diagram ${JSON.stringify(picture)} ≠ editor ${JSON.stringify(editor)}`];
}

/** An arrow head's path as numbers (the two write the same triangle with other spacing). */
const points = d => (d.match(/-?\d+(\.\d+)?/g) ?? []).map(Number);

test('kse diagram and the editor draw the Goalie alike, state by state', async () => {
    const shot = screenshotter('one-drawing');
    const model = copyGoalie('OneDrawing');
    const file = path.join(servedFolder(), model);
    const svgFile = path.join(servedFolder(), 'OneDrawing.svg');
    // the product's command, as a user runs it; both sides arrange the model (no notation file) with ELK alike
    execFileSync(path.join(repository, 'kse'), ['diagram', file, '-o', svgFile], { stdio: ['ignore', 'ignore', 'inherit'] });

    const editorPage = await openModel(browser.context, model);
    await shot(editorPage, 'editor');
    const root = await modelRoot(editorPage);
    const labels = Object.fromEntries(states(root).map(state => [state.id, String(state.args?.label ?? '')]));
    const names = Object.fromEntries(states(root).map(state => [String(state.args?.label ?? ''), String(state.args?.name ?? '')]));
    const editor = await drawing(editorPage, EDITOR, labels);

    const picturePage = await browser.context.newPage();
    await picturePage.setContent(`<!doctype html><body style="margin:0">${readFileSync(svgFile, 'utf8').replace(/^<\?xml[^>]*>/, '')}</body>`);
    await picturePage.screenshot({ path: path.join(path.dirname(await shot(editorPage, 'editor-again')), 'one-drawing-03-kse-diagram.png'), fullPage: true });
    const picture = await drawing(picturePage, PICTURE, null);
    await picturePage.close();

    // states, by their label
    assert.equal(editor.states.length, states(root).length, 'the editor draws every state');
    assert.equal(picture.states.length, editor.states.length, 'kse diagram draws as many states as the editor');
    const byLabel = list => new Map(list.map(state => [state.state, state]));
    const pictureStates = byLabel(picture.states);
    const editorStates = byLabel(editor.states);
    const problems = [];
    for (const label of [...new Set([...pictureStates.keys(), ...editorStates.keys()])].sort()) {
        const where = `state ${label} (${names[label] ?? '?'})`;
        if (!pictureStates.has(label) || !editorStates.has(label)) {
            problems.push(`${where}: drawn only by ${pictureStates.has(label) ? 'kse diagram' : 'the editor'}`);
            continue;
        }
        problems.push(...differences(pictureStates.get(label), editorStates.get(label), where));
    }

    // transitions: as many, the same expression texts, drawn alike
    problems.push(...differences(picture.transitions.length, editor.transitions.length, 'transitions.count'));
    const sortedTexts = list => list.map(transition => transition.expression?.text ?? '').sort();
    problems.push(...differences(sortedTexts(picture.transitions), sortedTexts(editor.transitions), 'transitions.expressions'));
    const look = list => [...new Set(list.map(transition => JSON.stringify({ line: transition.line, font: { ...transition.expression, text: undefined } })))];
    problems.push(...differences(look(picture.transitions), look(editor.transitions), 'transitions.look'));
    problems.push(...differences({ ...picture.arrow, d: points(picture.arrow.d) }, { ...editor.arrow, d: points(editor.arrow.d) }, 'transitions.arrow'));

    assert.deepEqual(problems, [], `kse diagram and the editor draw differently:\n${problems.join('\n')}`);

    // not two empty drawings alike: the thesis notation is there (each kind its own look)
    const kinds = new Map(editor.states.map(state => [state.kind, state]));
    assert.equal(kinds.get('start')?.shape.fill, 'rgb(0, 0, 0)', 'START a black disc');
    assert.equal(kinds.get('basic')?.shape.fill, 'rgb(185, 228, 164)', 'BASIC green');
    assert.equal(kinds.get('or')?.caption.fontWeight, '700', 'a composite caption bold');
    assert.ok(editor.transitions.filter(transition => transition.expression?.text).length > 10, 'labelled transitions');
    assert.ok(flatten(root).length > 50);
    assert.deepEqual(editorPage.problems, [], 'no errors in the page');
    await editorPage.close();
});
