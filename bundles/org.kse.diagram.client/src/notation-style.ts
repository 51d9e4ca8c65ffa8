/*
 * The thesis notation's style: shapes, colours, strokes and fonts per state kind, and the
 * transitions' line, arrow head and expression font. It is org.kse.notation's
 * notation-style.json, bundled into the page by esbuild, the same file `kse diagram` draws its
 * SVG from (org.kse.notation.NotationStyle), so the editor and the picture cannot drift apart.
 * The page's CSS (kse.css) keeps only what is interaction: selection, hover, drop targets.
 */
import style from '../../org.kse.notation/src/org/kse/notation/notation-style.json';
import type { StateKind } from './model';

export type Shape = 'disc' | 'ringedDisc' | 'circledLetter' | 'roundedBox' | 'compositeBox';

export interface StateStyle {
    shape: Shape;
    fill: string;
    stroke: string;
    strokeWidth: number;
    /** Boxes: the corners' radius. */
    cornerRadius?: number;
    /** Circles: how far the circle lies inside half the smaller side (a thick ring stays inside the bounds). */
    inset?: number;
    /** An SVG dash array for the outline. */
    dash?: string;
    /** The END's centre: its radius as a part of the whole, and its colour. */
    innerDisc?: { ratio: number; fill: string };
    /** The circled letter (CONDITION's "C"); the server sends it as the state's name label. */
    letter?: string;
    size?: { width: number; height: number };
}

export interface TextStyle {
    size: number;
    weight: string;
    colour: string;
}

export interface NotationStyle {
    fontFamily: string;
    states: Record<StateKind, StateStyle>;
    captions: {
        centred: TextStyle;
        letter: TextStyle;
        /** A composite's caption: `x` from the left, its baseline `baseline` below the top. */
        header: TextStyle & { x: number; baseline: number };
        /** A composite's hierarchical label: `right` from the right, its baseline `baseline` below the top. */
        label: TextStyle & { right: number; baseline: number };
    };
    transitions: {
        line: { colour: string; width: number };
        /** A triangle `length` long and `width` wide at its base, its tip at the line's end. */
        arrow: { length: number; width: number; fill: string; stroke: string; strokeWidth: number };
        /** The expression's text, offset by `x`, `y` from the corner of the box the server placed it in. */
        label: TextStyle & { x: number; y: number };
    };
}

const SHAPES: readonly string[] = ['disc', 'ringedDisc', 'circledLetter', 'roundedBox', 'compositeBox'];

/** The style, checked as far as the views rely on it (org.kse.notation's tests check the rest of the file). */
function checked(value: unknown): NotationStyle {
    const notation = value as NotationStyle;
    for (const kind of ['start', 'end', 'condition', 'basic', 'or', 'and', 'unknown'] as StateKind[]) {
        const shape = notation.states?.[kind]?.shape;
        if (!SHAPES.includes(shape)) {
            throw new Error(`notation-style.json: states.${kind}.shape: ${JSON.stringify(shape)} is no shape (${SHAPES.join(', ')})`);
        }
    }
    return notation;
}

export const NOTATION: NotationStyle = checked(style);

/** Whether a kind is drawn as a circle (its edges end on the circle, not on a box). */
export function isCircle(kind: StateKind): boolean {
    const shape = NOTATION.states[kind].shape;
    return shape === 'disc' || shape === 'ringedDisc' || shape === 'circledLetter';
}

/**
 * A text's font, colour and anchoring as its inline style. Not as presentation attributes (as
 * kse diagram's SVG writes them): GLSP's CSS sets every text's fill, font and anchor, and any CSS
 * rule beats an attribute. kse.css changes a text only where it must win over this (selection).
 */
export function textStyle(text: TextStyle, anchor: 'start' | 'middle' | 'end', baseline?: 'central' | 'text-before-edge'): { style: Record<string, string> } {
    return {
        style: {
            fontFamily: NOTATION.fontFamily,
            fontSize: `${text.size}px`,
            fontWeight: text.weight,
            fill: text.colour,
            stroke: 'none',
            textAnchor: anchor,
            ...(baseline ? { dominantBaseline: baseline } : {})
        }
    };
}
