import type { MorphInterpolation, MorphPin } from '../../../src/index.js';

/**
 * What the user set up in the morph mode, as an immutable value (undo swaps whole specs): the two
 * keys (a sample id, 'current' for the open drawing, or a file the user opened, kept as text so
 * it autosaves), the pins, the interpolation and t.
 */
export interface KeyChoice {
  /** 'current', a sample id, or 'file'. */
  source: string;
  /** File name (for 'file'). */
  name?: string;
  /** SVG markup (for 'file'). */
  text?: string;
}

export interface MorphSpec {
  a: KeyChoice;
  b: KeyChoice;
  pins: readonly MorphPin[];
  interpolation: MorphInterpolation;
  t: number;
}

export const DEFAULT_SPEC: MorphSpec = {
  a: { source: 'blob' },
  b: { source: 'star' },
  pins: [],
  interpolation: 'linear',
  t: 0.5,
};

function key(v: unknown): KeyChoice | null {
  const k = v as KeyChoice;
  if (!k || typeof k.source !== 'string') return null;
  if (k.source === 'file' && (typeof k.text !== 'string' || typeof k.name !== 'string')) return null;
  return k.source === 'file' ? { source: 'file', name: k.name, text: k.text } : { source: k.source };
}

/** A spec from stored JSON, or null when it is not one. */
export function specFromJSON(v: unknown): MorphSpec | null {
  const o = v as Partial<MorphSpec>;
  if (!o || typeof o !== 'object') return null;
  const a = key(o.a), b = key(o.b);
  if (!a || !b) return null;
  const finite = (x: unknown) => typeof x === 'number' && Number.isFinite(x);
  const pins = Array.isArray(o.pins)
    ? o.pins.filter((p) => p && Array.isArray(p.a) && Array.isArray(p.b) && [...p.a, ...p.b].length === 4 && [...p.a, ...p.b].every(finite))
    : [];
  return {
    a,
    b,
    pins: pins.map((p) => ({ a: [p.a[0], p.a[1]] as const, b: [p.b[0], p.b[1]] as const })),
    interpolation: o.interpolation === 'intrinsic' ? 'intrinsic' : 'linear',
    t: finite(o.t) ? Math.min(1, Math.max(0, o.t!)) : 0.5,
  };
}
