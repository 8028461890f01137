// Every ordered pair of glyphs of one letter in ../shared/data/svg/morph (four fonts, letters G, S,
// a and &; TrueType and CFF outlines wind opposite ways, contour counts differ): no in-between
// contour crosses itself, no two contours cross, every hole stays inside its outer contour and
// keeps its winding (bench/morph-quality.mjs, which the benchmark also runs on flubber's blends).
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, test } from 'vitest';
import { init, Morph, parseSVG, type SvgDocument } from '../../src/index.js';
import { bezierRings, frameFailures, parents, signedArea2 } from '../../bench/morph-quality.mjs';
import { sharedData } from './helpers.js';

const dir = join(sharedData, 'svg/morph');
const files = readdirSync(dir).filter((f) => f.endsWith('.svg')).sort();
const letters = [...new Set(files.map((f) => f.replace(/\.svg$/, '').split('_').slice(1).join('_')))];
const docs = new Map<string, SvgDocument>();

beforeAll(async () => {
  await init();
  for (const f of files) docs.set(f, parseSVG(readFileSync(join(dir, f)), { name: f }));
});

/** Failures over the in-betweens at t = 0.1 … 0.9 of one pair. */
function failures(a: string, b: string): string[] {
  const m = Morph.create(docs.get(a)!, docs.get(b)!);
  try {
    const rings = (t: number) => bezierRings(m.at(t).slice(), m.starts, m.counts);
    const r0 = rings(0), r1 = rings(1);
    const p0 = parents(r0), p1 = parents(r1);
    // Nesting and winding from the key a contour exists in (a growing contour: the second).
    const nesting = m.correspondence.contours.map((c, i) => (c.contourA >= 0 ? p0[i] : p1[i]));
    const winding = nesting.map((p, i) => (p < 0 ? 0 : Math.sign(signedArea2(m.correspondence.contours[i].contourA >= 0 ? r0[i] : r1[i]))));
    const out: string[] = [];
    for (let k = 1; k < 10; k++) {
      const f = frameFailures(rings(k / 10), nesting, winding);
      if (f.any) out.push(`t=${k / 10}: ${JSON.stringify(f)}`);
    }
    return out;
  } finally {
    m.dispose();
  }
}

describe.each(letters)('glyph %s', (letter) => {
  const fonts = files.filter((f) => f.endsWith(`_${letter}.svg`));
  test(`every ordered pair of the ${fonts.length} fonts blends without crossings, holes inside and keeping their winding`, () => {
    expect(fonts.length).toBeGreaterThanOrEqual(4);
    const bad: string[] = [];
    for (const a of fonts) for (const b of fonts) if (a !== b) for (const f of failures(a, b)) bad.push(`${a} → ${b} ${f}`);
    expect(bad).toEqual([]);
  });
});

test('the quality checks see a crossing: a figure eight and a hole pushed out fail', () => {
  // An independent check that the checks can fail (a check that never fails tests nothing).
  const eight = [0, 0, 10, 10, 10, 0, 0, 10];
  expect(frameFailures([eight], [-1], [0]).self).toBe(1);
  const outer = [0, 0, 10, 0, 10, 10, 0, 10], hole = [20, 20, 21, 20, 21, 21];
  expect(frameFailures([outer, hole], [-1, 0], [0, 1]).holeOut).toBe(1);
  const flipped = [2, 2, 2, 3, 3, 3];
  expect(frameFailures([outer, flipped], [-1, 0], [0, 1]).holeFlip).toBe(1);
});
