/**
 * 2D affine matrices, the package's one home for them: the flat tuple `AffineMatrix` that the skin
 * rig, animations and embedders pass around ([a, b, c, d, e, f], SVG's matrix(a b c d e f):
 * x' = a·x + c·y + e, y' = b·x + d·y + f), its identity, composition and the pose-editing
 * constructors (rotate or scale about a point), and conversions to and from the object form
 * `Matrix` ({a, b, c, d, e, f}) that SVG import uses (src/svg/matrix.ts).
 *
 *   import { affine, IDENTITY_MATRIX } from 'splinekit';
 *   const turn = affine.multiply(affine.rotationAbout(0.3, cx, cy), pose[i]);   // first pose, then turn
 *
 * Every function returns a new array; none changes its arguments.
 */
import type { Matrix } from 'transformation-matrix';

/** A 2×3 affine matrix as in SVG's matrix(a b c d e f): x' = a·x + c·y + e, y' = b·x + d·y + f. */
export type AffineMatrix = readonly [number, number, number, number, number, number];

/** The identity [1, 0, 0, 1, 0, 0] (frozen). */
export const IDENTITY_MATRIX: AffineMatrix = Object.freeze([1, 0, 0, 1, 0, 0] as const);

/** m·n: first n, then m. */
export function multiply(m: AffineMatrix, n: AffineMatrix): AffineMatrix {
  return [
    m[0] * n[0] + m[2] * n[1],
    m[1] * n[0] + m[3] * n[1],
    m[0] * n[2] + m[2] * n[3],
    m[1] * n[2] + m[3] * n[3],
    m[0] * n[4] + m[2] * n[5] + m[4],
    m[1] * n[4] + m[3] * n[5] + m[5],
  ];
}

/** The image of the point (x, y). */
export function apply(m: AffineMatrix, x: number, y: number): [number, number] {
  return [m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]];
}

/** Translation by (dx, dy). */
export function translation(dx: number, dy: number): AffineMatrix {
  return [1, 0, 0, 1, dx, dy];
}

/** Rotation by `theta` radians about (cx, cy) (from +x towards +y: clockwise on screen, where y points down). */
export function rotationAbout(theta: number, cx: number, cy: number): AffineMatrix {
  const c = Math.cos(theta), s = Math.sin(theta);
  return [c, s, -s, c, cx - c * cx + s * cy, cy - s * cx - c * cy];
}

/** Uniform scaling by `k` about (cx, cy). */
export function scalingAbout(k: number, cx: number, cy: number): AffineMatrix {
  return [k, 0, 0, k, cx - k * cx, cy - k * cy];
}

/** The inverse, or null for a singular matrix (|det| below 1e-14 or not finite). */
export function invert(m: AffineMatrix): AffineMatrix | null {
  const det = m[0] * m[3] - m[1] * m[2];
  if (!Number.isFinite(det) || Math.abs(det) < 1e-14) return null;
  const a = m[3] / det, b = -m[1] / det, c = -m[2] / det, d = m[0] / det;
  return [a, b, c, d, -(a * m[4] + c * m[5]), -(b * m[4] + d * m[5])];
}

/** The rotation angle of the linear part (radians), as its polar decomposition sees it. */
export function angleOf(m: AffineMatrix): number {
  return Math.atan2(m[1] - m[2], m[0] + m[3]);
}

/** The mean scale of the linear part: sqrt(|det|). */
export function scaleOf(m: AffineMatrix): number {
  return Math.sqrt(Math.abs(m[0] * m[3] - m[1] * m[2]));
}

/** True when every entry is within `eps` of the identity's. */
export function isIdentity(m: AffineMatrix, eps = 1e-12): boolean {
  return m.every((v, i) => Math.abs(v - IDENTITY_MATRIX[i]) <= eps);
}

/** True when every entry of m is within `eps` of n's. */
export function sameMatrix(m: AffineMatrix, n: AffineMatrix, eps = 0): boolean {
  return m.every((v, i) => Math.abs(v - n[i]) <= eps);
}

/** True for an array of 6 finite numbers (e.g. a matrix read from JSON). */
export function isFiniteMatrix(m: unknown): m is AffineMatrix {
  return Array.isArray(m) && m.length === 6 && m.every((v) => typeof v === 'number' && Number.isFinite(v));
}

/** The object form {a, b, c, d, e, f} of a tuple matrix. */
export function toMatrix(m: AffineMatrix): Matrix {
  return { a: m[0], b: m[1], c: m[2], d: m[3], e: m[4], f: m[5] };
}

/** The tuple form [a, b, c, d, e, f] of an object matrix. */
export function fromMatrix(m: Readonly<Matrix>): AffineMatrix {
  return [m.a, m.b, m.c, m.d, m.e, m.f];
}
