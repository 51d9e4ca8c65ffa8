// Moving and deleting states, undone and redone with the keyboard (Ctrl+Z, Ctrl+Shift+Z, Ctrl+Y)
// and with the toolbar.
import assert from 'node:assert/strict';
import { after, afterEach, before, test } from 'node:test';
import { andUpdate, clickState, copyGoalie, launch, modelRoot, openModel, screenshotter, shapeBox, stateNamed, closePages } from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

const position = async (page, name) => stateNamed(await modelRoot(page), name)?.bounds;

test('a move is undone and redone with the keyboard and the toolbar', async () => {
    const shot = screenshotter('undo');
    const model = copyGoalie('undo');
    const page = await openModel(browser.context, model);
    const kick = stateNamed(await modelRoot(page), 'Kick');
    assert.ok(kick, 'the Goalie has a state Kick');
    const original = kick.bounds;

    // drag Kick 80 pixels to the right
    await clickState(page, kick.id);
    const box = await shapeBox(page, kick.id);
    await andUpdate(page, async () => {
        await page.mouse.move(box.x + 8, box.y + 8);
        await page.mouse.down();
        await page.mouse.move(box.x + 48, box.y + 8, { steps: 6 });
        await page.mouse.move(box.x + 88, box.y + 8, { steps: 6 });
        await page.mouse.up();
    });
    const moved = await position(page, 'Kick');
    assert.ok(moved.x > original.x + 20, `Kick moved right (${original.x} → ${moved.x})`);
    assert.equal(await page.evaluate(() => window.kse.isDirty()), true, 'a move makes the model dirty');
    await shot(page, 'moved');

    await andUpdate(page, () => page.keyboard.press('Control+z'));
    assert.deepEqual(await position(page, 'Kick'), original, 'Ctrl+Z undoes the move');
    await shot(page, 'undone-ctrl-z');

    await andUpdate(page, () => page.keyboard.press('Control+Shift+z'));
    assert.deepEqual(await position(page, 'Kick'), moved, 'Ctrl+Shift+Z redoes it');
    await shot(page, 'redone-ctrl-shift-z');

    await andUpdate(page, () => page.locator('[data-action="undo"]').click());
    assert.deepEqual(await position(page, 'Kick'), original, 'the Undo button undoes it');
    await shot(page, 'undone-button');

    await andUpdate(page, () => page.keyboard.press('Control+y'));
    assert.deepEqual(await position(page, 'Kick'), moved, 'Ctrl+Y redoes it (after a toolbar click the keys still reach the diagram)');
    await shot(page, 'redone-ctrl-y');

    await andUpdate(page, () => page.locator('[data-action="undo"]').click());
    await andUpdate(page, () => page.locator('[data-action="redo"]').click());
    assert.deepEqual(await position(page, 'Kick'), moved, 'the Redo button redoes it');
    await shot(page, 'redone-button');
    assert.deepEqual(page.problems, [], 'no errors in the page');
    await page.close();
});

test('a deleted state comes back with undo', async () => {
    const shot = screenshotter('delete');
    const model = copyGoalie('delete');
    const page = await openModel(browser.context, model);
    const kick = stateNamed(await modelRoot(page), 'Kick');
    await clickState(page, kick.id);
    await shot(page, 'selected');
    await andUpdate(page, () => page.keyboard.press('Delete'));
    assert.equal(stateNamed(await modelRoot(page), 'Kick'), undefined, 'Delete removes the selected state');
    await shot(page, 'deleted');
    await andUpdate(page, () => page.keyboard.press('Control+z'));
    assert.ok(stateNamed(await modelRoot(page), 'Kick'), 'undo brings it back');
    await shot(page, 'restored');
    await page.close();
});
