import { junctionCount, type Spline } from '../../src/index.js';

/**
 * The junction at anchor point `anchor` of a spline, or -1 for the ends of an open spline (the
 * inverse of the package's junctionAnchor).
 */
export function anchorJunction(s: Pick<Spline, 'closed' | 'points'>, anchor: number): number {
  if (anchor % 3 !== 0) return -1;
  const j = s.closed ? anchor / 3 : anchor / 3 - 1;
  return j >= 0 && j < junctionCount(s) ? j : -1;
}
