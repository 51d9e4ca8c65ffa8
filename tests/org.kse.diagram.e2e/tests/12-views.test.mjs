// Issue 14, item 3: one model, many views. Two tabs of one file share the model on the server: a
// change in one shows in the other at once, a save in one is the other's too, and nothing is lost
// between them. A file changed on disk by another program is read again when nobody has unsaved
// edits; with unsaved edits the pages ask (Reload / Keep mine), and Keep mine then overwrites the
// file knowingly.
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { after, afterEach, before, test } from 'node:test';
import {
    closePages,
    copyGoalie,
    renameState,
    launch,
    modelRoot,
    openModel,
    readModelFile,
    revision,
    screenshotter,
    servedFolder,
    stateNamed,
    waitForUpdate
} from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());


const dirty = page => page.evaluate(() => window.kse.isDirty());
const named = async (page, name) => stateNamed(await modelRoot(page), name) !== undefined;

/** Another program changes the model file: one state renamed in the XML. */
function renameOnDisk(model, from, to) {
    const file = path.join(servedFolder(), model);
    const xml = readModelFile(model);
    assert.match(xml, new RegExp(`name="${from}"`));
    writeFileSync(file, xml.replace(`name="${from}"`, `name="${to}"`));
}

test('two tabs of one file: a rename in one shows in the other, a save in one is both, nothing is lost', async () => {
    const shot = screenshotter('views-tabs');
    const model = copyGoalie('views-tabs');
    const first = await openModel(browser.context, model);
    const second = await openModel(browser.context, model);

    const before = await revision(second);
    await renameState(first, 'Kick', 'KickFirst');
    await waitForUpdate(second, before);
    assert.ok(await named(second, 'KickFirst'), 'the other tab shows the rename at once');
    assert.equal(await dirty(second), true, 'and that the model has unsaved edits');
    await shot(second, 'second-sees-rename');

    await first.locator('[data-action="save"]').click();
    await first.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
    await second.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
    assert.match(readModelFile(model), /name="KickFirst"/, 'the first tab saved its rename');

    const firstBefore = await revision(first);
    await renameState(second, 'Scan', 'ScanSecond');
    await waitForUpdate(first, firstBefore);
    assert.ok(await named(first, 'ScanSecond'), 'a rename in the second tab shows in the first');
    await second.locator('[data-action="save"]').click();
    await second.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
    const saved = readModelFile(model);
    assert.match(saved, /name="ScanSecond"/, "the second tab's save has its own edit");
    assert.match(saved, /name="KickFirst"/, "and the first tab's, saved before: nothing is lost");
    await first.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 }); // the first tab learns it is saved
    assert.deepEqual([...first.problems, ...second.problems], [], 'no errors in the pages');
});

test('a file changed on disk while nobody has unsaved edits is shown anew in every tab', async () => {
    const shot = screenshotter('views-disk');
    const model = copyGoalie('views-disk');
    const first = await openModel(browser.context, model);
    const second = await openModel(browser.context, model);
    const before = [await revision(first), await revision(second)];
    renameOnDisk(model, 'Kick', 'KickOnDisk');
    await waitForUpdate(first, before[0]);
    await waitForUpdate(second, before[1]);
    for (const page of [first, second]) {
        assert.ok(await named(page, 'KickOnDisk'), 'the page shows the version on disk');
        assert.equal(await dirty(page), false, 'which is saved');
        assert.match(await page.locator('#kse-disk-change').innerText(), /changed on disk: reloaded/, 'and says why');
    }
    await shot(first, 'reloaded');
    // the reloaded model is edited and saved as any other
    await renameState(first, 'Scan', 'ScanAfter');
    await first.locator('[data-action="save"]').click();
    await first.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
    const saved = readModelFile(model);
    assert.match(saved, /name="KickOnDisk"/);
    assert.match(saved, /name="ScanAfter"/);
});

test('a file changed on disk under unsaved edits: the pages ask, and Keep mine overwrites it knowingly', async () => {
    const shot = screenshotter('views-conflict');
    const model = copyGoalie('views-conflict');
    const first = await openModel(browser.context, model);
    const second = await openModel(browser.context, model);
    await renameState(first, 'Scan', 'ScanMine');
    renameOnDisk(model, 'Kick', 'KickTheirs');
    for (const page of [first, second]) {
        await page.waitForFunction(() => document.body.dataset.kseDiskChange === 'conflict', null, { timeout: 15000 });
        assert.match(await page.locator('#kse-disk-change').innerText(), /changed on disk.*unsaved edits/s, 'the page asks');
    }
    assert.ok(await named(first, 'ScanMine'), 'nothing was thrown away unasked');
    await shot(first, 'asked');

    // a save before the choice is refused: it would overwrite a change it has not seen
    await first.locator('[data-action="save"]').click();
    await first.waitForFunction(() => /changed on disk/.test(document.querySelector('#kse-status')?.textContent ?? ''), null, { timeout: 15000 });
    assert.match(readModelFile(model), /name="KickTheirs"/, 'their version is still on disk');
    assert.equal(await dirty(first), true);

    await second.locator('#kse-disk-change button', { hasText: 'Keep mine' }).click();
    for (const page of [first, second]) {
        await page.waitForFunction(() => document.body.dataset.kseDiskChange === 'kept', null, { timeout: 15000 });
        assert.equal(await page.locator('#kse-disk-change button').count(), 0, 'the choice is made for every page: no more question');
    }
    await first.locator('[data-action="save"]').click();
    await first.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
    const saved = readModelFile(model);
    assert.match(saved, /name="ScanMine"/, 'Keep mine: the edits are saved');
    assert.match(saved, /name="Kick"/, 'over the version on disk, as chosen');
    assert.doesNotMatch(saved, /KickTheirs/);
    await shot(first, 'kept-and-saved');
});

test('a file changed on disk under unsaved edits: Reload shows the version on disk in every tab', async () => {
    const shot = screenshotter('views-reload');
    const model = copyGoalie('views-reload');
    const first = await openModel(browser.context, model);
    const second = await openModel(browser.context, model);
    await renameState(first, 'Scan', 'ScanDropped');
    renameOnDisk(model, 'Kick', 'KickTheirs');
    await first.waitForFunction(() => document.body.dataset.kseDiskChange === 'conflict', null, { timeout: 15000 });
    await second.waitForFunction(() => document.body.dataset.kseDiskChange === 'conflict', null, { timeout: 15000 });
    const before = [await revision(first), await revision(second)];
    await first.locator('#kse-disk-change button', { hasText: 'Reload' }).click();
    await waitForUpdate(first, before[0]);
    await waitForUpdate(second, before[1]);
    for (const page of [first, second]) {
        await page.waitForFunction(() => document.body.dataset.kseDiskChange === 'reloaded', null, { timeout: 15000 });
        assert.ok(await named(page, 'KickTheirs'), 'the version on disk is shown');
        assert.ok(await named(page, 'Scan'), 'without the dropped edit');
        assert.equal(await dirty(page), false);
    }
    await shot(second, 'reloaded');
});
