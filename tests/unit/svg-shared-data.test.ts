// Every SVG of ../shared/data loads, matches the data set's own counts (manifest.json, made with
// svgelements), and survives a round trip through export with its geometry intact.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, test } from 'vitest';
import { SplineSet, init, parseSVG } from '../../src/index.js';
import { maxDistance, readShared, sharedData, sharedSvgs } from './helpers.js';

interface ManifestSvg {
  shapes: number;
  segments: Record<string, number>;
}
const manifest = JSON.parse(readFileSync(join(sharedData, 'manifest.json'), 'utf8')) as { svg: Record<string, ManifestSvg> };

beforeAll(async () => {
  await init();
});

describe.each(sharedSvgs())('%s', (file) => {
  test('loads with the data set\'s shape and segment counts', () => {
    const doc = parseSVG(readShared(file), { name: file });
    const m = manifest.svg[file];
    expect(m, `manifest entry for ${file}`).toBeDefined();
    const stats = doc.stats();
    expect(stats.elements).toBe(m.shapes);
    // svgelements counts every Z as a segment and an arc as one; we add a closing line only when
    // Z has a gap to close, and split arcs into pieces of at most 90°.
    const s = m.segments;
    const drawn = (s.CubicBezier ?? 0) + (s.QuadraticBezier ?? 0) + (s.Line ?? 0);
    expect(stats.segments).toBeGreaterThanOrEqual(drawn + (s.Arc ?? 0));
    expect(stats.segments).toBeLessThanOrEqual(drawn + 8 * (s.Arc ?? 0) + (s.Close ?? 0));
    const tags = Object.values(stats.continuity).reduce((a, b) => a + b, 0);
    const expected = doc.splines.reduce((n, sp) => {
      const k = sp.points.length / 2;
      const segs = k <= 1 ? 0 : sp.closed ? k / 3 : (k - 1) / 3;
      return n + (segs === 0 ? 0 : sp.closed ? segs : segs - 1);
    }, 0);
    expect(tags).toBe(expected);
    expect(doc.splines.every((sp) => sp.points.every(Number.isFinite))).toBe(true);
  });

  test('round trip through export keeps every control point and sample within 1e-6 of the size', () => {
    const doc = parseSVG(readShared(file), { name: file });
    const back = parseSVG(doc.toSVG({ rewrite: 'all' }), { name: `${file} (exported)` });
    expect(back.shapes.length).toBe(doc.shapes.length);
    expect(back.splines.length).toBe(doc.splines.length);
    const tol = 1e-6 * doc.size;
    let worst = 0;
    doc.splines.forEach((s, i) => {
      expect(back.splines[i].closed).toBe(s.closed);
      worst = Math.max(worst, maxDistance(s.points, back.splines[i].points));
    });
    expect(worst).toBeLessThanOrEqual(tol);
    const a = SplineSet.from(doc.splines), b = SplineSet.from(back.splines);
    try {
      expect(maxDistance(a.sample(7), b.sample(7))).toBeLessThanOrEqual(tol);
    } finally {
      a.dispose();
      b.dispose();
    }
    // Continuity survives too (the tags are detected again from the written points).
    expect(back.stats().continuity).toEqual(doc.stats().continuity);
    // Styles are kept: every shape paints the same way.
    back.shapes.forEach((sh, i) => expect(sh.style).toEqual(doc.shapes[i].style));
  });
});
