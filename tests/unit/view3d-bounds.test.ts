// The 3D view's coordinates (web/view3d/bounds.ts): a mesh near the origin is shown in the file's own
// coordinates; one far from it for its size (a scan in georeferenced coordinates) relative to its
// centre, so that single precision keeps its shape.
import { expect, test } from 'vitest';
import { displayOrigin as originOfBox, meshBounds, toDisplay } from '../../web/view3d/bounds.js';

const displayOrigin = (P: ArrayLike<number>) => originOfBox(meshBounds(P).box);

/** A sphere of radius r about c, as a point cloud (latitude × longitude). */
function sphere(c: [number, number, number], r: number, n = 24): Float64Array {
  const out: number[] = [];
  for (let i = 0; i <= n; i++)
    for (let j = 0; j < 2 * n; j++) {
      const a = (Math.PI * i) / n, b = (Math.PI * j) / n;
      out.push(c[0] + r * Math.sin(a) * Math.cos(b), c[1] + r * Math.sin(a) * Math.sin(b), c[2] + r * Math.cos(a));
    }
  return Float64Array.from(out);
}

/** The largest error of the distances from point 0 to every point, taken in `shown` against `exact`. */
function worstDistanceError(exact: ArrayLike<number>, shown: ArrayLike<number>): number {
  let worst = 0;
  for (let i = 3; i < exact.length; i += 3) {
    const d = Math.hypot(exact[i] - exact[0], exact[i + 1] - exact[1], exact[i + 2] - exact[2]);
    const s = Math.hypot(shown[i] - shown[0], shown[i + 1] - shown[1], shown[i + 2] - shown[2]);
    worst = Math.max(worst, Math.abs(d - s));
  }
  return worst;
}

test('a mesh near the origin keeps the coordinates of its file', () => {
  // Its centre 10 times its size away: still shown as it is.
  for (const c of [[0, 0, 0], [0.3, -0.2, 0.1], [10, 10, -20]] as [number, number, number][]) {
    const P = sphere(c, 0.5);
    expect(displayOrigin(P)).toEqual([0, 0, 0]);
    expect(Array.from(toDisplay(P, [0, 0, 0]))).toEqual(Array.from(Float32Array.from(P)));
  }
  expect(displayOrigin(new Float64Array(0))).toEqual([0, 0, 0]);
});

test('a mesh far from the origin is shown about its centre, where single precision keeps its shape', () => {
  const c: [number, number, number] = [500000, 4000000, 100];
  const P = sphere(c, 1);
  const origin = displayOrigin(P);
  for (let k = 0; k < 3; k++) expect(origin[k]).toBeCloseTo(c[k], 6);
  const shown = toDisplay(P, origin);
  // Relative to the centre: single-precision rounding of unit coordinates.
  expect(worstDistanceError(P, shown)).toBeLessThan(1e-6);
  // As they are: a float is 0.25 apart at 4e6, and the sphere of radius 1 comes out blocky.
  expect(worstDistanceError(P, Float32Array.from(P))).toBeGreaterThan(0.05);
  // The shown points are the file's less the origin.
  for (let i = 0; i < P.length; i++) expect(Math.abs(shown[i] - (P[i] - origin[i % 3]))).toBeLessThan(1e-6);
});
