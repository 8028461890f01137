import { Vector2 } from 'three';
import { segmentCount, type Spline } from '../../src/index.js';
import { cubicPointInto } from './cubic.js';

/**
 * Flattens a spline into a polyline whose distance to the curve stays within `tolerance`
 * (document units). Each cubic segment gets n uniform steps with n from the classic bound
 * error ≤ (1/8)·max|B''|/n², max|B''| ≤ 6·max(|P0−2P1+P2|, |P1−2P2+P3|). A closed spline's
 * polyline ends on its first point.
 */
export function flattenSpline(s: Spline, tolerance: number, maxSteps = 96): Vector2[] {
  const p = s.points;
  const n = p.length / 2;
  const segments = segmentCount(s);
  const out: Vector2[] = [];
  const xy: [number, number] = [0, 0];
  if (n === 0) return out;
  out.push(new Vector2(p[0], p[1]));
  for (let k = 0; k < segments; k++) {
    const i0 = 6 * k, i1 = i0 + 2, i2 = i0 + 4, i3 = (i0 + 6) % (2 * n);
    const x0 = p[i0], y0 = p[i0 + 1];
    const x1 = p[i1], y1 = p[i1 + 1];
    const x2 = p[i2], y2 = p[i2 + 1];
    const x3 = p[i3], y3 = p[i3 + 1];
    const dd = Math.max(Math.hypot(x0 - 2 * x1 + x2, y0 - 2 * y1 + y2), Math.hypot(x1 - 2 * x2 + x3, y1 - 2 * y2 + y3));
    const steps = Math.min(maxSteps, Math.max(1, Math.ceil(Math.sqrt((0.75 * dd) / tolerance))));
    for (let j = 1; j <= steps; j++) {
      cubicPointInto(p, i0, i1, i2, i3, j / steps, xy, 0);
      out.push(new Vector2(xy[0], xy[1]));
    }
  }
  return out;
}
