/*
 * Ctrl+F on the diagram: a small box that finds states by name (as drawn or as in the model) or by
 * their hierarchical label ("0.2.1"). Enter selects the next match and centres it, Shift+Enter the
 * previous one, Escape closes the box and gives the keyboard back to the diagram.
 */
import { Args, CenterAction, EditorContextService, IActionDispatcher, SelectAction, TYPES, ViewerOptions } from '@eclipse-glsp/client';
import { inject, injectable } from 'inversify';
import { focusDiagram } from './diagram-page';
import { StateNode } from './model';

function argument(state: StateNode, name: string): string {
    const value = (state as unknown as { args?: Args }).args?.[name];
    return value === undefined || value === null ? '' : String(value);
}

/** The texts a state is found by: the name it shows, its name in the model, its hierarchical label. */
function searchableTexts(state: StateNode): string[] {
    return [state.nameLabel?.text ?? '', argument(state, 'name'), state.hierarchicalLabel].filter(text => text.length > 0);
}

/** The states matching a query, those whose name or label is the query itself first, then in the order of the model. */
export function statesMatching(states: StateNode[], query: string): StateNode[] {
    const wanted = query.trim().toLowerCase();
    if (wanted.length === 0) {
        return [];
    }
    const exact = states.filter(state => searchableTexts(state).some(text => text.toLowerCase() === wanted));
    const partial = states.filter(state => !exact.includes(state) && searchableTexts(state).some(text => text.toLowerCase().includes(wanted)));
    return [...exact, ...partial];
}

@injectable()
export class FindBox {
    @inject(TYPES.IActionDispatcher) protected dispatcher!: IActionDispatcher;
    @inject(EditorContextService) protected editorContext!: EditorContextService;
    @inject(TYPES.ViewerOptions) protected viewerOptions!: ViewerOptions;

    protected box?: HTMLElement;
    protected input?: HTMLInputElement;
    protected count?: HTMLElement;
    protected matches: string[] = [];
    protected current = -1;
    protected searched = '';

    get isOpen(): boolean {
        return this.box !== undefined && !this.box.hidden;
    }

    open(): void {
        const input = this.create();
        this.box!.hidden = false;
        input.focus();
        input.select();
    }

    close(): void {
        if (this.box) {
            this.box.hidden = true;
        }
        focusDiagram(this.viewerOptions.baseDiv);
    }

    protected create(): HTMLInputElement {
        if (this.input) {
            return this.input;
        }
        const box = document.createElement('div');
        box.className = 'kse-find';
        box.setAttribute('role', 'search');
        const input = document.createElement('input');
        input.type = 'search';
        input.placeholder = 'Find state (name or label)';
        input.setAttribute('aria-label', 'Find a state by name or label');
        input.spellcheck = false;
        const count = document.createElement('span');
        count.className = 'kse-find-count';
        count.setAttribute('aria-live', 'polite');
        const close = document.createElement('button');
        close.type = 'button';
        close.className = 'kse-find-close codicon codicon-close';
        close.title = 'Close (Escape)';
        close.addEventListener('click', () => this.close());
        box.append(input, count, close);
        input.addEventListener('keydown', event => {
            // the box's keys are its own: none of them reaches the diagram's shortcuts
            event.stopPropagation();
            if (event.key === 'Enter') {
                event.preventDefault();
                void this.reveal(event.shiftKey ? -1 : 1);
            } else if (event.key === 'Escape') {
                event.preventDefault();
                this.close();
            }
        });
        input.addEventListener('input', () => this.showCount());
        const host = document.getElementById(this.viewerOptions.baseDiv)?.parentElement ?? document.body;
        host.appendChild(box);
        this.box = box;
        this.input = input;
        this.count = count;
        return input;
    }

    protected states(): StateNode[] {
        const root = this.editorContext.modelRoot;
        return root ? Array.from(root.index.all()).filter((element): element is StateNode => element instanceof StateNode) : [];
    }

    protected showCount(): void {
        const query = this.input?.value ?? '';
        const found = statesMatching(this.states(), query).length;
        if (this.count) {
            this.count.textContent = query.trim() === '' ? '' : found === 0 ? 'no state' : `${found} found`;
        }
    }

    /** Selects and centres the next (or previous) match; the same query again goes on from the last one. */
    protected async reveal(step: 1 | -1): Promise<void> {
        const query = this.input?.value ?? '';
        // found anew each time: the model may have changed since the last Enter
        this.matches = statesMatching(this.states(), query).map(state => state.id);
        if (query !== this.searched) {
            this.searched = query;
            this.current = step === 1 ? -1 : 0;
        }
        if (this.matches.length === 0) {
            if (this.count) {
                this.count.textContent = query.trim() === '' ? '' : 'no state';
            }
            return;
        }
        this.current = (this.current + step + this.matches.length) % this.matches.length;
        const id = this.matches[this.current];
        if (this.count) {
            this.count.textContent = `${this.current + 1} of ${this.matches.length}`;
        }
        await this.dispatcher.dispatchAll([SelectAction.setSelection([id]), CenterAction.create([id], { animate: true, retainZoom: true })]);
    }
}
