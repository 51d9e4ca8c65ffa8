// Copy and paste (GLSP's clipboard: Ctrl+C / Ctrl+V on the focused diagram).
import assert from 'node:assert/strict';
import { after, afterEach, before, test } from 'node:test';
import { andUpdate, clickState, copyGoalie, launch, modelRoot, openModel, readModelFile, screenshotter, stateNamed, states, closePages } from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

test('a copied state is pasted', async () => {
    const shot = screenshotter('clipboard');
    const model = copyGoalie('clipboard');
    const page = await openModel(browser.context, model);
    const before = states(await modelRoot(page));
    const kick = stateNamed(await modelRoot(page), 'Kick');
    await clickState(page, kick.id);
    await shot(page, 'selected');
    await page.keyboard.press('Control+c');
    // the copied data comes from the server (RequestClipboardDataAction), a moment later
    await page.waitForTimeout(800);
    await andUpdate(page, () => page.keyboard.press('Control+v'));
    const after = states(await modelRoot(page));
    await shot(page, 'pasted');
    assert.equal(after.length, before.length + 1, 'one more state');
    const added = after.filter(state => !before.some(old => old.id === state.id) || false);
    assert.ok(added.some(state => state.type === 'state:basic'), 'the pasted state is a BASIC state');
    await andUpdate(page, () => page.keyboard.press('Control+z'));
    assert.equal(states(await modelRoot(page)).length, before.length, 'undo removes the pasted state');
    await page.close();
});

test('a copied composite is pasted into another one, relabelled, and saved', async () => {
    const shot = screenshotter('clipboard-composite');
    const model = copyGoalie('clipboard-composite');
    const page = await openModel(browser.context, model);
    const root = await modelRoot(page);
    // Scan_one_or_more_times_ (0.2.2.3.3: START, Scan, END and the transitions between them)
    // copied into followBall (0.2.2.3.6)
    const composite = stateNamed(root, 'Scan_one_or_more_times_');
    const target = stateNamed(root, 'followBall');
    await clickState(page, composite.id);
    await page.keyboard.press('Control+c');
    await page.waitForTimeout(800);
    await clickState(page, target.id);
    await shot(page, 'target-selected');
    await andUpdate(page, () => page.keyboard.press('Control+v'));
    await shot(page, 'pasted');
    await page.locator('[data-action="save"]').click();
    await page.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
    const saved = readModelFile(model);
    const followBallChildren = [...saved.matchAll(/label="0\.2\.2\.3\.6\.(\d+)"/g)].map(match => Number(match[1]));
    const next = Math.max(...followBallChildren);
    const pasted = saved.match(new RegExp(`<Children name="Scan_one_or_more_times_" label="0\\.2\\.2\\.3\\.6\\.${next}" type="OR">`));
    assert.ok(pasted, `the composite is pasted as the last child of followBall, labelled 0.2.2.3.6.${next}`);
    const inside = `0.2.2.3.6.${next}`;
    assert.match(saved, new RegExp(`label="${inside.replace(/\./g, '\\.')}\\.1" type="START"`), 'its START is relabelled below it');
    assert.match(saved, new RegExp(`name="Scan" label="${inside.replace(/\./g, '\\.')}\\.2" type="BASIC"`), 'its activity is relabelled below it');
    assert.match(saved, new RegExp(`label="${inside.replace(/\./g, '\\.')}\\.3" type="END"`), 'its END is relabelled below it');
    const labels = [...saved.matchAll(/<(?:nodes|Children) name="[^"]*" label="([^"]*)"/g)].map(match => match[1]);
    assert.equal(new Set(labels).size, labels.length, 'every label stays unique');
    assert.equal(labels.filter(label => label.startsWith('0.2.2.3.3.')).length, 3, 'the original is unchanged');
    // the pasted composite is followBall's child number `next`, at index next - 1
    const pastedPath = `//@nodes.0/@Children.1/@Children.1/@Children.2/@Children.5/@Children.${next - 1}/`;
    const innerTransitions = [...saved.matchAll(/<transitions [^>]*source="([^"]*)" target="([^"]*)"/g)]
        .filter(match => match[1].startsWith(pastedPath) && match[2].startsWith(pastedPath));
    assert.ok(innerTransitions.length >= 2, `the inner transitions come along (${innerTransitions.length})`);
    await page.close();
});
