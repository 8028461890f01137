// The editor's 2D drawing (web/view2d/drawing.ts) built in Node from the spline model: square caps
// extend open strokes by half the width (three.js SVGLoader used to throw on them: "reading '7'"),
// and a shape that fails to draw is left out whole, named, while every other shape is drawn.
import { SVGLoader } from 'three/examples/jsm/loaders/SVGLoader.js';
import { afterEach, beforeAll, describe, expect, test, vi } from 'vitest';
import { init, parseSVG } from '../../src/index.js';
import { buildDrawing } from '../../web/view2d/drawing.js';

// The browser parses CSS colours with a canvas, which Node has not: the three colours used here.
vi.mock('../../web/view2d/color.js', () => ({
  cssColor: (text: string) => ({ black: [0, 0, 0, 1], red: [1, 0, 0, 1], blue: [0, 0, 1, 1] })[text.trim()] ?? null,
}));

beforeAll(async () => {
  await init();
});

afterEach(() => {
  vi.restoreAllMocks();
});

const svg = (body: string) => `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">${body}</svg>`;

/** x/y extent of the drawing's vertices. */
function extent(doc: ReturnType<typeof parseSVG>) {
  const { mesh, stats } = buildDrawing(doc, 0.05);
  mesh.geometry.computeBoundingBox();
  const box = mesh.geometry.boundingBox!;
  mesh.geometry.dispose();
  return { stats, minX: box.min.x, maxX: box.max.x, minY: box.min.y, maxY: box.max.y };
}

describe('stroke caps', () => {
  test.each([
    ['butt', 10, 90],
    ['round', 5, 95],
    ['square', 5, 95],
  ])('an open horizontal line with %s caps spans x %d..%d', (cap, from, to) => {
    // A second subpath turning left then right, so that both join-side branches of the cap code run.
    const doc = parseSVG(svg(`<path d="M10 50 L90 50 M10 20 L50 20 L50 30 L90 30" stroke="black" stroke-width="10" fill="none" stroke-linecap="${cap}"/>`));
    const e = extent(doc);
    expect(e.stats.skipped).toEqual([]);
    expect(e.stats.triangles).toBeGreaterThan(0);
    expect(e.minX).toBeCloseTo(from, 6);
    expect(e.maxX).toBeCloseTo(to, 6);
    expect(e.minY).toBeCloseTo(15, 6);
    expect(e.maxY).toBeCloseTo(55, 6);
  });
});

describe('one shape never takes the drawing down', () => {
  test('a shape whose stroke throws is left out and named; the shapes before and after it are drawn', () => {
    const doc = parseSVG(
      svg(`<rect x="0" y="0" width="10" height="10" fill="red"/>
           <path id="leg" d="M20 20 L80 80" stroke="black" stroke-width="4"/>
           <rect x="90" y="90" width="10" height="10" fill="blue"/>`),
    );
    const whole = extent(doc);
    const real = SVGLoader.pointsToStrokeWithBuffers;
    vi.spyOn(SVGLoader, 'pointsToStrokeWithBuffers').mockImplementation((...args: Parameters<typeof real>) => {
      real(...args); // half-written buffers must be rolled back too
      throw new TypeError('stroke failed');
    });
    const broken = extent(doc);
    expect(broken.stats.skipped).toEqual([{ element: '<path id="leg"> at line 2', reason: 'stroke failed' }]);
    // Both rectangles are there (the drawing still spans 0..100); the stroke's triangles are not.
    expect([broken.minX, broken.maxX, broken.minY, broken.maxY]).toEqual([0, 100, 0, 100]);
    expect(broken.stats.triangles).toBe(4);
    expect(whole.stats.triangles).toBeGreaterThan(4);
    expect(broken.stats.vertices).toBe(8);
  });
});
