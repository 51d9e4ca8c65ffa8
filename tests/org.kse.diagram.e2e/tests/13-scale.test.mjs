// Issue 14, item 2: no size cliff. A 1,000-state and a 5,000-state statechart (made by
// `kse transform`, without a notation: the server arranges them when they are opened) open in the
// browser, a state is renamed and moved with the mouse, and the save writes both edits and every
// state. How long each took to open is printed, not asserted.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { after, afterEach, before, test } from 'node:test';
import {
    andUpdate,
    centre,
    closePages,
    launch,
    modelRoot,
    openModel,
    readModelFile,
    renameState,
    screenshotter,
    servedFolder,
    shapeBox,
    stateNamed,
    states
} from '../lib/harness.mjs';
import { generatedModel, stateCount } from '../lib/models.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

async function openEditSave(name, capabilities, activities) {
    const shot = screenshotter(name.toLowerCase());
    const { model, states: count } = generatedModel(name, capabilities, activities);
    const started = Date.now();
    const page = await openModel(browser.context, model);
    console.log(`# ${name}: ${count} states opened (arranged by the server, drawn) in ${Date.now() - started} ms`);
    let root = await modelRoot(page);
    assert.equal(states(root).length, count, 'every state of the file is in the diagram');
    await shot(page, 'opened');

    // rename the first activity by editing its name in place
    await renameState(page, 'Act0_0', 'Renamed0_0');
    root = await modelRoot(page);
    assert.ok(stateNamed(root, 'Renamed0_0'), 'the state is renamed');

    // move the Init state 60 pixels to the right with the mouse
    const init = stateNamed(root, 'Init');
    await centre(page, init.id);
    const box = await shapeBox(page, init.id);
    await page.mouse.click(box.x + 6, box.y + box.height / 2);
    await andUpdate(page, async () => {
        await page.mouse.move(box.x + 6, box.y + box.height / 2);
        await page.mouse.down();
        await page.mouse.move(box.x + 36, box.y + box.height / 2, { steps: 5 });
        await page.mouse.move(box.x + 66, box.y + box.height / 2, { steps: 5 });
        await page.mouse.up();
    });
    const moved = stateNamed(await modelRoot(page), 'Init');
    assert.ok(moved.bounds.x > init.bounds.x + 20, `Init moved right (${init.bounds.x} → ${moved.bounds.x})`);
    await shot(page, 'edited');

    await page.locator('[data-action="save"]').click();
    await page.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 60000 });
    const saved = readModelFile(model);
    assert.match(saved, /name="Renamed0_0"/, 'the rename is saved');
    assert.doesNotMatch(saved, /name="Act0_0"/);
    assert.equal(stateCount(saved), count, 'every state is saved');
    const notation = JSON.parse(readFileSync(path.join(servedFolder(), `${name}.notation.json`), 'utf8'));
    const entry = notation.states.find(each => each.element === moved.id);
    assert.ok(entry, 'the notation places the moved state');
    assert.equal(entry.bounds.x, moved.bounds.x, 'the move is saved');
    assert.equal(notation.states.length, count, 'the notation places every state');
    assert.deepEqual(page.problems, [], 'no errors in the page');
    await page.close();
}

test('a 1,000-state statechart opens, is edited and saved', () => openEditSave('Scale1000', 10, 24));

test('a 5,000-state statechart opens, is edited and saved', () => openEditSave('Scale5000', 50, 24));
