/*
 * Direct editing of names and transition expressions. The diagram shows only the first line of an
 * expression; its editor starts with the whole expression (a text area: Shift+Enter for a new line,
 * Enter to apply, Escape to cancel). The edit goes to the server as ApplyLabelEditOperation.
 */
import { GlspEditLabelUI } from '@eclipse-glsp/client';
import { injectable } from 'inversify';
import { ExpressionLabel } from './model';

@injectable()
export class KseEditLabelUI extends GlspEditLabelUI {
    protected override applyTextContents(): void {
        super.applyTextContents();
        if (this.label instanceof ExpressionLabel) {
            this.editControl.value = this.label.fullText;
            this.previousLabelContent = this.label.fullText;
        }
    }

    protected override async applyLabelEdit(): Promise<void> {
        if (this.isActive && this.label instanceof ExpressionLabel && this.editControl.value === this.label.fullText) {
            this.hide();
            return;
        }
        return super.applyLabelEdit();
    }
}
