// Dragging states into another composite (issue 14, item 4): a drop on another composite or on the
// empty canvas moves the state there (ChangeContainer, one undo step), a drop the rules forbid is
// refused with a message and the state snaps back.
import assert from 'node:assert/strict';
import { after, afterEach, before, test } from 'node:test';
import {
    andUpdate,
    clickState,
    closePages,
    copyGoalie,
    fitTo,
    flatten,
    focusDiagram,
    launch,
    modelRoot,
    openModel,
    readModelFile,
    revision,
    screenshotter,
    shapeBox,
    stateNamed,
    states,
    transitions
} from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

/** The page of a model with the whole diagram in the window (it opens at a readable zoom, maybe larger). */
async function openWhole(model) {
    const page = await openModel(browser.context, model);
    await page.evaluate(() => window.kse.run('fit'));
    await page.waitForTimeout(700);
    return page;
}

const attachedTo = (root, id) => transitions(root).filter(edge => edge.sourceId === id || edge.targetId === id).length;
const inside = (point, box) => point.x > box.x && point.x < box.x + box.width && point.y > box.y && point.y < box.y + box.height;

/** A point of the composite's box (on screen) that lies on none of its states, away from its header. */
async function emptyPointIn(page, root, compositeId) {
    const box = await shapeBox(page, compositeId);
    const children = states(root).filter(state => state.parentId === compositeId);
    const boxes = await Promise.all(children.map(child => shapeBox(page, child.id)));
    for (let fy = 0.9; fy > 0.3; fy -= 0.05) {
        for (let fx = 0.9; fx > 0.1; fx -= 0.05) {
            const point = { x: box.x + box.width * fx, y: box.y + box.height * fy };
            if (boxes.every(child => !inside(point, { x: child.x - 6, y: child.y - 6, width: child.width + 12, height: child.height + 12 }))) {
                return point;
            }
        }
    }
    throw new Error(`no empty point in ${compositeId}`);
}

/** Drags a state by a point near its top left corner to `to` (screen coordinates); `during` runs before the mouse is released. */
async function drag(page, stateId, to, during = async () => undefined) {
    const box = await shapeBox(page, stateId);
    const from = { x: box.x + Math.min(8, box.width / 3), y: box.y + Math.min(8, box.height / 3) };
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    await page.mouse.move((from.x + to.x) / 2, (from.y + to.y) / 2, { steps: 8 });
    await page.mouse.move(to.x, to.y, { steps: 8 });
    await during();
    await page.mouse.up();
}

/** The name of the state that holds the state called `name` in a saved .stct (null at the top of the model). */
function savedParentOf(xml, name) {
    const stack = [];
    for (const tag of xml.matchAll(/<(\/?)(nodes|Children)\b([^>]*?)(\/?)>/g)) {
        const [, closing, , attributes, selfClosing] = tag;
        if (closing) {
            stack.pop();
            continue;
        }
        const own = attributes.match(/\bname="([^"]*)"/)?.[1];
        if (own === name) {
            return stack.length > 0 ? stack[stack.length - 1] : null;
        }
        if (!selfClosing) {
            stack.push(own);
        }
    }
    throw new Error(`${name} is not in the file`);
}

test('a state dragged onto another composite goes into it with its transitions, undo puts it back, the file nests it', async () => {
    const shot = screenshotter('reparent');
    const model = copyGoalie('reparent');
    const page = await openWhole(model);
    let root = await modelRoot(page);
    const kick = stateNamed(root, 'Kick');
    const playingId = kick.parentId;
    await fitTo(page, playingId);
    const attached = attachedTo(root, kick.id);
    assert.ok(attached > 0, 'Kick has transitions');
    const target = await emptyPointIn(page, root, stateNamed(root, 'followBall').id);
    await clickState(page, kick.id);
    await andUpdate(page, () =>
        drag(page, kick.id, target, async () => {
            const during = await modelRoot(page);
            const outlined = flatten(during).find(element => element.cssClasses?.includes('kse-drop-target'));
            assert.equal(outlined?.id, stateNamed(during, 'followBall').id, 'followBall is outlined as the drop target');
            await shot(page, 'dragging');
        })
    );
    await shot(page, 'dropped');
    root = await modelRoot(page);
    const moved = stateNamed(root, 'Kick');
    const followBall = stateNamed(root, 'followBall');
    assert.equal(moved.parentId, followBall.id, 'Kick is inside followBall now');
    assert.equal(attachedTo(root, moved.id), attached, 'its transitions come along');
    assert.ok(!flatten(root).some(element => element.cssClasses?.includes('kse-drop-target')), 'no outline is left');
    const kickBox = await shapeBox(page, moved.id);
    const followBallBox = await shapeBox(page, followBall.id);
    assert.ok(inside({ x: kickBox.x + 1, y: kickBox.y + 1 }, followBallBox), 'drawn inside followBall');

    await focusDiagram(page);
    await andUpdate(page, () => page.keyboard.press('Control+z'));
    root = await modelRoot(page);
    assert.equal(stateNamed(root, 'Kick').parentId, playingId, 'one undo puts Kick back into playing');
    assert.equal(attachedTo(root, stateNamed(root, 'Kick').id), attached);

    await andUpdate(page, () => page.keyboard.press('Control+Shift+z'));
    assert.equal(stateNamed(await modelRoot(page), 'Kick').parentId, stateNamed(await modelRoot(page), 'followBall').id, 'redone');
    await page.locator('[data-action="save"]').click();
    await page.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
    const saved = readModelFile(model);
    assert.equal(savedParentOf(saved, 'Kick'), 'followBall', 'the saved file has Kick inside followBall');
    assert.equal(savedParentOf(saved, 'followBall'), 'playing');
    await page.close();
});

test('a state dragged onto the empty canvas goes to the top of the model', async () => {
    const shot = screenshotter('reparent-top');
    const model = copyGoalie('reparent-top');
    const page = await openWhole(model);
    await page.evaluate(() => window.kse.run('zoom-out'));
    await page.waitForTimeout(700);
    let root = await modelRoot(page);
    const scan = stateNamed(root, 'Scan');
    const top = states(root).find(state => state.parentId === root.id);
    const topBox = await shapeBox(page, top.id);
    const diagram = await page.locator('#kse-diagram').boundingBox();
    const target = { x: Math.min(topBox.x + topBox.width + 60, diagram.x + diagram.width - 20), y: topBox.y + 40 };
    assert.ok(target.x > topBox.x + topBox.width + 10, 'there is empty canvas right of the model');
    await clickState(page, scan.id);
    await andUpdate(page, () => drag(page, scan.id, target));
    await shot(page, 'dropped');
    root = await modelRoot(page);
    assert.equal(stateNamed(root, 'Scan').parentId, root.id, 'Scan is a top-level state now');
    await page.close();
});

test('a drop the statechart rules forbid is refused with a message and the state snaps back', async () => {
    const shot = screenshotter('reparent-refused');
    const model = copyGoalie('reparent-refused');
    const page = await openWhole(model);
    let root = await modelRoot(page);
    const scan = stateNamed(root, 'Scan');
    const kick = stateNamed(root, 'Kick');
    await fitTo(page, kick.parentId);
    const before = await shapeBox(page, scan.id);
    const kickBox = await shapeBox(page, kick.id);
    const updates = await revision(page);
    await clickState(page, scan.id);
    await drag(page, scan.id, { x: kickBox.x + kickBox.width / 2, y: kickBox.y + kickBox.height / 2 }, async () => {
        const during = await modelRoot(page);
        const refused = flatten(during).find(element => element.cssClasses?.includes('kse-drop-refused'));
        assert.equal(refused?.id, kick.id, 'Kick is outlined as a refused target');
        await shot(page, 'over-basic');
    });
    await page.waitForTimeout(800);
    await shot(page, 'refused');
    const status = await page.locator('#kse-status').innerText();
    assert.match(status, /cannot hold other states/, `the status line says why: ${status}`);
    const after = await shapeBox(page, scan.id);
    assert.ok(Math.abs(after.x - before.x) < 1 && Math.abs(after.y - before.y) < 1, 'Scan is back where it was');
    assert.equal(await revision(page), updates, 'nothing was sent to change the model');
    assert.equal(await page.evaluate(() => window.kse.isDirty()), false);

    // an AND state holds only OR regions
    const top = states(root).find(state => state.parentId === root.id).bounds;
    const corner = { x: top.x + top.width + 40, y: top.y };
    await andUpdate(page, () =>
        page.evaluate(location => window.kse.dispatch({ kind: 'createNode', elementTypeId: 'state:and', location, containerId: 'statechart', args: {} }), corner)
    );
    await page.evaluate(() => window.kse.run('fit'));
    await page.waitForTimeout(600);
    root = await modelRoot(page);
    const and = states(root).find(state => state.type === 'state:and');
    assert.ok(and, 'an AND state was added');
    const andBox = await shapeBox(page, and.id);
    await clickState(page, stateNamed(root, 'Kick').id);
    await drag(page, stateNamed(root, 'Kick').id, { x: andBox.x + andBox.width / 2, y: andBox.y + andBox.height * 0.7 });
    await page.waitForTimeout(800);
    await shot(page, 'refused-and');
    assert.match(await page.locator('#kse-status').innerText(), /holds only OR regions/);
    assert.equal(stateNamed(await modelRoot(page), 'Kick').parentId, kick.parentId, 'Kick stays in playing');
    await page.close();
});
