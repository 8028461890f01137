// Small pieces of the editor (web/) that its modes share and that run without a browser: the
// cubic point kernel both 2D drawing paths use.
import { beforeAll, describe, expect, test } from 'vitest';
import { Bezier, init } from '../../src/index.js';
import { cubicPointInto } from '../../web/view2d/cubic.js';
import { cubicAt } from './helpers.js';

beforeAll(async () => {
  await init();
});

describe('cubicPointInto', () => {
  test('agrees with the power basis and with the core (Bezier.point), at offsets in a longer array', () => {
    // Two segments sharing an end, x,y pairs: P0 P1 P2 P3 P4 P5 P6.
    const p = Float64Array.from([0, 0, 10, 40, 60, -20, 100, 10, 140, 40, 150, 90, 80, 120]);
    const out = new Float64Array(6);
    for (const seg of [0, 1]) {
      const i = 6 * seg;
      const c = Array.from(p.subarray(i, i + 8));
      for (const t of [0, 0.1, 0.25, 0.5, 0.73, 1]) {
        cubicPointInto(p, i, i + 2, i + 4, i + 6, t, out, 2);
        const power = cubicAt(c, t), core = Bezier.point(c, t);
        expect(out[2]).toBeCloseTo(power[0], 10);
        expect(out[3]).toBeCloseTo(power[1], 10);
        expect(out[2]).toBeCloseTo(core[0], 10);
        expect(out[3]).toBeCloseTo(core[1], 10);
      }
    }
    // The ends are the end points exactly, and nothing else in `out` was written.
    cubicPointInto(p, 6, 8, 10, 12, 1, out, 4);
    expect([out[4], out[5]]).toEqual([80, 120]);
    expect([out[0], out[1]]).toEqual([0, 0]);
  });

  test('a closed spline wraps: the last segment ends on the first point', () => {
    const p = [0, 0, 1, 2, 3, 2, 4, 0, 3, -2, 1, -2]; // 3 segments' worth: 3n = 6 points
    const out = [NaN, NaN];
    cubicPointInto(p, 6, 8, 10, 0, 1, out, 0);
    expect(out).toEqual([0, 0]);
  });
});
