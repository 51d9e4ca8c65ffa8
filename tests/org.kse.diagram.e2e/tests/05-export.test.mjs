// Export SVG and Export PNG download pictures of the diagram named after the model; the grid,
// zoom and print view work.
import assert from 'node:assert/strict';
import { mkdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { after, afterEach, before, test } from 'node:test';
import { clickState, copyGoalie, downloads, launch, modelRoot, openModel, screenshotter, stateNamed, states, transitions as transitionsOf, closePages } from '../lib/harness.mjs';

let browser;
before(async () => (browser = await launch()));
afterEach(() => closePages());
after(async () => browser?.close());

async function download(page, action) {
    mkdirSync(downloads, { recursive: true });
    const [file] = await Promise.all([page.waitForEvent('download', { timeout: 20000 }), page.locator(`[data-action="${action}"]`).click()]);
    const target = path.join(downloads, file.suggestedFilename());
    await file.saveAs(target);
    return { name: file.suggestedFilename(), path: target };
}

test('Export SVG downloads <model>.svg with the states', async () => {
    const shot = screenshotter('export-svg');
    const model = copyGoalie('Exported');
    const page = await openModel(browser.context, model);
    await shot(page, 'opened');
    const file = await download(page, 'export-svg');
    assert.equal(file.name, 'Exported.svg');
    const svg = readFileSync(file.path, 'utf8');
    assert.match(svg, /^(<\?xml[^>]*>\s*)?<svg\b/, 'an SVG document');
    assert.match(svg, /xmlns="http:\/\/www\.w3\.org\/2000\/svg"/);
    const root = await modelRoot(page);
    const names = states(root)
        .map(state => root && findName(root, state.id))
        .filter(name => name && name !== 'C');
    assert.ok(names.length > 10);
    for (const name of names) {
        assert.ok(svg.includes(`>${escapeXml(name)}<`), `the SVG shows the state ${name}`);
    }
    assert.match(svg, /rgb\(185, 228, 164\)|#b9e4a4/i, 'BASIC states keep their green');

    // the exported picture renders: open it in the browser and look at it
    const view = await browser.context.newPage();
    await view.setContent(`<body style="margin:0;background:#fff">${svg.replace(/^<\?xml[^>]*>/, '')}</body>`);
    await view.screenshot({ path: path.join(path.dirname(await shot(page, 'exported')), 'export-svg-03-file.png'), fullPage: true });
    await view.close();
    await page.close();
});

function findName(root, id) {
    const stack = [root];
    while (stack.length) {
        const element = stack.pop();
        if (element.id === `${id}#name`) {
            return element.text;
        }
        stack.push(...(element.children ?? []));
    }
    return undefined;
}

function escapeXml(text) {
    return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

test('Export SVG with a composite selected pictures that composite only', async () => {
    const shot = screenshotter('export-composite');
    const model = copyGoalie('Composite');
    const page = await openModel(browser.context, model);
    const whole = viewBox(await page.evaluate(() => window.kse.exportSvg()));
    const root = await modelRoot(page);
    const followBall = stateNamed(root, 'followBall');
    assert.equal(followBall?.type, 'state:or', 'followBall is an OR state');
    await clickState(page, followBall.id);
    await page.waitForFunction(id => window.kse.selection().includes(id), followBall.id);
    await shot(page, 'selected');
    const file = await download(page, 'export-svg');
    const svg = readFileSync(file.path, 'utf8');
    const [, , width, height] = viewBox(svg);
    assert.equal(width, followBall.bounds.width + 24, 'as wide as the composite, with the margin');
    assert.equal(height, followBall.bounds.height + 24, 'as high as the composite, with the margin');
    assert.ok(width < whole[2] && height < whole[3], `smaller than the whole diagram (${width} against ${whole[2]})`);
    assert.ok(svg.includes('>followBall<'), 'the composite is in the picture');
    assert.ok(svg.includes('>Stare<'), 'with its insides');
    assert.ok(!svg.includes('>nonPlaying<') && !svg.includes('>playing<'), 'and nothing beside or around it');
    const drawnTransitions = svg.match(/data-kind="transition"/g)?.length ?? 0;
    assert.ok(drawnTransitions > 0 && drawnTransitions < transitionsOf(root).length, `only the transitions inside it (${drawnTransitions})`);
    const view = await browser.context.newPage();
    await view.setContent(`<body style="margin:0;background:#fff">${svg.replace(/^<\?xml[^>]*>/, '')}</body>`);
    await view.screenshot({ path: path.join(path.dirname(await shot(page, 'exported')), 'export-composite-03-file.png'), fullPage: true });
    await view.close();
    await page.close();
});

function viewBox(svg) {
    const match = /<svg[^>]*\sviewBox="([^"]+)"/.exec(svg);
    assert.ok(match, 'the SVG has a viewBox');
    return match[1].split(/[\s,]+/).map(Number);
}

test('Export PNG downloads <model>.png', async () => {
    const shot = screenshotter('export-png');
    const model = copyGoalie('Pictured');
    const page = await openModel(browser.context, model);
    const file = await download(page, 'export-png');
    assert.equal(file.name, 'Pictured.png');
    const png = readFileSync(file.path);
    assert.deepEqual([...png.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a], 'a PNG file');
    const width = png.readUInt32BE(16);
    const height = png.readUInt32BE(20);
    assert.ok(width > 800 && height > 400, `a picture of the whole diagram (${width}×${height})`);
    // look at it
    const view = await browser.context.newPage();
    await view.setContent(`<img src="data:image/png;base64,${png.toString('base64')}" style="max-width:100%">`);
    await view.waitForTimeout(300);
    await view.screenshot({ path: path.join(path.dirname(await shot(page, 'exported')), 'export-png-02-file.png') });
    await view.close();
    await page.close();
});

test('zoom, grid and the print view', async () => {
    const shot = screenshotter('view');
    const model = copyGoalie('view');
    const page = await openModel(browser.context, model);
    const zoom = async () => (await modelRoot(page)).viewport.zoom;
    const initial = await zoom();
    await page.locator('[data-action="zoom-in"]').click();
    await page.waitForTimeout(700);
    const zoomedIn = await zoom();
    assert.ok(zoomedIn > initial, 'Zoom in enlarges');
    await shot(page, 'zoomed-in');
    await page.locator('[data-action="zoom-out"]').click();
    await page.locator('[data-action="zoom-out"]').click();
    await page.waitForTimeout(700);
    assert.ok((await zoom()) < zoomedIn, 'Zoom out shrinks');
    await page.locator('[data-action="fit"]').click();
    await page.waitForTimeout(700);
    await shot(page, 'fit');

    await page.locator('[data-action="grid"]').click();
    await page.waitForTimeout(300);
    assert.equal(await page.locator('[data-action="grid"]').getAttribute('aria-pressed'), 'true', 'the grid is on');
    const background = await page.evaluate(() => getComputedStyle(document.querySelector('#kse-diagram svg')).backgroundImage);
    assert.notEqual(background, 'none', 'the grid is drawn');
    await shot(page, 'grid');
    await page.locator('[data-action="grid"]').click();
    assert.equal(await page.locator('[data-action="grid"]').getAttribute('aria-pressed'), 'false', 'the grid is off again');

    await page.emulateMedia({ media: 'print' });
    assert.equal(await page.locator('#kse-toolbar').isVisible(), false, 'the toolbar is not printed');
    assert.equal(await page.locator('#kse-status').isVisible(), false, 'the status line is not printed');
    await shot(page, 'print-view');
    await page.emulateMedia({ media: 'screen' });
    await page.close();
});
