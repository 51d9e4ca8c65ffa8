// Creating states and a transition with the tool palette, resizing, saving: the saved .stct holds them.
import assert from 'node:assert/strict';
import { after, afterEach, before, test } from 'node:test';
import {
    andUpdate,
    clickState,
    copyGoalie,
    launch,
    modelRoot,
    openModel,
    paletteTool,
    readModelFile,
    screenshotter,
    shapeBox,
    states,
    transitions,
    closePages
} from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

/** The top-level `<nodes …>…</nodes>` elements of a .stct file, as text. */
function topLevelNodes(xml) {
    const nodes = [];
    const pattern = /<nodes\b[^>]*?(\/>|>[\s\S]*?<\/nodes>)/g;
    for (const match of xml.matchAll(pattern)) {
        nodes.push(match[0]);
    }
    return nodes;
}

test('an OR state with a START, a BASIC and a transition is created from the palette and saved', async () => {
    const shot = screenshotter('create');
    const model = copyGoalie('create');
    const page = await openModel(browser.context, model);
    await shot(page, 'opened');
    const before = await modelRoot(page);
    const topBefore = before.children.filter(child => child.type.startsWith('state:')).map(child => child.id);

    // room next to the Goalie's root state
    await page.locator('[data-action="zoom-out"]').click();
    await page.waitForTimeout(600);
    await page.locator('[data-action="zoom-out"]').click();
    await page.waitForTimeout(800);
    // an OR state at the top level: a click on the empty canvas below the Goalie's root state
    const goalie = await shapeBox(page, topBefore[0]);
    await paletteTool(page, 'OR (sequence)');
    await andUpdate(page, () => page.mouse.click(goalie.x + 10, goalie.y + goalie.height + 25));
    let root = await modelRoot(page);
    const created = root.children.filter(child => child.type === 'state:or' && !topBefore.includes(child.id));
    assert.equal(created.length, 1, 'one new OR state at the top level');
    const or = created[0];
    await shot(page, 'or-created');
    // the server validates live: an OR state without a START is marked (SetMarkersAction)
    await page.locator(`#kse-diagram [data-id="${or.id}"] .sprotty-issue`).first().waitFor({ state: 'attached', timeout: 10000 });

    // make it large enough for two states: drag its bottom right resize handle
    await clickState(page, or.id);
    await page.waitForTimeout(300);
    const handle = await page.evaluate(id => {
        const circles = [...document.querySelectorAll(`#kse-diagram [data-id="${id}"] circle.sprotty-resize-handle`)];
        const boxes = circles.map(circle => circle.getBoundingClientRect());
        boxes.sort((a, b) => b.x + b.y - (a.x + a.y));
        return boxes.length ? { x: boxes[0].x + boxes[0].width / 2, y: boxes[0].y + boxes[0].height / 2 } : undefined;
    }, or.id);
    assert.ok(handle, 'a selected OR state has resize handles');
    await shot(page, 'or-selected');
    const sizeBefore = (await shapeBox(page, or.id)).width;
    // (the mouse is released inside the diagram: a release over the status line would not end the resize)
    const diagram = await page.locator('#kse-diagram').boundingBox();
    const target = { x: handle.x + 160, y: Math.min(handle.y + 70, diagram.y + diagram.height - 12) };
    await andUpdate(page, async () => {
        await page.mouse.move(handle.x, handle.y);
        await page.mouse.down();
        await page.mouse.move((handle.x + target.x) / 2, (handle.y + target.y) / 2, { steps: 8 });
        await page.mouse.move(target.x, target.y, { steps: 8 });
        await shot(page, 'resizing');
        await page.mouse.up();
    });
    const orBox = await shapeBox(page, or.id);
    assert.ok(orBox.width > sizeBefore + 50, 'the OR state grew');
    await shot(page, 'or-resized');

    // a START and a BASIC inside it
    await paletteTool(page, /^Start$/);
    await andUpdate(page, () => page.mouse.click(orBox.x + 25, orBox.y + orBox.height * 0.6));
    await paletteTool(page, 'Basic (activity)');
    await andUpdate(page, () => page.mouse.click(orBox.x + orBox.width * 0.5, orBox.y + orBox.height * 0.5));
    root = await modelRoot(page);
    const inside = states(root).filter(state => state.parentId === or.id);
    const start = inside.find(state => state.type === 'state:start');
    const basic = inside.find(state => state.type === 'state:basic');
    assert.ok(start, 'a START inside the new OR state');
    assert.ok(basic, 'a BASIC inside the new OR state');
    await shot(page, 'children-created');

    // a transition from the START to the BASIC
    await paletteTool(page, /^Transition$/);
    await clickState(page, start.id);
    await andUpdate(page, () => clickState(page, basic.id));
    root = await modelRoot(page);
    const edge = transitions(root).find(t => t.sourceId === start.id && t.targetId === basic.id);
    assert.ok(edge, 'a transition from the START to the BASIC');
    assert.equal(await page.locator(`#kse-diagram [data-id="${or.id}"] > .sprotty-issue`).count(), 0, 'the OR state is valid now: its marker is gone');
    await shot(page, 'transition-created');

    // save: the file holds the new states and the transition
    assert.equal(await page.evaluate(() => window.kse.isDirty()), true, 'the model is dirty before saving');
    await page.locator('[data-action="save"]').click();
    await page.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
    await shot(page, 'saved');
    const xml = readModelFile(model);
    const nodes = topLevelNodes(xml);
    assert.equal(nodes.length, topBefore.length + 1, 'one more top-level state in the file');
    const savedOr = nodes[nodes.length - 1];
    assert.match(savedOr, /^<nodes\b[^>]*type="OR"/, 'the new top-level state is an OR state');
    assert.match(savedOr, /<Children\b[^>]*type="START"/, 'it contains a START');
    assert.match(savedOr, /<Children\b[^>]*type="BASIC"/, 'it contains a BASIC');
    const saved = [...xml.matchAll(/<transitions\b[^>]*>/g)].map(match => match[0]);
    assert.ok(
        saved.some(t => t.includes(`source="${start.id}"`) && t.includes(`target="${basic.id}"`)),
        `a saved transition from ${start.id} to ${basic.id}`
    );
    assert.deepEqual(page.problems, [], 'no errors in the page');
    await page.close();
});
