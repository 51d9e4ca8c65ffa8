// The live monitor's benchmark in headless Chromium against kse serve (run by bench/monitor.sh,
// which names the kse-match): a 5-against-5 match watched on a board of all 10 robots (each its own
// monitor page in a frame, as a user would watch it), once at real speed and once at 10x. Per speed
// it prints the transitions a second the match took (from its log, over its wall time), the
// transitions a second the pages drew, the delay from the engine taking a transition (the record's
// `wall`) to the diagram showing it (median, p95, max over every transition of every robot), and
// whether the board fell behind: a transition still undrawn at the end, or the last ones drawn
// late. Figures are printed, never asserted.
import { spawn } from 'node:child_process';
import { copyFileSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { launch, pageUrl, repository, servedFolder } from '../lib/harness.mjs';

const binary = process.env.KSE_MATCH;
if (!binary) {
    throw new Error('KSE_MATCH is not set: run bench/monitor.sh <kse-match>');
}
const TEAM = 'Goalie:1,Defender:2,Defender:3,Attacker:4,Attacker:5';
const ROBOTS = ['home-1', 'home-2', 'home-3', 'home-4', 'home-5', 'away-1', 'away-2', 'away-3', 'away-4', 'away-5'];
const RUNS = [
    { speed: 1, half: Number(process.env.KSE_MONITOR_BENCH_HALF_1 ?? 20) },
    { speed: 10, half: Number(process.env.KSE_MONITOR_BENCH_HALF_10 ?? 60) }
];
// the board draws each robot from its behaviour's model, as the examples' kse-match was built from them
for (const behaviour of ['Defender', 'Attacker']) {
    copyFileSync(path.join(repository, 'examples', behaviour, `${behaviour}.stct`), path.join(servedFolder(), `${behaviour}.stct`));
}

const percentile = (sorted, p) => (sorted.length === 0 ? NaN : sorted[Math.min(sorted.length - 1, Math.ceil((p / 100) * sorted.length) - 1)]);
const ms = value => `${value.toFixed(value < 10 ? 1 : 0)} ms`;

async function run(browser, { speed, half }) {
    const work = mkdtempSync(path.join(os.tmpdir(), 'kse-monitor-bench-'));
    const log = path.join(work, 'match.jsonl');
    const match = spawn(
        binary,
        ['--seed', '1', '--half', String(half), '--start-playing', '--home', TEAM, '--away', TEAM, '--monitor', '--monitor-watchers', '10', '--speed', String(speed), '--quiet', '--log', log],
        { stdio: ['ignore', 'pipe', 'pipe'] }
    );
    let stderr = '';
    let stdout = '';
    match.stderr.on('data', chunk => (stderr += chunk));
    match.stdout.on('data', chunk => (stdout += chunk));
    const exited = new Promise(resolve => match.on('exit', code => resolve(code)));
    const page = await browser.context.newPage();
    try {
        for (const end = Date.now() + 30000; !/monitor on/.test(stderr); ) {
            if (Date.now() > end) {
                throw new Error(`kse-match printed no monitor line: ${stderr}`);
            }
            await new Promise(resolve => setTimeout(resolve, 20));
        }
        const url = new URL(pageUrl());
        url.searchParams.delete('model');
        url.searchParams.set('monitor', 'board');
        url.searchParams.set('match', String(match.pid));
        url.searchParams.set('robots', ROBOTS.join(','));
        const opened = Date.now();
        await page.goto(url.toString());
        await page.waitForFunction(
            () => document.querySelectorAll('iframe').length > 0 && [...document.querySelectorAll('iframe')].every(f => f.contentDocument?.body?.dataset.kseMonitor === 'live'),
            null,
            { timeout: 120000, polling: 50 }
        );
        const allLive = Date.now() - opened;
        await page.waitForFunction(
            () => [...document.querySelectorAll('iframe')].every(f => ['ended', 'error'].includes(f.contentDocument?.body?.dataset.kseMonitor)),
            null,
            { timeout: 600000, polling: 200 }
        );
        const code = await exited;
        const tiles = await page.evaluate(() =>
            [...document.querySelectorAll('iframe')].map(frame => {
                const monitor = frame.contentWindow.kse.monitor;
                return {
                    state: frame.contentDocument.body.dataset.kseMonitor,
                    taken: monitor.taken(),
                    delays: monitor.delays(),
                    last: monitor.lastDelayMs,
                    rate: monitor.eventsPerSecond()
                };
            })
        );
        const records = readFileSync(log, 'utf8').split('\n').filter(line => line.length > 0).map(line => JSON.parse(line));
        const logged = records.filter(r => r.type === 'frame').reduce((sum, frame) => sum + frame.robots.reduce((s, robot) => s + robot.taken.length, 0), 0);
        const factor = Number(/real-time factor: (\d+)x/.exec(stdout)?.[1] ?? NaN);
        const delays = tiles.flatMap(tile => tile.delays).sort((a, b) => a - b);
        const received = tiles.reduce((sum, tile) => sum + tile.taken, 0);
        const undrawn = received - delays.length;
        const lastLate = Math.max(...tiles.map(tile => tile.last));
        const behind = undrawn > 0 || lastLate > 1000 || tiles.some(tile => tile.state !== 'ended');
        console.log(
            `monitor benchmark at --speed ${speed} (5 against 5, ${half} s half, all 10 robots on one board; kse-match exit ${code}, ran at ${factor}x): ` +
                `the match took ${(logged / (half / speed)).toFixed(0)} transitions/s (${logged} in ${half} match s); ` +
                `the board drew ${tiles.reduce((sum, tile) => sum + tile.rate, 0).toFixed(0)} transitions/s (${received} received, all 10 live ${allLive} ms after opening); ` +
                `transition to drawn median ${ms(percentile(delays, 50))}, p95 ${ms(percentile(delays, 95))}, max ${ms(delays[delays.length - 1] ?? NaN)} (${delays.length} measured); ` +
                `fell behind: ${behind ? 'YES' : 'no'} (${undrawn} undrawn at the end, the last transition drawn ${ms(lastLate)} after it was taken)`
        );
    } finally {
        await page.close();
        match.kill('SIGTERM');
        await exited;
        rmSync(work, { recursive: true, force: true });
    }
}

const browser = await launch();
try {
    for (const configuration of RUNS) {
        await run(browser, configuration);
    }
} finally {
    await browser.close();
}
