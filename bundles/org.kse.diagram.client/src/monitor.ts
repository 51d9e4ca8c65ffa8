/*
 * The live monitor: the page opened with `&monitor=P&key=K&robot=R` shows the statechart read-only
 * and watches robot R of the kse-match whose monitor listens on 127.0.0.1:P (key K, printed by
 * `kse-match --monitor`), through the server's relay (ws://<host>/monitor). The active states are
 * outlined and tinted, each transition flashes as it fires, a side panel lists the last transitions
 * and shows the match's time, game state and score; Pause freezes the drawing, Resume jumps to now.
 *
 * At 10x a robot takes several hundred transitions a second, far more than frames: records only
 * change the monitor's state, and the diagram is updated once per animation frame with what changed
 * (GLSP's CSS feedback, as the drop feedback of reparent.ts). The relay's messages carry the lines
 * of kse-match, several per message (docs: the live monitor protocol).
 *
 * `body[data-kse-monitor]` says connecting, live, ended or error; `window.kse.monitor` lets tests and
 * hosts read what is drawn and how long a transition took from the engine to the diagram.
 */
import { ModifyCSSFeedbackAction } from '@eclipse-glsp/client';
import { DiagramPage } from './diagram-page';
import { CSS_ACTIVE, CSS_FIRED, cssChanges, emptyMapping, Mapping, mappingOf } from './highlight';
import { report } from './status-line';
import { fitStatesAction } from './viewport';

export { CSS_ACTIVE, CSS_FIRED };
/** How long a fired transition stays highlighted. */
const FLASH_MS = 400;
/** The least time between two drawings of a page in a board's tile (see schedule()). */
const TILE_FRAME_MS = 50;
/** How many transitions the side panel lists. */
const LISTED = 50;
/** The delays kept for window.kse.monitor.delays() (a long match at 10x takes far more transitions). */
const KEPT_DELAYS = 200_000;

export interface MonitorParameters {
    /** The kse-match monitor's port on 127.0.0.1 ('' when the match is named by its pid). */
    port: string;
    /** The kse-match monitor's key (its token; '' when the match is named by its pid). */
    key: string;
    /** The match's process id, as the picker names it (the relay looks its port and key up), or ''. */
    match: string;
    /** The robot watched, e.g. home-1. */
    robot: string;
    /** The relay's address on this page's server. */
    socketUrl: string;
    /** Shown in a tile of the monitor's board (monitor-hub.ts): no toolbar. */
    tile: boolean;
}

/** The monitor's parameters when the page was opened to watch a match (&monitor=P&key=K or &match=PID), else undefined. */
export function readMonitorParameters(location: Location): MonitorParameters | undefined {
    const query = new URLSearchParams(location.search);
    const port = query.get('monitor');
    const match = query.get('match') ?? '';
    if (port === null && match === '') {
        return undefined;
    }
    const key = query.get('key') ?? '';
    const robot = query.get('robot') ?? '';
    const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
    // a match picked by pid: the page never holds its key
    const source = match ? `&match=${encodeURIComponent(match)}` : `&port=${encodeURIComponent(port ?? '')}&key=${encodeURIComponent(key)}`;
    const socketUrl =
        `${scheme}//${location.host}/monitor?token=${encodeURIComponent(query.get('token') ?? '')}` + `${source}&robots=${encodeURIComponent(robot)}`;
    return { port: match ? '' : (port ?? ''), key: match ? '' : key, match, robot, socketUrl, tile: query.get('tile') === '1' };
}

/** The match as the messages name it. */
function matchName(parameters: MonitorParameters): string {
    return parameters.match ? `match ${parameters.match}` : `the match on 127.0.0.1:${parameters.port}`;
}

export type MonitorState = 'connecting' | 'live' | 'ended' | 'error';

export interface MonitorHandle {
    /** connecting, live, ended or error (also body[data-kse-monitor]). */
    state(): MonitorState;
    /** The ids of the states drawn as active. */
    active(): string[];
    /** How many transitions of the robot the page received. */
    taken(): number;
    /** The match time the page started following the robot (its first configuration), NaN before. */
    since(): number;
    /** The delay of the last transition drawn: from the engine taking it (the record's wall) to the diagram showing it, in ms. */
    readonly lastDelayMs: number;
    /** Every transition's delay until drawn, in ms, in the order drawn (not while paused). */
    delays(): number[];
    /** Transitions received per second of wall time, from the first to the last. */
    eventsPerSecond(): number;
    /** The ids of the transitions that flashed at least once. */
    fired(): string[];
    /** Whether the drawing is paused. */
    paused(): boolean;
    pause(): void;
    resume(): void;
    /** Asks the match for the robot's blackboard; the answer shows in the panel and in blackboard(). */
    askBlackboard(): void;
    /** The last blackboard answer ([] for a refusal), undefined before one. */
    blackboard(): BlackboardEntry[] | undefined;
}

export interface BlackboardEntry {
    topic: string;
    type: string;
    /** Seconds since it was published. */
    age: number;
    /** Its fields in protobuf's one-line text format. */
    text: string;
}

interface Listed {
    t: number;
    from: string;
    to: string;
    guard: string;
    expression: string;
}

// the runtime names' element ids (states by label, transitions by their index in the model): highlight.ts

/** The guard of a transition expression "guard / actions" (the whole text when it has no actions). */
function guardOf(expression: string): string {
    const slash = expression.indexOf('/');
    return (slash < 0 ? expression : expression.slice(0, slash)).trim();
}

function now(): number {
    return performance.timeOrigin + performance.now();
}

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text?: string): HTMLElementTagNameMap[K] {
    const made = document.createElement(tag);
    made.className = className;
    if (text !== undefined) {
        made.textContent = text;
    }
    return made;
}

/** Builds the monitor's panel beside the diagram. */
function createPanel(robot: string): {
    panel: HTMLElement;
    state: HTMLElement;
    clock: HTMLElement;
    game: HTMLElement;
    score: HTMLElement;
    pause: HTMLButtonElement;
    warning: HTMLElement;
    list: HTMLOListElement;
    count: HTMLElement;
    ask: HTMLButtonElement;
    blackboard: HTMLElement;
} {
    const panel = element('aside', 'kse-monitor');
    panel.id = 'kse-monitor';
    panel.setAttribute('aria-label', 'Live monitor');
    const head = element('div', 'kse-monitor-head');
    const title = element('div', 'kse-monitor-title');
    title.append(element('span', 'kse-monitor-robot', robot || '(no robot)'));
    const state = element('span', 'kse-monitor-state', 'connecting');
    title.append(state);
    const pause = element('button', 'kse-monitor-pause', 'Pause');
    pause.type = 'button';
    pause.dataset.action = 'monitor-pause';
    pause.title = 'Freeze the drawing (the monitor keeps listening); Resume jumps to the live configuration';
    title.append(pause);
    const ask = element('button', 'kse-monitor-ask', 'Blackboard');
    ask.type = 'button';
    ask.dataset.action = 'monitor-blackboard';
    ask.title = "Show the State messages the robot's blackboard holds now (topic, type, age, fields)";
    title.append(ask);
    head.append(title);
    const facts = element('div', 'kse-monitor-facts');
    const clock = element('span', 'kse-monitor-clock', 't = –');
    const game = element('span', 'kse-monitor-game', '–');
    const score = element('span', 'kse-monitor-score', '– : –');
    facts.append(clock, game, score);
    head.append(facts);
    const warning = element('div', 'kse-monitor-warning');
    warning.hidden = true;
    const caption = element('div', 'kse-monitor-caption');
    caption.append(document.createTextNode(`Last ${LISTED} transitions`));
    const count = element('span', 'kse-monitor-count', '0 taken');
    caption.append(count);
    const list = element('ol', 'kse-monitor-list');
    list.reversed = true;
    const blackboard = element('section', 'kse-monitor-blackboard');
    blackboard.hidden = true;
    panel.append(head, warning, blackboard, caption, list);
    return { panel, state, clock, game, score, pause, warning, list, count, ask, blackboard };
}

/** Watches the robot once the diagram is shown. */
export function installMonitor(page: DiagramPage, ready: Promise<void>, parameters: MonitorParameters): MonitorHandle {
    const { dispatcher, editorContext } = page;
    document.body.classList.add('kse-monitoring');
    if (parameters.tile) {
        document.body.classList.add('kse-monitor-tile');
    }
    const ui = createPanel(parameters.robot);
    document.getElementById('kse-diagram')?.append(ui.panel);

    let state: MonitorState = 'connecting';
    let mapping: Mapping = emptyMapping();
    // what the engine says now
    let activeLabels: string[] = [];
    const firedAt = new Map<string, number>();
    const listed: Listed[] = [];
    let takenCount = 0;
    // a watcher that joins a running match sees its transitions from then on
    let since = NaN;
    let firstReceived = 0;
    let lastReceived = 0;
    let header = { t: NaN, game: '', score: '' };
    let result = '';
    // transitions received since the last frame drawn: their engine times (wall, ms since the epoch)
    let undrawn: number[] = [];
    // what the diagram shows
    let drawnActive = new Set<string>();
    let drawnFired = new Set<string>();
    const everFired = new Set<string>();
    const delays: number[] = [];
    let lastDelayMs = NaN;
    let paused = false;
    let frameRequested = false;
    let drawing: Promise<void> = Promise.resolve();
    let listChanged = false;

    function setState(next: MonitorState, message?: string, severity = 'INFO'): void {
        state = next;
        document.body.dataset.kseMonitor = next;
        ui.state.textContent = next;
        ui.state.dataset.state = next;
        if (message) {
            report({ kind: 'connection', severity, message });
        }
    }

    function warn(message: string): void {
        ui.warning.hidden = false;
        ui.warning.textContent = message;
        report({ kind: 'status', severity: 'WARNING', message });
    }

    // A board shows up to ten of these pages at once, each redrawing its diagram as often as the
    // screen refreshes: on a small machine they fall behind together. A tile redraws at most every
    // TILE_FRAME_MS, which costs each transition that much delay at most and saves the rest.
    const frameMs = parameters.tile ? TILE_FRAME_MS : 0;
    let lastFrame = 0;
    function schedule(): void {
        if (!frameRequested && !paused) {
            frameRequested = true;
            const frame = (): void => {
                requestAnimationFrame(() => {
                    frameRequested = false;
                    lastFrame = performance.now();
                    drawing = drawing.then(draw);
                });
            };
            const wait = lastFrame + frameMs - performance.now();
            if (wait > 0) {
                setTimeout(frame, wait);
            } else {
                frame();
            }
        }
    }

    /** Brings the diagram and the panel up to what the engine said last: one update of the diagram at most. */
    async function draw(): Promise<void> {
        if (paused) {
            return;
        }
        const at = now();
        const active = new Set<string>();
        for (const label of activeLabels) {
            const id = mapping.stateByLabel.get(label);
            if (id) {
                active.add(id);
            }
        }
        const fired = new Set<string>();
        for (const [id, time] of firedAt) {
            if (at - time < FLASH_MS) {
                fired.add(id);
            } else {
                firedAt.delete(id);
            }
        }
        const actions: ModifyCSSFeedbackAction[] = [...cssChanges(drawnActive, active, CSS_ACTIVE), ...cssChanges(drawnFired, fired, CSS_FIRED)];
        const waiting = undrawn;
        undrawn = [];
        if (actions.length > 0) {
            await dispatcher.dispatchAll(actions);
        }
        drawnActive = active;
        drawnFired = fired;
        fired.forEach(id => everFired.add(id));
        const drawn = now();
        for (const wall of waiting) {
            lastDelayMs = drawn - wall;
            if (delays.length < KEPT_DELAYS) {
                delays.push(lastDelayMs);
            }
        }
        drawPanel();
        if (firedAt.size > 0) {
            schedule(); // the flashes end
        }
    }

    function drawPanel(): void {
        ui.clock.textContent = Number.isNaN(header.t) ? 't = –' : `t = ${header.t.toFixed(1)} s`;
        ui.game.textContent = result || header.game || '–';
        ui.score.textContent = header.score || '– : –';
        ui.count.textContent = `${takenCount} taken`;
        if (!listChanged) {
            return;
        }
        listChanged = false;
        const rows = listed
            .slice()
            .reverse()
            .map(entry => {
                const row = element('li', 'kse-monitor-row');
                row.append(element('span', 'kse-monitor-time', entry.t.toFixed(2)));
                row.append(element('span', 'kse-monitor-move', `${entry.from} → ${entry.to}`));
                const guard = element('span', 'kse-monitor-guard', entry.guard);
                guard.title = entry.expression;
                row.append(guard);
                return row;
            });
        ui.list.replaceChildren(...rows);
    }

    function handle(record: Record<string, unknown>): void {
        switch (record.type) {
            case 'match':
                onMatch(record);
                break;
            case 'active':
                if (record.robot === parameters.robot && Array.isArray(record.active)) {
                    activeLabels = record.active.filter((label): label is string => typeof label === 'string');
                    if (Number.isNaN(since) && typeof record.t === 'number') {
                        since = record.t;
                    }
                }
                break;
            case 'taken':
                if (record.robot === parameters.robot) {
                    onTaken(record);
                }
                break;
            case 'frame':
                header = {
                    t: typeof record.t === 'number' ? record.t : NaN,
                    game: typeof record.state === 'string' ? record.state : '',
                    score: Array.isArray(record.score) ? record.score.join(' : ') : ''
                };
                break;
            case 'result':
                result = `${typeof record.state === 'string' ? record.state : 'ended'}`;
                if (Array.isArray(record.score)) {
                    header.score = record.score.join(' : ');
                }
                break;
            case 'blackboard':
                if (record.robot === parameters.robot) {
                    showBlackboard(record);
                }
                break;
            case 'aborted':
                result = 'aborted';
                warn(`The match was aborted: ${String(record.reason ?? '')}${record.detail ? ` (${String(record.detail)})` : ''}`);
                break;
            default:
                break;
        }
    }

    function onMatch(record: Record<string, unknown>): void {
        const robots = Array.isArray(record.robots) ? (record.robots as Array<Record<string, unknown>>) : [];
        const robot = robots.find(entry => entry.id === parameters.robot);
        if (!robot) {
            const known = robots.map(entry => String(entry.id)).join(', ');
            setState('error', `Robot ${parameters.robot || '(none given: &robot=…)'} does not play in this match (its robots: ${known || 'none'}).`, 'ERROR');
            socket?.close(1000);
            return;
        }
        setState('live', `Watching ${parameters.robot} (${String(robot.behaviour ?? '')}) of ${matchName(parameters)}`);
        if (robot.states !== mapping.states || robot.transitions !== mapping.transitions.size) {
            warn(
                `${parameters.robot} runs ${String(robot.behaviour ?? 'a statechart')} with ${String(robot.states)} states and ` +
                    `${String(robot.transitions)} transitions, but this diagram has ${mapping.states} and ${mapping.transitions.size}: ` +
                    'what is highlighted may be wrong (open the model the match was built from).'
            );
        }
    }

    function onTaken(record: Record<string, unknown>): void {
        takenCount++;
        const id = `//@transitions.${String(record.tr)}`;
        // the diagram's text, else the one the robot's generated code carries (a model drawn from another version)
        const expression = mapping.expressionOf.get(id) ?? (typeof record.expression === 'string' ? record.expression : '');
        if (mapping.transitions.has(id)) {
            firedAt.set(id, now());
        }
        if (typeof record.wall === 'number') {
            undrawn.push(record.wall);
        }
        listed.push({
            t: typeof record.t === 'number' ? record.t : NaN,
            from: String(record.from ?? '?'),
            to: String(record.to ?? '?'),
            guard: guardOf(expression),
            expression
        });
        if (listed.length > LISTED) {
            listed.splice(0, listed.length - LISTED);
        }
        listChanged = true;
    }

    // the robot's State messages as the match answered: a table under the panel's head
    let blackboard: BlackboardEntry[] | undefined;
    function showBlackboard(record: Record<string, unknown>): void {
        const heading = element('div', 'kse-monitor-caption', typeof record.t === 'number' ? `Blackboard at t = ${record.t.toFixed(2)} s` : 'Blackboard');
        const close = element('button', 'kse-monitor-close', '×');
        close.type = 'button';
        close.title = 'Hide the blackboard';
        close.addEventListener('click', () => (ui.blackboard.hidden = true));
        heading.append(close);
        if (typeof record.error === 'string') {
            blackboard = [];
            ui.blackboard.replaceChildren(heading, element('p', 'kse-monitor-none', `No blackboard: ${record.error}.`));
            ui.blackboard.hidden = false;
            return;
        }
        const states = Array.isArray(record.states) ? (record.states as Array<Record<string, unknown>>) : [];
        blackboard = states.map(entry => ({
            topic: String(entry.topic ?? ''),
            type: String(entry.type ?? ''),
            age: typeof entry.age === 'number' ? entry.age : NaN,
            text: String(entry.text ?? '') + (entry.cut === true ? ' …' : '')
        }));
        // each message its own block: a head (topic, type, age), then its fields, which may be long
        const rows = blackboard.map(entry => {
            const row = element('div', 'kse-monitor-message');
            const head = element('div', 'kse-monitor-message-head');
            head.append(element('span', 'kse-monitor-topic', entry.topic), element('span', 'kse-monitor-type', entry.type));
            head.append(element('span', 'kse-monitor-age', Number.isNaN(entry.age) ? '' : `${entry.age.toFixed(2)} s ago`));
            row.append(head, element('div', 'kse-monitor-fields', entry.text));
            return row;
        });
        const table = element('div', 'kse-monitor-messages');
        table.append(...rows);
        ui.blackboard.replaceChildren(heading, rows.length > 0 ? table : element('p', 'kse-monitor-none', 'It holds no State message yet.'));
        ui.blackboard.hidden = false;
    }

    function askBlackboard(): void {
        if (socket?.readyState === WebSocket.OPEN && parameters.robot) {
            socket.send(JSON.stringify({ type: 'blackboard', robot: parameters.robot }));
        }
    }
    ui.ask.addEventListener('click', askBlackboard);

    function pause(): void {
        paused = true;
        ui.pause.textContent = 'Resume';
        ui.pause.setAttribute('aria-pressed', 'true');
        document.body.dataset.kseMonitorPaused = 'true';
    }

    function resume(): void {
        paused = false;
        ui.pause.textContent = 'Pause';
        ui.pause.setAttribute('aria-pressed', 'false');
        delete document.body.dataset.kseMonitorPaused;
        // what was received while paused is not a delay of drawing
        undrawn = [];
        schedule();
    }

    ui.pause.addEventListener('click', () => (paused ? resume() : pause()));

    // a model shown anew (the file changed on disk) has lost the classes: draw everything again
    editorContext.onModelRootChanged(root => {
        if (root.type === 'NONE' || root.id === 'EMPTY') {
            return;
        }
        mapping = mappingOf(root);
        drawnActive = new Set();
        drawnFired = new Set();
        schedule();
    });

    let socket: WebSocket | undefined;
    setState('connecting');
    void ready.then(() => {
        mapping = mappingOf(editorContext.modelRoot);
        if (parameters.tile) {
            // a tile of the board is small: the whole chart, or states out of view would not be drawn at all
            void dispatcher.dispatch(fitStatesAction(editorContext.modelRoot, 1, false));
        }
        if (!parameters.robot) {
            setState('error', 'No robot given: open the page with &robot=<id> (e.g. home-1).', 'ERROR');
            return;
        }
        report({ kind: 'connection', severity: 'INFO', message: `Connecting to ${matchName(parameters)}…` });
        socket = new WebSocket(parameters.socketUrl);
        socket.addEventListener('message', event => {
            const received = now();
            if (firstReceived === 0) {
                firstReceived = received;
            }
            lastReceived = received;
            for (const line of String(event.data).split('\n')) {
                if (line.length === 0) {
                    continue;
                }
                try {
                    const record = JSON.parse(line) as unknown;
                    if (record && typeof record === 'object' && !Array.isArray(record)) {
                        handle(record as Record<string, unknown>);
                    }
                } catch {
                    warn('The monitor received a line that is not JSON: ' + line.slice(0, 80));
                }
            }
            schedule();
        });
        socket.addEventListener('close', event => {
            if (state === 'error') {
                return;
            }
            if (event.code === 1000) {
                // the last records are drawn before the page says the match ended (now: a tile's
                // next frame may be up to TILE_FRAME_MS away)
                if (!paused) {
                    drawing = drawing.then(draw);
                }
                void (paused ? Promise.resolve() : new Promise<void>(resolve => requestAnimationFrame(() => resolve())).then(() => drawing)).then(() =>
                    setState('ended', `The match ended (${result || 'connection closed'}).`)
                );
                return;
            }
            const reason = event.reason ? `: ${event.reason}` : '';
            setState('error', `The monitor's connection closed (${event.code}${reason}).`, 'ERROR');
        });
    });

    return {
        state: () => state,
        active: () => [...drawnActive],
        taken: () => takenCount,
        since: () => since,
        get lastDelayMs() {
            return lastDelayMs;
        },
        delays: () => delays.slice(),
        eventsPerSecond: () => (lastReceived > firstReceived ? takenCount / ((lastReceived - firstReceived) / 1000) : 0),
        fired: () => [...everFired],
        paused: () => paused,
        pause,
        resume,
        askBlackboard,
        blackboard: () => blackboard?.slice()
    };
}
