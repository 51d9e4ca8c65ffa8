/*
 * Reads a match log (docs/match-log.md, JSON lines) as it arrives into compact arrays for the
 * replay (replay.ts): per frame its time, game state, score and ball; per frame and robot the pose,
 * motion and penalty, an index of its active configuration (configurations repeat: each distinct
 * one is kept once) and its transitions, as indices into one table of names. A 10-minute
 * 5-against-5 log (~37 MB, 6,000 frames, 60,000 robot frames) then takes a few MB, and drawing a
 * time is reading a few numbers.
 *
 * The log's problems are results, never exceptions: a file that is not a match log or has another
 * version is an error with a message; a last line cut short, or a log without `result`, a notice.
 */

export interface MatchHeader {
    version: number;
    seed: number;
    field: { length: number; width: number; goalWidth: number };
    halfSeconds: number;
    teams: { number: number; name: string; players: { id: string; number: number; behaviour: string }[] }[];
}

export interface LogEvent {
    t: number;
    event: string;
    team?: number;
    robot?: string;
    detail?: string;
}

export interface RobotInfo {
    id: string;
    team: number;
    number: number;
    behaviour: string;
}

/** A growable Float64Array / Int32Array. */
class Column<T extends Float64Array | Int32Array | Float32Array | Uint8Array> {
    length = 0;
    constructor(
        public data: T,
        private readonly make: (size: number) => T
    ) {}
    push(value: number): void {
        if (this.length === this.data.length) {
            const bigger = this.make(Math.max(1024, this.data.length * 2));
            bigger.set(this.data);
            this.data = bigger;
        }
        this.data[this.length++] = value;
    }
}

const f64 = (n: number) => new Float64Array(n);
const f32 = (n: number) => new Float32Array(n);
const i32 = (n: number) => new Int32Array(n);
const u8 = (n: number) => new Uint8Array(n);

export const MOTIONS = ['stand', 'walk', 'kick', 'dive', 'fallen', 'getting-up', 'pose'];

export class MatchLog {
    header: MatchHeader | undefined;
    robots: RobotInfo[] = [];
    private robotIndex = new Map<string, number>();
    readonly events: LogEvent[] = [];
    /** The last line: `result` or `aborted`, when the log has one. */
    end: { type: 'result' | 'aborted'; t: number; record: Record<string, unknown> } | undefined;

    // per frame
    private times = new Column(f64(0), f64);
    private ball = new Column(f32(0), f32); // x, y
    private gameState = new Column(u8(0), u8); // index into gameStates
    private scores = new Column(i32(0), i32); // home, away
    readonly gameStates: string[] = [];

    // per frame and robot (frame * robots + robot)
    private poses = new Column(f32(0), f32); // x, y, theta
    private motion = new Column(u8(0), u8);
    private penalty = new Column(u8(0), u8);
    private present = new Column(u8(0), u8);
    private active = new Column(i32(0), i32); // index into configurations, -1 none
    private takenFrom = new Column(i32(0), i32); // start in takenNames (the end is the next robot frame's start)
    private takenNames = new Column(i32(0), i32);

    /** The distinct active configurations, each a list of indices into names. */
    readonly configurations: number[][] = [];
    private configurationIndex = new Map<string, number>();
    /** The engine names of states and transitions the log mentions. */
    readonly names: string[] = [];
    private nameIndex = new Map<string, number>();

    /** Lines read; a line that was not JSON in the middle of the log (counted, skipped). */
    lines = 0;
    badLines: number[] = [];
    /** Why the log cannot be replayed (then nothing else counts). */
    error: string | undefined;
    /** The last line was cut short (the writer stopped in the middle of a line). */
    truncatedLine = false;

    get frameCount(): number {
        return this.times.length;
    }

    get robotCount(): number {
        return this.robots.length;
    }

    time(frame: number): number {
        return this.times.data[frame];
    }

    /** The last frame at or before t (0 before the first). */
    frameAt(t: number): number {
        const times = this.times.data;
        let low = 0;
        let high = this.times.length - 1;
        if (high < 0) {
            return 0;
        }
        while (low < high) {
            const middle = (low + high + 1) >> 1;
            if (times[middle] <= t + 1e-6) {
                low = middle;
            } else {
                high = middle - 1;
            }
        }
        return low;
    }

    ballAt(frame: number): [number, number] {
        return [this.ball.data[frame * 2], this.ball.data[frame * 2 + 1]];
    }

    gameStateAt(frame: number): string {
        return this.gameStates[this.gameState.data[frame]] ?? '';
    }

    scoreAt(frame: number): [number, number] {
        return [this.scores.data[frame * 2], this.scores.data[frame * 2 + 1]];
    }

    /** Whether the robot is in the frame at all (it may leave a log of another build). */
    isPresent(frame: number, robot: number): boolean {
        return this.present.data[frame * this.robots.length + robot] === 1;
    }

    poseAt(frame: number, robot: number): [number, number, number] {
        const at = (frame * this.robots.length + robot) * 3;
        const data = this.poses.data;
        return [data[at], data[at + 1], data[at + 2]];
    }

    /** The pose array itself and where a robot frame's pose starts (the drawing of paths reads it in bulk). */
    poseData(): Float32Array {
        return this.poses.data;
    }

    motionAt(frame: number, robot: number): string {
        return MOTIONS[this.motion.data[frame * this.robots.length + robot]] ?? '';
    }

    penaltyAt(frame: number, robot: number): number {
        return this.penalty.data[frame * this.robots.length + robot];
    }

    activeAt(frame: number, robot: number): string[] {
        const index = this.active.data[frame * this.robots.length + robot];
        return index < 0 ? [] : this.configurations[index].map(name => this.names[name]);
    }

    takenAt(frame: number, robot: number): string[] {
        const at = frame * this.robots.length + robot;
        const from = this.takenFrom.data[at];
        const to = at + 1 < this.takenFrom.length ? this.takenFrom.data[at + 1] : this.takenNames.length;
        const out: string[] = [];
        for (let i = from; i < to; i++) {
            out.push(this.names[this.takenNames.data[i]]);
        }
        return out;
    }

    robotIndexOf(id: string): number {
        return this.robotIndex.get(id) ?? -1;
    }

    private intern(name: string): number {
        let index = this.nameIndex.get(name);
        if (index === undefined) {
            index = this.names.length;
            this.names.push(name);
            this.nameIndex.set(name, index);
        }
        return index;
    }

    private configuration(active: unknown): number {
        if (!Array.isArray(active)) {
            return -1;
        }
        const key = active.join('\n');
        let index = this.configurationIndex.get(key);
        if (index === undefined) {
            index = this.configurations.length;
            this.configurations.push(active.map(name => this.intern(String(name))));
            this.configurationIndex.set(key, index);
        }
        return index;
    }

    /** Reads one whole line; `last` when no line follows (it may be cut short). */
    line(text: string, last: boolean): void {
        if (this.error !== undefined) {
            return;
        }
        const lineNumber = ++this.lines;
        if (text.trim().length === 0) {
            return;
        }
        let record: unknown;
        try {
            record = JSON.parse(text);
        } catch {
            if (lineNumber === 1) {
                this.error = `This is not a match log: its first line is not JSON (${preview(text)}).`;
            } else if (last) {
                this.truncatedLine = true;
            } else {
                this.badLines.push(lineNumber);
            }
            return;
        }
        if (record === null || typeof record !== 'object' || Array.isArray(record)) {
            if (lineNumber === 1) {
                this.error = `This is not a match log: its first line is not a JSON object (${preview(text)}).`;
            } else {
                this.badLines.push(lineNumber);
            }
            return;
        }
        const fields = record as Record<string, unknown>;
        if (lineNumber === 1) {
            this.onHeader(fields, text);
            return;
        }
        switch (fields.type) {
            case 'frame':
                this.onFrame(fields);
                break;
            case 'event':
                this.events.push({
                    t: num(fields.t),
                    event: String(fields.event ?? ''),
                    team: typeof fields.team === 'number' ? fields.team : undefined,
                    robot: typeof fields.robot === 'string' ? fields.robot : undefined,
                    detail: typeof fields.detail === 'string' ? fields.detail : undefined
                });
                break;
            case 'result':
            case 'aborted':
                this.end = { type: fields.type, t: num(fields.t), record: fields };
                break;
            default:
                break;
        }
    }

    private onHeader(fields: Record<string, unknown>, text: string): void {
        if (fields.type !== 'match') {
            this.error = `This is not a match log: its first line is not a "match" record (${preview(text)}).`;
            return;
        }
        if (fields.version !== 1) {
            this.error =
                `This match log has version ${JSON.stringify(fields.version ?? null)}; this page replays version 1 ` +
                '(docs/match-log.md). Make the log again with the kse-match of this KSE.';
            return;
        }
        const field = (fields.field ?? {}) as Record<string, unknown>;
        const teams = Array.isArray(fields.teams) ? (fields.teams as Array<Record<string, unknown>>) : [];
        this.header = {
            version: 1,
            seed: num(fields.seed),
            field: { length: num(field.length, 9), width: num(field.width, 6), goalWidth: num(field.goalWidth, 1.5) },
            halfSeconds: num(fields.halfSeconds),
            teams: teams.map(team => ({
                number: num(team.number),
                name: String(team.name ?? ''),
                players: (Array.isArray(team.players) ? (team.players as Array<Record<string, unknown>>) : []).map(player => ({
                    id: String(player.id ?? ''),
                    number: num(player.number),
                    behaviour: String(player.behaviour ?? '')
                }))
            }))
        };
        this.header.teams.forEach((team, teamIndex) =>
            team.players.forEach(player => {
                this.robotIndex.set(player.id, this.robots.length);
                this.robots.push({ id: player.id, team: teamIndex, number: player.number, behaviour: player.behaviour });
            })
        );
    }

    private onFrame(fields: Record<string, unknown>): void {
        if (!this.header) {
            return;
        }
        this.times.push(num(fields.t));
        const ball = Array.isArray(fields.ball) ? fields.ball : [];
        this.ball.push(num(ball[0]));
        this.ball.push(num(ball[1]));
        const state = String(fields.state ?? '');
        let stateIndex = this.gameStates.indexOf(state);
        if (stateIndex < 0) {
            stateIndex = this.gameStates.length;
            this.gameStates.push(state);
        }
        this.gameState.push(stateIndex);
        const score = Array.isArray(fields.score) ? fields.score : [];
        this.scores.push(num(score[0]));
        this.scores.push(num(score[1]));
        const robots = Array.isArray(fields.robots) ? (fields.robots as Array<Record<string, unknown>>) : [];
        const count = this.robots.length;
        // a robot frame for each robot of the header, in its order; one the frame leaves out is absent
        const slots: Array<Record<string, unknown> | undefined> = new Array<Record<string, unknown> | undefined>(count);
        robots.forEach((robot, position) => {
            const index = this.robots[position]?.id === robot.id ? position : this.robotIndex.get(String(robot.id));
            if (index !== undefined) {
                slots[index] = robot;
            }
        });
        for (let r = 0; r < count; r++) {
            const robot = slots[r];
            const pose = robot && Array.isArray(robot.pose) ? robot.pose : [];
            this.poses.push(num(pose[0]));
            this.poses.push(num(pose[1]));
            this.poses.push(num(pose[2]));
            this.present.push(robot ? 1 : 0);
            this.motion.push(Math.max(0, MOTIONS.indexOf(String(robot?.motion ?? ''))));
            this.penalty.push(num(robot?.penalty));
            this.active.push(this.configuration(robot?.active));
            this.takenFrom.push(this.takenNames.length);
            if (robot && Array.isArray(robot.taken)) {
                for (const name of robot.taken) {
                    this.takenNames.push(this.intern(String(name)));
                }
            }
        }
    }
}

function num(value: unknown, fallback = 0): number {
    return typeof value === 'number' && Number.isFinite(value) ? value : fallback;
}

function preview(text: string): string {
    const short = text.length > 60 ? text.slice(0, 60) + '…' : text;
    return JSON.stringify(short);
}

/**
 * Reads a log from a response body as it arrives, line by line (a chunk may end inside a line or
 * inside a character: TextDecoder's stream mode keeps the bytes). `progress` gets the bytes read.
 */
export async function readLog(body: ReadableStream<Uint8Array>, progress?: (bytes: number) => void): Promise<MatchLog> {
    const log = new MatchLog();
    const reader = body.getReader();
    const decoder = new TextDecoder('utf-8');
    let pending = '';
    let bytes = 0;
    for (;;) {
        const { done, value } = await reader.read();
        if (done) {
            break;
        }
        bytes += value.byteLength;
        pending += decoder.decode(value, { stream: true });
        let start = 0;
        for (let newline = pending.indexOf('\n', start); newline >= 0; newline = pending.indexOf('\n', start)) {
            log.line(pending.slice(start, newline), false);
            start = newline + 1;
        }
        pending = pending.slice(start);
        if (log.error !== undefined) {
            await reader.cancel();
            return log;
        }
        progress?.(bytes);
    }
    pending += decoder.decode();
    if (pending.length > 0) {
        // no newline after the last line: the writer stopped in the middle of it, or it is whole
        log.line(pending, true);
        if (!log.truncatedLine) {
            // a whole record, but kse-match ends every line: still a log cut short
            log.truncatedLine = log.end === undefined;
        }
    }
    if (log.lines === 0) {
        log.error = 'This match log is empty.';
    } else if (!log.header && log.error === undefined) {
        log.error = 'This is not a match log: it has no "match" record.';
    }
    return log;
}
