// Shared helpers of the diagram end-to-end tests: the browser, the page of a model, screenshots,
// the client model (window.kse) and the served folder. run.sh starts the server and passes
// KSE_E2E_URL (a page URL with the session token) and KSE_E2E_FOLDER (the served folder).
import { after, before } from 'node:test';
import { chromium } from 'playwright-core';
import { copyFileSync, existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
export const moduleDir = path.resolve(here, '..');
export const repository = path.resolve(moduleDir, '..', '..');
export const screenshots = path.join(moduleDir, 'target', 'screenshots');
export const downloads = path.join(moduleDir, 'target', 'downloads');
export const goalieSource = path.join(repository, 'examples', 'Goalie', 'Goalie.stct');

function required(name) {
    const value = process.env[name];
    if (!value) {
        throw new Error(`${name} is not set: run the tests with run.sh (it starts the diagram server)`);
    }
    return value;
}

export const pageUrl = () => required('KSE_E2E_URL');
export const servedFolder = () => required('KSE_E2E_FOLDER');
/** What the server printed (run.sh's KSE_E2E_SERVER_LOG). */
export const serverLog = () => readFileSync(required('KSE_E2E_SERVER_LOG'), 'utf8');

/** A copy of the Goalie example in the served folder, under a name of its own (tests do not share files). */
export function copyGoalie(name) {
    const file = path.join(servedFolder(), `${name}.stct`);
    copyFileSync(goalieSource, file);
    return `${name}.stct`;
}

/**
 * A copy of a model of the repository (a path relative to it) in the served folder under a name of
 * its own, with the files that give its layout (the original's .kse diagram, a notation file).
 */
export function copyModel(source, name) {
    const from = path.join(repository, source);
    const base = from.replace(/\.stct$/, '');
    copyFileSync(from, path.join(servedFolder(), `${name}.stct`));
    for (const suffix of ['.kse', '.notation.json']) {
        if (existsSync(base + suffix)) {
            copyFileSync(base + suffix, path.join(servedFolder(), name + suffix));
        }
    }
    return `${name}.stct`;
}

export function readModelFile(model) {
    return readFileSync(path.join(servedFolder(), model), 'utf8');
}

/** Chromium (Debian's), headless, with a fresh profile. */
export async function launch() {
    const profile = mkdtempSync(path.join(os.tmpdir(), 'kse-e2e-profile-'));
    const context = await chromium.launchPersistentContext(profile, {
        executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
        headless: true,
        args: [
            '--headless',
            '--no-sandbox',
            '--disable-gpu',
            '--disable-quic',
            '--no-first-run',
            '--disable-background-networking',
            '--disable-component-update',
            '--disable-sync'
        ],
        viewport: { width: 1400, height: 900 },
        acceptDownloads: true
    });
    const close = async () => {
        await context.close();
        rmSync(profile, { recursive: true, force: true });
    };
    return { context, close };
}

/**
 * The browser of a test file: launched before its tests (unless the file's tests are all skipped:
 * `skip` is their node:test skip), closed after them with the pages a test left open. Its `context`
 * is there once the tests run.
 */
export function fileBrowser({ skip = false } = {}) {
    const browser = {};
    before(async () => {
        if (!skip) {
            Object.assign(browser, await launch());
        }
    });
    after(async () => {
        await closePages();
        await browser.close?.();
    });
    return browser;
}

/** The kse-match of the tests that play a match (KSE_MATCH), or undefined. */
export const kseMatch = process.env.KSE_MATCH;

/**
 * node:test's skip for the tests of a file (its import.meta.url) that watch a kse-match built with
 * --monitor: false when KSE_MATCH gives one, otherwise how to run them.
 */
export function skipWithoutKseMatch(testFileUrl) {
    const file = path.basename(fileURLToPath(testFileUrl));
    return kseMatch ? false : `KSE_MATCH is not set: give it a kse-match built with --monitor (e.g. KSE_MATCH=build/examples/kse-match run.sh tests/${file})`;
}

/**
 * The engine's name of a state (GenerationPlan.stateName), as the match log and the monitor name
 * active states: Node_ and its name, or its label with '_' for what is not a letter or digit.
 */
export function engineName(state) {
    const label = state.args?.label ?? '';
    const name = state.args?.name ?? '';
    const byLabel = name === '' || name === label;
    return 'Node_' + (byLabel ? (label === '' ? 'unlabeled' : label.replace(/[^A-Za-z0-9_]/g, '_')) : name);
}

const openPages = new Set();

/**
 * Closes the pages a test left open (e.g. when it failed): pages of one file share its model on
 * the server, so a page left open would carry its edits into the next test's page of that file.
 */
export async function closePages() {
    for (const page of [...openPages]) {
        await page.close().catch(() => undefined);
    }
}

/**
 * Opens the page of a model (relative to the served folder) and waits until its diagram is shown;
 * `through` is another page URL of the server to open it by (a relay's). A page opens at a readable
 * zoom, showing a large diagram only in part; unless `fit` is false the whole diagram is then
 * fitted into the window (at most at 100 %), as a user clicking Fit, so that a test reaches every state.
 */
export async function openModel(context, model, { expectError = false, through = pageUrl(), fit = true } = {}) {
    const url = new URL(through);
    url.searchParams.set('model', model);
    const page = await context.newPage();
    const problems = [];
    page.on('pageerror', error => problems.push(error.message));
    page.on('console', message => {
        if (message.type() === 'error' && !/favicon|Failed to load resource/.test(message.text())) {
            problems.push(message.text());
        }
    });
    page.problems = problems;
    if (process.env.KSE_E2E_TRACE) {
        // KSE_E2E_TRACE=1 prints the GLSP messages (for debugging a test)
        page.on('websocket', socket => {
            socket.on('framesent', frame => console.log('>>', String(frame.payload).slice(0, 400)));
            socket.on('framereceived', frame => console.log('<<', String(frame.payload).slice(0, 400)));
        });
    }
    openPages.add(page);
    page.on('close', () => openPages.delete(page));
    await page.goto(url.toString());
    await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.kse), null, { timeout: 60000 });
    const state = await page.evaluate(() => document.body.dataset.kse);
    if (!expectError && state !== 'ready') {
        const status = await page.locator('#kse-status').innerText();
        throw new Error(`the diagram of ${model} did not open: ${status}`);
    }
    if (fit && state === 'ready') {
        await page.evaluate(async () => {
            const root = window.kse.modelRoot();
            const elementIds = root.children.filter(child => child.type.startsWith('state:')).map(child => child.id);
            await window.kse.dispatch({ kind: 'fit', elementIds, padding: 24, maxZoom: 1, animate: false });
            await new Promise(resolve => requestAnimationFrame(() => requestAnimationFrame(resolve)));
        });
    }
    return page;
}

/** Screenshots of a test's steps: target/screenshots/<test>-<nn>-<step>.png. */
export function screenshotter(test) {
    mkdirSync(screenshots, { recursive: true });
    let count = 0;
    return async (page, step) => {
        count++;
        const file = path.join(screenshots, `${test}-${String(count).padStart(2, '0')}-${step}.png`);
        await page.screenshot({ path: file });
        return file;
    };
}

export const modelRoot = page => page.evaluate(() => window.kse.modelRoot());

export function flatten(root) {
    const all = [];
    (function walk(element, parent) {
        all.push({ ...element, parentId: parent?.id });
        for (const child of element.children ?? []) {
            walk(child, element);
        }
    })(root, undefined);
    return all;
}

export const states = root => flatten(root).filter(element => element.type.startsWith('state:'));
export const transitions = root => flatten(root).filter(element => element.type === 'transition');

export function nameOf(root, stateId) {
    return flatten(root).find(element => element.id === `${stateId}#name`)?.text;
}

export function stateNamed(root, name) {
    // a state named after a formula shows the formula as caption: its name is its `name` argument
    const named = states(root).find(state => state.args?.name === name);
    if (named) {
        return named;
    }
    const label = flatten(root).find(element => element.type === 'label:name' && element.text === name);
    return label ? states(root).find(state => state.id === label.parentId) : undefined;
}

export const revision = async page => Number(await page.evaluate(() => document.body.dataset.kseRevision ?? 0));

/** Waits for a model update after `previous` (the revision counter the page keeps). */
export async function waitForUpdate(page, previous, timeout = 15000) {
    await page.waitForFunction(before => Number(document.body.dataset.kseRevision ?? 0) > before, previous, { timeout });
    await page.waitForTimeout(150);
}

/** Does something and waits for the model update it causes. */
export async function andUpdate(page, action) {
    const before = await revision(page);
    await action();
    await waitForUpdate(page, before);
}

/** The on-screen box of a state's shape (in the visible diagram, not the hidden one). */
export async function shapeBox(page, stateId) {
    const box = await page.locator(`#kse-diagram [data-id="${cssString(stateId)}"] > .kse-shape`).first().boundingBox();
    if (!box) {
        throw new Error(`state ${stateId} is not shown`);
    }
    return box;
}

export function cssString(value) {
    return value.replace(/\\/g, '\\\\').replace(/"/g, '\\"');
}

/**
 * Clicks a state: a box near its left side (not on its name), a disc (START, END, CONDITION) in
 * its centre; `dx`/`dy` choose another point of its box.
 */
export async function clickState(page, stateId, options = {}) {
    const box = await shapeBox(page, stateId);
    const round = await page.locator(`#kse-diagram [data-id="${cssString(stateId)}"] > circle.kse-shape`).count();
    const inset = Math.min(6, box.width / 4, box.height / 4);
    const dx = options.dx ?? (round ? box.width / 2 : inset);
    const dy = options.dy ?? box.height / 2;
    await page.mouse.click(box.x + dx, box.y + dy);
}

export async function paletteTool(page, label) {
    await page.locator('.tool-palette .tool-button', { hasText: label }).first().click();
}

/** Focuses the diagram (its keyboard shortcuts work then) without selecting anything. */
export async function focusDiagram(page) {
    await page.evaluate(() => document.querySelector('#kse-diagram svg')?.focus());
}

/** Whether two boxes overlap (touching edges do not count). */
export function overlap(a, b) {
    return a.x < b.x + b.width - 0.5 && b.x < a.x + a.width - 0.5 && a.y < b.y + b.height - 0.5 && b.y < a.y + a.height - 0.5;
}

/** How many states of each kind a .stct file declares (type="START", …). */
export function kindCounts(xml) {
    const counts = {};
    for (const match of xml.matchAll(/<(?:nodes|Children)\b[^>]*\btype="([A-Z]+)"/g)) {
        const kind = match[1].toLowerCase();
        counts[kind] = (counts[kind] ?? 0) + 1;
    }
    return counts;
}

export function clientKindCounts(root) {
    const counts = {};
    for (const state of states(root)) {
        const kind = state.type.substring('state:'.length);
        counts[kind] = (counts[kind] ?? 0) + 1;
    }
    return counts;
}

/** Fits one state into the window (its insides large enough to see and to hit). */
export async function fitTo(page, stateId) {
    await page.evaluate(id => window.kse.dispatch({ kind: 'fit', elementIds: [id], padding: 24, maxZoom: 2, animate: false }), stateId);
    await page.waitForTimeout(300);
}

/** Scrolls the diagram to put the element in the middle of the window (states out of view are not drawn). */
export async function centre(page, id) {
    await page.evaluate(id => window.kse.dispatch({ kind: 'center', elementIds: [id], animate: false, retainZoom: true }), id);
}

/** Renames a state by editing its name in place, and waits for the model update. */
export async function renameState(page, from, to) {
    const state = stateNamed(await modelRoot(page), from);
    if (!state) {
        throw new Error(`the model has no state ${from}`);
    }
    await centre(page, state.id);
    await page.locator(`#kse-diagram [id$="${cssString(state.id)}#name"]`).dblclick();
    const editor = page.locator('.label-edit input');
    await editor.waitFor({ state: 'visible' });
    await editor.fill(to);
    await andUpdate(page, () => editor.press('Enter'));
}
