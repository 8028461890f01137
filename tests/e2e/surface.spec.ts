import { readFileSync, statSync } from 'node:fs';
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures.js';
import { bumpyTorusPLY } from '../../bench/meshes.mjs';
import { docsScreenshot, frames, openEditor, publicFile } from './helpers.js';

/**
 * Surface mode end to end: a sample mesh opens in the 3D view; four clicks on it draw a spline
 * whose traced polyline lies on the mesh (every point on its face, every piece inside one face);
 * dragging an anchor retraces it, undo and redo bring back the exact polylines; moving and
 * turning the spline, the tracing options, an SVG placed on the mesh, a bad mesh file and the
 * autosave after a reload.
 */

type SurfaceState = ReturnType<NonNullable<Window['splinekitEditor']>['surface']['state']>;
type Spline = SurfaceState['splines'][number];
type XY = { x: number; y: number };

function surface(page: Page): Promise<SurfaceState> {
  return page.evaluate(() => window.splinekitEditor!.surface.state());
}

/** Waits until the mesh is shown and no load, edit or trace is under way. */
async function settled(page: Page): Promise<SurfaceState> {
  await page.evaluate(() => window.splinekitEditor!.surface.ready());
  await frames(page);
  return surface(page);
}

async function openSurface(page: Page): Promise<SurfaceState> {
  await openEditor(page);
  await page.getByRole('button', { name: 'Surface', exact: true }).click();
  const s = await settled(page);
  expect(s.active).toBe(true);
  return s;
}

/** Client position of a point given as fractions of the 3D canvas. */
async function canvasAt(page: Page, fx: number, fy: number): Promise<XY> {
  const box = (await page.getByTestId('view3d').boundingBox())!;
  return { x: box.x + fx * box.width, y: box.y + fy * box.height };
}

async function projected(page: Page, p: { face: number; uv: [number, number] }): Promise<XY & { visible: boolean }> {
  const at = await page.evaluate((q) => window.splinekitEditor!.surface.project(q), p);
  expect(at, 'the mesh point projects on the canvas').not.toBeNull();
  return at!;
}

/** Resolves on the page's next animation frame. */
function nextFrame(page: Page): Promise<void> {
  return page.evaluate(() => new Promise<void>((r) => requestAnimationFrame(() => r())));
}

/**
 * Presses at `from`, moves in `steps` to `to` (as a user drags), releases. Each move waits for
 * the next animation frame, so that the moves spread over frames as a user's do (each move asks
 * the worker for a retrace that supersedes the one before, drawn when it arrives) instead of
 * all landing before the first frame.
 */
async function drag(page: Page, from: XY, to: XY, steps = 10): Promise<void> {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) {
    await page.mouse.move(from.x + ((to.x - from.x) * i) / steps, from.y + ((to.y - from.y) * i) / steps);
    await nextFrame(page);
  }
  await page.mouse.up();
}

/**
 * Surface mode takes a second click as a double click (which ends the spline) when it comes
 * within 400 ms and closer than this many pixels to the first (DOUBLE_CLICK_PX in
 * web/modes/surface/surface-mode.ts).
 */
const DOUBLE_CLICK_PX = 6;

/**
 * Clicks the points on the mesh (each must be on it), then Enter. Consecutive spots are further
 * apart than the double-click distance, so no pair of clicks is a double click however quickly
 * they follow each other (and Playwright's single clicks never make the browser's dblclick).
 * After each click the test waits until the mode has taken it: the first point waits for the
 * second, then every click adds an anchor to the spline being drawn.
 */
async function drawSpline(page: Page, spots: [number, number][]): Promise<SurfaceState> {
  let previous: XY | null = null;
  for (const [k, [fx, fy]] of spots.entries()) {
    const p = await canvasAt(page, fx, fy);
    expect(await page.evaluate(({ x, y }) => window.splinekitEditor!.surface.meshPointAt(x, y), p), `(${fx}, ${fy}) is on the mesh`).not.toBeNull();
    if (previous) expect(Math.hypot(p.x - previous.x, p.y - previous.y), `click ${k} is not a double click`).toBeGreaterThan(4 * DOUBLE_CLICK_PX);
    previous = p;
    await page.mouse.click(p.x, p.y);
    const s = await settled(page);
    if (k === 0) expect(s.pending, 'the first point waits for the second').toBe(true);
    else {
      const drawing = s.splines.find((sp) => sp.id === s.drawingId);
      expect(drawing?.json.points, `anchors after click ${k}`).toHaveLength(3 * k + 1);
    }
  }
  await page.keyboard.press('Enter');
  return settled(page);
}

/**
 * Checks that a traced polyline lies on the mesh: each point is the barycentric combination of
 * its mesh point's face, and each piece between two points stays in one face (the next point lies
 * on the face of the previous one, or the other way round) — so no piece cuts through the volume.
 */
async function expectOnMesh(page: Page, spline: Spline, scale: number): Promise<void> {
  const { polyline: X, where: W } = spline;
  const n = X.length / 3;
  expect(n, 'polyline points').toBeGreaterThan(8);
  expect(W.length).toBe(3 * n);
  const faces = [...new Set(Array.from({ length: n }, (_, i) => W[3 * i]))];
  const V = await page.evaluate((f) => window.splinekitEditor!.surface.faceVertices(f), faces);
  const corners = new Map<number, number[][]>();
  faces.forEach((f, k) => corners.set(f, [0, 1, 2].map((c) => V.slice(9 * k + 3 * c, 9 * k + 3 * c + 3))));
  const tol = 1e-5 * scale;
  const at = (i: number) => [X[3 * i], X[3 * i + 1], X[3 * i + 2]];
  let worst = 0;
  for (let i = 0; i < n; i++) {
    const [a, b, c] = corners.get(W[3 * i])!, u = W[3 * i + 1], v = W[3 * i + 2], w = 1 - u - v;
    expect(u, `u of point ${i}`).toBeGreaterThanOrEqual(-1e-6);
    expect(v, `v of point ${i}`).toBeGreaterThanOrEqual(-1e-6);
    expect(w, `1-u-v of point ${i}`).toBeGreaterThanOrEqual(-1e-6);
    const p = at(i);
    worst = Math.max(worst, Math.hypot(...[0, 1, 2].map((k) => w * a[k] + u * b[k] + v * c[k] - p[k])));
  }
  expect(worst, 'largest distance from a polyline point to its mesh point').toBeLessThan(tol);
  /** Whether q lies on the closed triangle (a, b, c), within tol. */
  const onFace = (q: number[], [a, b, c]: number[][]) => {
    const e1 = [0, 1, 2].map((k) => b[k] - a[k]), e2 = [0, 1, 2].map((k) => c[k] - a[k]), d = [0, 1, 2].map((k) => q[k] - a[k]);
    const dot = (x: number[], y: number[]) => x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    const a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2), b1 = dot(d, e1), b2 = dot(d, e2);
    const det = a11 * a22 - a12 * a12;
    const s = (a22 * b1 - a12 * b2) / det, t = (a11 * b2 - a12 * b1) / det;
    const off = Math.hypot(...[0, 1, 2].map((k) => a[k] + s * e1[k] + t * e2[k] - q[k]));
    const slack = 1e-6;
    return off < tol && s >= -slack && t >= -slack && s + t <= 1 + slack;
  };
  let cuts = 0;
  for (let i = 0; i + 1 < n; i++) {
    const fi = W[3 * i], fj = W[3 * i + 3];
    if (fi === fj) continue;
    if (!onFace(at(i + 1), corners.get(fi)!) && !onFace(at(i), corners.get(fj)!)) cuts++;
  }
  expect(cuts, 'polyline pieces that leave the faces of their ends').toBe(0);
}

/** Length of a polyline. */
function length(X: number[]): number {
  let l = 0;
  for (let i = 3; i < X.length; i += 3) l += Math.hypot(X[i] - X[i - 3], X[i + 1] - X[i - 2], X[i + 2] - X[i - 1]);
  return l;
}

/** Largest distance from a point of polyline A to the nearest point of polyline B. */
function hausdorff(A: number[], B: number[]): number {
  let worst = 0;
  for (let i = 0; i < A.length; i += 3) {
    let best = Infinity;
    for (let j = 0; j < B.length; j += 3) best = Math.min(best, Math.hypot(A[i] - B[j], A[i + 1] - B[j + 1], A[i + 2] - B[j + 2]));
    worst = Math.max(worst, best);
  }
  return worst;
}

/** Where the clicks go, as fractions of the 3D view (all on the pebble as it is framed). */
const SPOTS: [number, number][] = [
  [0.22, 0.56],
  [0.38, 0.36],
  [0.57, 0.6],
  [0.76, 0.42],
];

test('Surface mode: draw a spline on a mesh, drag an anchor, undo and redo', async ({ page }) => {
  let s = await openSurface(page);
  expect(s.file).toBe('pebble.ply');
  expect(s.meshInfo?.faces).toBe(20480);
  expect(s.splines).toHaveLength(0);
  await expect(page.getByTestId('surface-status-mesh')).toContainText('20,480 triangles');
  await expect(page.getByTestId('mode-keys')).toContainText('Alt+click a curve');
  // Headless Chromium renders WebGL in software: the view leaves multisampling out there (it would
  // double the frame time of a big mesh).
  const gl = await page.evaluate(() => {
    const ctx = (document.querySelector('[data-testid="view3d"]') as HTMLCanvasElement).getContext('webgl2')!;
    const info = ctx.getExtension('WEBGL_debug_renderer_info');
    return { renderer: String(info ? ctx.getParameter(info.UNMASKED_RENDERER_WEBGL) : ''), antialias: ctx.getContextAttributes()?.antialias };
  });
  expect(gl.renderer).toMatch(/SwiftShader/i);
  expect(gl.antialias).toBe(false);

  s = await drawSpline(page, SPOTS);
  expect(s.splines).toHaveLength(1);
  expect(s.drawingId).toBeNull();
  const drawn = s.splines[0];
  expect(drawn.json.points).toHaveLength(3 * (SPOTS.length - 1) + 1);
  expect(drawn.segmentStarts).toHaveLength(SPOTS.length - 1);
  const scale = s.scale!;
  await expectOnMesh(page, drawn, scale);
  // The anchors are where the clicks were.
  for (let k = 0; k < SPOTS.length; k++) {
    const at = await projected(page, drawn.json.points[3 * k]);
    const want = await canvasAt(page, ...SPOTS[k]);
    expect(Math.hypot(at.x - want.x, at.y - want.y), `anchor ${k} under its click`).toBeLessThan(1.5);
  }
  // The status bar reports the last trace: the core's time for it and the points of the polyline.
  expect(Number.isFinite(s.lastTraceMs) && s.lastTraceMs! > 0, `last trace time ${s.lastTraceMs}`).toBe(true);
  await expect(page.getByTestId('surface-status-trace')).toHaveText(`traced in ${s.lastTraceMs!.toFixed(2)} ms (${(drawn.polyline.length / 3).toLocaleString('en-US')} points)`);

  // Drag the second anchor down and right: the curve is traced again, still on the mesh.
  const from = await projected(page, drawn.json.points[3]);
  expect(from.visible).toBe(true);
  await drag(page, from, { x: from.x + 50, y: from.y + 60 });
  s = await settled(page);
  const moved = s.splines[0];
  expect(moved.json.points[3]).not.toEqual(drawn.json.points[3]);
  const at = await projected(page, moved.json.points[3]);
  expect(Math.hypot(at.x - (from.x + 50), at.y - (from.y + 60)), 'the anchor followed the pointer').toBeLessThan(2);
  expect(hausdorff(moved.polyline, drawn.polyline), 'the curve moved').toBeGreaterThan(0.01 * scale);
  await expectOnMesh(page, moved, scale);

  // Undo brings back the curve exactly; redo the dragged one.
  await page.keyboard.press('Control+z');
  s = await settled(page);
  expect(s.splines[0].json).toEqual(drawn.json);
  expect(s.splines[0].polyline).toEqual(drawn.polyline);
  await page.keyboard.press('Control+Shift+z');
  s = await settled(page);
  expect(s.splines[0].json).toEqual(moved.json);
  expect(s.splines[0].polyline).toEqual(moved.polyline);

  await page.getByTestId('view3d').focus();
  const shot = test.info().outputPath('surface.png');
  await page.screenshot({ path: shot });
  expect(statSync(shot).size).toBeLessThan(300_000);
  await docsScreenshot(page, 'surface.png');
});

test('Surface mode: move, turn and scale a spline, switch RDC/OLR and adaptive, insert and delete points', async ({ page }) => {
  await openSurface(page);
  let s = await drawSpline(page, SPOTS.slice(0, 3));
  const scale = s.scale!;
  const first = s.splines[0];
  // Click the curve to select it, then G + drag moves it along the surface.
  const m = Math.floor(first.polyline.length / 3 * 0.3); // away from the anchors
  const onCurve = await projected(page, { face: first.where[3 * m], uv: [first.where[3 * m + 1], first.where[3 * m + 2]] });
  await page.keyboard.press('Escape'); // deselect
  await page.mouse.click(onCurve.x, onCurve.y);
  s = await settled(page);
  expect(s.selection).toEqual({ spline: first.id, point: null });
  await page.keyboard.press('g');
  expect((await surface(page)).tool).toBe('move');
  await drag(page, onCurve, { x: onCurve.x + 40, y: onCurve.y - 30 });
  s = await settled(page);
  const movedSpline = s.splines[0];
  expect(hausdorff(movedSpline.polyline, first.polyline)).toBeGreaterThan(0.01 * scale);
  await expectOnMesh(page, movedSpline, scale);
  expect(movedSpline.json.points).toHaveLength(first.json.points.length);

  // R + drag around the centre turns it.
  await page.keyboard.press('r');
  const c = await canvasAt(page, 0.5, 0.5);
  await drag(page, { x: c.x + 120, y: c.y }, { x: c.x, y: c.y - 120 });
  s = await settled(page);
  const turned = s.splines[0];
  expect(hausdorff(turned.polyline, movedSpline.polyline)).toBeGreaterThan(0.01 * scale);
  await expectOnMesh(page, turned, scale);

  // S + drag away from the centre grows it: the traced curve gets longer.
  await page.keyboard.press('s');
  await drag(page, { x: c.x + 80, y: c.y + 10 }, { x: c.x + 130, y: c.y + 16 });
  s = await settled(page);
  const grown = s.splines[0];
  expect(length(grown.polyline), 'the curve grew').toBeGreaterThan(1.2 * length(turned.polyline));
  await expectOnMesh(page, grown, scale);
  await page.keyboard.press('Escape'); // back to drawing
  expect((await surface(page)).tool).toBe('draw');

  // RDC, then adaptive: everything is traced again (the polyline changes, stays on the mesh).
  await page.getByRole('button', { name: 'RDC', exact: true }).click();
  s = await settled(page);
  expect(s.options.scheme).toBe('rdc');
  expect(s.splines[0].polyline).not.toEqual(turned.polyline);
  await expectOnMesh(page, s.splines[0], scale);
  const uniform = s.splines[0];
  await page.getByRole('button', { name: 'Adaptive', exact: true }).click();
  s = await settled(page);
  expect(s.options.adaptive, 'an angle threshold in degrees').toBeGreaterThan(0);
  expect(s.options.adaptive).toBeLessThan(180);
  expect(s.splines[0].polyline, 'adaptive subdivision traces the curve again').not.toEqual(uniform.polyline);
  await expectOnMesh(page, s.splines[0], scale);
  await page.getByRole('button', { name: 'OLR', exact: true }).click();
  await page.getByRole('button', { name: 'Uniform', exact: true }).click();
  s = await settled(page);

  // Alt+click on the curve inserts an anchor; Delete removes the selected one.
  const sp = s.splines[0];
  const k = Math.floor(sp.polyline.length / 3 / 4);
  const p = await projected(page, { face: sp.where[3 * k], uv: [sp.where[3 * k + 1], sp.where[3 * k + 2]] });
  await page.keyboard.down('Alt');
  await page.mouse.click(p.x, p.y);
  await page.keyboard.up('Alt');
  s = await settled(page);
  expect(s.splines[0].json.points).toHaveLength(sp.json.points.length + 3);
  expect(s.selection?.point).toBe(3);
  const smooth = s.splines[0].json.smooth[1];
  await page.keyboard.press('c'); // the new anchor: smooth ⇄ corner
  s = await settled(page);
  expect(s.splines[0].json.smooth[1]).toBe(!smooth);
  await page.keyboard.press('Delete');
  s = await settled(page);
  expect(s.splines[0].json.points).toHaveLength(sp.json.points.length);
  await expectOnMesh(page, s.splines[0], scale);
});

test('Surface mode: place an SVG, save and load it, a bad mesh keeps the old one, the autosave comes back', async ({ page }) => {
  await openSurface(page);
  await page.getByTestId('surface-svg-select').selectOption('spline-badge.svg');
  await expect.poll(async () => (await surface(page)).placing).toBe(true);
  const centre = await canvasAt(page, 0.5, 0.5);
  await page.mouse.click(centre.x, centre.y);
  let s = await settled(page);
  expect(s.placing).toBe(false);
  expect(s.splines.length).toBeGreaterThan(3);
  for (const sp of s.splines.slice(0, 3)) await expectOnMesh(page, sp, s.scale!);
  const placed = s.splines.length;
  await page.keyboard.press('Control+z');
  s = await settled(page);
  expect(s.splines).toHaveLength(0);
  await page.keyboard.press('Control+Shift+z');
  s = await settled(page);
  expect(s.splines).toHaveLength(placed);

  // Save the drawing as JSON: mesh points on this mesh.
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('surface-save').click()]);
  const saved = JSON.parse(readFileSync((await download.path())!, 'utf8')) as { mesh: string; splines: unknown[] };
  expect(saved.mesh).toBe('pebble.ply');
  expect(saved.splines).toHaveLength(placed);
  // Clear, then load it back: the same splines (undo of the load brings the empty drawing).
  await page.getByTestId('surface-clear').click();
  expect((await settled(page)).splines).toHaveLength(0);
  await page.getByTestId('surface-drawing-input').setInputFiles((await download.path())!);
  await expect.poll(async () => (await surface(page)).splines.length).toBe(placed);
  s = await settled(page);
  expect(s.splines.map((sp) => sp.json)).toEqual(saved.splines);

  // Not a mesh: the error shows, the pebble and its drawing stay.
  await page.getByTestId('surface-mesh-input').setInputFiles({ name: 'broken.obj', mimeType: 'text/plain', buffer: Buffer.from('v 0 0 0\nf 1 2 3\n') });
  await expect(page.getByTestId('status-error')).toBeVisible();
  s = await settled(page);
  expect(s.file).toBe('pebble.ply');
  expect(s.splines).toHaveLength(placed);
  await page.getByTestId('status-error').getByRole('button').click();

  // Another sample, then undo: back to the pebble with its drawing.
  await page.getByTestId('surface-mesh-sample').selectOption('torus-knot.ply');
  await expect.poll(async () => (await surface(page)).file).toBe('torus-knot.ply');
  s = await settled(page);
  expect(s.splines).toHaveLength(0);
  expect(s.meshInfo?.boundaryLoops).toBe(0);
  await page.keyboard.press('Control+z');
  await expect.poll(async () => (await surface(page)).file).toBe('pebble.ply');
  s = await settled(page);
  expect(s.splines).toHaveLength(placed);

  // Reload: Surface mode, the pebble and the drawing come back from the autosave.
  await expect.poll(async () => (await surface(page)).saved).toBe(true);
  await page.reload();
  await page.waitForFunction(() => window.splinekitEditor !== undefined);
  await page.evaluate(() => window.splinekitEditor!.ready);
  s = await settled(page);
  expect(s.active).toBe(true);
  expect(s.file).toBe('pebble.ply');
  expect(s.splines).toHaveLength(placed);
});

test('Surface mode: the sample meshes are small files', () => {
  for (const f of ['pebble.ply', 'torus-knot.ply', 'vase.obj']) expect(statSync(publicFile(`samples/meshes/${f}`)).size).toBeLessThan(600_000);
});

/**
 * Copies the 3D canvas, as it is on screen now, into a 2D canvas the page keeps
 * (window.__view3dCopy), for the evaluations that read its pixels.
 */
function copyView3d(page: Page): Promise<void> {
  return page.evaluate(() => {
    const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="view3d"]')!;
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    copy.getContext('2d', { willReadFrequently: true })!.drawImage(canvas, 0, 0);
    (window as unknown as { __view3dCopy: HTMLCanvasElement }).__view3dCopy = copy;
  });
}

/**
 * The 3D canvas on a grid of `cols` × `rows` points: the pixel there and whether the view picks
 * the mesh there.
 */
async function canvasGrid(page: Page, cols: number, rows: number): Promise<{ rgb: number[]; hit: boolean }[]> {
  await copyView3d(page);
  return page.evaluate(
    ({ cols, rows }) => {
      const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="view3d"]')!;
      const ctx = (window as unknown as { __view3dCopy: HTMLCanvasElement }).__view3dCopy.getContext('2d')!;
      const box = canvas.getBoundingClientRect();
      const out: { rgb: number[]; hit: boolean }[] = [];
      for (let i = 0; i < rows; i++) {
        for (let j = 0; j < cols; j++) {
          const x = box.left + ((j + 0.5) / cols) * box.width, y = box.top + ((i + 0.5) / rows) * box.height;
          const px = ctx.getImageData(Math.floor(((x - box.left) * canvas.width) / box.width), Math.floor(((y - box.top) * canvas.height) / box.height), 1, 1).data;
          out.push({ rgb: [px[0], px[1], px[2]], hit: window.splinekitEditor!.surface.meshPointAt(x, y) !== null });
        }
      }
      return out;
    },
    { cols, rows },
  );
}

/** Mean color of the points of `grid` where `picked` (a grid of the same view) hit the mesh. */
function meanOnMesh(grid: { rgb: number[] }[], picked: { hit: boolean }[]): number[] {
  const on = grid.filter((_, i) => picked[i].hit);
  return [0, 1, 2].map((k) => on.reduce((s, g) => s + g.rgb[k], 0) / on.length);
}

test('Surface mode: a mesh too large to draw in a frame shows a stand-in, then all of it, picked and traced on', async ({ page }) => {
  test.setTimeout(180_000);
  await openSurface(page);
  // 627,200 triangles: more than a software rasteriser draws in a frame (the view draws it in pieces).
  const n = 560, faces = 2 * n * n;
  await page.getByTestId('surface-mesh-input').setInputFiles({ name: 'bumpy-torus.ply', mimeType: 'application/octet-stream', buffer: bumpyTorusPLY(n) });
  // The first frame that shows it shows its stand-in (the camera has not been still long enough).
  const first = await page.waitForFunction(
    () => {
      const s = window.splinekitEditor!.surface.state();
      return s.file === 'bumpy-torus.ply' ? s.pictureTriangles : null;
    },
    undefined,
    { timeout: 120_000, polling: 'raf' },
  );
  const proxyTriangles = (await first.jsonValue()) as number;
  expect(proxyTriangles).toBeGreaterThan(1000);
  expect(proxyTriangles).toBeLessThan(faces / 4);
  await frames(page);
  const proxyGrid = await canvasGrid(page, 40, 25);

  // Once still, the picture is the whole mesh; picking works (the hierarchy came from the worker).
  await page.waitForFunction((f) => {
    const s = window.splinekitEditor!.surface.state();
    return s.meshReady && s.pictureTriangles === f;
  }, faces, { timeout: 120_000 });
  let s = await settled(page);
  expect(s.meshInfo?.faces).toBe(faces);
  const grid = await canvasGrid(page, 40, 25);
  const background = [0x1b, 0x1d, 0x21];
  const isBackground = (rgb: number[]) => rgb.every((c, k) => Math.abs(c - background[k]) <= 3);
  const hits = grid.filter((g) => g.hit).length;
  expect(hits, 'grid points on the mesh').toBeGreaterThan(200);
  // Where the mesh is picked, it is drawn (no piece left out), and only there (silhouette pixels aside).
  const mismatched = grid.filter((g) => g.hit === isBackground(g.rgb)).length;
  expect(mismatched, 'grid points where the picture and picking disagree').toBeLessThanOrEqual(3);
  // Drawn in the screen's colors, as the stand-in was (not darker, not lighter: same lighting).
  // (the stand-in is shown before the picking hierarchy comes: its grid is read where this one hits)
  const full = meanOnMesh(grid, grid), proxy = meanOnMesh(proxyGrid, grid);
  for (let k = 0; k < 3; k++) expect(Math.abs(full[k] - proxy[k]), `mean channel ${k} of the mesh, all of it against its stand-in`).toBeLessThan(12);

  // A spline drawn on it is traced on its faces and drawn over it.
  s = await drawSpline(page, [
    [0.29, 0.4],
    [0.39, 0.24],
    [0.55, 0.2],
  ]);
  expect(s.splines).toHaveLength(1);
  await expectOnMesh(page, s.splines[0], s.scale!);
  await page.waitForFunction((f) => window.splinekitEditor!.surface.state().pictureTriangles === f, faces);
  await frames(page);
  await copyView3d(page);
  const [curve, selected] = await page.evaluate(() => {
    const copy = (window as unknown as { __view3dCopy: HTMLCanvasElement }).__view3dCopy;
    const data = copy.getContext('2d')!.getImageData(0, 0, copy.width, copy.height).data;
    const near = (i: number, [r, g, b]: number[]) => Math.abs(data[i] - r) <= 24 && Math.abs(data[i + 1] - g) <= 24 && Math.abs(data[i + 2] - b) <= 24;
    let a = 0, b = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (near(i, [0xe8, 0x59, 0x0c])) a++;
      if (near(i, [0x18, 0x64, 0xab])) b++;
    }
    return [a, b];
  });
  expect(curve + selected, 'pixels of the curve over the mesh').toBeGreaterThan(100);
});

/** A torus (radii 1 and 0.35, n × n quads split in two) about `centre`, as OBJ text (double precision). */
function torusOBJ(n: number, centre: [number, number, number]): string {
  const lines: string[] = [];
  for (let i = 0; i < n; i++)
    for (let j = 0; j < n; j++) {
      const u = (2 * Math.PI * i) / n, v = (2 * Math.PI * j) / n;
      const p = [(1 + 0.35 * Math.cos(v)) * Math.cos(u), (1 + 0.35 * Math.cos(v)) * Math.sin(u), 0.35 * Math.sin(v)];
      lines.push(`v ${(centre[0] + p[0]).toFixed(9)} ${(centre[1] + p[1]).toFixed(9)} ${(centre[2] + p[2]).toFixed(9)}`);
    }
  const id = (i: number, j: number) => (i % n) * n + (j % n) + 1;
  for (let i = 0; i < n; i++)
    for (let j = 0; j < n; j++) lines.push(`f ${id(i, j)} ${id(i + 1, j)} ${id(i + 1, j + 1)}`, `f ${id(i, j)} ${id(i + 1, j + 1)} ${id(i, j + 1)}`);
  return lines.join('\n') + '\n';
}

/** Opens the OBJ text as `name` in Surface mode, once ready and settled: its canvas on a 40 × 25 grid. */
async function meshGrid(page: Page, name: string, text: string) {
  await page.getByTestId('surface-mesh-input').setInputFiles({ name, mimeType: 'text/plain', buffer: Buffer.from(text) });
  await page.waitForFunction((f) => {
    const s = window.splinekitEditor!.surface.state();
    return s.file === f && s.meshReady;
  }, name);
  await settled(page);
  return canvasGrid(page, 40, 25);
}

/** A spline drawn by three clicks across the view traces on the mesh's faces and is drawn over it. */
async function drawsOnMesh(page: Page) {
  const s = await drawSpline(page, [
    [0.3, 0.5],
    [0.45, 0.3],
    [0.7, 0.5],
  ]);
  expect(s.splines).toHaveLength(1);
  await expectOnMesh(page, s.splines[0], s.scale!);
}

test('Surface mode: a scan in georeferenced coordinates is shown, picked and traced on like the same mesh at the origin', async ({ page }) => {
  await openSurface(page);
  // Far away, the file's coordinates are 0.25-0.5 apart in single precision: shown as they were, the
  // torus came out blocky and clicks picked the wrong faces.
  const near = await meshGrid(page, 'torus.obj', torusOBJ(64, [0, 0, 0]));
  const far = await meshGrid(page, 'georeferenced-torus.obj', torusOBJ(64, [500000, 4000000, 100]));
  expect(near.filter((g) => g.hit).length, 'grid points on the torus').toBeGreaterThan(150);
  // The same picture and the same picking, point for point (silhouette pixels aside).
  expect(far.filter((g, i) => g.hit !== near[i].hit).length, 'grid points picked in one and not the other').toBeLessThanOrEqual(3);
  const background = [0x1b, 0x1d, 0x21];
  const isBackground = (rgb: number[]) => rgb.every((c, k) => Math.abs(c - background[k]) <= 3);
  expect(far.filter((g) => g.hit === isBackground(g.rgb)).length, 'grid points where picture and picking disagree').toBeLessThanOrEqual(3);
  // A spline drawn on it traces on its faces and is drawn over it.
  await drawsOnMesh(page);
});

test('Surface mode: a double-sided mesh is shown, picked and traced on as one surface', async ({ page }) => {
  await openSurface(page);
  // Every face written again with the other winding: drawn as they were, the two sides fought for
  // the pixels and their normals cancelled; built as they were, every edge had four faces and the
  // mesh fell apart into single faces, so no curve could join two clicks.
  const once = torusOBJ(48, [0, 0, 0]);
  const faces = once.split('\n').filter((l) => l.startsWith('f '));
  const twice = once + faces.map((l) => { const [, a, b, c] = l.split(' '); return `f ${a} ${c} ${b}`; }).join('\n') + '\n';
  const single = await meshGrid(page, 'torus.obj', once);
  const double = await meshGrid(page, 'double-sided-torus.obj', twice);
  const info = await page.evaluate(() => window.splinekitEditor!.surface.state().meshInfo!);
  expect(info.duplicateFaces).toBe(faces.length);
  expect(info.components).toBe(1);
  expect(single.filter((g) => g.hit).length, 'grid points on the torus').toBeGreaterThan(150);
  expect(double.filter((g, i) => g.hit !== single[i].hit).length, 'grid points picked in one and not the other').toBeLessThanOrEqual(3);
  // The same shading where both are hit (two sides fighting, or normals summed to nothing, are not).
  const differ = double.filter((g, i) => g.hit && single[i].hit && g.rgb.some((c, k) => Math.abs(c - single[i].rgb[k]) > 12));
  expect(differ.length, 'grid points shaded differently').toBeLessThanOrEqual(3);
  await drawsOnMesh(page);
});
