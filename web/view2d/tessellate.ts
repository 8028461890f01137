import { Vector2 } from 'three';
import { segmentCount, type Spline } from '../../src/index.js';

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
  if (n === 0) return out;
  out.push(new Vector2(p[0], p[1]));
  for (let k = 0; k < segments; k++) {
    const i0 = 3 * k, i1 = i0 + 1, i2 = i0 + 2, i3 = (i0 + 3) % n;
    const x0 = p[2 * i0], y0 = p[2 * i0 + 1];
    const x1 = p[2 * i1], y1 = p[2 * i1 + 1];
    const x2 = p[2 * i2], y2 = p[2 * i2 + 1];
    const x3 = p[2 * i3], y3 = p[2 * i3 + 1];
    const dd = Math.max(Math.hypot(x0 - 2 * x1 + x2, y0 - 2 * y1 + y2), Math.hypot(x1 - 2 * x2 + x3, y1 - 2 * y2 + y3));
    const steps = Math.min(maxSteps, Math.max(1, Math.ceil(Math.sqrt((0.75 * dd) / tolerance))));
    for (let j = 1; j <= steps; j++) {
      const t = j / steps, u = 1 - t;
      const b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
      out.push(new Vector2(b0 * x0 + b1 * x1 + b2 * x2 + b3 * x3, b0 * y0 + b1 * y1 + b2 * y2 + b3 * y3));
    }
  }
  return out;
}
