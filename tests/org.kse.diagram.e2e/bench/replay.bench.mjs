// The replay's benchmark in headless Chromium against kse serve (run by bench/replay.sh, which makes
// the log): a long match log (KSE_REPLAY_LOG, e.g. 10 minutes of 5 against 5) opened in the page's
// replay (from navigation to body[data-kse-replay=ready]; goal under 2 s), and scrubbing: 100 jumps
// to random times, each timed from the jump to the frame painted (median, p95), without and with a
// robot's statechart shown. Baselines measured in the same page and run: fetching the whole log,
// fetching and parsing every line (without building anything), and an animation frame with no
// jump. Figures are printed, never asserted.
import { copyFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { launch, pageUrl, servedFolder } from '../lib/harness.mjs';

const JUMPS = 100;
const OPENS = 3;
const source = process.env.KSE_REPLAY_LOG;
if (!source) {
    throw new Error('KSE_REPLAY_LOG is not set: run bench/replay.sh <kse-match>');
}
const name = 'bench-replay.jsonl';
copyFileSync(source, path.join(servedFolder(), name));
// the page's Goalie.stct is the examples' (run.sh copies it): home-1's statechart
const bytes = statSync(source).size;

const percentile = (values, p) => {
    const sorted = [...values].sort((a, b) => a - b);
    return sorted[Math.min(sorted.length - 1, Math.ceil((p / 100) * sorted.length) - 1)];
};
const median = values => percentile(values, 50);
const ms = value => `${value.toFixed(value < 10 ? 1 : 0)} ms`;

const url = new URL(pageUrl());
url.searchParams.delete('model');
url.searchParams.set('replay', name);

const browser = await launch();
try {
    const opens = [];
    const inPage = [];
    let page;
    for (let i = 0; i < OPENS; i++) {
        await page?.close();
        page = await browser.context.newPage();
        const start = Date.now();
        await page.goto(url.toString());
        await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.kseReplay), null, { timeout: 120000, polling: 10 });
        opens.push(Date.now() - start);
        const state = await page.evaluate(() => ({ state: window.kse.replay.state(), message: window.kse.replay.message(), ...window.kse.replay.timings() }));
        if (state.state !== 'ready') {
            throw new Error(`the replay did not open: ${state.message}`);
        }
        inPage.push(state.readyMs);
    }
    const facts = await page.evaluate(() => ({ frames: window.kse.replay.frameCount(), robots: window.kse.replay.robots().length, events: window.kse.replay.events().length, end: window.kse.replay.time() }));
    await page.evaluate(() => window.kse.replay.step(1e9));
    const last = await page.evaluate(() => window.kse.replay.time());

    // baselines in the same page: the bytes alone, and every line parsed without building anything
    const baseline = await page.evaluate(async name => {
        const token = new URLSearchParams(location.search).get('token');
        const fetchTimes = [];
        const parseTimes = [];
        for (let i = 0; i < 3; i++) {
            let start = performance.now();
            const text = await (await fetch(`/logs/${name}?token=${token}`)).text();
            fetchTimes.push(performance.now() - start);
            start = performance.now();
            let records = 0;
            for (const line of text.split('\n')) {
                if (line) {
                    JSON.parse(line);
                    records++;
                }
            }
            parseTimes.push(performance.now() - start);
        }
        const min = values => Math.min(...values);
        return { fetch: min(fetchTimes), parse: min(parseTimes) };
    }, name);

    // scrubbing: a jump to a random time, until the frame is painted (an animation frame, then a task after its paint)
    const scrub = async withChart =>
        page.evaluate(
            async ({ jumps, withChart }) => {
                const replay = window.kse.replay;
                const painted = () => new Promise(resolve => requestAnimationFrame(() => setTimeout(resolve, 0)));
                const end = replay.time();
                let seed = 12345;
                const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
                const idle = [];
                const jumpsMs = [];
                for (let i = 0; i < 10; i++) {
                    const start = performance.now();
                    await painted();
                    idle.push(performance.now() - start);
                }
                for (let i = 0; i < jumps + 5; i++) {
                    const t = random() * end;
                    const start = performance.now();
                    replay.seek(t);
                    if (withChart) {
                        await replay.settled();
                    }
                    await painted();
                    if (i >= 5) {
                        jumpsMs.push(performance.now() - start);
                    }
                }
                return { idle, jumps: jumpsMs };
            },
            { jumps: JUMPS, withChart }
        );
    const field = await scrub(false);
    await page.evaluate(() => window.kse.replay.select('home-1'));
    const chart = await scrub(true);
    const activeShown = await page.evaluate(() => window.kse.replay.active().length);

    console.log(`KSE replay in headless Chromium (kse serve on loopback): ${(bytes / 1e6).toFixed(1)} MB log, ${facts.robots} robots, ${facts.frames} frames up to t = ${last.toFixed(1)} s, ${facts.events} events`);
    console.log(`  open to ready (navigation to body[data-kse-replay=ready], ${OPENS} opens): median ${ms(median(opens))}, max ${ms(Math.max(...opens))} (goal < 2000 ms); in the page, script start to ready: median ${ms(median(inPage))}`);
    console.log(`  baseline: fetch the whole log ${ms(baseline.fetch)}; fetch and JSON.parse every line, building nothing, ${ms(baseline.fetch + baseline.parse)}`);
    console.log(`  baseline: one animation frame with no jump: median ${ms(median(field.idle))}`);
    console.log(`  scrub, field only (${JUMPS} jumps to random times, jump to painted): median ${ms(median(field.jumps))}, p95 ${ms(percentile(field.jumps, 95))}`);
    console.log(`  scrub, field and home-1's statechart (${activeShown} states outlined; jump to diagram updated and painted): median ${ms(median(chart.jumps))}, p95 ${ms(percentile(chart.jumps, 95))}`);
    await page.close();
} finally {
    await browser.close();
}
