/*
 * What the page was opened with: http://127.0.0.1:<port>/?token=<token>&model=<path of a .stct file
 * relative to the served folder>.
 */

export interface PageParameters {
    /** The session token the server requires of WebSocket connections. */
    token: string;
    /** The model file, relative to the served folder (the GLSP source URI). */
    model: string;
    /** The model's file name without folder and extension (names the exported files). */
    modelName: string;
    /** Where the GLSP server listens. */
    socketUrl: string;
}

export function modelNameOf(model: string): string {
    const file = model.split(/[\\/]/).filter(part => part.length > 0).pop() ?? '';
    const name = file.replace(/\.stct$/i, '');
    return name.length > 0 ? name : 'statechart';
}

export function readPageParameters(location: Location): PageParameters {
    const query = new URLSearchParams(location.search);
    const token = query.get('token') ?? '';
    const model = query.get('model') ?? '';
    const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
    const socketUrl = `${scheme}//${location.host}/kse?token=${encodeURIComponent(token)}`;
    return { token, model, modelName: modelNameOf(model), socketUrl };
}

/** A DOM-safe id, unique for this page: the GLSP client id and the id of the diagram's base div. */
export function newClientId(): string {
    const random = new Uint8Array(8);
    crypto.getRandomValues(random);
    return 'kse_' + Array.from(random, byte => byte.toString(16).padStart(2, '0')).join('');
}
