// The live monitor (issue 19): the page watches robot home-1 of a running, seeded kse-match through
// the server's /monitor relay. The match's own log is the reference: the page must have received
// every transition the log lists for home-1, and must show as active exactly the states the log's
// last frame names. Needs a kse-match built with --monitor (the examples' one): KSE_MATCH=<binary>.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { copyGoalie, engineName, fileBrowser, kseMatch, modelRoot, openModel, pageUrl, screenshotter, skipWithoutKseMatch, states } from '../lib/harness.mjs';

const skip = skipWithoutKseMatch(import.meta.url);

const browser = fileBrowser({ skip });
const shot = screenshotter('16-monitor');

/** Starts the match; resolves with its monitor's port and key once it printed them (standard error). */
function startMatch(log) {
    const match = spawn(kseMatch, ['--seed', '1', '--half', '20', '--start-playing', '--monitor', '--monitor-wait', '--speed', '10', '--quiet', '--log', log], {
        stdio: ['ignore', 'pipe', 'pipe']
    });
    let stderr = '';
    const exited = new Promise(resolve => match.on('exit', (code, signal) => resolve({ code, signal, stderr })));
    match.stdout.resume();
    const monitor = new Promise((resolve, reject) => {
        const timer = setTimeout(() => reject(new Error(`kse-match printed no monitor line within 30 s: ${stderr}`)), 30000);
        match.stderr.on('data', chunk => {
            stderr += chunk;
            const found = /kse-match: monitor on 127\.0\.0\.1:(\d+) token ([A-Za-z0-9_-]{43})/.exec(stderr);
            if (found) {
                clearTimeout(timer);
                resolve({ port: found[1], key: found[2] });
            }
        });
        match.on('exit', () => reject(new Error(`kse-match ended before it printed the monitor line: ${stderr}`)));
    });
    return { match, monitor, exited };
}

function percentile(sorted, p) {
    return sorted.length === 0 ? NaN : sorted[Math.min(sorted.length - 1, Math.floor((p / 100) * sorted.length))];
}

test('the page highlights what the robot of a running match does, as the match log says', { skip, timeout: 240000 }, async () => {
    const folder = mkdtempSync(path.join(os.tmpdir(), 'kse-e2e-monitor-'));
    const log = path.join(folder, 'm.jsonl');
    const { match, monitor, exited } = startMatch(log);
    try {
        const { port, key } = await monitor;
        // the examples' kse-match plays home-1 with the Goalie built from examples/Goalie/Goalie.stct
        const model = copyGoalie('MonitorGoalie');
        const url = new URL(pageUrl());
        url.searchParams.set('monitor', port);
        url.searchParams.set('key', key);
        url.searchParams.set('robot', 'home-1');
        const page = await openModel(browser.context, model, { through: url.toString() });
        // every frame, the transitions the diagram shows as fired (the DOM, not the monitor's own account)
        await page.evaluate(() => {
            window.firedSeen = new Set();
            const look = () => {
                document.querySelectorAll('g.kse-fired[data-id]').forEach(edge => window.firedSeen.add(edge.getAttribute('data-id')));
                if (document.body.dataset.kseMonitor !== 'ended' && document.body.dataset.kseMonitor !== 'error') {
                    requestAnimationFrame(look);
                }
            };
            requestAnimationFrame(look);
        });
        await page.waitForFunction(() => document.body.dataset.kseMonitor === 'live' || document.body.dataset.kseMonitor === 'error', null, { timeout: 30000 });
        await page.waitForTimeout(300);
        // on request, the State messages the robot's blackboard holds: the game controller's says PLAYING
        await page.click('.kse-monitor-ask');
        await page.waitForFunction(() => window.kse.monitor.blackboard() !== undefined, null, { timeout: 10000 });
        const blackboard = await page.evaluate(() => window.kse.monitor.blackboard());
        const game = blackboard.find(entry => entry.topic === 'worldstate' && entry.type === 'GameStateMessage');
        assert.ok(game, `the blackboard holds the game state: ${JSON.stringify(blackboard)}`);
        assert.match(game.text, /player_state: 3\b/, 'the robot plays (--start-playing)');
        assert.equal(await page.locator('.kse-monitor-blackboard .kse-monitor-message').count(), blackboard.length, 'each message is a row of the panel');
        await shot(page, 'live');
        // Pause freezes the drawing while the records keep coming; Resume draws the live configuration
        const drawnNow = () =>
            page.evaluate(() => ({
                taken: window.kse.monitor.taken(),
                active: [...document.querySelectorAll('#kse-diagram g.kse-active[data-id]')].map(g => g.getAttribute('data-id')).sort(),
                rows: document.querySelector('.kse-monitor-list').textContent,
                state: document.body.dataset.kseMonitor
            }));
        await page.click('.kse-monitor-pause');
        const paused = await drawnNow();
        await page.waitForTimeout(250);
        const later = await drawnNow();
        if (later.state === 'live') {
            assert.ok(later.taken > paused.taken, 'transitions keep coming while paused');
            assert.deepEqual(later.active, paused.active, 'the highlighted states stay while paused');
            assert.equal(later.rows, paused.rows, 'the list stays while paused');
        }
        assert.equal(await page.locator('.kse-monitor-pause').innerText(), 'Resume');
        await page.click('.kse-monitor-pause');
        await page.waitForFunction(() => ['ended', 'error'].includes(document.body.dataset.kseMonitor), null, { timeout: 180000 });
        const status = await page.locator('#kse-status').innerText();
        assert.equal(await page.evaluate(() => document.body.dataset.kseMonitor), 'ended', `the monitor ended with the match: ${status}`);
        await shot(page, 'ended');
        const ended = await exited;
        assert.equal(ended.code, 0, `kse-match succeeded: ${ended.stderr.slice(-500)}`);

        const records = readFileSync(log, 'utf8').split('\n').filter(line => line.length > 0).map(line => JSON.parse(line));
        const frames = records.filter(record => record.type === 'frame').map(frame => frame.robots.find(robot => robot.id === 'home-1'));
        assert.ok(frames.length > 10 && frames.every(Boolean), 'the log has frames of home-1');
        const loggedTaken = frames.reduce((sum, robot) => sum + robot.taken.length, 0);
        const seen = await page.evaluate(() => ({
            taken: window.kse.monitor.taken(),
            active: [...document.querySelectorAll('#kse-diagram g.kse-active[data-id]')].map(g => g.getAttribute('data-id')).sort(),
            fired: [...window.firedSeen],
            delays: window.kse.monitor.delays(),
            rate: window.kse.monitor.eventsPerSecond(),
            warning: document.querySelector('.kse-monitor-warning')?.hidden === false ? document.querySelector('.kse-monitor-warning').textContent : ''
        }));
        assert.equal(seen.warning, '', 'the match runs the statechart drawn (states and transitions counted alike)');
        assert.ok(loggedTaken > 0, 'home-1 took transitions');
        assert.equal(seen.taken, loggedTaken, 'the page received as many transitions of home-1 as the log lists');

        const root = await modelRoot(page);
        const idByName = new Map(states(root).map(state => [engineName(state), state.id]));
        const lastActive = frames[frames.length - 1].active;
        const expected = lastActive.map(name => {
            assert.ok(idByName.has(name), `the log's active state ${name} is a state of the diagram`);
            return idByName.get(name);
        });
        assert.deepEqual(seen.active, [...expected].sort(), 'the highlighted states are those the log names active at the end');
        assert.ok(seen.fired.length > 0, 'transitions were seen flashing while the match ran');
        assert.ok(seen.fired.every(id => id.startsWith('//@transitions.')), `only transitions flash: ${seen.fired.join(', ')}`);
        assert.deepEqual(page.problems, [], 'no script errors');

        const sorted = [...seen.delays].sort((a, b) => a - b);
        console.log(
            `benchmark: monitor of home-1 at --speed 10: ${seen.taken} transitions, ${seen.rate.toFixed(0)} events/s received, ` +
                `transition-to-drawn delay median ${percentile(sorted, 50).toFixed(1)} ms, p95 ${percentile(sorted, 95).toFixed(1)} ms, ` +
                `max ${sorted[sorted.length - 1]?.toFixed(1)} ms (${sorted.length} measured)`
        );
    } finally {
        match.kill('SIGTERM');
        await exited;
        rmSync(folder, { recursive: true, force: true });
    }
});

/** The status of a WebSocket upgrade request to /monitor with the given Origin (101: accepted). */
function upgradeStatus(origin, query) {
    const target = new URL(pageUrl());
    return new Promise((resolve, reject) => {
        const request = http.request({
            host: target.hostname,
            port: target.port,
            path: `/monitor?${query}`,
            headers: {
                Connection: 'Upgrade',
                Upgrade: 'websocket',
                'Sec-WebSocket-Version': '13',
                'Sec-WebSocket-Key': 'dGhlIHNhbXBsZSBub25jZQ==',
                ...(origin ? { Origin: origin } : {})
            }
        });
        request.on('upgrade', (response, socket) => {
            socket.destroy();
            resolve(response.statusCode);
        });
        request.on('response', response => {
            response.resume();
            resolve(response.statusCode);
        });
        request.on('error', reject);
        request.end();
    });
}

test('/monitor refuses pages without the token and pages of other origins', { skip, timeout: 60000 }, async () => {
    const target = new URL(pageUrl());
    const token = target.searchParams.get('token');
    // a browser page of this server, with the token left out: the connection is closed for a policy violation
    const page = await openModel(browser.context, copyGoalie('MonitorSecurity'));
    const closed = await page.evaluate(
        address =>
            new Promise(resolve => {
                const socket = new WebSocket(address);
                socket.addEventListener('close', event => resolve({ code: event.code, reason: event.reason }));
            }),
        `ws://${target.host}/monitor?port=9&key=k&robots=home-1`
    );
    assert.equal(closed.code, 1008, `closed without the token: ${JSON.stringify(closed)}`);
    const query = `token=${encodeURIComponent(token)}&port=9&key=k&robots=home-1`;
    assert.equal(await upgradeStatus('http://evil.example', query), 403, 'a page of another site is refused');
    assert.equal(await upgradeStatus(`http://127.0.0.1:${Number(target.port) === 1 ? 2 : Number(target.port) - 1}`, query), 403, 'a page of another local port is refused');
    assert.equal(await upgradeStatus(`http://127.0.0.1:${target.port}`, query), 101, "this server's own page is accepted");
});
