// Paint that follows a deformed shape (src/svg/paint-follow.ts): the least-squares affine fit, and
// export giving each moved shape its own copy of a user-space gradient or pattern whose transform
// is that fit in the element's user space, while bounding-box paint is left alone.
import { DOMParser } from '@xmldom/xmldom';
import { beforeAll, describe, expect, test } from 'vitest';
import { init, parseSVG } from '../../src/index.js';
import { fitAffine, splineBounds } from '../../src/svg/paint-follow.js';

beforeAll(async () => {
  await init();
});

type M = { a: number; b: number; c: number; d: number; e: number; f: number };
const apply = (m: M, x: number, y: number): [number, number] => [m.a * x + m.c * y + m.e, m.b * x + m.d * y + m.f];
const mapPoints = (m: M, p: ArrayLike<number>) => {
  const out = new Float64Array(p.length);
  for (let i = 0; i < p.length; i += 2) [out[i], out[i + 1]] = apply(m, p[i], p[i + 1]);
  return out;
};
const expectMatrix = (got: M, want: M, digits = 9) => {
  for (const k of ['a', 'b', 'c', 'd', 'e', 'f'] as const) expect(got[k], k).toBeCloseTo(want[k], digits);
};

describe('fitAffine', () => {
  test('recovers an affine map exactly from points that span an area', () => {
    const m = { a: 1.3, b: -0.4, c: 0.25, d: 0.8, e: 12, f: -7 };
    const from = [0, 0, 10, 0, 3, 7, -4, 5, 8, 9];
    expectMatrix(fitAffine(from, mapPoints(m, from)), m);
  });

  test('is the least-squares map: noise that averages out leaves it unchanged', () => {
    // A unit square moved by (5, 2), with its corners pushed out symmetrically: the fit is the
    // scale about the centre that the symmetric push amounts to, plus the move.
    const from = [0, 0, 1, 0, 1, 1, 0, 1];
    const to = [-0.1 + 5, -0.1 + 2, 1.1 + 5, -0.1 + 2, 1.1 + 5, 1.1 + 2, -0.1 + 5, 1.1 + 2];
    expectMatrix(fitAffine(from, to), { a: 1.2, b: 0, c: 0, d: 1.2, e: 5 - 0.1, f: 2 - 0.1 });
  });

  test('points on a line determine only the translation of their centroid', () => {
    // Centroids (1, 1) and (7, 2).
    expectMatrix(fitAffine([0, 0, 1, 1, 2, 2], [5, 1, 6, 2, 10, 3]), { a: 1, b: 0, c: 0, d: 1, e: 6, f: 1 });
  });
});

describe('splineBounds', () => {
  test('a cubic arch reaches 3/4 of its control height at t = 1/2; an S bulges both ways', () => {
    expect(splineBounds([{ closed: false, points: [0, 0, 0, 1, 1, 1, 1, 0] }])).toEqual([0, 0, 1, 0.75]);
    // x(t) = 3t(1−t)² − 3t²(1−t)·… : the S from (0,0) with handles (2,0) and (−1,1) to (1,1).
    const [x, , w] = splineBounds([{ closed: false, points: [0, 0, 2, 0, -1, 1, 1, 1] }])!;
    // x(t) = 6t(1−t)² − 3t²(1−t) + t³ = 12t³ − 15t² + 6t; x'(t) = 36t² − 30t + 6 = 0 at t = 1/2, 1/3.
    const at = (t: number) => 12 * t ** 3 - 15 * t ** 2 + 6 * t;
    expect(x).toBeCloseTo(Math.min(0, at(0.5)), 12);
    expect(x + w).toBeCloseTo(Math.max(1, at(1 / 3)), 12);
  });

  test('a closed spline wraps to its first point; no points, no bounds', () => {
    // The closing segment (1,1) (1,2) (0,2) → (0,0) holds the top: its y, sampled densely.
    let top = 0;
    for (let k = 0; k <= 100000; k++) {
      const t = k / 100000, u = 1 - t;
      top = Math.max(top, u ** 3 * 1 + 3 * u * u * t * 2 + 3 * u * t * t * 2);
    }
    const b = splineBounds([{ closed: true, points: [0, 0, 1, 0, 1, 0, 1, 1, 1, 2, 0, 2] }])!;
    expect(b[1]).toBe(0);
    expect(b[3]).toBeCloseTo(top, 8);
    expect(b[3]).toBeLessThan(2); // not the control points' box
    expect(splineBounds([])).toBeNull();
  });
});

/** The svg root of exported markup, and its elements by id. */
function exported(markup: string) {
  const dom = new DOMParser().parseFromString(markup, 'image/svg+xml');
  const byId = (id: string) => {
    const all = dom.getElementsByTagName('*');
    for (let i = 0; i < all.length; i++) if (all[i].getAttribute('id') === id) return all[i];
    return null;
  };
  return { dom, byId };
}

const FILE = `<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 200 100">
  <defs>
    <linearGradient id="user" gradientUnits="userSpaceOnUse" x1="0" y1="0" x2="50" y2="0" gradientTransform="rotate(10)">
      <stop offset="0" stop-color="red"/><stop offset="1" stop-color="blue"/>
    </linearGradient>
    <linearGradient id="inherits" xlink:href="#user"/>
    <linearGradient id="box"><stop offset="0" stop-color="red"/><stop offset="1" stop-color="blue"/></linearGradient>
    <pattern id="tiles" patternUnits="userSpaceOnUse" width="8" height="8"><rect width="4" height="4" fill="green"/></pattern>
  </defs>
  <g transform="translate(100 0) scale(2 1)">
    <rect id="a" x="0" y="0" width="40" height="30" fill="url(#inherits)" stroke="url(#tiles)"/>
  </g>
  <rect id="b" x="10" y="50" width="40" height="30" fill="url(#box)"/>
  <rect id="c" x="60" y="50" width="40" height="30" fill="url(#user)"/>
</svg>`;

describe('export of deformed shapes', () => {
  test('a moved shape gets its own copy of its user-space gradient and pattern, mapped by the fit in its user space', () => {
    const doc = parseSVG(FILE);
    // Move shape a (in document space) by a known affine map: its user space is (x, y) ↦ (100 + 2x, y).
    const move = { a: Math.cos(0.3), b: Math.sin(0.3), c: -Math.sin(0.3), d: Math.cos(0.3), e: 20, f: -5 };
    for (const s of doc.splinesOf(0)) s.points.set(mapPoints(move, s.points));
    const { byId } = exported(doc.toSVG());

    // The same map seen in the element's user space: L⁻¹ · move · L with L = translate(100 0) scale(2 1).
    const L = { a: 2, b: 0, c: 0, d: 1, e: 100, f: 0 };
    const Linv = { a: 0.5, b: 0, c: 0, d: 1, e: -50, f: 0 };
    const compose = (p: M, q: M): M => ({ a: p.a * q.a + p.c * q.b, b: p.b * q.a + p.d * q.b, c: p.a * q.c + p.c * q.d, d: p.b * q.c + p.d * q.d, e: p.a * q.e + p.c * q.f + p.e, f: p.b * q.e + p.d * q.f + p.f });
    const local = compose(Linv, compose(move, L));

    const fill = byId('inherits-splinekit-0-fill')!;
    expect(fill, 'a copy of the fill gradient').not.toBeNull();
    expect(fill.localName).toBe('linearGradient');
    expect(fill.getAttribute('xlink:href') ?? fill.getAttribute('href')).toBe('#inherits');
    // matrix(local) followed by the transform the copy would otherwise inherit (through #inherits from #user).
    const m = /^matrix\(([^)]*)\) rotate\(10\)$/.exec(fill.getAttribute('gradientTransform')!);
    expect(m, fill.getAttribute('gradientTransform')!).not.toBeNull();
    const [a, b, c, d, e, f] = m![1].split(' ').map(Number);
    expectMatrix({ a, b, c, d, e, f }, local, 8);

    const stroke = byId('inherits-splinekit-0-fill')!.parentNode!;
    expect(stroke).toBe(byId('user')!.parentNode); // placed beside the servers, in defs
    const tiles = byId('tiles-splinekit-0-stroke')!;
    expect(tiles.localName).toBe('pattern');
    expect(tiles.getAttribute('patternTransform')!.startsWith('matrix(')).toBe(true);

    const shape = byId('a')!;
    expect(shape.getAttribute('style')).toContain('fill:url(#inherits-splinekit-0-fill)');
    expect(shape.getAttribute('style')).toContain('stroke:url(#tiles-splinekit-0-stroke)');
  });

  test('a bounding-box gradient is written in user space over the box as imported; unmoved shapes are left as they are', () => {
    const doc = parseSVG(FILE);
    for (const s of doc.splinesOf(1)) s.points.set(mapPoints({ a: 1, b: 0, c: 0, d: 1, e: 3, f: 4 }, s.points));
    const { byId } = exported(doc.toSVG());
    const copy = byId('box-splinekit-1-fill')!;
    expect(copy.getAttribute('gradientUnits')).toBe('userSpaceOnUse');
    expect(['x1', 'y1', 'x2', 'y2'].map((n) => copy.getAttribute(n))).toEqual(['0', '0', '1', '0']);
    // The move, then the box of <rect x=10 y=50 width=40 height=30>.
    expect(copy.getAttribute('gradientTransform')).toBe('matrix(1 0 0 1 3 4) matrix(40 0 0 30 10 50)');
    expect(byId('b')!.getAttribute('style')).toBe('fill:url(#box-splinekit-1-fill)');
    expect(byId('c')!.getAttribute('style')).toBeNull();
    expect(byId('a')!.getAttribute('style')).toBeNull();
  });

  test('reading the bounds as imported changes nothing: an unmoved shape stays unmoved', () => {
    const doc = parseSVG(FILE);
    expect(doc.importedBounds(0)).toEqual([0, 0, 40, 30]); // in the rect's own user space
    expect(doc.importedBounds(0)).toEqual([0, 0, 40, 30]);
    expect(doc.paintTransform(0)).toBeNull();
    expect(doc.clone().paintTransform(0)).toBeNull();
    expect(doc.toSVG()).not.toContain('splinekit-');
  });

  test('an exported copy reads back with the same splines, and the copy carries over another export', () => {
    const doc = parseSVG(FILE);
    for (const s of doc.splinesOf(2)) s.points.set(mapPoints({ a: 0.5, b: 0.2, c: 0, d: 1.5, e: 10, f: 0 }, s.points));
    const once = doc.toSVG();
    const back = parseSVG(once);
    expect(back.splines.length).toBe(doc.splines.length);
    back.splines.forEach((s, k) => s.points.forEach((v, j) => expect(v).toBeCloseTo(doc.splines[k].points[j], 9)));
    expect(back.shapes[2].style.fill).toBe('url(#user-splinekit-2-fill)');
  });
});
