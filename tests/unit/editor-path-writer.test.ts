// The 2D view writes a shape's path data in one pass (web/view2d/svg-layer.ts, writePathData):
// it must be the very text the document writes (SvgDocument.pathData, which export uses), for
// every shape of every shared drawing, with and without element transforms, at full precision and
// with the fixed-decimal formatter the view uses.
import { beforeAll, expect, test } from 'vitest';
import { fixedFormatter, formatNumber, init, parseSVG } from '../../src/index.js';
import { invert, isIdentity } from '../../src/svg/matrix.js';
import { writePathData } from '../../web/view2d/svg-layer.js';
import { readShared, sharedSvgs } from './helpers.js';

beforeAll(async () => {
  await init();
});

test('writePathData writes what SvgDocument.pathData writes, shape by shape', () => {
  let shapes = 0, transformed = 0;
  for (const rel of sharedSvgs()) {
    const doc = parseSVG(readShared(rel), { name: rel });
    doc.shapes.forEach((shape, i) => {
      const toLocal = invert(shape.transform);
      if (!toLocal) return;
      const m = isIdentity(toLocal) ? undefined : toLocal;
      if (m) transformed++;
      for (const format of [formatNumber, fixedFormatter(5), fixedFormatter(1)]) {
        expect(writePathData(doc.splines, shape.firstSpline, shape.splineCount, m, format), `${rel} shape ${i}`).toBe(doc.pathData(i, format));
      }
      shapes++;
    });
  }
  expect(shapes).toBeGreaterThan(4000);
  expect(transformed).toBeGreaterThan(100);
});
