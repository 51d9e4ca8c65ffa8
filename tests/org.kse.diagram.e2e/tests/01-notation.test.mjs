// Opening the Goalie example shows every state in the thesis notation: START a black disc, END a
// ringed disc, CONDITION a white circle with "C", BASIC a green rounded box, OR a yellow box with
// its name in bold and its label in grey; transitions are arrows labelled with their expression.
import assert from 'node:assert/strict';
import { after, afterEach, before, test } from 'node:test';
import { clientKindCounts, copyGoalie, goalieSource, kindCounts, launch, modelRoot, nameOf, openModel, screenshotter, states, transitions, closePages } from '../lib/harness.mjs';
import { readFileSync } from 'node:fs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

const rgb = {
    black: 'rgb(0, 0, 0)',
    white: 'rgb(255, 255, 255)',
    basicFill: 'rgb(185, 228, 164)',
    basicStroke: 'rgb(61, 122, 43)',
    orFill: 'rgb(255, 245, 194)',
    orStroke: 'rgb(166, 139, 34)',
    andFill: 'rgb(216, 236, 255)',
    andStroke: 'rgb(74, 127, 176)',
    arrow: 'rgb(51, 51, 51)'
};

/** The computed look of every state drawn in the visible diagram, by kind. */
function drawnStates(page) {
    return page.evaluate(() =>
        [...document.querySelectorAll('#kse-diagram g.kse-state')].map(group => {
            const shape = group.querySelector(':scope > .kse-shape');
            const style = shape ? getComputedStyle(shape) : undefined;
            const centre = group.querySelector(':scope > .kse-end-centre');
            // a composite named after a formula has its caption in a group with the name as hover title
            const name = group.querySelector(':scope > .kse-name, :scope > .kse-caption > .kse-name');
            const label = group.querySelector(':scope > .kse-hierarchical-label');
            return {
                id: group.dataset.id,
                kind: group.dataset.kind,
                tag: shape?.tagName,
                fill: style?.fill,
                stroke: style?.stroke,
                rx: shape?.getAttribute('rx'),
                centreFill: centre ? getComputedStyle(centre).fill : undefined,
                name: name?.textContent,
                nameWeight: name ? getComputedStyle(name).fontWeight : undefined,
                label: label?.textContent,
                labelFill: label ? getComputedStyle(label).fill : undefined
            };
        })
    );
}

test('the Goalie is drawn in the thesis notation', async () => {
    const shot = screenshotter('notation');
    const model = copyGoalie('notation');
    const page = await openModel(browser.context, model);
    await shot(page, 'opened');

    const root = await modelRoot(page);
    const file = readFileSync(goalieSource, 'utf8');
    const expected = kindCounts(file);
    assert.deepEqual(clientKindCounts(root), expected, 'one node per state of the .stct, of its kind');
    assert.equal(transitions(root).length, (file.match(/<transitions\b/g) ?? []).length, 'one edge per transition');

    const drawn = await drawnStates(page);
    const byKind = kind => drawn.filter(state => state.kind === kind);
    for (const [kind, count] of Object.entries(expected)) {
        assert.equal(byKind(kind).length, count, `${count} ${kind} states drawn`);
    }
    for (const start of byKind('start')) {
        assert.equal(start.tag, 'circle', 'START is a disc');
        assert.equal(start.fill, rgb.black, 'START is black');
    }
    for (const end of byKind('end')) {
        assert.equal(end.tag, 'circle', 'END is a circle');
        assert.equal(end.fill, rgb.white, 'END is white');
        assert.equal(end.stroke, rgb.black, 'END has a black outline');
        assert.equal(end.centreFill, rgb.black, 'END has a black centre');
    }
    for (const condition of byKind('condition')) {
        assert.equal(condition.tag, 'circle', 'CONDITION is a circle');
        assert.equal(condition.fill, rgb.white);
        assert.equal(condition.stroke, rgb.black);
        assert.equal(condition.name, 'C', 'CONDITION shows "C"');
    }
    for (const basic of byKind('basic')) {
        assert.equal(basic.tag, 'rect', 'BASIC is a box');
        assert.equal(basic.fill, rgb.basicFill, 'BASIC is green');
        assert.equal(basic.stroke, rgb.basicStroke);
        assert.ok(Number(basic.rx) > 0, 'BASIC has round corners');
        assert.equal(basic.name, nameOf(root, basic.id), 'BASIC shows its name');
    }
    const stateArgs = new Map(states(root).map(state => [state.id, state.args ?? {}]));
    for (const [kind, fill, stroke] of [
        ['or', rgb.orFill, rgb.orStroke],
        ['and', rgb.andFill, rgb.andStroke]
    ]) {
        for (const composite of byKind(kind)) {
            assert.equal(composite.tag, 'rect');
            assert.equal(composite.fill, fill, `${kind.toUpperCase()} fill`);
            assert.equal(composite.stroke, stroke, `${kind.toUpperCase()} stroke`);
            assert.equal(composite.name, nameOf(root, composite.id), `${kind.toUpperCase()} shows its name`);
            assert.ok(Number(composite.nameWeight) >= 600, 'the name of a composite is bold');
            assert.equal(composite.label, String(stateArgs.get(composite.id).label), 'the label at the top right');
            assert.equal(composite.labelFill, 'rgb(102, 102, 102)', 'the label is grey');
        }
    }

    // transitions: a line and an arrow head in dark grey, labelled with the first line of their expression
    const edges = await page.evaluate(() =>
        [...document.querySelectorAll('#kse-diagram g.kse-transition')].map(edge => ({
            id: edge.dataset.id,
            line: getComputedStyle(edge.querySelector('.kse-line')).stroke,
            arrow: edge.querySelector('.kse-arrow') ? getComputedStyle(edge.querySelector('.kse-arrow')).fill : undefined,
            label: edge.querySelector('.kse-expression')?.textContent
        }))
    );
    assert.equal(edges.length, transitions(root).length, 'every transition is drawn');
    for (const edge of edges) {
        assert.equal(edge.line, rgb.arrow);
        assert.equal(edge.arrow, rgb.arrow, 'an arrow head');
        const expression = String(transitions(root).find(t => t.id === edge.id).args.expression ?? '');
        const lines = expression.split('\n');
        if (expression.trim()) {
            // the first line, its start only when long (or followed by more lines): ' …' marks the cut
            const first = lines[0].trim();
            const cut = edge.label.endsWith(' …') ? edge.label.slice(0, -2) : edge.label;
            assert.ok(first.startsWith(cut) && cut.length > 0, `the first line of the expression: ${edge.label}`);
            assert.ok(edge.label.length <= 38, `a long line is cut: ${edge.label}`);
            assert.equal(edge.label.endsWith(' …'), lines.length > 1 || cut !== first, 'an ellipsis where the label shows less than the expression');
        }
    }
    assert.deepEqual(page.problems, [], 'no errors in the page');
    await page.close();
});

test('hovering a transition shows its whole expression', async () => {
    const shot = screenshotter('hover');
    const model = copyGoalie('hover');
    const page = await openModel(browser.context, model);
    const root = await modelRoot(page);
    const edge = transitions(root).find(t => String(t.args.expression ?? '').includes('\n'));
    assert.ok(edge, 'the Goalie has a transition with a multi-line expression');
    // the middle of the edge's first segment, in page coordinates
    const point = await page.evaluate(id => {
        const line = document.querySelector(`#kse-diagram [data-id="${id}"] .kse-line`);
        const length = line.getTotalLength();
        const middle = line.getPointAtLength(length / 2);
        const matrix = line.getScreenCTM();
        return { x: matrix.a * middle.x + matrix.c * middle.y + matrix.e, y: matrix.b * middle.x + matrix.d * middle.y + matrix.f };
    }, edge.id);
    await page.mouse.move(point.x - 30, point.y - 30);
    await page.mouse.move(point.x, point.y, { steps: 5 });
    const popup = page.locator('.sprotty-popup:not(.sprotty-popup-closed)');
    await popup.waitFor({ state: 'visible', timeout: 10000 });
    await shot(page, 'popup');
    const text = (await popup.innerText()).replace(/\s+/g, ' ');
    for (const line of String(edge.args.expression).split('\n')) {
        assert.ok(text.includes(line.trim().replace(/\s+/g, ' ')), `the popup shows "${line.trim()}"`);
    }
    await page.close();
});

test('a model the server cannot open is reported in the status line', async () => {
    const shot = screenshotter('missing');
    const page = await openModel(browser.context, 'does-not-exist.stct', { expectError: true });
    await page.waitForFunction(() => document.querySelector('#kse-status .kse-status-text')?.textContent.trim().length > 0);
    await shot(page, 'status');
    assert.equal(await page.evaluate(() => document.body.dataset.kse), 'error');
    const status = await page.locator('#kse-status').innerText();
    assert.match(status, /does-not-exist\.stct/, 'the status line names the model');
    assert.equal(await page.locator('#kse-status').getAttribute('data-severity'), 'error');
    await page.close();
});
