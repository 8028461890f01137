import { compose, fromDefinition, fromTransformAttribute, inverse, type Matrix } from 'transformation-matrix';
import { IDENTITY_MATRIX, toMatrix } from '../core/affine.js';

/**
 * An SVG affine matrix(a b c d e f) as an object: x' = a x + c y + e, y' = b x + d y + f (the form
 * of the transformation-matrix library that parses transform lists; src/core/affine.ts has the
 * tuple form `AffineMatrix` and the conversions).
 */
export type { Matrix };

/** The identity in object form: IDENTITY_MATRIX of src/core/affine.ts (frozen). */
export const IDENTITY: Readonly<Matrix> = Object.freeze(toMatrix(IDENTITY_MATRIX));

/** m1 · m2 (m2 applied first). */
export function multiply(m1: Matrix, m2: Matrix): Matrix {
  return compose(m1, m2);
}

export function translation(x: number, y: number): Matrix {
  return { a: 1, b: 0, c: 0, d: 1, e: x, f: y };
}

export function isIdentity(m: Matrix): boolean {
  return m.a === 1 && m.b === 0 && m.c === 0 && m.d === 1 && m.e === 0 && m.f === 0;
}

export function determinant(m: Matrix): number {
  return m.a * m.d - m.b * m.c;
}

/** The inverse, or null when the matrix is singular (the element collapses and cannot be written back). */
export function invert(m: Matrix): Matrix | null {
  const det = determinant(m);
  const scale = Math.max(Math.abs(m.a), Math.abs(m.b), Math.abs(m.c), Math.abs(m.d));
  if (!Number.isFinite(det) || Math.abs(det) <= 1e-14 * scale * scale) return null;
  return inverse(m);
}

/**
 * Parses an SVG transform list ("translate(10) rotate(30 5 5) …"); throws with the parser's reason.
 * The grammar lets transforms follow one another with no separator ("translate(84.9)scale(.9375)",
 * as flag-icons and svgo write them), which the parser library does not accept: a space goes in.
 */
export function parseTransform(text: string): Matrix {
  const trimmed = text.trim().replace(/\)(?=[a-zA-Z])/g, ') ');
  if (trimmed === '') return { ...IDENTITY };
  const m = compose(...fromDefinition(fromTransformAttribute(trimmed)), IDENTITY);
  for (const v of [m.a, m.b, m.c, m.d, m.e, m.f]) if (!Number.isFinite(v)) throw new Error('a transform value is not finite');
  return m;
}

/** Applies m to every x,y pair of `points` in place. */
export function transformPoints(m: Matrix, points: Float64Array): Float64Array {
  for (let i = 0; i < points.length; i += 2) {
    const x = points[i], y = points[i + 1];
    points[i] = m.a * x + m.c * y + m.e;
    points[i + 1] = m.b * x + m.d * y + m.f;
  }
  return points;
}

/**
 * The viewBox → viewport transform of SVG's preserveAspectRatio (SVG 1.1 §7.8), for nested
 * `svg` and instantiated `symbol` elements.
 */
export function viewBoxTransform(
  viewBox: [number, number, number, number],
  width: number,
  height: number,
  preserveAspectRatio = 'xMidYMid meet',
): Matrix {
  const [vx, vy, vw, vh] = viewBox;
  let sx = width / vw, sy = height / vh;
  const [align = 'xMidYMid', meetOrSlice = 'meet'] = preserveAspectRatio.trim().split(/\s+/);
  if (align !== 'none') {
    const s = meetOrSlice === 'slice' ? Math.max(sx, sy) : Math.min(sx, sy);
    sx = sy = s;
  }
  let tx = -vx * sx, ty = -vy * sy;
  if (align.includes('xMid')) tx += (width - vw * sx) / 2;
  if (align.includes('xMax')) tx += width - vw * sx;
  if (align.includes('YMid')) ty += (height - vh * sy) / 2;
  if (align.includes('YMax')) ty += height - vh * sy;
  return { a: sx, b: 0, c: 0, d: sy, e: tx, f: ty };
}
