import { readFileSync } from 'node:fs';
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures.js';
import { docsScreenshot, frames, openEditor } from './helpers.js';

/**
 * Edit mode end to end (issue 16): sketch a stroke, drag a control point with an active window,
 * widen one side by dragging its end, undo and redo, export, and get the curve back from the
 * autosave; then turn a path of the drawing into a curve, set a tangent, draw with a pen (pressure
 * kept) and close the curve.
 */

type EditState = ReturnType<NonNullable<Window['splinekitEditor']>['edit']>;

function edit(page: Page): Promise<EditState> {
  return page.evaluate(() => window.splinekitEditor!.edit());
}

async function pointAt(page: Page, curve: number, point: number): Promise<{ x: number; y: number }> {
  const at = await page.evaluate(([c, p]) => window.splinekitEditor!.editPointOnScreen(c, p), [curve, point]);
  expect(at, `point ${point} of curve ${curve} is drawn`).not.toBeNull();
  return at!;
}

/** Presses at `from` and moves in `steps` to `to`, then releases. */
async function drag(page: Page, from: { x: number; y: number }, to: { x: number; y: number }, steps = 10): Promise<void> {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) await page.mouse.move(from.x + ((to.x - from.x) * i) / steps, from.y + ((to.y - from.y) * i) / steps);
  await page.mouse.up();
  await frames(page);
}

function pointsOf(s: EditState, curve = 0): [number, number][] {
  const p = s.curves[curve].points;
  return Array.from({ length: p.length / 2 }, (_, i) => [p[2 * i], p[2 * i + 1]]);
}

async function openEditMode(page: Page): Promise<void> {
  await openEditor(page);
  await page.getByRole('button', { name: 'Edit', exact: true }).click();
  await frames(page);
}

test('sketch a stroke, drag with a window, widen one side, undo, export, reload', async ({ page }) => {
  await openEditMode(page);
  await page.getByTestId('edit-tool-draw').click();
  // A wave across the view, drawn with the mouse in 60 moves.
  const box = (await page.locator('canvas').first().boundingBox())!;
  const x0 = box.x + box.width * 0.2, y0 = box.y + box.height * 0.5, w = box.width * 0.5;
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  for (let i = 1; i <= 60; i++) await page.mouse.move(x0 + (w * i) / 60, y0 + 40 * Math.sin((i / 60) * 2 * Math.PI));
  await page.mouse.up();
  await frames(page);
  let s = await edit(page);
  expect(s.curves).toHaveLength(1);
  const stroke = pointsOf(s);
  expect(stroke.length).toBeGreaterThan(30);
  expect(s.curves[0].closed).toBe(false);
  expect(s.curves[0].pressure).toBeNull(); // a mouse has no pressure

  // Edit: a window of 4 on each side around the middle point.
  await page.keyboard.press('e');
  const mid = Math.floor(stroke.length / 2);
  await page.mouse.click((await pointAt(page, 0, mid)).x, (await pointAt(page, 0, mid)).y);
  await page.getByTestId('edit-left').fill('4');
  await page.getByTestId('edit-left').press('Tab');
  await page.getByTestId('edit-right').fill('4');
  await page.getByTestId('edit-right').press('Tab');
  s = await edit(page);
  expect(s.selected).toEqual({ curve: 0, point: mid });
  expect(s.window!.indices).toEqual(Array.from({ length: 9 }, (_, k) => mid - 4 + k));
  expect(s.window!.weights[4]).toBe(1);
  expect(s.window!.weights[0]).toBe(0);
  expect(s.window!.weights[8]).toBe(0);

  const from = await pointAt(page, 0, mid);
  await drag(page, from, { x: from.x, y: from.y - 60 });
  s = await edit(page);
  const once = pointsOf(s);
  const to = await pointAt(page, 0, mid);
  expect(Math.abs(to.x - from.x)).toBeLessThan(0.5);
  expect(Math.abs(to.y - (from.y - 60))).toBeLessThan(0.5);
  once.forEach((p, i) => {
    const inside = i > mid - 4 && i < mid + 4;
    if (inside) expect(p, `point ${i} moved`).not.toEqual(stroke[i]);
    else expect(p, `point ${i} stayed`).toEqual(stroke[i]);
  });

  // Widen the right side: drag its end (blue) onto the point 8 to the right of the dragged one.
  const end = await page.evaluate(() => window.splinekitEditor!.editWindowEndOnScreen('right'));
  expect(end).not.toBeNull();
  await drag(page, end!, await pointAt(page, 0, mid + 8), 6);
  s = await edit(page);
  expect(s.settings.right).toBe(8);
  expect(s.settings.left).toBe(4);
  expect(s.window!.indices.at(-1)).toBe(mid + 8);
  expect(pointsOf(s)).toEqual(once); // resizing the window moves nothing
  await docsScreenshot(page, 'edit.png'); // the README's picture of Edit mode

  const again = await pointAt(page, 0, mid);
  await drag(page, again, { x: again.x + 30, y: again.y });
  const twice = pointsOf(await edit(page));
  twice.forEach((p, i) => {
    const inside = i > mid - 4 && i < mid + 8;
    if (inside) expect(p, `point ${i} moved`).not.toEqual(once[i]);
    else expect(p, `point ${i} stayed`).toEqual(once[i]);
  });

  // Undo twice: the first drag, then the stroke as drawn; redo brings the first drag back.
  await page.keyboard.press('Control+z');
  expect(pointsOf(await edit(page))).toEqual(once);
  await page.keyboard.press('Control+z');
  expect(pointsOf(await edit(page))).toEqual(stroke);
  await page.keyboard.press('Control+Shift+z');
  expect(pointsOf(await edit(page))).toEqual(once);

  // Export: the drawing with the curve added as a cubic Bézier path (one C per segment).
  const [saved] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('Control+s')]);
  const svg = readFileSync((await saved.path())!, 'utf8');
  const d = /<path id="splinekit-edit-0" d="([^"]+)"/.exec(svg);
  expect(d, 'the exported SVG holds the curve').not.toBeNull();
  expect(d![1].startsWith('M')).toBe(true);
  expect(d![1].match(/C/g)).toHaveLength(once.length - 1);

  // The curves are autosaved with the document: a reload brings them back, in Edit mode.
  await page.waitForTimeout(500);
  await page.reload();
  await page.waitForFunction(() => window.splinekitEditor !== undefined);
  await page.evaluate(() => window.splinekitEditor!.ready);
  await page.waitForFunction(() => window.splinekitEditor!.edit().curves.length === 1);
  expect(pointsOf(await edit(page))).toEqual(once);
});

test('a path of the drawing becomes a curve; a tangent is set and undone; the drop-off shows in the preview; a pen stroke keeps its pressure; close and undo', async ({ page }) => {
  await openEditMode(page);
  await page.keyboard.press('c');
  const anchor = await page.evaluate(() => window.splinekitEditor!.anchorOnScreen(0, 0));
  expect(anchor).not.toBeNull();
  await page.mouse.click(anchor!.x, anchor!.y);
  await frames(page);
  let s = await edit(page);
  expect(s.curves).toHaveLength(1);
  expect(s.tool).toBe('edit');
  expect(s.selected).not.toBeNull();
  // The linear drop-off: weights fall monotonically from the dragged point to both ends.
  await page.getByTestId('edit-falloff').selectOption('linear');
  s = await edit(page);
  const weights = s.window!.weights, c = weights.indexOf(1);
  for (let k = 0; k < c; k++) expect(weights[k]).toBeLessThan(weights[k + 1]);
  for (let k = c; k < weights.length - 1; k++) expect(weights[k]).toBeGreaterThan(weights[k + 1]);

  await page.keyboard.press('t');
  const at = s.selected!;
  const knob = await page.evaluate(([ci, pi]) => {
    const e = window.splinekitEditor!;
    const state = e.edit();
    const p = state.curves[ci].points;
    const q = e.editPointOnScreen(ci, pi)!;
    // The knob sits a third of the tangent past the point; find it from two neighbours' chord.
    const n = p.length / 2;
    const a = e.editPointOnScreen(ci, Math.max(0, pi - 1))!, b = e.editPointOnScreen(ci, Math.min(n - 1, pi + 1))!;
    return { x: q.x + (b.x - a.x) / 6, y: q.y + (b.y - a.y) / 6, approx: true };
  }, [at.curve, at.point]);
  // Press near the knob: the layer picks within 10 pixels; move it out sideways.
  await drag(page, knob, { x: knob.x + 25, y: knob.y + 25 }, 5);
  s = await edit(page);
  expect(s.curves[0].tangents).toBe(1);
  await page.keyboard.press('Control+z');
  expect((await edit(page)).curves[0].tangents).toBe(0);

  // A pen stroke (pressure rising from 0.2 to 0.8) keeps its pressure per control point.
  await page.keyboard.press('d');
  const box = (await page.locator('canvas').first().boundingBox())!;
  const cdp = await page.context().newCDPSession(page);
  const pen = (type: string, i: number) =>
    cdp.send('Input.dispatchMouseEvent', {
      type,
      x: box.x + box.width * (0.3 + 0.01 * i),
      y: box.y + box.height * (0.3 + 0.004 * i * (i % 3)),
      button: 'left',
      buttons: type === 'mouseReleased' ? 0 : 1,
      clickCount: 1,
      pointerType: 'pen',
      force: 0.2 + 0.02 * i,
    });
  await pen('mousePressed', 0);
  for (let i = 1; i <= 30; i++) await pen('mouseMoved', i);
  await pen('mouseReleased', 30);
  await frames(page);
  s = await edit(page);
  expect(s.curves).toHaveLength(2);
  const pressure = s.curves[1].pressure!;
  expect(pressure, 'the pen stroke kept its pressure').not.toBeNull();
  expect(pressure).toHaveLength(s.curves[1].points.length / 2);
  expect(pressure[0]).toBeCloseTo(0.2, 2);
  expect(pressure.at(-1)!).toBeCloseTo(0.8, 2);
  expect(pressure.every((p, i) => i === 0 || p >= pressure[i - 1] - 1e-9)).toBe(true);

  // Close the pen curve, and undo that.
  await page.getByTestId('edit-close').click();
  expect((await edit(page)).curves[1].closed).toBe(true);
  await page.keyboard.press('Control+z');
  expect((await edit(page)).curves[1].closed).toBe(false);
});
