// Leaving a page with unsaved edits asks first (issue 14, item 6): closing the tab or going
// elsewhere raises the browser's "leave site?" question, and staying keeps the edits; a page
// whose edits are saved, or that has none, closes without a question.
import assert from 'node:assert/strict';
import { after, afterEach, before, test } from 'node:test';
import { andUpdate, clickState, closePages, copyGoalie, launch, modelRoot, openModel, stateNamed } from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

/** Closes the page as a user closes a tab; answers the question, if one comes, with `stay` or leave. Returns whether it was asked. */
async function closeTab(page, { stay }) {
    let asked = false;
    const answered = new Promise(resolve => {
        page.once('dialog', async dialog => {
            asked = dialog.type() === 'beforeunload';
            await (stay ? dialog.dismiss() : dialog.accept());
            resolve();
        });
    });
    await page.close({ runBeforeUnload: true });
    await Promise.race([answered, page.waitForEvent('close', { timeout: 3000 }).catch(() => undefined), new Promise(resolve => setTimeout(resolve, 3000))]);
    return asked;
}

test('a page with unsaved edits asks before it is closed; one without closes at once', async () => {
    const model = copyGoalie('leave');
    const page = await openModel(browser.context, model);
    const kick = stateNamed(await modelRoot(page), 'Kick');
    await clickState(page, kick.id);
    await andUpdate(page, () => page.keyboard.press('ArrowDown'));
    assert.equal(await page.evaluate(() => window.kse.isDirty()), true, 'an unsaved nudge');

    assert.equal(await closeTab(page, { stay: true }), true, 'closing asks');
    assert.equal(page.isClosed(), false, 'staying keeps the page');
    assert.equal(await page.evaluate(() => window.kse.isDirty()), true, 'with its edit');

    await page.evaluate(() => window.kse.run('save'));
    await page.waitForFunction(() => document.body.dataset.kseDirty === 'false');
    assert.equal(await closeTab(page, { stay: false }), false, 'a saved page closes without a question');
    assert.equal(page.isClosed(), true);

    const untouched = await openModel(browser.context, model);
    assert.equal(await closeTab(untouched, { stay: false }), false, 'a page without edits closes without a question');
});
