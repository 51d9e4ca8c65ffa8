/*
 * Registries that know every kind of state the server sends without a list of kinds here: a type
 * "state:<kind>" without a registration of its own is created and drawn as "state" (StateNode and
 * StateView, which draw by kind). Which kinds exist, and what they may hold, is the server's rule
 * book (ADR 0018); only kinds with behaviour of their own (a BASIC state edits its name on a
 * double click) are registered one by one.
 */
import { GModelRegistry, GViewRegistry, IView } from '@eclipse-glsp/client';
import { injectable } from 'inversify';
import { STATE_PREFIX } from './model';

/** The registration a "state:<kind>" type falls back to. */
export const ANY_STATE = STATE_PREFIX.substring(0, STATE_PREFIX.length - 1);

function isStateType(key: string): boolean {
    return key.startsWith(STATE_PREFIX);
}

@injectable()
export class KseModelRegistry extends GModelRegistry {
    // also asked by register(): kinds of their own must be registered before ANY_STATE
    override hasKey(key: string): boolean {
        return this.elements.has(key) || (isStateType(key) && this.elements.has(ANY_STATE));
    }

    // eslint-disable-next-line @typescript-eslint/no-explicit-any
    override missing(key: string, arg?: any): any {
        return isStateType(key) && this.elements.has(ANY_STATE) ? super.get(ANY_STATE, arg) : super.missing(key, arg);
    }
}

@injectable()
export class KseViewRegistry extends GViewRegistry {
    override missing(key: string): IView {
        return isStateType(key) && this.elements.has(ANY_STATE) ? this.get(ANY_STATE) : super.missing(key);
    }
}
