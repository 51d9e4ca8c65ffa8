/*
 * The live monitor's picker and board: pages without a diagram of their own.
 *
 * - Picker, `?token=T&monitor=pick` (or `&monitor` without a model): the matches running with
 *   `kse-match --monitor` on this machine (the server's /matches, from the discovery folder; never
 *   their keys), each with its robots and their behaviours. Choosing robots opens them.
 * - Board, `?token=T&monitor=board&match=PID&robots=home-1,away-2`: the robots side by side, each
 *   in a frame that runs the single-robot monitor page (monitor.ts) on its behaviour's model,
 *   `<behaviour>.stct` of the served folder; a robot whose model is not there gets a message
 *   instead. Frames keep each robot's GLSP client, diagram and list apart, the simplest way to show
 *   several statecharts at once (one page is one GLSP diagram), and a slow robot cannot hold up another.
 *
 * The pages name a match by its process id: the server's relay (/monitor?match=PID) looks its port
 * and key up, so the key never reaches a page.
 *
 * `body[data-kse-monitor-hub]` says loading, picking, board or error; `window.kse.monitorHub` lets
 * tests and the benchmark read what is listed and reach the frames.
 */
import { MonitorHandle } from './monitor';
import './monitor-hub.css';

export interface HubParameters {
    token: string;
    view: 'pick' | 'board';
    /** The match's process id (board). */
    match: string;
    /** The robots shown (board). */
    robots: string[];
}

/** The hub's parameters when the page was opened as picker or board, else undefined. */
export function readHubParameters(location: Location): HubParameters | undefined {
    const query = new URLSearchParams(location.search);
    const monitor = query.get('monitor');
    if (monitor === null) {
        return undefined;
    }
    const token = query.get('token') ?? '';
    if (monitor === 'board') {
        const robots = (query.get('robots') ?? '').split(',').filter(robot => robot.length > 0);
        return { token, view: 'board', match: query.get('match') ?? '', robots };
    }
    // a monitor without a model to draw cannot watch a robot: show what there is to watch
    if (monitor === 'pick' || !query.get('model')) {
        return { token, view: 'pick', match: '', robots: [] };
    }
    return undefined;
}

export interface HubRobot {
    id: string;
    team: string;
    number: number;
    behaviour: string;
}

export interface HubMatch {
    pid: number;
    seed: number;
    started: number;
    robots: HubRobot[];
}

export interface HubHandle {
    /** loading, picking, board or error (also body[data-kse-monitor-hub]). */
    state(): string;
    /** The matches listed (picker) or the one shown (board). */
    matches(): HubMatch[];
    /** The board's robots with the monitor of their frame (undefined while it loads, or when the model is missing). */
    tiles(): Array<{ robot: string; model: string; missing: boolean; monitor: MonitorHandle | undefined }>;
    /** Reads /matches again (the picker also does every 2 s). */
    refresh(): Promise<void>;
}

const REFRESH_MS = 2000;

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text?: string): HTMLElementTagNameMap[K] {
    const made = document.createElement(tag);
    made.className = className;
    if (text !== undefined) {
        made.textContent = text;
    }
    return made;
}

/** The page's own address with another query. */
function address(query: Record<string, string>): string {
    return `${window.location.pathname}?${new URLSearchParams(query).toString()}`;
}

async function fetchJson<T>(path: string, token: string): Promise<T> {
    const response = await fetch(`${path}?token=${encodeURIComponent(token)}`, { cache: 'no-store' });
    if (!response.ok) {
        throw new Error(`${path} answered ${response.status}${response.status === 403 ? ' (the page needs the token kse serve printed)' : ''}`);
    }
    return (await response.json()) as T;
}

function describe(match: HubMatch): string {
    const started = new Date(match.started);
    return `Match ${match.pid} · seed ${match.seed} · started ${started.toLocaleTimeString()}`;
}

/** The single-robot monitor page of a robot of a running match. */
export function robotPageAddress(token: string, match: string | number, robot: string, model: string, tile = false): string {
    const query: Record<string, string> = { token, model, match: String(match), robot };
    if (tile) {
        query.tile = '1';
    }
    return address(query);
}

/** Shows the picker or the board in the page; it has no diagram of its own. */
export function installMonitorHub(parameters: HubParameters): HubHandle {
    document.body.classList.add('kse-monitor-hub');
    const host = document.getElementById('kse-diagram') ?? document.body;
    const root = element('div', 'kse-hub');
    root.id = 'kse-monitor-hub';
    host.append(root);
    let state = 'loading';
    let matches: HubMatch[] = [];
    let models = new Set<string>();
    const tiles: Array<{ robot: string; model: string; missing: boolean; frame?: HTMLIFrameElement }> = [];

    function setState(next: string): void {
        state = next;
        document.body.dataset.kseMonitorHub = next;
    }
    setState('loading');

    function fail(message: string): void {
        setState('error');
        const box = element('div', 'kse-hub-error', message);
        box.setAttribute('role', 'alert');
        root.replaceChildren(box);
    }

    async function load(): Promise<void> {
        const [listed, files] = await Promise.all([fetchJson<HubMatch[]>('/matches', parameters.token), fetchJson<string[]>('/models', parameters.token)]);
        matches = listed;
        models = new Set(files);
    }

    /** The model a robot's behaviour is drawn from: <behaviour>.stct at the top of the served folder, else anywhere in it. */
    function modelOf(behaviour: string): string | undefined {
        const file = `${behaviour}.stct`;
        if (models.has(file)) {
            return file;
        }
        return [...models].sort().find(model => model.endsWith(`/${file}`));
    }

    function drawPicker(): void {
        const title = element('h1', 'kse-hub-title', 'Watch a running match');
        const rows: HTMLElement[] = [title];
        if (matches.length === 0) {
            const empty = element('p', 'kse-hub-empty');
            empty.dataset.empty = 'true';
            empty.append(
                'No match is running with a monitor on this machine. Start one with ',
                element('code', '', 'kse-match --monitor --speed 1'),
                ' (it appears here within 2 s).'
            );
            rows.push(empty);
        }
        for (const match of matches) {
            const section = element('section', 'kse-hub-match');
            section.dataset.pid = String(match.pid);
            section.append(element('h2', 'kse-hub-match-title', describe(match)));
            // a column a team, home first
            const list = element('div', 'kse-hub-teams');
            const teams = new Map<string, HTMLUListElement>();
            for (const robot of match.robots) {
                let team = teams.get(robot.team);
                if (!team) {
                    team = element('ul', 'kse-hub-robots');
                    team.dataset.team = robot.team;
                    team.setAttribute('aria-label', robot.team);
                    teams.set(robot.team, team);
                    list.append(team);
                }
                const model = modelOf(robot.behaviour);
                const item = element('li', 'kse-hub-robot');
                item.dataset.robot = robot.id;
                const box = element('input', 'kse-hub-check');
                box.type = 'checkbox';
                box.value = robot.id;
                box.disabled = !model;
                box.setAttribute('aria-label', `${robot.id} ${robot.behaviour}`);
                const name = model
                    ? Object.assign(element('a', 'kse-hub-robot-link', robot.id), { href: robotPageAddress(parameters.token, match.pid, robot.id, model) })
                    : element('span', 'kse-hub-robot-name', robot.id);
                item.append(box, name, element('span', 'kse-hub-behaviour', robot.behaviour));
                if (!model) {
                    item.append(element('span', 'kse-hub-missing', `no ${robot.behaviour}.stct in the served folder`));
                }
                team.append(item);
            }
            const open = element('button', 'kse-hub-open', 'Watch the chosen robots side by side');
            open.type = 'button';
            open.dataset.action = 'open-board';
            open.addEventListener('click', () => {
                const chosen = [...list.querySelectorAll<HTMLInputElement>('input:checked')].map(box => box.value);
                const robots = chosen.length > 0 ? chosen : match.robots.filter(robot => modelOf(robot.behaviour)).map(robot => robot.id);
                window.location.assign(address({ token: parameters.token, monitor: 'board', match: String(match.pid), robots: robots.join(',') }));
            });
            const all = element('button', 'kse-hub-all', 'Choose all');
            all.type = 'button';
            all.addEventListener('click', () => list.querySelectorAll<HTMLInputElement>('input:not(:disabled)').forEach(box => (box.checked = true)));
            section.append(list, all, open);
            rows.push(section);
        }
        // keep what the user ticked across refreshes
        const ticked = new Set([...root.querySelectorAll<HTMLInputElement>('input:checked')].map(box => `${box.closest('section')?.dataset.pid}/${box.value}`));
        root.replaceChildren(...rows);
        root.querySelectorAll<HTMLInputElement>('input.kse-hub-check').forEach(box => {
            box.checked = ticked.has(`${box.closest('section')?.dataset.pid}/${box.value}`);
        });
        setState('picking');
    }

    async function refreshPicker(): Promise<void> {
        try {
            await load();
            drawPicker();
        } catch (error) {
            fail(`Cannot list the running matches: ${error instanceof Error ? error.message : String(error)}`);
        }
    }

    async function showBoard(): Promise<void> {
        document.title = `Match ${parameters.match} – KSE monitor`;
        try {
            await load();
        } catch (error) {
            fail(`Cannot read the running matches: ${error instanceof Error ? error.message : String(error)}`);
            return;
        }
        const match = matches.find(entry => String(entry.pid) === parameters.match);
        if (!match) {
            fail(`No running match ${parameters.match || '(none given: &match=PID)'}: it ended, or it was started without --monitor.`);
            return;
        }
        matches = [match];
        const wanted = parameters.robots.length > 0 ? parameters.robots : match.robots.map(robot => robot.id);
        const board = element('div', 'kse-board');
        board.style.setProperty('--kse-board-columns', String(Math.ceil(Math.sqrt(wanted.length))));
        const head = element('div', 'kse-board-head');
        head.append(element('span', 'kse-board-title', describe(match)));
        const back = Object.assign(element('a', 'kse-board-back', 'Other matches and robots'), { href: address({ token: parameters.token, monitor: 'pick' }) });
        // one button for the whole board: each tile also has its own
        const pauseAll = element('button', 'kse-board-pause', 'Pause all');
        pauseAll.type = 'button';
        pauseAll.dataset.action = 'board-pause';
        pauseAll.title = 'Freeze every robot\'s drawing (they keep listening); Resume all jumps each to its live configuration';
        pauseAll.addEventListener('click', () => {
            const monitors = handle.tiles().flatMap(tile => (tile.monitor ? [tile.monitor] : []));
            const pausing = !monitors.every(monitor => monitor.paused());
            monitors.forEach(monitor => (pausing ? monitor.pause() : monitor.resume()));
            pauseAll.textContent = pausing ? 'Resume all' : 'Pause all';
            pauseAll.setAttribute('aria-pressed', String(pausing));
        });
        head.append(pauseAll, back);
        for (const id of wanted) {
            const robot = match.robots.find(entry => entry.id === id);
            const tile = element('div', 'kse-board-tile');
            tile.dataset.robot = id;
            const model = robot ? modelOf(robot.behaviour) : undefined;
            if (!robot || !model) {
                const message = robot
                    ? `${id} runs ${robot.behaviour}, and the served folder has no ${robot.behaviour}.stct to draw it with: serve the folder of the project that built this kse-match.`
                    : `${id} does not play in match ${match.pid} (its robots: ${match.robots.map(entry => entry.id).join(', ')}).`;
                const box = element('div', 'kse-board-missing', message);
                box.setAttribute('role', 'alert');
                tile.append(element('div', 'kse-board-tile-title', robot ? `${id} · ${robot.behaviour}` : id), box);
                tiles.push({ robot: id, model: model ?? '', missing: true });
            } else {
                const frame = element('iframe', 'kse-board-frame');
                frame.title = `${id} (${robot.behaviour})`;
                frame.src = robotPageAddress(parameters.token, match.pid, id, model, true);
                tile.append(frame);
                tiles.push({ robot: id, model, missing: false, frame });
            }
            board.append(tile);
        }
        root.replaceChildren(head, board);
        setState('board');
    }

    let timer: number | undefined;
    if (parameters.view === 'board') {
        void showBoard();
    } else {
        document.title = 'Running matches – KSE monitor';
        void refreshPicker();
        timer = window.setInterval(() => void refreshPicker(), REFRESH_MS);
    }
    window.addEventListener('pagehide', () => window.clearInterval(timer));

    const handle: HubHandle = {
        state: () => state,
        matches: () => matches,
        tiles: () =>
            tiles.map(tile => ({
                robot: tile.robot,
                model: tile.model,
                missing: tile.missing,
                monitor: (tile.frame?.contentWindow as (Window & { kse?: { monitor?: MonitorHandle } }) | null | undefined)?.kse?.monitor
            })),
        refresh: () => (parameters.view === 'board' ? Promise.resolve() : refreshPicker())
    };
    return handle;
}
