import { IDENTITY_MATRIX, type AffineMatrix } from '../../../src/index.js';

/**
 * 2×3 affine matrices as SVG writes them, [a b c d e f]: x' = a·x + c·y + e, y' = b·x + d·y + f.
 * The pose editing math of skin mode (compose, rotate or scale about a point), plain functions.
 */

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

export function apply(m: AffineMatrix, x: number, y: number): [number, number] {
  return [m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]];
}

export function translation(dx: number, dy: number): AffineMatrix {
  return [1, 0, 0, 1, dx, dy];
}

/** Rotation by `theta` radians (clockwise on screen, as y points down) about (cx, cy). */
export function rotationAbout(theta: number, cx: number, cy: number): AffineMatrix {
  const c = Math.cos(theta), s = Math.sin(theta);
  return [c, s, -s, c, cx - c * cx + s * cy, cy - s * cx - c * cy];
}

/** Uniform scaling by `k` about (cx, cy). */
export function scalingAbout(k: number, cx: number, cy: number): AffineMatrix {
  return [k, 0, 0, k, cx - k * cx, cy - k * cy];
}

/** The rotation angle of the linear part (radians), as the polar decomposition sees it. */
export function angleOf(m: AffineMatrix): number {
  return Math.atan2(m[1] - m[2], m[0] + m[3]);
}

/** The mean scale of the linear part: sqrt(|det|). */
export function scaleOf(m: AffineMatrix): number {
  return Math.sqrt(Math.abs(m[0] * m[3] - m[1] * m[2]));
}

export function isIdentity(m: AffineMatrix, eps = 1e-12): boolean {
  return m.every((v, i) => Math.abs(v - IDENTITY_MATRIX[i]) <= eps);
}

export function sameMatrix(m: AffineMatrix, n: AffineMatrix, eps = 0): boolean {
  return m.every((v, i) => Math.abs(v - n[i]) <= eps);
}

export function isFiniteMatrix(m: unknown): m is AffineMatrix {
  return Array.isArray(m) && m.length === 6 && m.every((v) => typeof v === 'number' && Number.isFinite(v));
}

/** The inverse, or null for a singular matrix. */
export function invert(m: AffineMatrix): AffineMatrix | null {
  const det = m[0] * m[3] - m[1] * m[2];
  if (!Number.isFinite(det) || Math.abs(det) < 1e-14) return null;
  const a = m[3] / det, b = -m[1] / det, c = -m[2] / det, d = m[0] / det;
  return [a, b, c, d, -(a * m[4] + c * m[5]), -(b * m[4] + d * m[5])];
}
