/*
 * The page's status line: shows what the client and the server report (StatusAction: progress
 * and state; MessageAction: e.g. an error the server met, like a model it cannot open).
 */
import { Action, IActionHandler, MessageAction, StatusAction } from '@eclipse-glsp/client';
import { injectable } from 'inversify';

export interface StatusEntry {
    kind: 'status' | 'message' | 'connection';
    severity: string;
    message: string;
    details?: string;
    time: number;
}

/** Everything reported so far, oldest first (for tests and for the page's host). */
export const statusHistory: StatusEntry[] = [];

type Listener = (entry: StatusEntry) => void;
const listeners: Listener[] = [];

export function onStatus(listener: Listener): void {
    listeners.push(listener);
}

let clearTimer: number | undefined;
let shownKind: StatusEntry['kind'] | undefined;

function element(): HTMLElement | null {
    return document.getElementById('kse-status');
}

function iconFor(severity: string): string {
    switch (severity) {
        case 'FATAL':
        case 'ERROR':
            return 'codicon-error';
        case 'WARNING':
            return 'codicon-warning';
        case 'INFO':
            return 'codicon-info';
        case 'OK':
            return 'codicon-pass';
        default:
            return '';
    }
}

function render(entry: StatusEntry | undefined): void {
    const line = element();
    if (!line) {
        return;
    }
    const icon = line.querySelector<HTMLElement>('.kse-status-icon');
    const text = line.querySelector<HTMLElement>('.kse-status-text');
    const severity = entry ? entry.severity : 'NONE';
    line.dataset.severity = severity.toLowerCase();
    if (icon) {
        icon.className = 'kse-status-icon codicon ' + iconFor(severity);
    }
    if (text) {
        text.textContent = entry ? entry.message : '';
        text.title = entry?.details ? entry.details : entry ? entry.message : '';
    }
}

/** Shows an entry; entries of severity NONE (or an empty message) clear what their kind showed. */
export function report(entry: Omit<StatusEntry, 'time'>, timeout?: number): void {
    const full: StatusEntry = { ...entry, time: Date.now() };
    const empty = entry.severity === 'NONE' || entry.message.trim() === '';
    if (!empty) {
        statusHistory.push(full);
        listeners.forEach(listener => listener(full));
    }
    if (clearTimer !== undefined) {
        window.clearTimeout(clearTimer);
        clearTimer = undefined;
    }
    if (empty) {
        if (shownKind === entry.kind || shownKind === undefined) {
            shownKind = undefined;
            render(undefined);
        }
        return;
    }
    shownKind = entry.kind;
    render(full);
    if (timeout !== undefined && timeout > 0) {
        clearTimer = window.setTimeout(() => {
            shownKind = undefined;
            render(undefined);
        }, timeout);
    }
}

/** Reports a failure of what was done (e.g. a toolbar button's action) as "<what> failed: <message>". */
export function failed(what: string): (error: unknown) => void {
    return error => {
        const message = error instanceof Error ? error.message : String(error);
        report({ kind: 'status', severity: 'ERROR', message: `${what} failed: ${message}` });
    };
}

/**
 * What to show of a server message. A failed action arrives as "[GLSP-Server] Could not process
 * message: ActionMessage […]" whose details start with the cause ("cannot open x.stct: …") followed
 * by a stack trace: the cause is shown (the whole message stays in the details, as a tooltip).
 */
export function readableMessage(message: string, details?: string): string {
    if (!details || !/Could not process message/i.test(message)) {
        return message;
    }
    let cause = details.split('\n')[0].trim();
    while (/^[\w$.]+(Exception|Error)(: |$)/.test(cause)) {
        cause = cause.replace(/^[\w$.]+(Exception|Error):? ?/, '');
    }
    return cause.length > 0 ? cause : message;
}

/** Receives GLSP's StatusAction and MessageAction. */
@injectable()
export class StatusLineHandler implements IActionHandler {
    handle(action: Action): void {
        if (StatusAction.is(action)) {
            report({ kind: 'status', severity: action.severity, message: action.message ?? '' }, action.timeout);
        } else if (MessageAction.is(action)) {
            const lasting = action.severity === 'ERROR' || action.severity === 'FATAL';
            report(
                {
                    kind: 'message',
                    severity: action.severity,
                    message: readableMessage(action.message ?? '', action.details),
                    details: [action.message, action.details].filter(Boolean).join('\n')
                },
                lasting ? undefined : 10000
            );
        }
    }
}
