/**
 * The colour ramp of the distance-to-target map (the paper's Fig. 8): dark blue at zero through
 * cyan, green and yellow to red at the scale's top, as vertex colours and as the legend's CSS
 * gradient (the same stops, so the legend reads the surface).
 */

/** Ramp stops: position 0…1, then r g b in 0…1. */
const STOPS: readonly (readonly [number, number, number, number])[] = [
  [0, 0.13, 0.2, 0.55],
  [0.25, 0.1, 0.6, 0.85],
  [0.5, 0.25, 0.78, 0.35],
  [0.75, 0.98, 0.82, 0.2],
  [1, 0.85, 0.15, 0.12],
];

/** The ramp's colour at `v` (clamped to 0…1), written as r g b into `out` at `offset`. */
export function rampColor(v: number, out: Float32Array, offset: number): void {
  const x = Math.min(1, Math.max(0, Number.isFinite(v) ? v : 1));
  let i = 0;
  while (i < STOPS.length - 2 && x > STOPS[i + 1][0]) i++;
  const a = STOPS[i], b = STOPS[i + 1];
  const u = (x - a[0]) / (b[0] - a[0]);
  for (let k = 1; k <= 3; k++) out[offset + k - 1] = a[k] + u * (b[k] - a[k]);
}

/** Colours per vertex for `values` on the scale 0…`max` (3 per vertex, into `out`). */
export function rampColors(values: ArrayLike<number>, max: number, out: Float32Array): Float32Array {
  const inv = max > 0 ? 1 / max : 0;
  for (let i = 0; i < values.length; i++) rampColor(values[i] * inv, out, 3 * i);
  return out;
}

/** The ramp as a CSS linear gradient, left (0) to right (max). */
export function rampGradient(): string {
  const css = (c: readonly number[]) => `rgb(${Math.round(c[1] * 255)} ${Math.round(c[2] * 255)} ${Math.round(c[3] * 255)}) ${c[0] * 100}%`;
  return `linear-gradient(to right, ${STOPS.map(css).join(', ')})`;
}

/** A readable top of a scale: `max` rounded up to 1, 2 or 5 times a power of ten. */
export function niceCeil(max: number): number {
  if (!(max > 0) || !Number.isFinite(max)) return 0;
  const p = 10 ** Math.floor(Math.log10(max));
  for (const m of [1, 2, 5, 10]) if (m * p >= max * (1 - 1e-12)) return m * p;
  return 10 * p;
}
