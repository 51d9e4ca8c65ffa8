/*
 * The model's file changed on disk (another program, an editor, `git pull`). The server reads it
 * again when no page has unsaved edits, and the page says so; with unsaved edits nothing is thrown
 * away unasked: a bar over the diagram asks whether to reload (the edits are dropped) or to keep
 * the edits (the next save then overwrites the version on disk, knowingly). The choice goes to the
 * server, which tells every page of the file.
 */
import { Action, IActionDispatcher, IActionHandler, TYPES } from '@eclipse-glsp/client';
import { inject, injectable } from 'inversify';
import { report } from './status-line';
import './disk-changes.css';

export const DISK_CHANGE = 'kseDiskChange';
export const RESOLVE_DISK_CHANGE = 'kseResolveDiskChange';

/** From the server: what happened to the file (DiskChanges.DiskChangeAction). */
export interface DiskChangeAction extends Action {
    kind: typeof DISK_CHANGE;
    change: 'reloaded' | 'conflict' | 'unreadable' | 'kept';
    file: string;
    detail?: string;
}

function isDiskChange(action: Action): action is DiskChangeAction {
    return action.kind === DISK_CHANGE && typeof (action as DiskChangeAction).change === 'string';
}

/** To the server: the user's choice. */
export function resolveDiskChange(reload: boolean): Action {
    return { kind: RESOLVE_DISK_CHANGE, reload } as Action;
}

const BAR_ID = 'kse-disk-change';
/** How long a notice (no question) stays over the diagram. */
const NOTICE_MILLIS = 8000;

let noticeTimer: number | undefined;

/**
 * Shows the bar over the diagram with a text and, for a question, the buttons of the choices;
 * document.body.dataset.kseDiskChange tells the last change (for tests and hosts).
 */
function showBar(change: DiskChangeAction['change'], message: string, choices: HTMLButtonElement[]): void {
    document.getElementById(BAR_ID)?.remove();
    window.clearTimeout(noticeTimer);
    const bar = document.createElement('div');
    bar.id = BAR_ID;
    bar.setAttribute('role', choices.length > 0 ? 'alertdialog' : 'status');
    bar.setAttribute('aria-label', 'File changed on disk');
    bar.classList.toggle('kse-disk-change-notice', choices.length === 0);
    const text = document.createElement('span');
    text.className = 'kse-disk-change-text';
    text.textContent = message;
    bar.append(text, ...choices);
    (document.getElementById('kse-diagram') ?? document.body).appendChild(bar);
    document.body.dataset.kseDiskChange = change;
    if (choices.length === 0) {
        noticeTimer = window.setTimeout(() => bar.remove(), NOTICE_MILLIS);
    }
}

function button(label: string, title: string, choose: () => void): HTMLButtonElement {
    const element = document.createElement('button');
    element.type = 'button';
    element.textContent = label;
    element.title = title;
    element.addEventListener('click', () => {
        for (const each of Array.from(element.parentElement?.querySelectorAll('button') ?? [])) {
            each.disabled = true; // one choice: the server's answer replaces the bar
        }
        choose();
    });
    return element;
}

function question(action: DiskChangeAction): string {
    return action.change === 'unreadable'
        ? `${action.file} was changed on disk and cannot be read${action.detail ? `: ${action.detail}` : ''}. This page keeps its version.`
        : `${action.file} was changed on disk by another program, and this model has unsaved edits.`;
}

@injectable()
export class DiskChangeHandler implements IActionHandler {
    @inject(TYPES.IActionDispatcher) protected dispatcher!: IActionDispatcher;

    handle(action: Action): void {
        if (!isDiskChange(action)) {
            return;
        }
        switch (action.change) {
            case 'conflict':
            case 'unreadable': {
                const choose = (reload: boolean) => () => void this.dispatcher.dispatch(resolveDiskChange(reload));
                showBar(action.change, question(action), [
                    button('Reload', 'Show the file as it is on disk: the unsaved edits here are dropped', choose(true)),
                    button('Keep mine', 'Keep the edits made here: saving then overwrites the version on disk', choose(false))
                ]);
                report({ kind: 'status', severity: 'WARNING', message: `${action.file} was changed on disk: reload it or keep your edits` });
                break;
            }
            case 'reloaded':
                showBar(action.change, `${action.file} was changed on disk: reloaded`, []);
                report({ kind: 'status', severity: 'INFO', message: `${action.file} was changed on disk: reloaded` }, NOTICE_MILLIS);
                break;
            case 'kept':
                showBar(action.change, `Kept the edits: saving overwrites the version of ${action.file} on disk`, []);
                report({ kind: 'status', severity: 'INFO', message: `Kept the edits: saving overwrites the version of ${action.file} on disk` }, NOTICE_MILLIS);
                break;
        }
    }
}
