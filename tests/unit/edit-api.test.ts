// The edit API (CatmullRom, LocalEdit) on the real wasm: strokes, resampling, drags, tangents,
// errors, and the budgets of DESIGN.md (allocation-free updates, no leaks).
import { beforeAll, describe, expect, test } from 'vitest';
import { CatmullRom, LocalEdit, SplinekitError, init, memory, type StrokeSample } from '../../src/index.js';
import { cubicAt } from './helpers.js';

beforeAll(async () => {
  await init();
});

function spread(p: ArrayLike<number>): number {
  const gaps: number[] = [];
  for (let i = 2; i < p.length; i += 2) gaps.push(Math.hypot(p[i] - p[i - 2], p[i + 1] - p[i - 1]));
  const mean = gaps.reduce((a, b) => a + b, 0) / gaps.length;
  return Math.sqrt(gaps.reduce((a, g) => a + (g - mean) ** 2, 0) / gaps.length) / mean;
}

/** A stroke that speeds up: samples bunch at its start. */
function stroke(n: number): StrokeSample[] {
  return Array.from({ length: n }, (_, i) => {
    const t = (i / (n - 1)) ** 2;
    return { x: 200 * t, y: 40 * Math.sin(5 * t), pressure: 0.2 + 0.6 * t, time: 16 * i };
  });
}

describe('CatmullRom', () => {
  test('from a stroke: interpolates every sample, keeps pressure, and resampling evens the spacing keeping the count', () => {
    const samples = stroke(120);
    const raw = CatmullRom.fromStroke(samples);
    const even = CatmullRom.fromStroke(samples, { resample: true });
    try {
      expect(raw.count).toBe(120);
      expect(raw.pressure![119]).toBeCloseTo(0.8, 15);
      expect(raw.time![3]).toBe(48);
      const p = raw.points();
      samples.forEach((s, i) => expect([p[2 * i], p[2 * i + 1]]).toEqual([s.x, s.y]));
      // The curve passes through every control point: the Bézier anchors are the points.
      const b = raw.toBezier();
      for (let i = 0; i < raw.count; i++) expect(b.points[6 * i]).toBe(p[2 * i]);
      expect(even.count).toBe(120);
      expect(spread(p)).toBeGreaterThan(0.5);
      expect(spread(even.points())).toBeLessThan(0.02);
      expect(even.pressure!.every((v, i, a) => i === 0 || v >= a[i - 1])).toBe(true);
    } finally {
      raw.dispose();
      even.dispose();
    }
  });

  test('Bézier segments agree with point(): the pyramid evaluation and the exact conversion', () => {
    const c = CatmullRom.create([[0, 0], [3, 4], [5, 1], [9, 3], [10, 8]], { parameterization: 'chordal' });
    try {
      const b = c.toBezier();
      for (let s = 0; s < c.segmentCount; s++) {
        const seg = b.points.slice(6 * s, 6 * s + 8);
        for (const u of [0.1, 0.5, 0.77]) {
          const [x, y] = c.point(s, u);
          const [bx, by] = cubicAt(seg, u);
          expect(Math.hypot(x - bx, y - by)).toBeLessThan(1e-12 * 15);
        }
      }
      expect(b.continuity.map((t) => t.kind)).toEqual(['G1', 'G1', 'G1']);
      const n = c.normal(1, 0.5);
      expect(Math.hypot(...n)).toBeCloseTo(1, 14);
    } finally {
      c.dispose();
    }
  });

  test('resampling the window replaces its inside only, at the chosen resolution', () => {
    const c = CatmullRom.create(Array.from({ length: 12 }, (_, i) => [i * i * 0.3, Math.sin(i)] as [number, number]));
    try {
      const before = c.points();
      const ends = c.resampleRange(3, 6, 8);
      expect(ends).toEqual({ first: 3, last: 12 });
      expect(c.count).toBe(12 - 2 + 8);
      const after = c.points();
      expect(Array.from(after.slice(0, 8))).toEqual(Array.from(before.slice(0, 8)));
      expect(Array.from(after.slice(24))).toEqual(Array.from(before.slice(12)));
      expect(spread(after.slice(6, 26))).toBeLessThan(0.05);
    } finally {
      c.dispose();
    }
  });

  test('tangent editing sets the handles at a control point and nowhere else', () => {
    const c = CatmullRom.create([[0, 0], [1, 0], [2, 0], [3, 0], [4, 0]], { parameterization: 'uniform' });
    try {
      expect(c.tangent(2)).toEqual([1, 0]);
      const before = c.toBezier().points;
      c.setTangent(2, [0, 3]);
      expect(c.tangentOverridden(2)).toBe(true);
      const after = c.toBezier().points;
      expect([after[14], after[15]]).toEqual([2, 1]); // P2 + T/3
      expect([after[10], after[11]]).toEqual([2, -1]); // P2 − T/3
      expect(Array.from(after.slice(0, 8))).toEqual(Array.from(before.slice(0, 8)));
      c.clearTangent(2);
      expect(Array.from(c.toBezier().points)).toEqual(Array.from(before));
    } finally {
      c.dispose();
    }
  });

  test('bad input throws a SplinekitError naming it; a disposed curve refuses use', () => {
    expect(() => CatmullRom.create([[0, 0]])).toThrow(/at least 2 control points/);
    expect(() => CatmullRom.create([[0, 0], [1, 1]], { closed: true })).toThrow(/at least 3/);
    expect(() => CatmullRom.create([0, 0, NaN, 1])).toThrow(/control point 1 has a non-finite x/);
    expect(() => CatmullRom.fromStroke([{ x: 1, y: 1 }, { x: 1, y: 1 }])).toThrow(/fewer than 2 distinct points/);
    expect(() => CatmullRom.fromJSON({ points: [[0, 0], [1]] }, 'c.json')).toThrow(/c.json: point 1 must be/);
    const c = CatmullRom.create([[0, 0], [1, 1], [2, 0]]);
    expect(() => c.setPoints([[0, 0]])).toThrow(SplinekitError);
    expect(c.count).toBe(3); // kept
    expect(() => c.resampleRange(2, 1, 3)).toThrow(/must come before/);
    c.dispose();
    expect(() => c.count).toThrow(/after dispose/);
  });
});

describe('LocalEdit', () => {
  test('a drag spreads over the window, the ends and outside stay, end() commits and cancel() does not', () => {
    const c = CatmullRom.create(Array.from({ length: 30 }, (_, i) => [i, Math.sin(i / 3)] as [number, number]));
    try {
      const before = c.points();
      const e = LocalEdit.begin(c, 10, { left: 4, right: 6, falloff: 'gaussian' });
      expect(e.window.first).toBe(6);
      expect(e.window.last).toBe(16);
      expect(e.window.weights[4]).toBe(1);
      expect(e.window.weights[0]).toBe(0);
      expect(e.window.weights[10]).toBe(0);
      const p = e.move(2, 5);
      expect(p[20]).toBe(before[20] + 2);
      expect(p[21]).toBe(before[21] + 5);
      for (let i = 0; i < 30; i++) {
        const inside = i > 6 && i < 16;
        expect(p[2 * i] === before[2 * i] && p[2 * i + 1] === before[2 * i + 1]).toBe(!inside);
      }
      e.end();
      expect(Array.from(c.points())).toEqual(Array.from(p));
      expect(() => e.move(1, 1)).toThrow(/after end/);
      const moved = c.points();
      const again = LocalEdit.begin(c, 3);
      again.move(100, 100);
      again.cancel();
      expect(Array.from(c.points())).toEqual(Array.from(moved));
    } finally {
      c.dispose();
    }
  });

  test('apply() shows a drag in flight without changing where later moves start; cancel() undoes it', () => {
    const c = CatmullRom.create(Array.from({ length: 12 }, (_, i) => [i, 0] as [number, number]), { parameterization: 'uniform' });
    try {
      const before = c.points();
      c.setTangent(9, [0, 2]);
      const e = LocalEdit.begin(c, 5, { left: 3, right: 3, falloff: 'linear' });
      e.move(0, 3);
      e.apply();
      expect(c.points()[11]).toBe(3);
      expect(c.tangentOverridden(9)).toBe(true); // the curve keeps its tangents
      // The next move starts from the positions at begin, not from the applied ones.
      expect(e.move(0, 1)[11]).toBe(1);
      expect(e.move(0, 1)[9]).toBeCloseTo(2 / 3, 14); // linear: 1 - 1/3 of the way to the end
      e.cancel();
      expect(Array.from(c.points())).toEqual(Array.from(before));
    } finally {
      c.dispose();
    }
  });

  test('moves allocate nothing, and 1,000 curves and edits made and disposed leave the heap where it was', () => {
    const c = CatmullRom.fromStroke(stroke(2000));
    const e = LocalEdit.begin(c, 1000, { left: 400, right: 400, normals: true });
    e.move(1, 1);
    const heap = memory();
    for (let i = 0; i < 1000; i++) e.move(Math.sin(i), Math.cos(i));
    expect(memory()).toEqual(heap);
    e.dispose();
    c.dispose();
    const used = memory().used;
    for (let i = 0; i < 1000; i++) {
      const k = CatmullRom.create([[0, 0], [1, 2], [3, 1], [4, 4]]);
      LocalEdit.begin(k, 1, { left: 1, right: 2 }).end();
      k.dispose();
    }
    expect(memory().used).toBe(used);
  });

  test('bad requests throw naming the problem and leave the curve as it was', () => {
    const c = CatmullRom.create([[0, 0], [1, 1], [2, 0], [3, 1]]);
    try {
      expect(() => LocalEdit.begin(c, 4)).toThrow(/control point 4 is out of range/);
      expect(() => LocalEdit.begin(c, 1, { alpha: 0 })).toThrow(/alpha must be a positive number/);
      expect(() => LocalEdit.begin(c, 1, { left: -1 })).toThrow(/left side/);
      expect(() => LocalEdit.begin(c, 1, { falloff: 'box' as never })).toThrow(/falloff must be/);
      const e = LocalEdit.begin(c, 1);
      expect(() => e.move(NaN, 0)).toThrow(/finite/);
      e.dispose();
      expect(Array.from(c.points())).toEqual([0, 0, 1, 1, 2, 0, 3, 1]);
    } finally {
      c.dispose();
    }
  });
});
