// The editor's control-point overlay (web/overlay/overlay.ts) built in Node (three.js geometry
// needs no WebGL): following a pose in place gives the same markers, handle lines and picking as
// building the overlay anew from the posed document, and keeps the selection.
import { Group } from 'three';
import { beforeAll, expect, test } from 'vitest';
import { init, parseSVG, type SvgDocument } from '../../src/index.js';
import { ControlOverlay } from '../../web/overlay/overlay.js';
import type { View2D } from '../../web/view2d/view2d.js';
import { Viewport } from '../../web/view2d/viewport.js';

beforeAll(async () => {
  await init();
});

function overlay(): { o: ControlOverlay; view: View2D } {
  const viewport = new Viewport();
  viewport.resize(400, 400);
  viewport.fit([0, 0, 100, 100]);
  const view = { renderer: { getPixelRatio: () => 1 }, overlayLayer: new Group(), viewport, requestRender() {} } as unknown as View2D;
  return { o: new ControlOverlay(view), view };
}

/** Every position buffer of the overlay's objects, in order. */
function positions(o: ControlOverlay): number[][] {
  return o.group.children.map((c) => Array.from(((c as unknown as { geometry: { getAttribute(n: string): { array: ArrayLike<number> } | undefined } }).geometry.getAttribute('position')?.array ?? [])));
}

const SVG = `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
  <path d="M10 10 C20 0 30 0 40 10 S60 20 70 10"/><path d="M20 60 L50 90 L80 60 Z"/></svg>`;

function posed(doc: SvgDocument): SvgDocument {
  const p = doc.clone();
  for (const s of p.splines) for (let i = 0; i < s.points.length; i += 2) [s.points[i], s.points[i + 1]] = [0.9 * s.points[i] - 0.2 * s.points[i + 1] + 7, 0.3 * s.points[i] + s.points[i + 1] - 4];
  return p;
}

test('update() moves the markers in place exactly as setDocument() of the posed document places them', () => {
  const rest = parseSVG(SVG);
  const moved = posed(rest);
  const a = overlay(), b = overlay();
  a.o.setDocument(rest);
  a.o.setSelection({ spline: 0, anchor: 3 });
  const before = positions(a.o);
  a.o.update(moved);
  b.o.setDocument(moved);
  b.o.setSelection({ spline: 0, anchor: 3 });
  expect(positions(a.o)).toEqual(positions(b.o));
  expect(positions(a.o)).not.toEqual(before);
  expect(a.o.counts).toEqual(b.o.counts);
  // Picking finds the anchor where it went, not where it was.
  a.o.visible = true;
  const at = (doc: SvgDocument) => a.view.viewport.toScreen(doc.splines[1].points[6], doc.splines[1].points[7]);
  expect(a.o.pick(...at(moved))).toEqual({ spline: 1, anchor: 3 });
  expect(a.o.pick(...at(rest))).toBeNull();
});

test('update() with other splines sets the document anew', () => {
  const a = overlay(), b = overlay();
  const other = parseSVG(`<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><path d="M0 0 L50 50 L90 10"/></svg>`);
  a.o.setDocument(parseSVG(SVG));
  a.o.update(other);
  b.o.setDocument(other);
  expect(positions(a.o)).toEqual(positions(b.o));
  expect(a.o.counts).toEqual({ anchors: 3, handles: 4 });
});
