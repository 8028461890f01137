/**
 * The spline data model every capability shares (see DESIGN.md, "Data model").
 *
 * A spline is a chain of cubic Bézier segments stored as flat x,y control points: 3n+1 points
 * for an open spline of n segments, 3n for a closed one (the last segment ends at point 0).
 * Each junction carries a continuity tag: for an open spline tag j sits at point 3(j+1)
 * (interior anchors only), for a closed one tag j sits at anchor point 3j.
 */

/** What is preserved at a junction; 'angle' and 'none' are only ever set by the user. */
export type ContinuityKind = 'none' | 'C0' | 'C1' | 'G1' | 'angle';

/** Every {@link ContinuityKind}, from the weakest ('none', a break) to the user-only 'angle'. */
export const CONTINUITY_KINDS: readonly ContinuityKind[] = ['none', 'C0', 'C1', 'G1', 'angle'];

/** The continuity at one junction of a spline, as detected on import or set by the user. */
export interface ContinuityTag {
  /** What is preserved at the junction. */
  kind: ContinuityKind;
  /** |H_out − P| / |P − H_in| at import (1 for C1, the kept ratio for G1, 0 if a handle is degenerate). */
  ratio: number;
  /** Signed turn in radians from the incoming to the outgoing tangent (the corner kept by 'angle'). */
  angle: number;
}

/**
 * A chain of cubic Bézier segments with one continuity tag per junction (see the module comment
 * for the point layout).
 */
export interface Spline {
  /** Whether the last segment ends at point 0 (3n points) rather than at its own end (3n+1). */
  closed: boolean;
  /** x,y pairs: 2·(3n+1) numbers when open, 2·3n when closed. */
  points: Float64Array;
  /** One tag per junction: n−1 when open, n when closed. */
  continuity: ContinuityTag[];
}

/** Number of cubic segments of a spline. */
export function segmentCount(s: Pick<Spline, 'closed' | 'points'>): number {
  const n = s.points.length / 2;
  if (n <= 1) return 0;
  return s.closed ? Math.floor(n / 3) : Math.floor((n - 1) / 3);
}

/** Number of junctions (continuity tags) of a spline. */
export function junctionCount(s: Pick<Spline, 'closed' | 'points'>): number {
  const n = segmentCount(s);
  return n === 0 ? 0 : s.closed ? n : n - 1;
}

/** Point index of the anchor of junction j. */
export function junctionAnchor(s: Pick<Spline, 'closed'>, j: number): number {
  return s.closed ? 3 * j : 3 * (j + 1);
}

/** The junction at anchor point `anchor`, or -1 for a handle or an end of an open spline (inverse of junctionAnchor). */
export function anchorJunction(s: Pick<Spline, 'closed' | 'points'>, anchor: number): number {
  if (anchor % 3 !== 0) return -1;
  const j = s.closed ? anchor / 3 : anchor / 3 - 1;
  return j >= 0 && j < junctionCount(s) ? j : -1;
}

/** Copies segment k of a spline into `target` (8 numbers: x0 y0 x1 y1 x2 y2 x3 y3). */
export function segmentOf(s: Pick<Spline, 'closed' | 'points'>, k: number, target = new Float64Array(8)): Float64Array {
  const n = s.points.length / 2;
  for (let i = 0; i < 4; i++) {
    let p = 3 * k + i;
    if (p >= n) p -= n;
    target[2 * i] = s.points[2 * p];
    target[2 * i + 1] = s.points[2 * p + 1];
  }
  return target;
}

/** A deep copy (points and tags). */
export function cloneSpline(s: Spline): Spline {
  return { closed: s.closed, points: s.points.slice(), continuity: s.continuity.map((t) => ({ ...t })) };
}
