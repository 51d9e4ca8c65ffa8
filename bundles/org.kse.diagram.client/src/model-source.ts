/*
 * The connection of the diagram to the GLSP server. A compound operation goes to the server as one
 * message; one part the server does not know (e.g. the routing point changes GLSP adds to a move)
 * makes it refuse the whole message. Such parts are left out: the server lists the action kinds it
 * handles when it is initialized, and the rest of the compound is still done. Once the connection
 * is lost, nothing is sent (the page reconnects).
 */
import { Action, ClientState, CompoundOperation, GLSPModelSource, Operation, SaveModelAction } from '@eclipse-glsp/client';
import { injectable } from 'inversify';
import { report } from './status-line';

@injectable()
export class KseModelSource extends GLSPModelSource {
    protected readonly reportedUnsupported = new Set<string>();

    protected serverKinds(): ReadonlySet<string> | undefined {
        const handled = this.glspClient?.initializeResult?.serverActions?.[this.diagramType];
        return handled ? new Set(handled) : undefined;
    }

    override forwardToServer(action: Action): void {
        if (this.connectionLost()) {
            // the page reconnects by itself (connection.ts); until then nothing reaches the server, and an
            // edit or a save the user asked for is not silently dropped
            if (Operation.is(action) || SaveModelAction.is(action)) {
                report({ kind: 'connection', severity: 'WARNING', message: 'Not connected to the diagram server: reconnecting… (that last edit or save was not done)' });
            }
            return;
        }
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

    /** The connection went away (GLSP's client would throw "not ready" at every action sent now). */
    protected connectionLost(): boolean {
        const state = this.glspClient?.currentState;
        return state === ClientState.ServerError || state === ClientState.Stopping || state === ClientState.Stopped;
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
