/*
 * The context menu (right click) of the diagram. GLSP collects the items (its Delete, Cut and Copy,
 * and ours below) and selects what was clicked; a standalone page has no menu to show them in,
 * so KseContextMenu draws one. Paste pastes what was copied last in this page: Chromium lets a
 * page read the system clipboard only from a paste key (Ctrl+V) or with a permission prompt.
 */
import {
    Action,
    Anchor,
    ClipboardData,
    CopyPasteContextMenuItemProvider,
    CreateNodeOperation,
    EditLabelAction,
    EditorContextService,
    GLSPContextMenuMouseListener,
    GModelElement,
    GModelRoot,
    IActionDispatcher,
    IContextMenuItemProvider,
    IContextMenuService,
    LayoutOperation,
    LocalClipboardService,
    MenuItem,
    PasteOperation,
    Point,
    TYPES,
    getAbsolutePositionByPoint,
    isSelected
} from '@eclipse-glsp/client';
import { inject, injectable } from 'inversify';
import { StateNode, TransitionEdge, holdRefusal } from './model';
import { fitStatesAction } from './viewport';

/**
 * Opens the menu for what the right button was pressed on. Chromium on Linux fires 'contextmenu' on
 * the press, after the diagram has redrawn for it, and its target was then what lay below (a right
 * click on a transition over a composite opened the composite's menu).
 */
@injectable()
export class KseContextMenuMouseListener extends GLSPContextMenuMouseListener {
    protected pressedId?: string;

    override mouseDown(target: GModelElement, event: MouseEvent): Action[] {
        this.pressedId = event.button === 2 ? target.id : undefined;
        return [];
    }

    override contextMenu(target: GModelElement, event: MouseEvent): (Action | Promise<Action>)[] {
        const pressed = this.pressedId !== undefined ? target.root.index.getById(this.pressedId) : undefined;
        this.pressedId = undefined;
        return super.contextMenu(pressed ?? target, event);
    }
}

/** GLSP's in-page clipboard, which also tells what was copied last (for Paste in the menu). */
@injectable()
export class KseClipboardService extends LocalClipboardService {
    latest(): ClipboardData | undefined {
        return this.data;
    }
}

/** GLSP's Cut and Copy; Paste pastes the last copy of this page into the selection (or the top of the model). */
@injectable()
export class KseCopyPasteMenuItems extends CopyPasteContextMenuItemProvider {
    @inject(TYPES.IAsyncClipboardService) protected clipboard!: KseClipboardService;
    @inject(EditorContextService) protected editorContext!: EditorContextService;

    protected override createPasteMenuItem(): MenuItem {
        const clipboardData = typeof this.clipboard.latest === 'function' ? this.clipboard.latest() : undefined;
        return {
            id: 'paste',
            label: 'Paste',
            group: 'copy-paste',
            actions: clipboardData ? [PasteOperation.create({ clipboardData, editorContext: this.editorContext.get() })] : [],
            isEnabled: () => clipboardData !== undefined
        };
    }
}

/** What the statechart adds: rename, add a state inside a composite, and for the canvas arrange and fit. */
@injectable()
export class KseMenuItems implements IContextMenuItemProvider {
    async getItems(root: Readonly<GModelRoot>, lastMousePosition?: Point): Promise<MenuItem[]> {
        const selected = Array.from(root.index.all()).filter(isSelected);
        if (selected.length === 0) {
            return [
                { id: 'arrange-all', label: 'Arrange all', group: 'layout', sortString: 'a', actions: [LayoutOperation.create()] },
                { id: 'fit', label: 'Fit to window', group: 'layout', sortString: 'b', actions: [fitStatesAction(root as GModelRoot, 2, true)] }
            ];
        }
        const items: MenuItem[] = [];
        if (selected.length === 1) {
            const element = selected[0];
            if (element instanceof StateNode && element.nameLabel && element.kind !== 'condition') {
                items.push({ id: 'rename', label: 'Rename…', group: 'a-edit', sortString: 'a', actions: [EditLabelAction.create(element.nameLabel.id)] });
            }
            const expression = element instanceof TransitionEdge ? element.editableLabel : undefined;
            if (expression) {
                items.push({ id: 'edit-expression', label: 'Edit expression…', group: 'a-edit', sortString: 'a', actions: [EditLabelAction.create(expression.id)] });
            }
            if (element instanceof StateNode && element.isComposite) {
                // a new state goes where the menu was opened, if that lies inside the composite
                const location = lastMousePosition ? getAbsolutePositionByPoint(root as GModelRoot, lastMousePosition) : undefined;
                // a BASIC state where the rule book allows one, else an OR region (an AND state's)
                const kind = holdRefusal(root, element.kind, 'basic') === undefined ? 'basic' : 'or';
                items.push({
                    id: 'add-inside',
                    label: kind === 'or' ? 'Add OR region inside' : 'Add BASIC state inside',
                    group: 'b-create',
                    actions: [CreateNodeOperation.create(`state:${kind}`, { containerId: element.id, location })]
                });
            }
        }
        return items;
    }
}

/** The menu itself: a list of buttons at the mouse, closed by a click elsewhere, Escape, scrolling or leaving the page. */
@injectable()
export class KseContextMenu implements IContextMenuService {
    @inject(TYPES.IActionDispatcher) protected dispatcher!: IActionDispatcher;

    protected menu?: HTMLElement;
    protected onHide?: () => void;
    protected readonly closeOnOutsideClick = (event: Event) => {
        if (this.menu && !this.menu.contains(event.target as Node)) {
            this.hide();
        }
    };
    protected readonly closeOnEscape = (event: KeyboardEvent) => {
        if (event.key === 'Escape') {
            event.preventDefault();
            event.stopPropagation();
            this.hide();
        }
    };
    protected readonly closeNow = () => this.hide();

    show(items: MenuItem[], anchor: Anchor, onHide?: () => void): void {
        this.hide();
        const visible = items.filter(item => (item.isVisible ? item.isVisible() : true));
        if (visible.length === 0) {
            onHide?.();
            return;
        }
        this.onHide = onHide;
        const menu = document.createElement('div');
        menu.className = 'kse-context-menu';
        menu.setAttribute('role', 'menu');
        const groups = new Map<string, MenuItem[]>();
        for (const item of visible) {
            const group = item.group ?? '';
            groups.set(group, [...(groups.get(group) ?? []), item]);
        }
        const ordered = Array.from(groups.keys()).sort();
        ordered.forEach((group, index) => {
            if (index > 0) {
                const separator = document.createElement('div');
                separator.className = 'kse-context-menu-separator';
                separator.setAttribute('role', 'separator');
                menu.appendChild(separator);
            }
            const inGroup = groups.get(group)!.slice().sort((a, b) => (a.sortString ?? a.label).localeCompare(b.sortString ?? b.label));
            for (const item of inGroup) {
                menu.appendChild(this.button(item));
            }
        });
        document.body.appendChild(menu);
        const x = 'clientX' in anchor ? anchor.clientX : anchor.x;
        const y = 'clientY' in anchor ? anchor.clientY : anchor.y;
        const width = menu.offsetWidth;
        const height = menu.offsetHeight;
        menu.style.left = `${Math.max(0, Math.min(x, window.innerWidth - width - 4))}px`;
        menu.style.top = `${Math.max(0, Math.min(y, window.innerHeight - height - 4))}px`;
        this.menu = menu;
        document.addEventListener('mousedown', this.closeOnOutsideClick, true);
        document.addEventListener('keydown', this.closeOnEscape, true);
        document.addEventListener('wheel', this.closeNow, true);
        window.addEventListener('blur', this.closeNow);
    }

    protected button(item: MenuItem): HTMLButtonElement {
        const button = document.createElement('button');
        button.type = 'button';
        button.className = 'kse-context-menu-item';
        button.setAttribute('role', 'menuitem');
        button.dataset.item = item.id;
        button.textContent = item.label;
        const enabled = (item.isEnabled ? item.isEnabled() : true) && (item.actions?.length ?? 0) > 0;
        button.disabled = !enabled;
        // the diagram keeps the keyboard focus: Cut and Copy work on its selection
        button.addEventListener('mousedown', event => event.preventDefault());
        button.addEventListener('click', () => {
            const actions: Action[] = item.actions ?? [];
            this.hide();
            void this.dispatcher.dispatchAll(actions);
        });
        return button;
    }

    hide(): void {
        if (!this.menu) {
            return;
        }
        this.menu.remove();
        this.menu = undefined;
        document.removeEventListener('mousedown', this.closeOnOutsideClick, true);
        document.removeEventListener('keydown', this.closeOnEscape, true);
        document.removeEventListener('wheel', this.closeNow, true);
        window.removeEventListener('blur', this.closeNow);
        const onHide = this.onHide;
        this.onHide = undefined;
        onHide?.();
    }
}
