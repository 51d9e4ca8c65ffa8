/*
 * The replay of a match log: the page opened with `?token=T&replay=<file>.jsonl` (a log in the
 * served folder, sent by the server's /logs) shows the field at time t (lines, goals, the robots as
 * oriented markers in their team's colour, the ball, each robot's path so far), a timeline with the
 * match's events to jump to, play/pause, speed, frame steps and scrubbing. Selecting a robot shows
 * its statechart (the model named after its behaviour, `<behaviour>.stct` in the served folder) with
 * the states active at t outlined and the transitions taken around t listed. A host that serves
 * no folder of models (the workbench: its server opens only models it lends) names each
 * behaviour's model itself: `&models=Goalie:editor-KEY/Goalie.stct,Attacker:…` (see readModels).
 *
 * The statechart is a diagram page of its own in a frame (`?model=…&replayed=1`, read-only): the
 * page stays the one GLSP page there is, and this one only sends it CSS feedback through its
 * `window.kse` (highlight.ts, shared with the live monitor). The log's names of states are the
 * engine's (GenerationPlan.stateName), mapped to the diagram's ids by the same rule.
 *
 * `body[data-kse-replay]` says loading, ready or error; `window.kse.replay` lets tests and hosts
 * read what is drawn and move in time.
 */
import { CSS_ACTIVE, CSS_FIRED, cssChanges, ElementLike, engineStateName, Mapping, mappingOf } from './highlight';
import { LogEvent, MatchLog, readLog } from './replay-log';
import './replay.css';

export interface ReplayParameters {
    token: string;
    /** The log, relative to the served folder. */
    log: string;
    /** A robot to select at the start, e.g. home-1. */
    robot: string;
    /** A time to start at, in seconds. */
    t: number;
    /**
     * The model of each behaviour, as the server names it, when the host said (&models=); then a
     * behaviour it does not name has no model, and the folder is not searched.
     */
    models?: Map<string, string>;
}

/**
 * `&models=Goalie:editor-KEY/Goalie.stct,Attacker:…` as behaviour → model. A behaviour is an
 * identifier and a model's name has no comma, so the first colon and the commas split it; an
 * entry without a colon names nothing.
 */
export function readModels(value: string): Map<string, string> {
    const models = new Map<string, string>();
    for (const entry of value.split(',')) {
        const colon = entry.indexOf(':');
        if (colon > 0 && colon < entry.length - 1) {
            models.set(entry.slice(0, colon), entry.slice(colon + 1));
        }
    }
    return models;
}

/** The replay's parameters when the page was opened to replay a log, else undefined. */
export function readReplayParameters(location: Location): ReplayParameters | undefined {
    const query = new URLSearchParams(location.search);
    const log = query.get('replay');
    if (log === null) {
        return undefined;
    }
    const t = Number(query.get('t') ?? '0');
    const models = query.get('models');
    return {
        token: query.get('token') ?? '',
        log,
        robot: query.get('robot') ?? '',
        t: Number.isFinite(t) ? t : 0,
        models: models === null ? undefined : readModels(models)
    };
}

/** Whether this page is a statechart shown inside a replay (read-only, no editing tools). */
export function isReplayedDiagram(location: Location): boolean {
    return new URLSearchParams(location.search).has('replayed');
}

export type ReplayState = 'loading' | 'ready' | 'error';

export interface DrawnRobot {
    id: string;
    x: number;
    y: number;
    theta: number;
}

export interface ReplayHandle {
    /** loading, ready or error (also body[data-kse-replay]). */
    state(): ReplayState;
    /** The message shown: an error, or a notice about a log cut short (empty when none). */
    message(): string;
    /** The match time drawn, in s. */
    time(): number;
    /** The index of the frame drawn. */
    frame(): number;
    frameCount(): number;
    /** The log's events (goals, kicks, falls, penalties, ...). */
    events(): LogEvent[];
    /** The robots' ids, home first. */
    robots(): string[];
    /** The robots as drawn (from the SVG: what a user sees). */
    drawnRobots(): DrawnRobot[];
    /** The selected robot ('' none). */
    selected(): string;
    /** The selected robot's active states at the frame drawn, as the log names them. */
    activeNames(): string[];
    /** The ids of the states the diagram shows as active. */
    active(): string[];
    /** Resolved when the diagram shows the frame drawn (at once when no diagram is shown). */
    settled(): Promise<void>;
    /** Draws the frame at t (seconds), synchronously; returns the frame's index. */
    seek(t: number): number;
    /** Moves by n frames. */
    step(n: number): number;
    select(robot: string): Promise<void>;
    play(): void;
    pause(): void;
    playing(): boolean;
    setSpeed(speed: number): void;
    speed(): number;
    /** Timings of the loading, in ms since the page started: fetched (whole file read) and ready. */
    timings(): { readyMs: number; bytes: number };
}

const SPEEDS = [0.25, 0.5, 1, 2, 5, 10];
/** Frames in a piece of a robot's drawn path (20 s of match). */
const PIECE = 200;
/** The events that get a marker on the timeline (a kick-off position and the like would only crowd it). */
const MARKED = new Set(['goal', 'kick', 'missed-kick', 'fall', 'penalty', 'stuck', 'failed', 'state', 'dive', 'ball-out', 'game-stuck', 'half-time']);
/** How far around t the transitions list reaches, in s. */
const AROUND = 2;
const SVG = 'http://www.w3.org/2000/svg';

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text?: string): HTMLElementTagNameMap[K] {
    const made = document.createElement(tag);
    made.className = className;
    if (text !== undefined) {
        made.textContent = text;
    }
    return made;
}

function svg<K extends keyof SVGElementTagNameMap>(tag: K, attributes: Record<string, string | number>, parent?: Element): SVGElementTagNameMap[K] {
    const made = document.createElementNS(SVG, tag);
    for (const [name, value] of Object.entries(attributes)) {
        made.setAttribute(name, String(value));
    }
    parent?.append(made);
    return made;
}

function button(text: string, action: string, title: string): HTMLButtonElement {
    const made = element('button', 'kse-replay-button', text);
    made.type = 'button';
    made.dataset.action = action;
    made.title = title;
    return made;
}

/** The window.kse of the statechart's frame (the diagram page's handle). */
interface FrameKse {
    ready: Promise<void>;
    dispatch(action: unknown): Promise<void>;
    modelRoot(): ElementLike & { children?: Array<ElementLike & { sourceId?: string; targetId?: string }> };
}

/** Shows the replay in the page; the page has no diagram of its own. */
export function installReplay(parameters: ReplayParameters): ReplayHandle {
    const started = performance.now();
    document.body.classList.add('kse-replay');
    document.body.dataset.kseReplay = 'loading';
    document.title = `${parameters.log} – KSE replay`;
    const host = document.getElementById('kse-diagram') ?? document.body;

    // ---- the page's parts ----
    const view = element('div', 'kse-replay');
    const left = element('section', 'kse-replay-match');
    const notice = element('div', 'kse-replay-notice');
    notice.setAttribute('role', 'alert');
    notice.hidden = true;
    const facts = element('div', 'kse-replay-facts');
    const clock = element('span', 'kse-replay-clock', 't = –');
    const game = element('span', 'kse-replay-game', '');
    const score = element('span', 'kse-replay-score', '');
    facts.append(element('span', 'kse-replay-file', parameters.log), clock, game, score);
    const field = svg('svg', { class: 'kse-replay-field', role: 'img', 'aria-label': 'The field' });
    const controls = element('div', 'kse-replay-controls');
    const back = button('◀|', 'replay-back', 'One frame back (←)');
    const play = button('▶', 'replay-play', 'Play or pause (space)');
    const forward = button('|▶', 'replay-forward', 'One frame forward (→)');
    const speed = element('select', 'kse-replay-speed');
    speed.title = 'Speed';
    speed.dataset.action = 'replay-speed';
    for (const value of SPEEDS) {
        const option = element('option', '', `${value}x`);
        option.value = String(value);
        option.selected = value === 1;
        speed.append(option);
    }
    // the events also as a list: markers close together on the timeline cover each other
    const eventList = element('select', 'kse-replay-events');
    eventList.title = 'Jump to an event';
    eventList.dataset.action = 'replay-event';
    const timeline = element('div', 'kse-replay-timeline');
    const scrub = element('input', 'kse-replay-scrub');
    scrub.type = 'range';
    scrub.min = '0';
    scrub.max = '0';
    scrub.step = '1';
    scrub.value = '0';
    scrub.setAttribute('aria-label', 'Time');
    const markers = element('div', 'kse-replay-markers');
    timeline.append(markers, scrub);
    controls.append(back, play, forward, speed, timeline, eventList);
    left.append(facts, notice, field, controls);

    const right = element('section', 'kse-replay-robot');
    const robotList = element('div', 'kse-replay-robots');
    robotList.setAttribute('role', 'listbox');
    robotList.setAttribute('aria-label', 'Robots');
    const chartTitle = element('div', 'kse-replay-chart-title', 'Select a robot to see its statechart');
    const chartMessage = element('div', 'kse-replay-chart-message');
    chartMessage.hidden = true;
    const chart = element('iframe', 'kse-replay-chart');
    chart.title = 'The selected robot’s statechart';
    chart.hidden = true;
    const takenCaption = element('div', 'kse-replay-caption', `Transitions within ${AROUND} s of t`);
    const takenList = element('ol', 'kse-replay-taken');
    right.append(robotList, chartTitle, chartMessage, chart, takenCaption, takenList);
    view.append(left, right);
    host.replaceChildren(view);

    // ---- state ----
    let state: ReplayState = 'loading';
    let message = '';
    let log: MatchLog | undefined;
    let frame = 0;
    let playing = false;
    let rate = 1;
    let selected = '';
    let models: string[] | undefined;
    let readyMs = NaN;
    let bytes = 0;
    // the diagram of the selected robot
    let frameKse: FrameKse | undefined;
    let mapping: Mapping | undefined;
    let transitionIds = new Map<string, string[]>();
    let drawnActive = new Set<string>();
    let drawnFired = new Set<string>();
    let highlighting: Promise<void> = Promise.resolve();
    let highlightWanted = false;
    // the field's parts
    const robotMarks: SVGGElement[] = [];
    const robotLabels: SVGTextElement[] = [];
    /** Per robot, its path in pieces of PIECE frames (see drawField). */
    const pieces: SVGPathElement[][] = [];
    /** Per robot, the path's length from the start of its piece to each frame (a jump, a robot carried, adds nothing). */
    const pathLength: Float32Array[] = [];
    /** Per robot, the piece drawn in part (those before it are drawn whole, those after not at all). */
    const pieceShown: number[] = [];
    let ballMark: SVGCircleElement | undefined;

    function setState(next: ReplayState): void {
        state = next;
        document.body.dataset.kseReplay = next;
        view.dataset.state = next;
    }

    function fail(text: string): void {
        message = text;
        notice.hidden = false;
        notice.dataset.severity = 'error';
        notice.textContent = text;
        setState('error');
    }

    function warn(text: string): void {
        message = message ? `${message} ${text}` : text;
        notice.hidden = false;
        notice.dataset.severity = 'warning';
        notice.textContent = message;
    }

    // ---- the field ----
    function drawField(match: MatchLog): void {
        const { length, width, goalWidth } = match.header!.field;
        // room for a penalised robot, placed beside the field
        const margin = 1;
        field.setAttribute('viewBox', `${-length / 2 - margin} ${-width / 2 - margin} ${length + 2 * margin} ${width + 2 * margin}`);
        const lines = svg('g', { class: 'kse-replay-lines' }, field);
        svg('rect', { class: 'kse-replay-grass', x: -length / 2 - margin, y: -width / 2 - margin, width: length + 2 * margin, height: width + 2 * margin }, lines);
        svg('rect', { class: 'kse-replay-line', x: -length / 2, y: -width / 2, width: length, height: width }, lines);
        svg('line', { class: 'kse-replay-line', x1: 0, y1: -width / 2, x2: 0, y2: width / 2 }, lines);
        svg('circle', { class: 'kse-replay-line', cx: 0, cy: 0, r: 0.75 }, lines);
        // the SPL field's penalty areas (1.65 m by 4 m) and goal areas (0.6 m by 2.2 m), scaled to the log's field
        const scale = length / 9;
        for (const side of [-1, 1]) {
            const line = (side * length) / 2;
            const area = (depth: number, across: number): void => {
                const x = side < 0 ? line : line - depth * scale;
                svg('rect', { class: 'kse-replay-line', x, y: (-across * scale) / 2, width: depth * scale, height: across * scale }, lines);
            };
            area(1.65, 4);
            area(0.6, 2.2);
            svg('circle', { class: 'kse-replay-spot', cx: line - side * 1.3 * scale, cy: 0, r: 0.04 }, lines);
            const depth = 0.5 * scale;
            svg('rect', {
                class: `kse-replay-goal kse-replay-goal-${side < 0 ? 'home' : 'away'}`,
                x: side < 0 ? line - depth : line,
                y: -goalWidth / 2,
                width: depth,
                height: goalWidth
            }, lines);
        }
        const pathLayer = svg('g', { class: 'kse-replay-paths' }, field);
        const robotLayer = svg('g', { class: 'kse-replay-robots-drawn' }, field);
        const poses = match.poseData();
        const count = match.robotCount;
        match.robots.forEach((robot, r) => {
            const team = robot.team === 0 ? 'home' : 'away';
            // The path is made once, in pieces of PIECE frames: the pieces before t are drawn whole, the
            // one at t as a dash as long as the path up to t, the rest not at all. One dashed path of
            // the whole match would be dashed anew at every paint (some 40 ms for ten robots' 6,000 frames).
            const lengths = new Float32Array(match.frameCount);
            const robotPieces: SVGPathElement[] = [];
            let d = '';
            let total = 0;
            let lastX = NaN;
            let lastY = NaN;
            for (let f = 0; f < match.frameCount; f++) {
                if (f % PIECE === 0 && f > 0) {
                    robotPieces.push(svg('path', { class: `kse-replay-path kse-replay-${team}`, d: d || 'M0 0', 'data-robot': robot.id }, pathLayer));
                    // the next piece starts where this one ends
                    d = Number.isNaN(lastX) ? '' : `M${lastX.toFixed(2)} ${lastY.toFixed(2)}`;
                    total = 0;
                }
                if (match.isPresent(f, r)) {
                    const x = poses[(f * count + r) * 3];
                    const y = -poses[(f * count + r) * 3 + 1];
                    const step = Math.hypot(x - lastX, y - lastY);
                    if (Number.isNaN(step) || step > 1) {
                        d += `M${x.toFixed(2)} ${y.toFixed(2)}`;
                    } else if (step > 0.03) {
                        d += `L${x.toFixed(2)} ${y.toFixed(2)}`;
                        total += step;
                    } else {
                        lengths[f] = total;
                        continue; // standing: the path does not grow
                    }
                    lastX = x;
                    lastY = y;
                }
                lengths[f] = total;
            }
            robotPieces.push(svg('path', { class: `kse-replay-path kse-replay-${team}`, d: d || 'M0 0', 'data-robot': robot.id }, pathLayer));
            for (const piece of robotPieces) {
                piece.style.display = 'none';
            }
            pathLength.push(lengths);
            pieces.push(robotPieces);
            pieceShown.push(-1);
            const mark = svg('g', { class: `kse-replay-marker kse-replay-${team}`, 'data-robot': robot.id }, robotLayer);
            svg('circle', { r: 0.16 }, mark);
            svg('path', { class: 'kse-replay-heading', d: 'M0.26 0 L0.04 0.11 L0.04 -0.11 Z' }, mark);
            const title = svg('title', {}, mark);
            title.textContent = `${robot.id} (${robot.behaviour})`;
            mark.addEventListener('click', () => void select(robot.id));
            robotMarks.push(mark);
            const label = svg('text', { class: `kse-replay-label kse-replay-${team}`, 'data-robot': robot.id }, robotLayer);
            label.textContent = String(robot.number);
            robotLabels.push(label);
        });
        ballMark = svg('circle', { class: 'kse-replay-ball', r: 0.07 }, field);
    }

    /** Brings the field, the clock and the list up to the frame; the diagram follows asynchronously. */
    function drawFrame(): void {
        if (!log || log.frameCount === 0) {
            return;
        }
        const match = log;
        const t = match.time(frame);
        clock.textContent = `t = ${t.toFixed(1)} s`;
        game.textContent = match.gameStateAt(frame);
        const [home, away] = match.scoreAt(frame);
        score.textContent = `${home} : ${away}`;
        scrub.value = String(frame);
        for (let r = 0; r < match.robotCount; r++) {
            const mark = robotMarks[r];
            const present = match.isPresent(frame, r);
            mark.style.display = present ? '' : 'none';
            robotLabels[r].style.display = present ? '' : 'none';
            if (!present) {
                continue;
            }
            const [x, y, theta] = match.poseAt(frame, r);
            // the field's y is up, the picture's down: a pose (x, y, θ) is drawn at (x, -y) turned by -θ
            mark.setAttribute('transform', `translate(${x.toFixed(3)} ${(-y).toFixed(3)}) rotate(${((-theta * 180) / Math.PI).toFixed(1)})`);
            mark.dataset.motion = match.motionAt(frame, r);
            mark.dataset.penalised = String(match.penaltyAt(frame, r) !== 0);
            robotLabels[r].setAttribute('x', (x + 0.2).toFixed(3));
            robotLabels[r].setAttribute('y', (-y - 0.2).toFixed(3));
            showPath(r);
        }
        const [bx, by] = match.ballAt(frame);
        ballMark?.setAttribute('cx', bx.toFixed(3));
        ballMark?.setAttribute('cy', (-by).toFixed(3));
        drawTaken();
        wantHighlight();
    }

    /** Shows robot r's path up to the frame drawn, changing only the pieces between the last frame's and this one's. */
    function showPath(r: number): void {
        const robotPieces = pieces[r];
        const now = Math.floor(frame / PIECE);
        const before = pieceShown[r];
        const from = before < 0 ? 0 : Math.min(before, now);
        const to = before < 0 ? robotPieces.length - 1 : Math.max(before, now);
        for (let i = from; i <= to; i++) {
            const piece = robotPieces[i];
            piece.style.display = i <= now ? '' : 'none';
            piece.style.strokeDasharray = i === now ? `${pathLength[r][frame].toFixed(3)} 100000` : '';
        }
        pieceShown[r] = now;
    }

    function seekFrame(next: number): number {
        if (!log || log.frameCount === 0) {
            return 0;
        }
        frame = Math.max(0, Math.min(log.frameCount - 1, Math.round(next)));
        drawFrame();
        return frame;
    }

    // ---- the robot's statechart ----
    function drawTaken(): void {
        if (!log || !selected) {
            takenList.replaceChildren();
            return;
        }
        const r = log.robotIndexOf(selected);
        const t = log.time(frame);
        const first = log.frameAt(t - AROUND);
        const last = log.frameAt(t + AROUND);
        const rows: HTMLLIElement[] = [];
        for (let f = first; f <= last; f++) {
            for (const name of log.takenAt(f, r)) {
                const row = element('li', 'kse-replay-transition');
                if (f === frame) {
                    row.classList.add('kse-replay-now');
                }
                row.dataset.frame = String(f);
                const [from, to] = splitTransition(name);
                row.append(element('span', 'kse-replay-time', log.time(f).toFixed(1)), element('span', 'kse-replay-move', `${from} → ${to}`));
                row.title = name;
                row.addEventListener('click', () => seekFrame(f));
                rows.push(row);
            }
        }
        if (rows.length === 0) {
            rows.push(element('li', 'kse-replay-none', 'none'));
        }
        takenList.replaceChildren(...rows);
        takenList.querySelector('.kse-replay-now')?.scrollIntoView({ block: 'nearest' });
    }

    function wantHighlight(): void {
        if (highlightWanted) {
            return;
        }
        highlightWanted = true;
        // one update of the diagram per animation frame at most, however fast time moves
        requestAnimationFrame(() => {
            highlightWanted = false;
            highlighting = highlighting.then(highlight).catch(() => undefined);
        });
    }

    async function highlight(): Promise<void> {
        const target = frameKse;
        if (!log || !selected || !target || !mapping) {
            return;
        }
        const r = log.robotIndexOf(selected);
        const active = new Set<string>();
        for (const name of log.activeAt(frame, r)) {
            const id = mapping.stateByEngineName.get(name);
            if (id) {
                active.add(id);
            }
        }
        const fired = new Set<string>();
        for (const name of log.takenAt(frame, r)) {
            for (const id of transitionIds.get(name) ?? []) {
                fired.add(id);
            }
        }
        const actions = [...cssChanges(drawnActive, active, CSS_ACTIVE), ...cssChanges(drawnFired, fired, CSS_FIRED)];
        drawnActive = active;
        drawnFired = fired;
        const frameWindow = chart.contentWindow as (Window & { JSON: JSON }) | null;
        for (const action of actions) {
            // made in the frame's own realm: the diagram page checks what it receives as its own objects
            await target.dispatch(frameWindow ? frameWindow.JSON.parse(JSON.stringify(action)) : action);
        }
        if (actions.length > 0 && frameWindow) {
            // the diagram draws what it was sent in its next animation frame: settled() means drawn
            await new Promise<void>(resolve => frameWindow.requestAnimationFrame(() => frameWindow.requestAnimationFrame(() => resolve())));
        }
    }

    async function select(robot: string): Promise<void> {
        if (!log || log.robotIndexOf(robot) < 0 || robot === selected) {
            return;
        }
        selected = robot;
        for (const chip of robotList.querySelectorAll<HTMLButtonElement>('button')) {
            chip.setAttribute('aria-selected', String(chip.dataset.robot === robot));
        }
        robotMarks.forEach((mark, r) => mark.classList.toggle('kse-replay-selected', log!.robots[r].id === robot));
        const info = log.robots[log.robotIndexOf(robot)];
        const model = `${info.behaviour}.stct`;
        chartTitle.textContent = `${robot}: ${info.behaviour}`;
        frameKse = undefined;
        mapping = undefined;
        drawnActive = new Set();
        drawnFired = new Set();
        drawTaken();
        const found = await modelOf(info.behaviour);
        if (selected !== robot) {
            return;
        }
        if (found === undefined) {
            chart.hidden = true;
            chart.removeAttribute('src');
            chartMessage.hidden = false;
            chartMessage.textContent = `There is no ${model} ${parameters.models ? "in the workspace's open projects" : 'in the served folder'}: ${robot}'s statechart cannot be shown (the log names its active states: ${log
                .activeAt(frame, log.robotIndexOf(robot))
                .join(', ')}).`;
            return;
        }
        chartMessage.hidden = true;
        chart.hidden = false;
        const url = `/?token=${encodeURIComponent(parameters.token)}&model=${encodeURIComponent(found)}&replayed=1`;
        const loaded = new Promise<void>(resolve => chart.addEventListener('load', () => resolve(), { once: true }));
        chart.src = url;
        await loaded;
        const frameWindow = chart.contentWindow as (Window & { kse?: FrameKse; JSON: JSON }) | null;
        const kse = frameWindow?.kse;
        if (!kse || selected !== robot) {
            return;
        }
        await kse.ready;
        if (selected !== robot) {
            return;
        }
        const root = kse.modelRoot();
        // the whole chart in the frame: sprotty draws only what is in view, and the page opens at a readable zoom
        const tops = (root.children ?? []).filter(child => child.type.startsWith('state:')).map(child => child.id);
        await kse.dispatch(frameWindow.JSON.parse(JSON.stringify({ kind: 'fit', elementIds: tops, padding: 16, maxZoom: 1, animate: false })));
        mapping = mappingOf(root);
        transitionIds = transitionsByName(root);
        frameKse = kse;
        wantHighlight();
        await settled();
    }

    /** The model of a behaviour as the server names it: the host's when it named the models, else `<behaviour>.stct` of the folder. */
    async function modelOf(behaviour: string): Promise<string | undefined> {
        if (parameters.models) {
            return parameters.models.get(behaviour);
        }
        const model = `${behaviour}.stct`;
        const known = await modelsOfFolder();
        // at the folder's top, else the first below it (kse serve examples: Goalie/Goalie.stct)
        return known.includes(model) ? model : known.find(path => path.endsWith(`/${model}`));
    }

    async function modelsOfFolder(): Promise<string[]> {
        if (!models) {
            models = await listOf('models');
        }
        return models;
    }

    /** The server's list of the folder's models or logs (empty when it cannot be had). */
    async function listOf(what: 'models' | 'logs'): Promise<string[]> {
        try {
            const response = await fetch(`/${what}?token=${encodeURIComponent(parameters.token)}`);
            const list = response.ok ? ((await response.json()) as unknown) : [];
            return Array.isArray(list) ? list.filter((entry): entry is string => typeof entry === 'string') : [];
        } catch {
            return [];
        }
    }

    /** ?replay= with no file: the folder's logs, each a link to its replay. */
    async function listLogs(): Promise<void> {
        const logs = await listOf('logs');
        const list = element('ul', 'kse-replay-log-list');
        for (const log of logs) {
            const link = element('a', 'kse-replay-log-link', log);
            link.href = `/?token=${encodeURIComponent(parameters.token)}&replay=${encodeURIComponent(log)}`;
            const item = element('li', '');
            item.append(link);
            list.append(item);
        }
        left.replaceChildren(element('h2', 'kse-replay-title', logs.length > 0 ? 'Match logs of the served folder' : 'The served folder has no match log (.jsonl)'), list);
        right.replaceChildren();
        setState('ready');
    }

    async function settled(): Promise<void> {
        await new Promise<void>(resolve => requestAnimationFrame(() => resolve()));
        await highlighting;
    }

    // ---- playing ----
    let lastTick = 0;
    /** The match time playing has reached (the frame drawn is the last one at or before it). */
    let playTime = 0;
    function tick(now: number): void {
        if (!playing || !log) {
            return;
        }
        playTime += ((now - lastTick) / 1000) * rate;
        lastTick = now;
        const last = log.frameCount - 1;
        if (playTime >= log.time(last)) {
            seekFrame(last);
            pause();
            return;
        }
        const next = log.frameAt(playTime);
        if (next !== frame) {
            seekFrame(next);
        }
        requestAnimationFrame(tick);
    }

    function startPlaying(): void {
        if (!log || log.frameCount === 0 || playing) {
            return;
        }
        if (frame >= log.frameCount - 1) {
            seekFrame(0);
        }
        playing = true;
        playTime = log.time(frame);
        play.textContent = '❚❚';
        play.setAttribute('aria-pressed', 'true');
        lastTick = performance.now();
        requestAnimationFrame(tick);
    }

    function pause(): void {
        playing = false;
        play.textContent = '▶';
        play.setAttribute('aria-pressed', 'false');
    }

    play.addEventListener('click', () => (playing ? pause() : startPlaying()));
    back.addEventListener('click', () => {
        pause();
        seekFrame(frame - 1);
    });
    forward.addEventListener('click', () => {
        pause();
        seekFrame(frame + 1);
    });
    speed.addEventListener('change', () => {
        rate = Number(speed.value);
    });
    scrub.addEventListener('input', () => {
        seekFrame(Number(scrub.value));
        playTime = log ? log.time(frame) : 0;
    });
    document.addEventListener('keydown', event => {
        // a focused control keeps its own keys (space on a button presses it)
        if (state !== 'ready' || event.target instanceof HTMLSelectElement || event.target instanceof HTMLInputElement || event.target instanceof HTMLButtonElement) {
            return;
        }
        if (event.key === ' ') {
            event.preventDefault();
            playing ? pause() : startPlaying();
        } else if (event.key === 'ArrowLeft' || event.key === 'ArrowRight') {
            event.preventDefault();
            pause();
            seekFrame(frame + (event.key === 'ArrowLeft' ? -1 : 1));
        }
    });

    function drawTimeline(match: MatchLog): void {
        const first = match.time(0);
        const span = Math.max(0.1, match.time(match.frameCount - 1) - first);
        scrub.max = String(match.frameCount - 1);
        const marks: HTMLButtonElement[] = [];
        const options: HTMLOptionElement[] = [element('option', '', `Events (${match.events.filter(event => MARKED.has(event.event)).length})…`)];
        options[0].value = '';
        match.events.forEach((event, index) => {
            if (!MARKED.has(event.event)) {
                return;
            }
            const mark = element('button', `kse-replay-event kse-replay-event-${event.event}`);
            mark.type = 'button';
            mark.dataset.event = event.event;
            mark.dataset.index = String(index);
            mark.dataset.t = String(event.t);
            mark.style.left = `${(Math.max(0, Math.min(1, (event.t - first) / span)) * 100).toFixed(3)}%`;
            const who = event.robot ? ` ${event.robot}` : event.team !== undefined ? ` ${match.header!.teams[event.team]?.name ?? ''}` : '';
            mark.title = `${event.t.toFixed(1)} s: ${event.event}${who}${event.detail ? ` (${event.detail})` : ''}`;
            mark.setAttribute('aria-label', mark.title);
            mark.addEventListener('click', () => {
                pause();
                seekFrame(match.frameAt(event.t));
            });
            marks.push(mark);
            const option = element('option', '', mark.title);
            option.value = String(index);
            options.push(option);
        });
        markers.replaceChildren(...marks);
        eventList.replaceChildren(...options);
        eventList.addEventListener('change', () => {
            const event = match.events[Number(eventList.value)];
            if (eventList.value !== '' && event) {
                pause();
                seekFrame(match.frameAt(event.t));
            }
        });
    }

    function listRobots(match: MatchLog): void {
        const chips = match.robots.map(robot => {
            const chip = element('button', `kse-replay-chip kse-replay-${robot.team === 0 ? 'home' : 'away'}`, robot.id);
            chip.type = 'button';
            chip.dataset.robot = robot.id;
            chip.setAttribute('role', 'option');
            chip.setAttribute('aria-selected', 'false');
            chip.title = robot.behaviour;
            chip.addEventListener('click', () => void select(robot.id));
            return chip;
        });
        robotList.replaceChildren(...chips);
    }

    // ---- loading ----
    async function load(): Promise<void> {
        if (parameters.log === '') {
            await listLogs();
            return;
        }
        if (!/^[A-Za-z0-9._/-]+\.jsonl$/.test(parameters.log) || parameters.log.split('/').some(part => part === '' || part.startsWith('.'))) {
            fail(`Cannot replay ${JSON.stringify(parameters.log)}: name a match log (.jsonl) of the served folder, e.g. ?replay=match.jsonl.`);
            return;
        }
        let response: Response;
        try {
            response = await fetch(`/logs/${parameters.log.split('/').map(encodeURIComponent).join('/')}?token=${encodeURIComponent(parameters.token)}`);
        } catch (error) {
            fail(`Cannot read ${parameters.log}: ${String(error)}`);
            return;
        }
        if (!response.ok || !response.body) {
            fail(
                response.status === 403
                    ? `Cannot read ${parameters.log}: the session token is missing or wrong (open the address kse serve printed).`
                    : `There is no match log ${parameters.log} in the served folder (${response.status}).`
            );
            return;
        }
        const match = await readLog(response.body, read => (bytes = read));
        if (match.error !== undefined) {
            fail(`${parameters.log}: ${match.error}`);
            return;
        }
        if (match.frameCount === 0) {
            fail(`${parameters.log}: the log has no frame to show (it ends after its first ${match.lines} lines).`);
            return;
        }
        log = match;
        const endT = match.time(match.frameCount - 1).toFixed(1);
        if (match.truncatedLine) {
            warn(`The log ends at t = ${endT} s: truncated (its last line is cut short).`);
        } else if (!match.end) {
            warn(`The log ends at t = ${endT} s: truncated (it has no result; the match may still run or have stopped).`);
        } else if (match.end.type === 'aborted') {
            warn(`The match was aborted at t = ${match.end.t.toFixed(1)} s: ${String(match.end.record.reason ?? '')}${match.end.record.detail ? ` (${String(match.end.record.detail)})` : ''}.`);
        }
        if (match.badLines.length > 0) {
            warn(`${match.badLines.length} line(s) are not JSON and were skipped (first: line ${match.badLines[0]}).`);
        }
        drawField(match);
        drawTimeline(match);
        listRobots(match);
        seekFrame(match.frameAt(parameters.t));
        readyMs = performance.now() - started;
        setState('ready');
        if (parameters.robot) {
            await select(parameters.robot);
        }
    }

    void load().catch(error => fail(`Cannot replay ${parameters.log}: ${String(error)}`));

    return {
        state: () => state,
        message: () => message,
        time: () => (log && log.frameCount > 0 ? log.time(frame) : NaN),
        frame: () => frame,
        frameCount: () => log?.frameCount ?? 0,
        events: () => (log ? log.events.slice() : []),
        robots: () => (log ? log.robots.map(robot => robot.id) : []),
        drawnRobots: () =>
            robotMarks
                .filter(mark => mark.style.display !== 'none')
                .map(mark => {
                    const found = /translate\(([-\d.]+) ([-\d.]+)\) rotate\(([-\d.]+)\)/.exec(mark.getAttribute('transform') ?? '');
                    return {
                        id: mark.dataset.robot ?? '',
                        x: found ? Number(found[1]) : NaN,
                        y: found ? -Number(found[2]) : NaN,
                        theta: found ? (-Number(found[3]) * Math.PI) / 180 : NaN
                    };
                }),
        selected: () => selected,
        activeNames: () => (log && selected ? log.activeAt(frame, log.robotIndexOf(selected)) : []),
        active: () => [...drawnActive],
        settled,
        seek: t => (log ? seekFrame(log.frameAt(t)) : 0),
        step: n => seekFrame(frame + n),
        select,
        play: startPlaying,
        pause,
        playing: () => playing,
        setSpeed: value => {
            rate = value;
            speed.value = String(value);
        },
        speed: () => rate,
        timings: () => ({ readyMs, bytes })
    };
}

/** "Node_a_TO_Node_b" as its two states, without the engine's Node_ prefix. */
function splitTransition(name: string): [string, string] {
    const at = name.indexOf('_TO_Node_');
    if (at < 0) {
        return [name, '?'];
    }
    return [name.slice(0, at).replace(/^Node_/, ''), name.slice(at + 4).replace(/^Node_/, '')];
}

/**
 * The log's name of each transition of the diagram (TransitionSegmentBase::Name(): the source's
 * engine name, _TO_, the target's) → the transitions with that name (two between the same states share it).
 */
function transitionsByName(root: ElementLike & { children?: Array<ElementLike & { sourceId?: string; targetId?: string }> }): Map<string, string[]> {
    const stateName = new Map<string, string>();
    const edges: Array<{ id: string; source: string; target: string }> = [];
    const visit = (element: ElementLike & { sourceId?: string; targetId?: string }): void => {
        if (element.type.startsWith('state:')) {
            const args = element.args ?? {};
            stateName.set(element.id, engineStateName(typeof args.label === 'string' ? args.label : '', typeof args.name === 'string' ? args.name : ''));
        } else if (/^\/\/@transitions\.\d+$/.test(element.id) && element.sourceId && element.targetId) {
            edges.push({ id: element.id, source: element.sourceId, target: element.targetId });
        }
        for (const child of (element.children ?? []) as Array<ElementLike & { sourceId?: string; targetId?: string }>) {
            visit(child);
        }
    };
    visit(root);
    const byName = new Map<string, string[]>();
    for (const edge of edges) {
        const name = `${stateName.get(edge.source) ?? '?'}_TO_${stateName.get(edge.target) ?? '?'}`;
        byName.set(name, [...(byName.get(name) ?? []), edge.id]);
    }
    return byName;
}
