// Double clicking a name or a transition's expression edits it in place (ApplyLabelEditOperation).
import assert from 'node:assert/strict';
import { after, afterEach, before, test } from 'node:test';
import { andUpdate, copyGoalie, cssString, launch, modelRoot, openModel, readModelFile, screenshotter, stateNamed, transitions, closePages } from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

test('a state is renamed by double clicking its name', async () => {
    const shot = screenshotter('rename');
    const model = copyGoalie('rename');
    const page = await openModel(browser.context, model);
    const kick = stateNamed(await modelRoot(page), 'Kick');
    await page.locator(`#kse-diagram [id$="${cssString(kick.id)}#name"]`).dblclick();
    const editor = page.locator('.label-edit input');
    await editor.waitFor({ state: 'visible' });
    assert.equal(await editor.inputValue(), 'Kick', 'the editor starts with the name');
    await shot(page, 'editing');
    await editor.fill('KickHard');
    await andUpdate(page, () => editor.press('Enter'));
    const root = await modelRoot(page);
    assert.ok(stateNamed(root, 'KickHard'), 'the state is renamed');
    assert.equal(stateNamed(root, 'Kick'), undefined);
    await shot(page, 'renamed');
    await page.locator('[data-action="save"]').click();
    await page.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
    assert.match(readModelFile(model), /name="KickHard"/, 'the new name is saved');
    await page.close();
});

test('a transition expression is edited whole', async () => {
    const shot = screenshotter('expression');
    const model = copyGoalie('expression');
    const page = await openModel(browser.context, model);
    const root = await modelRoot(page);
    const edge = transitions(root).find(t => String(t.args.expression ?? '').includes('\n'));
    const label = page.locator(`#kse-diagram [id$="${cssString(edge.id)}#expression"]`);
    await label.dblclick({ force: true });
    const editor = page.locator('.label-edit textarea');
    await editor.waitFor({ state: 'visible' });
    assert.equal(await editor.inputValue(), edge.args.expression, 'the editor starts with the whole expression, all its lines');
    await shot(page, 'editing');
    // what the server refuses keeps the editor open with the reason
    await editor.fill('[ready()]\n/Stop');
    await editor.press('Enter');
    await page.locator('.label-edit.validation-error').waitFor({ state: 'attached', timeout: 10000 });
    assert.equal(await editor.isVisible(), true, 'an invalid expression is not applied');
    assert.ok((await page.locator('.label-edit').getAttribute('data-balloon'))?.length > 0, 'the reason is shown');
    await shot(page, 'invalid');
    // a valid expression (another transition's) is applied
    const other = transitions(root).find(t => t.id !== edge.id && String(t.args.expression ?? '').includes('\n'));
    const changed = other.args.expression;
    await editor.fill(changed);
    await andUpdate(page, () => editor.press('Enter'));
    const updated = transitions(await modelRoot(page)).find(t => t.id === edge.id);
    assert.equal(updated.args.expression, changed, 'the expression is replaced');
    await shot(page, 'edited');
    await page.close();
});

test("an answer to a name's check that comes after the editor stopped waiting is no error in the page", async () => {
    // GLSP's validator waits 2 s for it; a server busy with thousands of states can answer later
    const page = await openModel(browser.context, copyGoalie('late-check'));
    const kick = stateNamed(await modelRoot(page), 'Kick');
    await page.evaluate(id => window.kse.dispatch({
        kind: 'setEditValidationResult',
        responseId: 'a-request-nobody-waits-for',
        status: { severity: 0, message: '' },
        args: { element: id }
    }), kick.id);
    assert.deepEqual(page.problems, [], 'no errors in the page');
    await page.close();
});
