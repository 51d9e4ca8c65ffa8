// What users of diagram editors expect (issue 14, item 6): arrow keys nudge the selected states,
// + / - zoom, Ctrl+0 fits, Ctrl+F finds a state by name or label and centres it, a right click
// opens a context menu whose actions work.
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

const zoomOf = async page => (await modelRoot(page)).viewport.zoom;
const positionOf = async (page, name) => stateNamed(await modelRoot(page), name).bounds;

/** Waits until the viewport stops changing (zooms are animated). */
async function settled(page) {
    let last = JSON.stringify((await modelRoot(page)).viewport);
    for (let i = 0; i < 40; i++) {
        await page.waitForTimeout(100);
        const now = JSON.stringify((await modelRoot(page)).viewport);
        if (now === last) {
            return;
        }
        last = now;
    }
}

test('arrow keys nudge the selected state by a grid step (10 px), Shift by five, and Ctrl+Z takes a nudge back', async () => {
    const shot = screenshotter('keys-nudge');
    const model = copyGoalie('keys-nudge');
    const page = await openModel(browser.context, model);
    const kick = stateNamed(await modelRoot(page), 'Kick');
    await fitTo(page, kick.parentId);
    await clickState(page, kick.id);
    const start = await positionOf(page, 'Kick');
    const viewport = (await modelRoot(page)).viewport;
    await andUpdate(page, () => page.keyboard.press('ArrowRight'));
    let now = await positionOf(page, 'Kick');
    assert.deepEqual([now.x - start.x, now.y - start.y], [10, 0], 'ArrowRight: 10 px right');
    assert.deepEqual((await modelRoot(page)).viewport.scroll, viewport.scroll, 'the view stays where it was');
    await page.waitForTimeout(400);
    await andUpdate(page, () => page.keyboard.press('Shift+ArrowDown'));
    now = await positionOf(page, 'Kick');
    assert.deepEqual([now.x - start.x, now.y - start.y], [10, 50], 'Shift+ArrowDown: 50 px down');
    await shot(page, 'nudged');
    assert.equal(await page.evaluate(() => window.kse.isDirty()), true);
    await andUpdate(page, () => page.keyboard.press('Control+z'));
    now = await positionOf(page, 'Kick');
    assert.deepEqual([now.x - start.x, now.y - start.y], [10, 0], 'one undo takes back the last press');
    await andUpdate(page, () => page.keyboard.press('Control+z'));
    now = await positionOf(page, 'Kick');
    assert.deepEqual([now.x, now.y], [start.x, start.y], 'and the next one the first');

    // presses in quick succession are one step
    await andUpdate(page, async () => {
        for (let i = 0; i < 3; i++) {
            await page.keyboard.press('ArrowLeft');
        }
    });
    now = await positionOf(page, 'Kick');
    assert.deepEqual([now.x - start.x, now.y - start.y], [-30, 0], 'three presses: 30 px left');
    await andUpdate(page, () => page.keyboard.press('Control+z'));
    now = await positionOf(page, 'Kick');
    assert.deepEqual([now.x, now.y], [start.x, start.y], 'one undo takes them back');
    await page.close();
});

test('+ and - zoom, Ctrl+0 fits the diagram into the window', async () => {
    const shot = screenshotter('keys-zoom');
    const model = copyGoalie('keys-zoom');
    const page = await openModel(browser.context, model);
    await focusDiagram(page);
    const opening = await zoomOf(page);
    await page.keyboard.press('+');
    await settled(page);
    const zoomedIn = await zoomOf(page);
    assert.ok(Math.abs(zoomedIn / opening - 1.25) < 0.01, `+ zooms in by 1.25 (${opening} → ${zoomedIn})`);
    await page.keyboard.press('-');
    await page.keyboard.press('-');
    await settled(page);
    const zoomedOut = await zoomOf(page);
    assert.ok(Math.abs(zoomedOut / zoomedIn - 0.64) < 0.01, `- zooms out by 1.25 each (${zoomedIn} → ${zoomedOut})`);
    await page.keyboard.press('+');
    await page.keyboard.press('+');
    await page.keyboard.press('+');
    await settled(page);
    await page.keyboard.press('Control+0');
    await settled(page);
    await shot(page, 'fit');
    const root = await modelRoot(page);
    const top = states(root).find(state => state.parentId === root.id);
    const box = await shapeBox(page, top.id);
    const diagram = await page.locator('#kse-diagram').boundingBox();
    assert.ok(
        box.x >= diagram.x - 1 && box.y >= diagram.y - 1 && box.x + box.width <= diagram.x + diagram.width + 1 && box.y + box.height <= diagram.y + diagram.height + 1,
        'Ctrl+0: the whole model is in the window'
    );
    assert.ok(box.width > diagram.width * 0.8 || box.height > diagram.height * 0.8, 'and fills it');
    assert.equal(await page.evaluate(() => document.activeElement?.tagName.toLowerCase()), 'svg', 'the browser did not take Ctrl+0');
    await page.close();
});

test('Ctrl+F finds a state by name or label, Enter selects and centres it and the next match, Escape closes', async () => {
    const shot = screenshotter('keys-find');
    const model = copyGoalie('keys-find');
    const page = await openModel(browser.context, model);
    const root = await modelRoot(page);
    await focusDiagram(page);
    await page.keyboard.press('Control+f');
    const box = page.locator('.kse-find');
    await box.waitFor({ state: 'visible' });
    assert.equal(await page.evaluate(() => document.activeElement?.closest('.kse-find') !== null), true, 'the find box has the keyboard');

    const zoom = await zoomOf(page);
    await page.keyboard.type('kick+-');
    assert.equal(await zoomOf(page), zoom, 'typing + and - in the box zooms nothing');
    await page.keyboard.press('Backspace');
    await page.keyboard.press('Backspace');
    await page.keyboard.press('Enter');
    await settled(page);
    const kick = stateNamed(root, 'Kick');
    assert.deepEqual(await page.evaluate(() => window.kse.selection()), [kick.id], 'Kick is selected');
    const centred = async id => {
        const shape = await shapeBox(page, id);
        // the canvas: the diagram's area left of the palette
        const diagram = await page.locator('#kse-diagram svg').first().boundingBox();
        return Math.hypot(shape.x + shape.width / 2 - (diagram.x + diagram.width / 2), shape.y + shape.height / 2 - (diagram.y + diagram.height / 2));
    };
    const offCentre = await centred(kick.id);
    assert.ok(offCentre < 30, `and in the middle of the window (${offCentre} px off)`);
    await shot(page, 'kick');

    // by its hierarchical label
    const followBall = stateNamed(root, 'followBall');
    await page.locator('.kse-find input').fill(followBall.args.label);
    await page.keyboard.press('Enter');
    await settled(page);
    assert.deepEqual(await page.evaluate(() => window.kse.selection()), [followBall.id], `${followBall.args.label} finds followBall`);
    assert.ok((await centred(followBall.id)) < 30);

    // the next match on the next Enter
    await page.locator('.kse-find input').fill('Stare');
    const stares = states(root).filter(state => [flatten(root).find(e => e.id === `${state.id}#name`)?.text, state.args?.name].some(text => text?.toLowerCase().includes('stare')));
    assert.ok(stares.length >= 2, 'more than one state is called like Stare');
    const found = [];
    for (let i = 0; i < stares.length + 1; i++) {
        await page.keyboard.press('Enter');
        await settled(page);
        found.push((await page.evaluate(() => window.kse.selection()))[0]);
    }
    assert.equal(found[0], stateNamed(root, 'Stare').id, 'the state called exactly so comes first');
    assert.deepEqual(new Set(found.slice(0, stares.length)), new Set(stares.map(state => state.id)), 'each Enter the next match');
    assert.equal(found[stares.length], found[0], 'then the first again');
    assert.match(await page.locator('.kse-find-count').innerText(), new RegExp(`1 of ${stares.length}`));
    await shot(page, 'next');

    await page.keyboard.press('Escape');
    await box.waitFor({ state: 'hidden' });
    assert.equal(await page.evaluate(() => document.activeElement?.tagName.toLowerCase()), 'svg', 'Escape gives the keyboard back to the diagram');
    await page.close();
});

test('a right click opens a context menu on states and transitions whose actions work', async () => {
    const shot = screenshotter('keys-menu');
    const model = copyGoalie('keys-menu');
    const page = await openModel(browser.context, model);
    let root = await modelRoot(page);
    const kick = stateNamed(root, 'Kick');
    await fitTo(page, kick.parentId);
    const menu = page.locator('.kse-context-menu');
    const items = async () => (await menu.locator('[role="menuitem"]').allInnerTexts()).map(text => text.trim());

    // on a state: delete it, with its transitions
    const kickBox = await shapeBox(page, kick.id);
    const before = transitions(root).length;
    await page.mouse.click(kickBox.x + 5, kickBox.y + kickBox.height / 2, { button: 'right' });
    await menu.waitFor({ state: 'visible' });
    await shot(page, 'state-menu');
    assert.deepEqual(await page.evaluate(() => window.kse.selection()), [kick.id], 'the right click selects Kick');
    await andUpdate(page, () => menu.getByText('Delete', { exact: true }).click());
    root = await modelRoot(page);
    assert.equal(stateNamed(root, 'Kick'), undefined, 'Kick is deleted');
    assert.ok(transitions(root).length < before, 'with its transitions');

    // on a composite: add a state inside it
    const followBall = stateNamed(root, 'followBall');
    const followBallBox = await shapeBox(page, followBall.id);
    await page.mouse.click(followBallBox.x + followBallBox.width - 12, followBallBox.y + followBallBox.height - 12, { button: 'right' });
    await menu.waitFor({ state: 'visible' });
    await shot(page, 'composite-menu');
    assert.deepEqual(await page.evaluate(() => window.kse.selection()), [followBall.id], 'the right click selects the state');
    const compositeItems = await items();
    for (const expected of ['Rename…', 'Add BASIC state inside', 'Delete', 'Cut', 'Copy', 'Paste']) {
        assert.ok(compositeItems.includes(expected), `the menu has ${expected}: ${compositeItems}`);
    }
    const insideBefore = states(root).filter(state => state.parentId === followBall.id).length;
    await andUpdate(page, () => menu.getByText('Add BASIC state inside').click());
    assert.equal(await menu.count(), 0, 'the menu closes');
    root = await modelRoot(page);
    assert.equal(states(root).filter(state => state.parentId === followBall.id).length, insideBefore + 1, 'a state was added inside followBall');

    // on a transition: edit its expression; Escape closes the menu
    // a transition whose middle is not covered by anything else (once the page has settled)
    await page.waitForTimeout(500);
    const labelled = transitions(root).filter(each => flatten(root).some(element => element.id === `${each.id}#expression`)).map(each => each.id);
    const { id: edgeId, point } = await page.evaluate(ids => {
        for (const id of ids) {
            const line = document.querySelector(`#kse-diagram [data-id="${CSS.escape(id)}"] .kse-line`);
            if (!line) {
                continue;
            }
            const middle = line.getPointAtLength(line.getTotalLength() / 2);
            const matrix = line.getScreenCTM();
            const point = { x: matrix.a * middle.x + matrix.c * middle.y + matrix.e, y: matrix.b * middle.x + matrix.d * middle.y + matrix.f };
            const canvas = line.ownerSVGElement.getBoundingClientRect();
            const inCanvas = point.x > canvas.left + 20 && point.x < canvas.right - 20 && point.y > canvas.top + 20 && point.y < canvas.bottom - 20;
            const hit = document.elementFromPoint(point.x, point.y);
            const labelShown = line.closest('[data-kind="transition"]')?.querySelector('text.kse-expression') !== null;
            if (inCanvas && labelShown && hit?.classList.contains('kse-edge-handle') && hit.closest('[data-kind="transition"]')?.getAttribute('data-id') === id) {
                return { id, point };
            }
        }
        return { id: undefined, point: undefined };
    }, labelled);
    assert.ok(edgeId, 'a transition is shown uncovered');
    await page.mouse.click(point.x, point.y, { button: 'right' });
    await menu.waitFor({ state: 'visible' });
    await shot(page, 'transition-menu');
    assert.deepEqual(await page.evaluate(() => window.kse.selection()), [edgeId], 'the right click selects the transition');
    const edgeItems = await items();
    assert.ok(edgeItems.includes('Edit expression…') && edgeItems.includes('Delete'), `the transition's menu: ${edgeItems}`);
    await page.keyboard.press('Escape');
    assert.equal(await menu.count(), 0, 'Escape closes the menu');
    await page.mouse.click(point.x, point.y, { button: 'right' });
    await menu.waitFor({ state: 'visible' });
    await menu.getByText('Edit expression…').click();
    const editor = page.locator('.label-edit textarea');
    await editor.waitFor({ state: 'visible' });
    assert.ok((await editor.inputValue()).length > 0, 'the expression editor opens with the expression');
    await shot(page, 'editing');
    await page.keyboard.press('Escape');
    assert.deepEqual(page.problems, [], 'no errors in the page');
    await page.close();
});
