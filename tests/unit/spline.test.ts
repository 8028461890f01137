// The wasm spline kernels through the TS wrappers, against closed forms and plain-JS evaluation.
import { beforeAll, describe, expect, test } from 'vitest';
import { Bezier, SplineSet, SplinekitError, init, segmentOf, type Spline } from '../../src/index.js';
import { cubicAt, maxDistance } from './helpers.js';

const K = (4 / 3) * (Math.SQRT2 - 1);

/** A closed circle of radius r from four quarter cubics, anchors at 0°, 90°, 180°, 270°. */
function circle(r: number, cx = 0, cy = 0): Spline {
  const pts: number[] = [];
  for (let q = 0; q < 4; q++) {
    const a = (q * Math.PI) / 2, b = a + Math.PI / 2;
    pts.push(cx + r * Math.cos(a), cy + r * Math.sin(a));
    pts.push(cx + r * (Math.cos(a) - K * Math.sin(a)), cy + r * (Math.sin(a) + K * Math.cos(a)));
    pts.push(cx + r * (Math.cos(b) + K * Math.sin(b)), cy + r * (Math.sin(b) - K * Math.cos(b)));
  }
  return { closed: true, points: Float64Array.from(pts), continuity: [] };
}

beforeAll(async () => {
  await init();
});

describe('Bezier kernels', () => {
  const seg = [0, 0, 10, 30, 40, -20, 50, 10];

  test('point and derivatives agree with power-basis evaluation and finite differences', () => {
    for (const t of [0, 0.2, 0.5, 0.9, 1]) {
      const [x, y] = Bezier.point(seg, t);
      const [ex, ey] = cubicAt(seg, t);
      expect(x).toBeCloseTo(ex, 12);
      expect(y).toBeCloseTo(ey, 12);
    }
    const h = 1e-6, t = 0.37;
    const d = Bezier.derivative(seg, t, 1);
    const p1 = cubicAt(seg, t + h), p0 = cubicAt(seg, t - h);
    expect(d[0]).toBeCloseTo((p1[0] - p0[0]) / (2 * h), 4);
    expect(d[1]).toBeCloseTo((p1[1] - p0[1]) / (2 * h), 4);
  });

  test('split halves trace the original curve', () => {
    const [l, r] = Bezier.split(seg, 0.3);
    for (const s of [0, 0.25, 0.5, 1]) {
      expect(maxDistance(cubicAt(l, s), cubicAt(seg, 0.3 * s))).toBeLessThan(1e-12);
      expect(maxDistance(cubicAt(r, s), cubicAt(seg, 0.3 + 0.7 * s))).toBeLessThan(1e-12);
    }
  });

  test('arc length of a line and of a dense polyline', () => {
    expect(Bezier.arcLength([0, 0, 1, 1, 2, 2, 3, 3])).toBeCloseTo(3 * Math.SQRT2, 12);
    let poly = 0;
    const n = 100000;
    for (let k = 0; k < n; k++) poly += maxDistance(cubicAt(seg, (k + 1) / n), cubicAt(seg, k / n));
    expect(Math.abs(Bezier.arcLength(seg) - poly)).toBeLessThan(1e-6);
  });

  test('bounds are the curve extremes, tighter than the hull', () => {
    const b = Bezier.bounds(seg);
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (let k = 0; k <= 10000; k++) {
      const p = cubicAt(seg, k / 10000);
      lo = [Math.min(lo[0], p[0]), Math.min(lo[1], p[1])];
      hi = [Math.max(hi[0], p[0]), Math.max(hi[1], p[1])];
    }
    expect(b[1]).toBeCloseTo(lo[1], 5);
    expect(b[3]).toBeCloseTo(hi[1], 5);
    expect(b[3]).toBeLessThan(30); // the hull would say 30
  });

  test('Gram matrix of the Bernstein basis is exact', () => {
    const g = Bezier.gram();
    const binom = (n: number, k: number) => { let r = 1; for (let i = 1; i <= k; i++) r = (r * (n - k + i)) / i; return r; };
    for (let i = 0; i < 4; i++)
      for (let j = 0; j < 4; j++) expect(g[4 * i + j]).toBeCloseTo((binom(3, i) * binom(3, j)) / (7 * binom(6, i + j)), 15);
    expect(g.reduce((a, b) => a + b, 0)).toBeCloseTo(1, 14);
  });
});

describe('SplineSet', () => {
  test('bounds, sampling and lengths of a circle', () => {
    const set = SplineSet.from([circle(2, 5, -1)]);
    try {
      const b = set.totalBounds()!;
      expect(b[0]).toBeCloseTo(3, 12);
      expect(b[2]).toBeCloseTo(7, 12);
      expect(b[1]).toBeCloseTo(-3, 12);
      expect(b[3]).toBeCloseTo(1, 12);
      const samples = set.sample(9);
      expect(samples.length).toBe(2 * 9 * 4);
      // The classic cubic circle deviates from the true circle by at most 2.7e-4 r.
      for (let i = 0; i < samples.length; i += 2) {
        expect(Math.abs(Math.hypot(samples[i] - 5, samples[i + 1] + 1) - 2)).toBeLessThan(2.8e-4 * 2);
      }
      const lengths = set.segmentLengths();
      const total = lengths.reduce((a, b) => a + b, 0);
      expect(Math.abs(total - 4 * Math.PI)).toBeLessThan(4 * 2 * 3e-4);
    } finally {
      set.dispose();
    }
  });

  test('continuity of a circle (C1 everywhere) and of a square (corners turning by 90°)', () => {
    const square: Spline = { closed: true, points: new Float64Array(24), continuity: [] };
    const corners = [[0, 0], [3, 0], [3, 3], [0, 3], [0, 0]];
    for (let s = 0; s < 4; s++)
      for (let k = 0; k < 3; k++) {
        square.points[6 * s + 2 * k] = corners[s][0] + (k / 3) * (corners[s + 1][0] - corners[s][0]);
        square.points[6 * s + 2 * k + 1] = corners[s][1] + (k / 3) * (corners[s + 1][1] - corners[s][1]);
      }
    const set = SplineSet.from([circle(1), square]);
    const tags = set.classify(10);
    set.dispose();
    expect(tags[0].map((t) => t.kind)).toEqual(['C1', 'C1', 'C1', 'C1']);
    expect(tags[0].every((t) => Math.abs(t.ratio - 1) < 1e-12)).toBe(true);
    expect(tags[1].map((t) => t.kind)).toEqual(['C0', 'C0', 'C0', 'C0']);
    for (const t of tags[1]) expect(t.angle).toBeCloseTo(Math.PI / 2, 12);
  });

  test('G1 ratio and the relative tolerances', () => {
    // Open spline: junction at (10,0), in tangent (5,0), out tangent (10, 0.02·10·s).
    const make = (sin: number): Spline => ({
      closed: false,
      points: Float64Array.from([0, 0, 2, 0, 5, 0, 10, 0, 20, 10 * sin, 25, 0, 30, 0]),
      continuity: [],
    });
    const set = SplineSet.from([make(0), make(0.005), make(0.02)]);
    const tags = set.classify(30).map((t) => t[0]);
    const strict = set.classify(30, { angleTolerance: 1e-3 }).map((t) => t[0]);
    set.dispose();
    expect(tags[0]).toMatchObject({ kind: 'G1' });
    expect(tags[0].ratio).toBeCloseTo(2, 12);
    expect(tags[1].kind).toBe('G1'); // 0.29° is smooth under the default tolerance
    expect(strict[1].kind).toBe('C0'); // but not under a strict one
    expect(tags[2].kind).toBe('C0'); // 1.1° is a corner
  });

  test('segmentOf wraps around closed splines', () => {
    const c = circle(1);
    const last = segmentOf(c, 3);
    expect(last[6]).toBe(c.points[0]);
    expect(last[7]).toBe(c.points[1]);
  });

  test('malformed splines are rejected with a message naming the problem', () => {
    const bad = { closed: false, points: new Float64Array(6), continuity: [] };
    expect(() => SplineSet.from([bad])).toThrowError(SplinekitError);
    expect(() => SplineSet.from([bad])).toThrowError(/open spline needs 3n\+1/);
    const nan = { closed: false, points: Float64Array.from([0, 0, 1, NaN, 2, 2, 3, 3]), continuity: [] };
    expect(() => SplineSet.from([nan])).toThrowError(/point 1 has a non-finite coordinate/);
  });
});

describe('memory', () => {
  test('1,000 create/query/dispose cycles leave the wasm heap where it was', async () => {
    const { memory } = await import('../../src/index.js');
    const splines = [circle(3), circle(1, 4, 4)];
    const cycle = () => {
      const set = SplineSet.from(splines);
      set.classify(10);
      set.sample(5);
      set.dispose();
      Bezier.split(segmentOf(splines[0], 1), 0.5);
    };
    cycle(); // first use allocates the shared Bezier scratch
    const before = memory().used;
    for (let i = 0; i < 1000; i++) cycle();
    expect(memory().used).toBe(before);
    // And a set that is never disposed does show up: the check can fail.
    const leaked = SplineSet.from(splines);
    leaked.classify(10);
    expect(memory().used).toBeGreaterThan(before);
    leaked.dispose();
  });
});

test('anchorJunction inverts junctionAnchor', async () => {
  const { anchorJunction, junctionAnchor, junctionCount } = await import('../../src/index.js');
  const open = { closed: false, points: new Float64Array(2 * 10) }; // 3 segments
  const closed = { closed: true, points: new Float64Array(2 * 12) }; // 4 segments
  for (const s of [open, closed]) {
    for (let j = 0; j < junctionCount(s); j++) expect(anchorJunction(s, junctionAnchor(s, j))).toBe(j);
  }
  expect(anchorJunction(open, 0)).toBe(-1); // open ends are not junctions
  expect(anchorJunction(open, 9)).toBe(-1);
  expect(anchorJunction(open, 4)).toBe(-1); // a handle
  expect(anchorJunction(closed, 0)).toBe(0);
});
