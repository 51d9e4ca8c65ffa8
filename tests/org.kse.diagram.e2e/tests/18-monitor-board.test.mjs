// The live monitor's picker and board (issue 19): a running kse-match --monitor announces itself,
// the page opened with &monitor=pick lists it with its robots and their behaviours (never its key),
// and the robots chosen open side by side, each its own diagram and list in a frame, all following
// the match to its end as its log says. A robot whose behaviour has no model in the served folder
// gets a message instead of a diagram. Needs a kse-match built with --monitor: KSE_MATCH=<binary>.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { engineName, fileBrowser, kseMatch, pageUrl, screenshotter, skipWithoutKseMatch, states } from '../lib/harness.mjs';

const skip = skipWithoutKseMatch(import.meta.url);

const browser = fileBrowser({ skip });
const shot = screenshotter('18-monitor-board');

/** A page of the server at this query (the served folder has examples/Goalie/Goalie.stct, and no Defender.stct). */
async function open(query) {
    const url = new URL(pageUrl());
    url.searchParams.delete('model');
    for (const [name, value] of Object.entries(query)) {
        url.searchParams.set(name, value);
    }
    const page = await browser.context.newPage();
    page.problems = [];
    page.on('pageerror', error => page.problems.push(error.message));
    await page.goto(url.toString());
    return page;
}

test('a running match is picked, and two of its robots are watched side by side to its end', { skip, timeout: 240000 }, async () => {
    const folder = mkdtempSync(path.join(os.tmpdir(), 'kse-e2e-board-'));
    const log = path.join(folder, 'm.jsonl');
    // waits for both watchers (the board's two frames): the picker and the board are looked at
    // before it starts, and each frame sees its robot from the kick-off
    const match = spawn(
        kseMatch,
        ['--seed', '3', '--half', '15', '--start-playing', '--home', 'Goalie:1,Defender:2', '--away', 'Goalie:1', '--monitor', '--monitor-watchers', '2', '--speed', '10', '--quiet', '--log', log],
        { stdio: ['ignore', 'pipe', 'pipe'] }
    );
    let stderr = '';
    match.stderr.on('data', chunk => (stderr += chunk));
    match.stdout.resume();
    const exited = new Promise(resolve => match.on('exit', code => resolve(code)));
    try {
        const picker = await open({ monitor: 'pick' });
        const section = picker.locator(`section.kse-hub-match[data-pid="${match.pid}"]`);
        await section.waitFor({ timeout: 30000 });
        const key = /token ([A-Za-z0-9_-]{43})/.exec(stderr)?.[1];
        assert.ok(key, `kse-match printed its key: ${stderr}`);
        const listed = await section.locator('li.kse-hub-robot').evaluateAll(items =>
            items.map(item => ({
                robot: item.dataset.robot,
                behaviour: item.querySelector('.kse-hub-behaviour').textContent,
                missing: item.querySelector('.kse-hub-missing')?.textContent ?? '',
                enabled: !item.querySelector('input').disabled
            }))
        );
        assert.deepEqual(listed, [
            { robot: 'home-1', behaviour: 'Goalie', missing: '', enabled: true },
            { robot: 'home-2', behaviour: 'Defender', missing: 'no Defender.stct in the served folder', enabled: false },
            { robot: 'away-1', behaviour: 'Goalie', missing: '', enabled: true }
        ]);
        assert.ok(!(await picker.content()).includes(key), 'the page never holds the match key');
        const list = await picker.evaluate(() => fetch(`/matches?token=${new URLSearchParams(location.search).get('token')}`).then(response => response.text()));
        assert.ok(!list.includes(key), "/matches does not hand out the match's key");
        await shot(picker, 'picker');

        // a robot whose behaviour has no model in the folder, and one that does not play: a message each, no diagram
        const missing = await open({ monitor: 'board', match: String(match.pid), robots: 'home-2,away-7' });
        await missing.waitForFunction(() => ['board', 'error'].includes(document.body.dataset.kseMonitorHub), null, { timeout: 30000 });
        const messages = await missing.locator('.kse-board-missing').allInnerTexts();
        assert.equal(messages.length, 2);
        assert.match(messages[0], /^home-2 runs Defender, and the served folder has no Defender\.stct to draw it with/);
        assert.match(messages[1], /^away-7 does not play in match \d+ \(its robots: home-1, home-2, away-1\)/);
        assert.equal(await missing.locator('iframe').count(), 0);
        await missing.close();

        await section.locator('input[value="home-1"]').check();
        await section.locator('input[value="away-1"]').check();
        await Promise.all([picker.waitForURL(/monitor=board/), section.locator('button[data-action="open-board"]').click()]);
        const board = picker;
        assert.match(board.url(), new RegExp(`match=${match.pid}&robots=home-1%2Caway-1$`));
        assert.ok(!board.url().includes(key), 'the board is opened by pid, not by key');
        await board.waitForFunction(() => document.body.dataset.kseMonitorHub === 'board', null, { timeout: 30000 });
        assert.equal(await board.locator('iframe.kse-board-frame').count(), 2);
        const tiles = () =>
            board.evaluate(() =>
                [...document.querySelectorAll('.kse-board-tile')].map(tile => {
                    const win = tile.querySelector('iframe')?.contentWindow;
                    const doc = win?.document;
                    return {
                        robot: tile.dataset.robot,
                        state: doc?.body.dataset.kseMonitor ?? '',
                        taken: win?.kse?.monitor?.taken() ?? 0,
                        since: win?.kse?.monitor?.since() ?? NaN,
                        active: doc ? [...doc.querySelectorAll('#kse-diagram g.kse-active[data-id]')].map(g => g.getAttribute('data-id')).sort() : [],
                        listed: doc?.querySelectorAll('.kse-monitor-row').length ?? 0,
                        title: doc?.querySelector('.kse-monitor-robot')?.textContent ?? ''
                    };
                })
            );
        await board.waitForFunction(
            () => [...document.querySelectorAll('iframe')].every(frame => ['live', 'ended', 'error'].includes(frame.contentDocument?.body?.dataset.kseMonitor)),
            null,
            { timeout: 60000 }
        );
        await board.waitForTimeout(500);
        const live = await tiles();
        assert.deepEqual(live.map(tile => tile.title), ['home-1', 'away-1'], 'each frame watches its robot');
        assert.ok(live.every(tile => tile.state === 'live' || tile.state === 'ended'), JSON.stringify(live));
        await shot(board, 'board-live');
        // Pause all freezes every tile, Resume all lets every tile draw again
        const paused = () => board.evaluate(() => window.kse.monitorHub.tiles().map(tile => tile.monitor.paused()));
        await board.click('button[data-action="board-pause"]');
        assert.deepEqual(await paused(), [true, true], 'Pause all pauses every robot');
        assert.equal(await board.locator('button[data-action="board-pause"]').innerText(), 'Resume all');
        await board.click('button[data-action="board-pause"]');
        assert.deepEqual(await paused(), [false, false], 'Resume all resumes every robot');
        await board.waitForTimeout(300);
        await board.waitForFunction(
            () => [...document.querySelectorAll('iframe')].every(frame => ['ended', 'error'].includes(frame.contentDocument?.body?.dataset.kseMonitor)),
            null,
            { timeout: 180000 }
        );
        assert.equal(await exited, 0, `kse-match succeeded: ${stderr.slice(-500)}`);
        const ended = await tiles();
        await shot(board, 'board-ended');

        const records = readFileSync(log, 'utf8').split('\n').filter(line => line.length > 0).map(line => JSON.parse(line));
        const frames = records.filter(record => record.type === 'frame');
        const roots = await board.evaluate(() => [...document.querySelectorAll('iframe')].map(frame => frame.contentWindow.kse.modelRoot()));
        let exact = 0;
        for (const [i, tile] of ended.entries()) {
            assert.equal(tile.state, 'ended', `${tile.robot} followed the match to its end`);
            const robotFrames = frames.map(frame => ({ t: frame.t, ...frame.robots.find(robot => robot.id === tile.robot) }));
            // the match started once both frames had subscribed (--monitor-watchers 2), so each sees
            // every transition from its first configuration on: at least those of the log's frames
            // after it, at most those of the frames from its 0.1 s on, and here all of them
            const logged = from => robotFrames.filter(frame => frame.t >= from).reduce((sum, robot) => sum + robot.taken.length, 0);
            assert.ok(logged(0) > 0, `${tile.robot} took transitions`);
            assert.ok(tile.since >= 0, `${tile.robot} got its configuration: ${tile.since}`);
            assert.ok(
                tile.taken >= logged(tile.since + 0.1 + 1e-9) && tile.taken <= logged(tile.since - 1e-9),
                `${tile.robot}'s frame received every transition the log lists for it from t = ${tile.since}: ${tile.taken}, ` +
                    `log ${logged(tile.since + 0.1 + 1e-9)} to ${logged(tile.since - 1e-9)}`
            );
            exact += tile.taken === logged(0) ? 1 : 0;
            assert.equal(tile.listed, Math.min(50, tile.taken), `${tile.robot}'s own list shows its last transitions`);
            const idByName = new Map(states(roots[i]).map(state => [engineName(state), state.id]));
            const expected = robotFrames[robotFrames.length - 1].active.map(name => idByName.get(name)).sort();
            assert.deepEqual(tile.active, expected, `${tile.robot}'s diagram shows the states the log names active at the end`);
        }
        assert.equal(exact, ended.length, 'the match waited for both frames: each received exactly what the log lists for its robot');
        assert.notDeepEqual(ended[0].active, [], 'home-1 has active states drawn');
        assert.deepEqual(board.problems, [], 'no script errors');

        // the match is over: its announcement is gone, and the picker says there is nothing of it to watch
        const after = await open({ monitor: 'pick' });
        await after.waitForFunction(() => document.body.dataset.kseMonitorHub === 'picking', null, { timeout: 30000 });
        assert.equal(await after.locator(`section[data-pid="${match.pid}"]`).count(), 0, 'an ended match is no longer listed');
    } finally {
        match.kill('SIGTERM');
        await exited;
        rmSync(folder, { recursive: true, force: true });
    }
});

test('a board of a match that is not running says so', { skip, timeout: 60000 }, async () => {
    const page = await open({ monitor: 'board', match: '999999999', robots: 'home-1' });
    await page.waitForFunction(() => document.body.dataset.kseMonitorHub === 'error', null, { timeout: 30000 });
    assert.equal(await page.locator('.kse-hub-error').innerText(), 'No running match 999999999: it ended, or it was started without --monitor.');
    // no model and a monitor parameter: the picker, not a broken diagram
    const picker = await open({ monitor: '1' });
    await picker.waitForFunction(() => document.body.dataset.kseMonitorHub === 'picking', null, { timeout: 30000 });
    assert.equal(await picker.locator('h1').innerText(), 'Watch a running match');
});
