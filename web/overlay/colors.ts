import type { ContinuityKind } from '../../src/index.js';

/** Overlay colors (sRGB hex), shared by the anchors on the canvas and the legend in the panel. */
export const CONTINUITY_COLORS: Record<ContinuityKind, string> = {
  C0: '#ff8a3d',
  C1: '#3ddc84',
  G1: '#4cc2ff',
  angle: '#c77dff',
  none: '#ff4d6d',
};

/** Anchors that are no junction: the two ends of an open spline. */
export const END_COLOR = '#ffffff';
export const HANDLE_COLOR = '#ffffff';
export const HANDLE_LINE_COLOR = '#7c8594';
export const OUTLINE_COLOR = '#15171a';
export const SELECTION_COLOR = '#ffe066';

export const CONTINUITY_DESCRIPTIONS: Record<ContinuityKind, string> = {
  C0: 'corner: the curve only meets itself',
  C1: 'smooth: equal, opposite handles',
  G1: 'smooth: aligned handles, lengths keep their ratio',
  angle: 'corner kept at a fixed angle',
  none: 'break: nothing is kept',
};

export function hexToRGB(hex: string): [number, number, number] {
  const n = parseInt(hex.slice(1), 16);
  return [((n >> 16) & 255) / 255, ((n >> 8) & 255) / 255, (n & 255) / 255];
}
