/*
 * The diagram of this page: what the page was opened with, the GLSP client id, the dependency
 * injection container and the services the page's modules use; and where the diagram is in the
 * page (GLSP renders into the element whose id is the client id, the diagram's base div).
 */
import { EditorContextService, GLSPActionDispatcher, SelectionService } from '@eclipse-glsp/client';
import { Container } from 'inversify';
import { PageParameters } from './page';

export interface DiagramPage {
    parameters: PageParameters;
    /** The GLSP client id, also the id of the diagram's base div. */
    clientId: string;
    container: Container;
    dispatcher: GLSPActionDispatcher;
    editorContext: EditorContextService;
    selectionService: SelectionService;
}

export function diagramPage(parameters: PageParameters, clientId: string, container: Container): DiagramPage {
    return {
        parameters,
        clientId,
        container,
        dispatcher: container.get(GLSPActionDispatcher),
        editorContext: container.get(EditorContextService),
        selectionService: container.get(SelectionService)
    };
}

/** Puts the base div of the diagram into the page's #kse-diagram. */
export function createBaseDiv(clientId: string): HTMLElement {
    // the base div of the diagram has the client id as its id (GLSP renders into the element with that id)
    const host = document.getElementById('kse-diagram');
    if (!host) {
        throw new Error('the page has no #kse-diagram element');
    }
    const baseDiv = document.createElement('div');
    baseDiv.id = clientId;
    baseDiv.className = 'kse-base';
    host.appendChild(baseDiv);
    return baseDiv;
}

/** The diagram's SVG element (null until GLSP has rendered one). */
export function diagramSvg(baseDivId: string): SVGSVGElement | null {
    return document.getElementById(baseDivId)?.querySelector('svg') ?? null;
}

/** Gives the keyboard focus to the diagram (without scrolling), so that its shortcuts work. */
export function focusDiagram(baseDivId: string): void {
    const svg = diagramSvg(baseDivId);
    if (svg && typeof (svg as unknown as HTMLElement).focus === 'function') {
        (svg as unknown as HTMLElement).focus({ preventScroll: true });
    }
}
