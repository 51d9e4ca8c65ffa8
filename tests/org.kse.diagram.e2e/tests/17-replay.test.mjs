// The replay of a match log (issue 19, item 2): the page opened with &replay=<file>.jsonl draws the
// field at t from the log kse serve sends, jumps to an event from the timeline, and shows the
// selected robot's statechart with the states the log names active at t. The log itself (read
// here, apart from the page) is the reference. A log cut short, one of another version and a file
// that is not a log open with a message. data/seed3-half10.jsonl is a real log of the examples'
// kse-match (data/README.md); with KSE_MATCH=<kse-match> a fresh seeded match is replayed as well.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { copyFileSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { engineName, fileBrowser, moduleDir, pageUrl, screenshotter, servedFolder, states } from '../lib/harness.mjs';

const dataLog = path.join(moduleDir, 'data', 'seed3-half10.jsonl');
const binary = process.env.KSE_MATCH;

const browser = fileBrowser();
const shot = screenshotter('17-replay');

/** Opens the replay of a log of the served folder; resolves once it is ready or failed. */
async function openReplay(log, extra = {}) {
    const url = new URL(pageUrl());
    url.searchParams.delete('model');
    url.searchParams.set('replay', log);
    for (const [name, value] of Object.entries(extra)) {
        url.searchParams.set(name, value);
    }
    const page = await browser.context.newPage();
    const problems = [];
    page.on('pageerror', error => problems.push(error.message));
    page.on('console', message => {
        if (message.type() === 'error' && !/favicon|Failed to load resource/.test(message.text())) {
            problems.push(message.text());
        }
    });
    page.problems = problems;
    await page.goto(url.toString());
    await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.kseReplay), null, { timeout: 30000 });
    return page;
}

const replayState = page => page.evaluate(() => ({ state: window.kse.replay.state(), message: window.kse.replay.message(), notice: document.querySelector('.kse-replay-notice').hidden ? '' : document.querySelector('.kse-replay-notice').textContent }));

function records(file) {
    return readFileSync(file, 'utf8')
        .split('\n')
        .filter(line => line.length > 0)
        .map(line => JSON.parse(line));
}

/** The chart's frame: the diagram page of the selected robot. */
const chartFrame = page => page.frames().find(frame => frame !== page.mainFrame() && frame.url().includes('replayed=1'));

async function replaysLikeTheLog(name, file, viaList) {
    const log = records(file);
    const frames = log.filter(record => record.type === 'frame');
    const events = log.filter(record => record.type === 'event');
    const page = await openReplay(name);
    assert.deepEqual(await replayState(page), { state: 'ready', message: '', notice: '' }, 'a whole log opens without a notice');
    assert.equal(await page.evaluate(() => window.kse.replay.frameCount()), frames.length, 'every frame of the log is read');
    assert.equal(await page.evaluate(() => window.kse.replay.events().length), events.length, 'every event of the log is read');
    assert.deepEqual(
        await page.evaluate(() => window.kse.replay.robots()),
        log[0].teams.flatMap(team => team.players.map(player => player.id))
    );
    await shot(page, `${name}-opened`);

    // the event to jump to: a goal when the match has one, else the first kick, else the first state change
    const target = events.find(event => event.event === 'goal') ?? events.find(event => event.event === 'kick') ?? events.find(event => event.event === 'state');
    const index = events.indexOf(target);
    const marker = page.locator(`.kse-replay-event[data-index="${index}"]`);
    assert.equal(await marker.count(), 1, `the timeline has a marker for the ${target.event} at ${target.t} s`);
    assert.equal(await page.locator(`.kse-replay-events option[value="${index}"]`).count(), 1, `the list of events has the ${target.event}`);
    if (viaList) {
        // markers close together cover each other: the list reaches every event
        await page.selectOption('.kse-replay-events', String(index));
    } else {
        await marker.click();
    }
    // the frame shown is the last at or before the event
    const expected = frames.filter(frame => frame.t <= target.t + 1e-6).pop() ?? frames[0];
    assert.equal(await page.evaluate(() => window.kse.replay.time()), expected.t, `the ${target.event} marker jumps to t = ${expected.t}`);
    assert.match(await page.locator('.kse-replay-clock').innerText(), new RegExp(`t = ${expected.t.toFixed(1)} s`));
    assert.equal(await page.locator('.kse-replay-score').innerText(), expected.score.join(' : '));
    const drawn = await page.evaluate(() => window.kse.replay.drawnRobots());
    assert.equal(drawn.length, expected.robots.length, 'every robot of the frame is drawn');
    for (const robot of expected.robots) {
        const mark = drawn.find(candidate => candidate.id === robot.id);
        assert.ok(mark, `${robot.id} is drawn`);
        assert.ok(Math.abs(mark.x - robot.pose[0]) < 0.002 && Math.abs(mark.y - robot.pose[1]) < 0.002, `${robot.id} is drawn at the log's (${robot.pose[0]}, ${robot.pose[1]}), not (${mark.x}, ${mark.y})`);
        const turn = Math.abs(Math.atan2(Math.sin(mark.theta - robot.pose[2]), Math.cos(mark.theta - robot.pose[2])));
        assert.ok(turn < 0.01, `${robot.id} faces the log's ${robot.pose[2]} rad, not ${mark.theta}`);
    }
    const ball = await page.evaluate(() => [Number(document.querySelector('.kse-replay-ball').getAttribute('cx')), -Number(document.querySelector('.kse-replay-ball').getAttribute('cy'))]);
    assert.ok(Math.abs(ball[0] - expected.ball[0]) < 0.002 && Math.abs(ball[1] - expected.ball[1]) < 0.002, `the ball is at the log's ${expected.ball.slice(0, 2)}`);

    // home-1 plays the Goalie: its statechart, with the frame's active states outlined
    await page.click('.kse-replay-chip[data-robot="home-1"]');
    await page.waitForFunction(() => window.kse.replay.active().length > 0, null, { timeout: 60000 });
    await page.evaluate(() => window.kse.replay.settled());
    const chart = chartFrame(page);
    assert.ok(chart, 'the statechart is shown in the replay');
    const root = await chart.evaluate(() => window.kse.modelRoot());
    const idByName = new Map(states(root).map(state => [engineName(state), state.id]));
    const check = async (frame, what) => {
        const home1 = frame.robots.find(robot => robot.id === 'home-1');
        const wanted = home1.active.map(state => {
            assert.ok(idByName.has(state), `the log's active state ${state} is a state of Goalie.stct`);
            return idByName.get(state);
        });
        // what a user sees: the states outlined in the chart's diagram
        const outlined = await chart.evaluate(() => [...document.querySelectorAll('#kse-diagram g.kse-active[data-id]')].map(g => g.getAttribute('data-id')).sort());
        assert.deepEqual(outlined, [...wanted].sort(), `${what}: the outlined states are home-1's active states at t = ${frame.t}`);
        assert.deepEqual(await page.evaluate(() => window.kse.replay.activeNames()), home1.active);
    };
    await check(expected, `at the ${target.event}`);
    const rows = await page.locator('.kse-replay-taken .kse-replay-transition').count();
    // the frames from the last at or before t - 2 s to the last at or before t + 2 s
    const atOrBefore = t => Math.max(0, frames.findLastIndex(frame => frame.t <= t + 1e-6));
    const around = frames
        .slice(atOrBefore(expected.t - 2), atOrBefore(expected.t + 2) + 1)
        .reduce((sum, frame) => sum + frame.robots.find(robot => robot.id === 'home-1').taken.length, 0);
    assert.equal(rows, around, `the list shows home-1's transitions within 2 s of t`);
    await shot(page, `${name}-home-1-at-${target.event}`);

    // a step forward, then the last frame: the field and the chart follow
    await page.click('[data-action="replay-forward"]');
    await page.evaluate(() => window.kse.replay.settled());
    const next = frames[frames.indexOf(expected) + 1];
    assert.equal(await page.evaluate(() => window.kse.replay.time()), next.t, 'one frame forward');
    await check(next, 'one frame forward');
    const lastIndex = frames.length - 1;
    await page.evaluate(last => window.kse.replay.step(last), lastIndex);
    await page.evaluate(() => window.kse.replay.settled());
    await check(frames[lastIndex], 'at the end');
    await page.click('[data-action="replay-back"]');
    await page.evaluate(() => window.kse.replay.settled());
    await check(frames[lastIndex - 1], 'one frame back');

    // playing at 2x moves time on (the log is 10 s or more long), and pause stops it
    await page.evaluate(() => window.kse.replay.seek(0));
    await page.selectOption('.kse-replay-speed', '2');
    await page.click('[data-action="replay-play"]');
    await page.waitForTimeout(500);
    await page.click('[data-action="replay-play"]');
    const played = await page.evaluate(() => ({ t: window.kse.replay.time(), playing: window.kse.replay.playing(), speed: window.kse.replay.speed() }));
    assert.equal(played.playing, false, 'the second click pauses');
    assert.equal(played.speed, 2);
    assert.ok(played.t >= 0.5 && played.t <= 9, `half a second or a little more at 2x plays a match second or a few (t = ${played.t})`);
    const paused = played.t;
    await page.waitForTimeout(300);
    assert.equal(await page.evaluate(() => window.kse.replay.time()), paused, 'paused, time stands still');
    assert.deepEqual(page.problems, [], 'no errors on the page');
    await page.close();
}

test('the replay of a real log draws the log at an event and home-1’s active states', { timeout: 120000 }, async () => {
    copyFileSync(dataLog, path.join(servedFolder(), 'replay-data.jsonl'));
    await replaysLikeTheLog('replay-data.jsonl', dataLog, false);
});

test('the replay of a seeded match just played by kse-match', { skip: binary ? false : 'KSE_MATCH is not set', timeout: 180000 }, async () => {
    const file = path.join(servedFolder(), 'replay-fresh.jsonl');
    execFileSync(binary, ['--seed', '1', '--half', '20', '--start-playing', '--quiet', '--log', file], { stdio: 'ignore' });
    await replaysLikeTheLog('replay-fresh.jsonl', file, true);
});

test('a robot whose statechart is not in the folder: the page says so', { timeout: 60000 }, async () => {
    copyFileSync(dataLog, path.join(servedFolder(), 'replay-data.jsonl'));
    const page = await openReplay('replay-data.jsonl', { robot: 'home-2', t: '3' });
    await page.waitForFunction(() => !document.querySelector('.kse-replay-chart-message').hidden, null, { timeout: 15000 });
    assert.match(await page.locator('.kse-replay-chart-message').innerText(), /There is no Defender\.stct in the served folder/);
    assert.equal(await page.evaluate(() => window.kse.replay.selected()), 'home-2');
    assert.equal(await page.evaluate(() => window.kse.replay.time()), 3);
    await shot(page, 'no-model');
    assert.deepEqual(page.problems, []);
    await page.close();
});

test('?replay= with no file lists the folder\'s logs, each opening its replay', { timeout: 60000 }, async () => {
    copyFileSync(dataLog, path.join(servedFolder(), 'replay-data.jsonl'));
    const page = await openReplay('');
    const links = await page.locator('.kse-replay-log-link').allInnerTexts();
    assert.ok(links.includes('replay-data.jsonl'), `the list names the folder's log: ${links.join(', ')}`);
    assert.ok(links.every(link => link.endsWith('.jsonl')), 'only logs are listed');
    await Promise.all([page.waitForURL(/replay=replay-data\.jsonl/), page.click('.kse-replay-log-link:text-is("replay-data.jsonl")')]);
    await page.waitForFunction(() => window.kse?.replay && ['ready', 'error'].includes(document.body.dataset.kseReplay) && window.kse.replay.frameCount() > 0, null, { timeout: 30000 });
    assert.equal((await replayState(page)).state, 'ready');
    assert.deepEqual(page.problems, []);
    await page.close();
});

test('a log cut short, of another version, or not a log at all opens with a message', { timeout: 60000 }, async () => {
    const text = readFileSync(dataLog, 'utf8');
    const lines = text.split('\n');
    // cut in the middle of a frame's line, as a writer killed mid-line would leave it
    const kept = lines.slice(0, Math.floor(lines.length * 0.6));
    const lastFrame = kept.map(line => JSON.parse(line)).filter(record => record.type === 'frame').pop();
    const cut = lines[kept.length].slice(0, 200);
    writeFileSync(path.join(servedFolder(), 'replay-cut.jsonl'), kept.join('\n') + '\n' + cut);
    writeFileSync(path.join(servedFolder(), 'replay-v2.jsonl'), text.replace('"version":1', '"version":2'));
    writeFileSync(path.join(servedFolder(), 'replay-text.jsonl'), 'kse-match: this is a console transcript, not a log\n');
    writeFileSync(path.join(servedFolder(), 'replay-noresult.jsonl'), lines.slice(0, 40).join('\n') + '\n');

    const cutPage = await openReplay('replay-cut.jsonl');
    const cutState = await replayState(cutPage);
    assert.equal(cutState.state, 'ready', 'a log cut short is replayed up to where it ends');
    assert.equal(cutState.notice, `The log ends at t = ${lastFrame.t.toFixed(1)} s: truncated (its last line is cut short).`);
    assert.equal(await cutPage.evaluate(() => window.kse.replay.frameCount()), kept.filter(line => line.includes('"type":"frame"')).length);
    await shot(cutPage, 'truncated');

    const noResult = await openReplay('replay-noresult.jsonl');
    assert.match((await replayState(noResult)).notice, /^The log ends at t = [\d.]+ s: truncated \(it has no result/);

    const v2 = await openReplay('replay-v2.jsonl');
    const v2State = await replayState(v2);
    assert.equal(v2State.state, 'error');
    assert.match(v2State.notice, /replay-v2\.jsonl: This match log has version 2; this page replays version 1/);
    await shot(v2, 'version-2');

    const notLog = await openReplay('replay-text.jsonl');
    const notLogState = await replayState(notLog);
    assert.equal(notLogState.state, 'error');
    assert.match(notLogState.notice, /replay-text\.jsonl: This is not a match log: its first line is not JSON \("kse-match: this is/);
    await shot(notLog, 'not-a-log');

    const missing = await openReplay('replay-missing.jsonl');
    assert.match((await replayState(missing)).notice, /There is no match log replay-missing\.jsonl in the served folder \(404\)/);
    const outside = await openReplay('../etc/passwd.jsonl');
    assert.match((await replayState(outside)).notice, /Cannot replay "\.\.\/etc\/passwd\.jsonl": name a match log/);
    for (const page of [cutPage, noResult, v2, notLog, missing, outside]) {
        assert.deepEqual(page.problems, [], `no errors on the page of ${page.url()}`);
        await page.close();
    }
});
