/*
 * The connection of the diagram to the GLSP server. A compound operation goes to the server as one
 * message; one part the server does not know (e.g. the routing point changes GLSP adds to a move)
 * makes it refuse the whole message. Such parts are left out: the server lists the action kinds it
 * handles when it is initialized, and the rest of the compound is still done.
 */
import { Action, CompoundOperation, GLSPModelSource, Operation } from '@eclipse-glsp/client';
import { injectable } from 'inversify';

@injectable()
export class KseModelSource extends GLSPModelSource {
    protected readonly reportedUnsupported = new Set<string>();

    protected serverKinds(): ReadonlySet<string> | undefined {
        const handled = this.glspClient?.initializeResult?.serverActions?.[this.diagramType];
        return handled ? new Set(handled) : undefined;
    }

    override forwardToServer(action: Action): void {
        const kinds = this.serverKinds();
        if (kinds && CompoundOperation.is(action)) {
            const supported = action.operationList.filter(operation => this.isSupported(operation, kinds));
            if (supported.length === 0) {
                return;
            }
            if (supported.length !== action.operationList.length) {
                super.forwardToServer({ ...action, operationList: supported } as CompoundOperation);
                return;
            }
        }
        super.forwardToServer(action);
    }

    protected isSupported(operation: Operation, kinds: ReadonlySet<string>): boolean {
        if (kinds.has(operation.kind)) {
            return true;
        }
        if (!this.reportedUnsupported.has(operation.kind)) {
            this.reportedUnsupported.add(operation.kind);
            console.warn(`The diagram server does not handle '${operation.kind}': left out of compound operations.`);
        }
        return false;
    }
}
