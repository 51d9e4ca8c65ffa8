/*
 * What the page shows of the editor's state, for the user, for tests (body data-kse-* attributes)
 * and for a host that embeds the page: the title with a dirty mark, the Save button, the selection
 * told to the host, and a question before leaving a page with unsaved edits.
 */
import { ServerConnection } from './connection';
import { DiagramPage } from './diagram-page';
import { report } from './status-line';

declare global {
    interface Window {
        /**
         * Set by a host that embeds the page (the KSE workbench, through an SWT BrowserFunction):
         * told the selected ids, as a JSON array, whenever the selection changes.
         */
        kseHostSelection?: (idsJson: string) => unknown;
    }
}

export function followEditorState(page: DiagramPage, connection: ServerConnection): void {
    const { parameters, editorContext, selectionService } = page;

    selectionService.onSelectionChanged(() => {
        const ids = selectionService.getSelectedElementIDs();
        document.body.dataset.kseSelection = ids.join(' ');
        if (typeof window.kseHostSelection === 'function') {
            window.kseHostSelection(JSON.stringify(ids));
        }
    });

    editorContext.onDirtyStateChanged(change => {
        if (!change.isDirty && change.reason === 'save') {
            report({ kind: 'status', severity: 'OK', message: `Saved ${parameters.model}` }, 4000);
        }
        document.title = `${parameters.modelName}${change.isDirty ? ' *' : ''} – KSE`;
        document.body.dataset.kseDirty = String(change.isDirty);
        document.querySelector('[data-action="save"]')?.classList.toggle('kse-dirty', change.isDirty);
    });

    // Closing or leaving a page with unsaved edits asks first; in the workbench its editor asks instead.
    window.addEventListener('beforeunload', event => {
        if (editorContext.isDirty && !connection.isReopening && typeof window.kseHostSelection !== 'function') {
            event.preventDefault();
            event.returnValue = '';
        }
    });
}
