// "Arrange all" lays the whole diagram out again: states move, and no two siblings overlap.
import assert from 'node:assert/strict';
import { after, afterEach, before, test } from 'node:test';
import { andUpdate, clickState, closePages, copyGoalie, launch, modelRoot, openModel, overlap, screenshotter, shapeBox, stateNamed, states } from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

test('arrange all moves the states apart', async () => {
    const shot = screenshotter('layout');
    const model = copyGoalie('layout');
    const page = await openModel(browser.context, model);
    await shot(page, 'opened');
    // the example is laid out already: disturb it first (Kick moves onto its neighbours)
    const kick = stateNamed(await modelRoot(page), 'Kick');
    await clickState(page, kick.id);
    const box = await shapeBox(page, kick.id);
    await andUpdate(page, async () => {
        await page.mouse.move(box.x + 8, box.y + 8);
        await page.mouse.down();
        await page.mouse.move(box.x - 60, box.y + 40, { steps: 8 });
        await page.mouse.move(box.x - 120, box.y + 60, { steps: 8 });
        await page.mouse.up();
    });
    await shot(page, 'before');
    const before = new Map(states(await modelRoot(page)).map(state => [state.id, state.bounds]));

    await andUpdate(page, () => page.locator('[data-action="layout"]').click());
    await page.locator('[data-action="fit"]').click();
    await page.waitForTimeout(600);
    await shot(page, 'arranged');

    const after = states(await modelRoot(page));
    assert.equal(after.length, before.size, 'no state is lost');
    const changed = after.filter(state => {
        const old = before.get(state.id);
        return !old || old.x !== state.bounds.x || old.y !== state.bounds.y || old.width !== state.bounds.width || old.height !== state.bounds.height;
    });
    assert.ok(changed.length > 0, 'the layout changed some positions or sizes');

    const siblings = new Map();
    for (const state of after) {
        const list = siblings.get(state.parentId) ?? [];
        list.push(state);
        siblings.set(state.parentId, list);
    }
    const overlaps = [];
    for (const list of siblings.values()) {
        for (let i = 0; i < list.length; i++) {
            for (let j = i + 1; j < list.length; j++) {
                if (overlap(list[i].bounds, list[j].bounds)) {
                    overlaps.push(`${list[i].id} / ${list[j].id}`);
                }
            }
        }
    }
    assert.deepEqual(overlaps, [], 'siblings do not overlap');
    // each child lies inside its parent
    const byId = new Map(after.map(state => [state.id, state]));
    for (const state of after) {
        const parent = byId.get(state.parentId);
        if (parent) {
            assert.ok(state.bounds.x >= 0 && state.bounds.y >= 0, `${state.id} starts inside its parent`);
            assert.ok(state.bounds.x + state.bounds.width <= parent.bounds.width + 0.5, `${state.id} ends inside its parent (width)`);
            assert.ok(state.bounds.y + state.bounds.height <= parent.bounds.height + 0.5, `${state.id} ends inside its parent (height)`);
        }
    }

    await andUpdate(page, () => page.locator('[data-action="undo"]').click());
    await shot(page, 'undone');
    const undone = states(await modelRoot(page));
    assert.deepEqual(
        undone.map(state => [state.id, state.bounds]),
        [...before.entries()],
        'undo restores the former layout'
    );
    await page.close();
});
