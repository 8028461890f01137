// The Morph class of the package: keys in, Bézier in-betweens out. Checked against independent
// computations: the keys' own curves (sampled by the power basis in helpers.ts), rigid motions,
// the animated SVG's frames read back, the wasm heap around updates and create/dispose cycles.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, test } from 'vitest';
import { init, memory, Morph, parseSVG, SplinekitError, type Spline } from '../../src/index.js';
import { cubicAt, sharedData } from './helpers.js';

const glyph = (name: string) => parseSVG(readFileSync(join(sharedData, 'svg/morph', `${name}.svg`)), { name });
let monoG: ReturnType<typeof glyph>, romanG: ReturnType<typeof glyph>, monoA: ReturnType<typeof glyph>, serifA: ReturnType<typeof glyph>;

beforeAll(async () => {
  await init();
  monoG = glyph('NimbusMonoPS-Bold_G');
  romanG = glyph('NimbusRoman-Bold_G');
  monoA = glyph('LiberationMono-Bold_a');
  serifA = glyph('NimbusRoman-Bold_a');
});

/** Dense samples of every segment of closed or open splines (x,y pairs). */
function samples(splines: readonly Pick<Spline, 'closed' | 'points'>[], per = 40): number[] {
  const out: number[] = [];
  for (const s of splines) {
    const n = s.points.length / 2, segs = s.closed ? n / 3 : (n - 1) / 3;
    for (let k = 0; k < segs; k++) {
      const c: number[] = [];
      for (let i = 0; i < 4; i++) c.push(s.points[2 * ((3 * k + i) % n)], s.points[2 * ((3 * k + i) % n) + 1]);
      for (let i = 0; i <= per; i++) out.push(...cubicAt(c, i / per));
    }
  }
  return out;
}

/** Largest distance from points `a` to the nearest of points `b` (a one-sided Hausdorff distance). */
function hausdorff(a: number[], b: number[]): number {
  let worst = 0;
  for (let i = 0; i < a.length; i += 2) {
    let best = Infinity;
    for (let j = 0; j < b.length; j += 2) best = Math.min(best, Math.hypot(a[i] - b[j], a[i + 1] - b[j + 1]));
    worst = Math.max(worst, best);
  }
  return worst;
}

const square = (x: number, y: number, s: number): Spline => {
  const v = [[x, y], [x + s, y], [x + s, y + s], [x, y + s]];
  const p: number[] = [];
  v.forEach((a, i) => {
    const b = v[(i + 1) % 4];
    p.push(a[0], a[1], a[0] + (b[0] - a[0]) / 3, a[1] + (b[1] - a[1]) / 3, a[0] + (2 * (b[0] - a[0])) / 3, a[1] + (2 * (b[1] - a[1])) / 3);
  });
  return { closed: true, points: Float64Array.from(p), continuity: [] };
};

describe('Morph', () => {
  test('t = 0 and t = 1 trace the keys, for both interpolations', () => {
    for (const interpolation of ['linear', 'intrinsic'] as const) {
      const m = Morph.create(monoG, romanG, { interpolation });
      const size = romanG.size;
      // Every point of the in-between lies on the key and every point of the key on the in-between.
      const k0 = samples(m.splines(0), 6), k1 = samples(m.splines(1), 6);
      const a = samples(monoG.splines, 6), b = samples(romanG.splines, 6);
      expect(hausdorff(k0, samples(monoG.splines, 400))).toBeLessThan(1e-3 * size);
      expect(hausdorff(a, samples(m.splines(0), 200))).toBeLessThan(1e-3 * size);
      expect(hausdorff(k1, samples(romanG.splines, 400))).toBeLessThan(1e-3 * size);
      expect(hausdorff(b, samples(m.splines(1), 200))).toBeLessThan(1e-3 * size);
      m.dispose();
    }
  });

  test('a key blended with a translated copy of itself moves rigidly, with zero work', () => {
    const moved = monoG.splines.map((s) => ({ closed: s.closed, points: s.points.map((v, i) => v + (i % 2 ? -40 : 90)) }));
    const m = Morph.create(monoG, moved);
    expect(m.work).toBeLessThan(1e-9);
    const f0 = m.at(0).slice(), f = m.at(0.25).slice();
    for (let i = 0; i < f.length; i += 2) {
      expect(f[i] - f0[i]).toBeCloseTo(22.5, 9);
      expect(f[i + 1] - f0[i + 1]).toBeCloseTo(-10, 9);
    }
    m.dispose();
  });

  test('A → B at t traces B → A at 1 − t', () => {
    const ab = Morph.create(monoG, romanG), ba = Morph.create(romanG, monoG);
    expect(ab.work).toBeCloseTo(ba.work, 6);
    const f = samples(ab.splines(0.3), 8), g = samples(ba.splines(0.7), 80);
    expect(hausdorff(f, g)).toBeLessThan(2e-3 * romanG.size);
    ab.dispose();
    ba.dispose();
  });

  test('contours pair up by place: the bowl of one "a" blends into the bowl of the other', () => {
    const m = Morph.create(monoA, serifA);
    expect(m.contourCount).toBe(2);
    const pairs = m.correspondence.contours.map((c) => [c.contourA, c.contourB]);
    expect(pairs).toEqual([[0, 0], [1, 1]]);
    // Liberation (TrueType) and Nimbus (CFF) wind opposite ways: the search reverses B's contours.
    expect(m.correspondence.contours.every((c) => c.reversed)).toBe(true);
    m.dispose();
  });

  test('a contour without partner grows from a point inside its partner’s region', () => {
    const one = [square(0, 0, 100)];
    const two = [square(0, 0, 100), square(40, 40, 20)];
    const m = Morph.create(one, two);
    expect(m.contourCount).toBe(2);
    const grown = m.correspondence.contours[1];
    expect(grown).toMatchObject({ contourA: -1, contourB: 1 });
    const p = m.at(0), s = m.starts[1];
    for (let i = 0; i < m.counts[1]; i++) {
      expect(p[2 * (s + i)]).toBe(p[2 * s]);
      expect(p[2 * (s + i)]).toBeGreaterThan(0);
      expect(p[2 * (s + i)]).toBeLessThan(100);
      expect(p[2 * (s + i) + 1]).toBeGreaterThan(0);
      expect(p[2 * (s + i) + 1]).toBeLessThan(100);
    }
    m.dispose();
  });

  test('open paths morph as open paths, ends to ends; an open path never pairs with a closed one', () => {
    const wave = parseSVG('<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 50C30 0 60 0 80 50C100 100 130 100 160 50"/></svg>');
    const zigzag = parseSVG('<svg xmlns="http://www.w3.org/2000/svg"><path d="M0 90L40 10L80 90L120 10L160 90"/></svg>');
    const m = Morph.create(wave, zigzag);
    expect(m.closed).toEqual([false]);
    expect((m.counts[0] - 1) % 3).toBe(0);
    const n = m.counts[0];
    const at = (t: number) => Array.from(m.at(t));
    expect(at(0).slice(0, 2)).toEqual([0, 50]);
    expect(at(0).slice(2 * n - 2)).toEqual([160, 50]);
    expect(at(1).slice(0, 2)).toEqual([0, 90]);
    expect(at(1).slice(2 * n - 2)).toEqual([160, 90]);
    m.dispose();
    const mixed = Morph.create(wave, [square(0, 0, 100)]);
    expect(mixed.correspondence.contours.map((c) => [c.contourA, c.contourB])).toEqual([[0, -1], [-1, 0]]);
    expect(mixed.closed).toEqual([false, true]);
    mixed.dispose();
  });

  test('a pin holds its points together at both ends', () => {
    const a = [square(0, 0, 100)], b = [square(0, 0, 100)];
    const m = Morph.create(a, b, { pins: [{ a: [100, 0], b: [100, 100] }] });
    expect(m.correspondence.contours[0].pins).toBe(1);
    const { a: ka, b: kb } = m.correspondence;
    let held = false;
    for (let k = 0; k < ka.length; k += 2) if (ka[k] === 100 && ka[k + 1] === 0 && kb[k] === 100 && kb[k + 1] === 100) held = true;
    expect(held).toBe(true);
    expect(m.work).toBeGreaterThan(0); // without the pin the identity costs nothing
    m.dispose();
  });

  test('in-betweens stay cubic splines whose coupled joins are as smooth as the keys’ joins', () => {
    // A coupled join is C1 by construction; the keys' own joins are smooth only within the
    // continuity tolerance (font outlines round to integers), and that small offset is carried
    // over linearly: the in-between's turn at the join stays within the keys' turns there.
    const m = Morph.create(monoG, romanG);
    const turn = (s: Spline, j: number) => {
      const n = s.points.length / 2, p = 3 * j, hin = (p + n - 1) % n, hout = p + 1;
      const ax = s.points[2 * p] - s.points[2 * hin], ay = s.points[2 * p + 1] - s.points[2 * hin + 1];
      const bx = s.points[2 * hout] - s.points[2 * p], by = s.points[2 * hout + 1] - s.points[2 * p + 1];
      return Math.abs(ax * by - ay * bx) / (Math.hypot(ax, ay) * Math.hypot(bx, by));
    };
    const [k0, k1] = [m.splines(0), m.splines(1)];
    let coupled = 0, exact = 0;
    for (const t of [0.25, 0.5, 0.75]) {
      m.splines(t).forEach((s, c) => {
        expect((s.points.length / 2) % 3).toBe(0);
        s.continuity.forEach((tag, j) => {
          if (tag.kind !== 'C1') return;
          coupled++;
          const bound = Math.max(turn(k0[c], j), turn(k1[c], j));
          expect(turn(s, j)).toBeLessThanOrEqual(1.5 * bound + 1e-9);
          if (bound < 1e-12) exact++;
        });
      });
    }
    expect(coupled).toBeGreaterThan(60);
    expect(exact).toBeGreaterThan(0); // joins split by knot insertion are exactly C1 in both keys
    m.dispose();
  });

  test('at(t) allocates nothing and 200 create/dispose cycles leave the heap where it was', () => {
    const m = Morph.create(monoG, romanG);
    m.at(0.5);
    const before = memory().used;
    for (let i = 0; i < 1000; i++) m.at(i / 999);
    expect(memory().used).toBe(before);
    m.dispose();
    Morph.create(monoA, serifA).dispose();
    const start = memory().used;
    for (let i = 0; i < 200; i++) Morph.create(monoA, serifA).dispose();
    expect(memory().used).toBe(start);
  });

  test('the animated SVG has one command structure in every frame, SMIL or CSS', () => {
    const m = Morph.create(monoA, serifA);
    const smil = m.animatedSVG({ frames: 5, duration: 1 });
    const values = /values="([^"]+)"/.exec(smil)![1].split(';');
    expect(values).toHaveLength(9); // there and back
    const commands = (d: string) => d.replace(/[^MCZ]/g, '');
    expect(new Set(values.map(commands)).size).toBe(1);
    expect(values[0]).not.toBe(values[4]);
    expect(values[0]).toBe(values[8]);
    expect(smil).toContain('repeatCount="indefinite"');
    const doc = parseSVG(m.toSVG(0.5));
    expect(doc.splines).toHaveLength(2);
    const css = m.animatedSVG({ frames: 3, format: 'css', alternate: false });
    expect(css).toMatch(/@keyframes splinekit-morph/);
    expect(css.match(/d: path\("/g)).toHaveLength(3);
    m.dispose();
  });

  test('bad input and bad options are refused with a SplinekitError naming them', () => {
    expect(() => Morph.create([], monoG)).toThrow(/first shape has no contour/);
    expect(() => Morph.create(monoG, [])).toThrow(/second shape has no contour/);
    const nan = [{ closed: true, points: Float64Array.from([0, 0, 1, NaN, 2, 0]) }];
    expect(() => Morph.create(nan, monoG)).toThrow(SplinekitError);
    const dot = [{ closed: true, points: Float64Array.from([1, 1, 1, 1, 1, 1]) }];
    expect(() => Morph.create(dot, monoG)).toThrow(/zero/);
    expect(() => Morph.create(monoG, romanG, { kinkExponent: 0 })).toThrow(/e_k/);
    expect(() => Morph.create(monoG, romanG, { stretching: NaN })).toThrow(/stretching/);
    expect(() => Morph.create(monoG, romanG, { interpolation: 'cubic' as never })).toThrow(/interpolation/);
    expect(() => Morph.create(monoG, romanG, { pins: [{ a: [0, 0], b: [NaN, 1] }] })).toThrow(/pin 0/);
    const m = Morph.create(monoG, romanG);
    expect(() => m.at(NaN)).toThrow(/finite/);
    expect(() => m.animatedSVG({ frames: 1 })).toThrow(/frames/);
    m.dispose();
    expect(() => m.at(0.5)).toThrow(/dispose/);
  });
});
