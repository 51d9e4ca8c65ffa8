/*
 * Direct editing of names and transition expressions. The diagram shows only the first line of an
 * expression; its editor starts with the whole expression (a text area: Shift+Enter for a new line,
 * Enter to apply, Escape to cancel). The edit goes to the server as ApplyLabelEditOperation.
 */
import { GlspEditLabelUI, IActionHandler } from '@eclipse-glsp/client';
import { injectable } from 'inversify';
import { ExpressionLabel, NameLabel } from './model';

/** The labels that show less than what they edit: a first line, a caption. */
function fullTextOf(label: unknown): string | undefined {
    return label instanceof ExpressionLabel || label instanceof NameLabel ? label.fullText : undefined;
}

@injectable()
export class KseEditLabelUI extends GlspEditLabelUI {
    protected override applyTextContents(): void {
        super.applyTextContents();
        const fullText = fullTextOf(this.label);
        if (fullText !== undefined) {
            this.editControl.value = fullText;
            this.previousLabelContent = fullText;
        }
    }

    protected override async applyLabelEdit(): Promise<void> {
        if (this.isActive && fullTextOf(this.label) !== undefined && this.editControl.value === fullTextOf(this.label)) {
            this.hide();
            return;
        }
        return super.applyLabelEdit();
    }
}

/**
 * The answer to a name's check that comes after GLSP's validator stopped waiting for it (2 s: a
 * server busy with thousands of states). The editor went on without it and the server checks the
 * edit again when it applies it, so the late answer has nothing left to do; without a handler the
 * dispatcher would report it as an error in the page.
 */
@injectable()
export class LateEditValidationResults implements IActionHandler {
    handle(): void {
        // nothing: see above
    }
}
