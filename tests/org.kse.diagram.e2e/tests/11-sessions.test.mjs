// Issue 14, item 1: a session survives idle time, and a page whose connection drops (the network,
// not the page, cuts it) reconnects by itself to the same model and command stack on the server:
// no unsaved edit is lost, the user sees a short notice, the server logs the disconnect once.
import assert from 'node:assert/strict';
import { after, afterEach, before, test } from 'node:test';
import {
    andUpdate,
    closePages,
    copyGoalie,
    renameState,
    focusDiagram,
    launch,
    modelRoot,
    openModel,
    readModelFile,
    screenshotter,
    serverLog,
    stateNamed
} from '../lib/harness.mjs';
import { startRelay } from '../lib/relay.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

const disconnects = () => serverLog().split('\n').filter(line => line.includes('a diagram page disconnected')).length;


async function save(page) {
    await page.locator('[data-action="save"]').click();
    await page.waitForFunction(() => !window.kse.isDirty(), null, { timeout: 15000 });
}

test('a page left idle for 40 s keeps its connection and its unsaved edit, and saves it', async () => {
    const shot = screenshotter('idle');
    const model = copyGoalie('idle');
    const page = await openModel(browser.context, model);
    await renameState(page, 'Kick', 'KickIdle');
    const before = disconnects();
    // longer than the 30 s after which the WebSocket used to be closed as idle
    await page.waitForTimeout(40000);
    assert.equal(await page.evaluate(() => document.body.dataset.kseConnection), 'open', 'the page never lost its connection');
    assert.equal(disconnects(), before, 'the server logged no disconnect');
    assert.equal(await page.evaluate(() => window.kse.isDirty()), true, 'the edit is still unsaved');
    await shot(page, 'after-40s');
    await save(page);
    assert.match(readModelFile(model), /name="KickIdle"/, 'the save after the idle time wrote the edit');
    assert.deepEqual(page.problems, [], 'no errors in the page');
});

test('a page whose connection drops reconnects by itself with its unsaved edit and undo history', async () => {
    const shot = screenshotter('reconnect');
    const relay = await startRelay(process.env.KSE_E2E_URL);
    try {
        const model = copyGoalie('reconnect');
        const page = await openModel(browser.context, model, { through: relay.url });
        await renameState(page, 'Kick', 'KickOnce');
        assert.equal(await page.evaluate(() => window.kse.isDirty()), true);
        assert.equal(relay.connections(), 1, 'the page talks to the server through the relay');
        const before = disconnects();

        const notice = page.waitForFunction(
            () => document.body.dataset.kseConnection === 'reconnecting' && document.querySelector('#kse-status .kse-status-text')?.textContent,
            null,
            { polling: 20, timeout: 15000 }
        );
        relay.dropConnections();
        assert.match(String(await (await notice).jsonValue()), /lost.*reconnecting/i, 'the page says it lost the connection and reconnects');
        await page.waitForFunction(() => document.body.dataset.kse === 'ready' && document.body.dataset.kseConnection === 'reconnected', null, {
            timeout: 30000
        });
        const said = await page.evaluate(() => window.kse.messages().map(entry => entry.message));
        assert.ok(said.includes('Reconnected to the diagram server'), `and that it is back (${said.join(' | ')})`);
        await shot(page, 'reconnected');

        const root = await modelRoot(page);
        assert.ok(stateNamed(root, 'KickOnce'), 'the unsaved rename is still there');
        assert.equal(await page.evaluate(() => window.kse.isDirty()), true, 'and still unsaved');
        await focusDiagram(page);
        await andUpdate(page, () => page.keyboard.press('Control+z'));
        assert.ok(stateNamed(await modelRoot(page), 'Kick'), 'undo undoes the edit made before the drop');
        await andUpdate(page, () => page.keyboard.press('Control+Shift+z'));
        assert.ok(stateNamed(await modelRoot(page), 'KickOnce'), 'and redo redoes it');
        await save(page);
        assert.match(readModelFile(model), /name="KickOnce"/, 'the save writes it');
        assert.equal(disconnects(), before + 1, 'the server logged the disconnect in one line');
        // GLSP's client logs the drop itself; anything else would be a problem
        const problems = page.problems.filter(problem => !/Connection to server got closed/.test(problem));
        assert.deepEqual(problems, [], 'no errors in the page');
    } finally {
        await relay.close();
    }
});
