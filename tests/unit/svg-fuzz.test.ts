// Property test of the SVG importer on generated hostile documents (tests/fuzz/svg-arbitrary.ts):
// parseSVG either throws a SplinekitError naming the file, or returns a document whose splines are
// finite and well-shaped and which writes back to an SVG that reads again with the same splines.
// Never another exception, never a hang. Failures found so far are replayed by seed first.
import fc from 'fast-check';
import { readFileSync } from 'node:fs';
import { beforeAll, expect, test } from 'vitest';
import { SplinekitError, init, parseSVG } from '../../src/index.js';
import { svgDocument } from '../fuzz/svg-arbitrary.js';

beforeAll(async () => {
  await init();
});

interface Regression {
  what: string;
  seed: number;
  input: string;
}
const regressions = (JSON.parse(readFileSync(new URL('../fuzz/regressions.json', import.meta.url), 'utf8')) as { cases: Regression[] }).cases;

/** The property: a clean error or a sound document that survives a round trip. */
function importsCleanly(text: string): void {
  let doc;
  try {
    doc = parseSVG(text, { name: 'fuzz.svg' });
  } catch (err) {
    if (!(err instanceof SplinekitError)) throw new Error(`not a SplinekitError: ${String(err)}`, { cause: err });
    expect(err.message.startsWith('fuzz.svg: ')).toBe(true);
    return;
  }
  for (const s of doc.splines) {
    const n = s.points.length / 2;
    expect(Number.isInteger(n)).toBe(true);
    expect(s.closed ? n % 3 : (n - 1) % 3).toBe(0);
    expect(s.points.every(Number.isFinite)).toBe(true);
    expect(s.continuity).toHaveLength(s.closed ? n / 3 : Math.max(0, (n - 1) / 3 - 1));
  }
  const again = parseSVG(doc.toSVG(), { name: 'fuzz.svg' });
  expect(again.splines.length).toBe(doc.splines.length);
}

test.each(regressions.map((r) => [r.what, r.input] as const))('regression: %s', (_what, input) => {
  importsCleanly(input);
});

test('generated hostile documents import cleanly or fail with a SplinekitError', () => {
  fc.assert(fc.property(svgDocument, importsCleanly), { numRuns: 300 });
});
