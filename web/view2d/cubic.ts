/**
 * The cubic Bézier point kernel of the editor's drawing code, on flat x,y arrays and without
 * allocation: tessellation (view2d/tessellate.ts) and Skin mode's curve samples both evaluate
 * curves through it. (The package's Bezier.point computes the same in the wasm core, one call per
 * point: too slow for every frame.)
 */

/**
 * Writes B(t) = (1−t)³P0 + 3(1−t)²t P1 + 3(1−t)t² P2 + t³P3 to `out[at]`, `out[at + 1]`.
 * `p` holds x,y pairs; `i0 … i3` are the offsets of the x of P0 … P3 in it.
 */
export function cubicPointInto(p: ArrayLike<number>, i0: number, i1: number, i2: number, i3: number, t: number, out: { [k: number]: number }, at: number): void {
  const u = 1 - t;
  const b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
  out[at] = b0 * p[i0] + b1 * p[i1] + b2 * p[i2] + b3 * p[i3];
  out[at + 1] = b0 * p[i0 + 1] + b1 * p[i1 + 1] + b2 * p[i2 + 1] + b3 * p[i3 + 1];
}
