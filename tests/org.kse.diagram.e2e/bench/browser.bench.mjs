// The diagram editor's benchmark in a real browser (headless Chromium against kse serve, driven as
// the end-to-end tests drive it), in one run: opening a 1,000-state statechart (from the request
// of the page to the diagram drawn; the server arranges it, as it has no notation yet), moving a
// state of it with the mouse (from mouse-up to the moved state redrawn), and the same move in the
// 47-state Goalie as the baseline. Figures are printed, never asserted (goals: open under 2 s,
// move p95 under 50 ms). Run by bench/diagram-browser.sh.
import { centre, copyGoalie, launch, modelRoot, openModel, shapeBox, stateNamed } from '../lib/harness.mjs';
import { generatedModel } from '../lib/models.mjs';

const OPENS = 5;
const MOVES = 30;
const WARM_UP_MOVES = 3;

const percentile = (values, p) => {
    const sorted = [...values].sort((a, b) => a - b);
    return sorted[Math.min(sorted.length - 1, Math.ceil((p / 100) * sorted.length) - 1)];
};
const ms = value => `${value.toFixed(0)} ms`;

/** Times in the page from a mouse-up to the next drawn model (the page marks each in data-kse-revision after drawing it). */
async function watchMoves(page) {
    await page.evaluate(() => {
        window.kseBench = { times: [], released: undefined };
        window.addEventListener('mouseup', () => (window.kseBench.released = performance.now()), { capture: true });
        new MutationObserver(() => {
            if (window.kseBench.released !== undefined) {
                window.kseBench.times.push(performance.now() - window.kseBench.released);
                window.kseBench.released = undefined;
            }
        }).observe(document.body, { attributes: true, attributeFilter: ['data-kse-revision'] });
    });
}

/** Drags the state right and back, MOVES times after a warm-up, and returns the times in ms. */
async function moves(page, name) {
    const state = stateNamed(await modelRoot(page), name);
    await centre(page, state.id);
    await watchMoves(page);
    for (let i = 0; i < WARM_UP_MOVES + MOVES; i++) {
        const box = await shapeBox(page, state.id);
        const x = box.x + 6;
        const y = box.y + box.height / 2;
        const before = await page.evaluate(() => Number(document.body.dataset.kseRevision ?? 0));
        await page.mouse.move(x, y);
        await page.mouse.down();
        await page.mouse.move(x + (i % 2 === 0 ? 20 : -20), y, { steps: 4 });
        await page.mouse.up();
        await page.waitForFunction(before => Number(document.body.dataset.kseRevision ?? 0) > before, before, { timeout: 30000 });
    }
    const times = await page.evaluate(() => window.kseBench.times);
    return times.slice(WARM_UP_MOVES);
}

const browser = await launch();
try {
    const { model, states } = generatedModel('Bench1000', 10, 24);
    console.log(`KSE diagram editor in headless Chromium (kse serve on loopback): open ${states} states, move in ${states} and in the 47-state Goalie`);

    const opens = [];
    let page;
    for (let i = 0; i < OPENS; i++) {
        await page?.close();
        const started = performance.now();
        page = await openModel(browser.context, model);
        opens.push(performance.now() - started);
    }
    const large = await moves(page, 'Init');
    await page.close();

    const goalie = await openModel(browser.context, copyGoalie('bench-goalie'));
    const small = await moves(goalie, 'Kick');
    await goalie.close();

    const openMedian = percentile(opens, 50);
    console.log(`open ${states} states (request to drawn, arranged by the server): median ${ms(openMedian)} of ${OPENS} (first ${ms(opens[0])})`);
    console.log(`move a state, 47 states (baseline): median ${ms(percentile(small, 50))}, p95 ${ms(percentile(small, 95))} (${MOVES} moves)`);
    console.log(
        `move a state, ${states} states: median ${ms(percentile(large, 50))}, p95 ${ms(percentile(large, 95))} (${MOVES} moves); ` +
            `${(percentile(large, 50) / percentile(small, 50)).toFixed(1)}x the baseline's median`
    );
    console.log(
        `goals: open under 2 s ${openMedian < 2000 ? 'met' : 'NOT met'}; move p95 under 50 ms ${percentile(large, 95) < 50 ? 'met' : 'NOT met'} ` +
            `(47 states: ${percentile(small, 95) < 50 ? 'met' : 'NOT met'})`
    );
} finally {
    await browser.close();
}
