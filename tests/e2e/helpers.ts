import { expect, type Page } from '@playwright/test';
import type {} from '../../web/app/test-hook.js'; // window.splinekitEditor's type
import { existsSync, mkdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

/** A file of the shared test data (../shared/data beside the repository). */
export function sharedData(relative: string): string {
  return fileURLToPath(new URL(`../../../shared/data/${relative}`, import.meta.url));
}

/** A file of the app's public/ folder. */
export function publicFile(relative: string): string {
  return fileURLToPath(new URL(`../../public/${relative}`, import.meta.url));
}

/**
 * Writes docs/<name> (the README's screenshots) when it is missing or on request (UPDATE_DOCS=1),
 * so that test runs do not churn committed images (panels show timings that differ run to run).
 */
export async function docsScreenshot(page: Page, name: string): Promise<void> {
  const docs = fileURLToPath(new URL('../../docs/', import.meta.url));
  if (process.env.UPDATE_DOCS !== '1' && existsSync(`${docs}${name}`)) return;
  mkdirSync(docs, { recursive: true });
  await page.screenshot({ path: `${docs}${name}` });
}

export type EditorState = {
  file: string | null;
  elements: number;
  splines: number;
  segments: number;
  overlay: boolean;
  anchors: number;
  error: string | null;
  importMs: number | null;
  selection: { spline: number; anchor: number; kind: string | null } | null;
  canUndo: boolean;
  canRedo: boolean;
  documentsShown: number;
};

/** Console errors and uncaught page errors, collected from the moment the page is created. */
export function collectErrors(page: Page): string[] {
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(`console.error: ${m.text()}`);
  });
  page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
  return errors;
}

/** Opens the editor and waits until its starting sample is drawn. */
export async function openEditor(page: Page): Promise<void> {
  await page.goto('/');
  await page.waitForFunction(() => window.splinekitEditor !== undefined);
  await page.evaluate(() => window.splinekitEditor!.ready);
}

export function editorState(page: Page): Promise<EditorState> {
  return page.evaluate(() => window.splinekitEditor!.state());
}

/** Waits until two frames have been presented (rendering is on demand). */
export async function frames(page: Page): Promise<void> {
  await page.evaluate(() => new Promise<void>((r) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(r, 0)))));
}

/**
 * Waits for the editor to show `file` (or an error), then for it to be drawn. `shownBefore`: the
 * state's documentsShown before the file was chosen, so that reopening the file already shown
 * waits for the new copy instead of returning at once.
 */
export async function waitForFile(page: Page, file: string, shownBefore = -1): Promise<EditorState> {
  await page.waitForFunction(([f, n]) => {
    const s = window.splinekitEditor!.state();
    return s.file === f && s.documentsShown > n;
  }, [file, shownBefore] as const);
  await frames(page);
  return editorState(page);
}

function hexToRGB(hex: string): [number, number, number] {
  const n = parseInt(hex.replace('#', ''), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255];
}

/**
 * Takes a screenshot of the 2D view (the browser's drawing of the document under the overlay
 * canvas, composited as the user sees it) and decodes it into a canvas in the page
 * (window.__viewShot), where the readers below look at it.
 */
async function shootView(page: Page): Promise<void> {
  const canvas = page.locator('canvas.view2d-canvas');
  const png = (await canvas.screenshot({ animations: 'disabled', caret: 'hide' })).toString('base64');
  await page.evaluate(async (b64) => {
    const blob = await (await fetch(`data:image/png;base64,${b64}`)).blob();
    const bitmap = await createImageBitmap(blob);
    const shot = document.createElement('canvas');
    shot.width = bitmap.width;
    shot.height = bitmap.height;
    shot.getContext('2d', { willReadFrequently: true })!.drawImage(bitmap, 0, 0);
    (window as unknown as { __viewShot: HTMLCanvasElement }).__viewShot = shot;
  }, png);
}

/** Counts, for each color, the pixels of the view within `tolerance` of it on every channel. */
export async function countColors(page: Page, colors: string[], tolerance = 6): Promise<number[]> {
  await shootView(page);
  return page.evaluate(
    ({ targets, tolerance }) => {
      const shot = (window as unknown as { __viewShot: HTMLCanvasElement }).__viewShot;
      const data = shot.getContext('2d')!.getImageData(0, 0, shot.width, shot.height).data;
      const counts = targets.map(() => 0);
      for (let i = 0; i < data.length; i += 4) {
        for (let t = 0; t < targets.length; t++) {
          const [r, g, b] = targets[t];
          if (Math.abs(data[i] - r) <= tolerance && Math.abs(data[i + 1] - g) <= tolerance && Math.abs(data[i + 2] - b) <= tolerance) counts[t]++;
        }
      }
      return counts;
    },
    { targets: colors.map(hexToRGB), tolerance },
  );
}

/** The color of the view's pixel at client coordinates (x, y), as '#rrggbb'. */
export async function pixelAt(page: Page, x: number, y: number): Promise<string> {
  await shootView(page);
  return page.evaluate(
    ({ x, y }) => {
      const shot = (window as unknown as { __viewShot: HTMLCanvasElement }).__viewShot;
      const r = document.querySelector<HTMLCanvasElement>('canvas.view2d-canvas')!.getBoundingClientRect();
      const sx = Math.round(((x - r.left) * shot.width) / r.width), sy = Math.round(((y - r.top) * shot.height) / r.height);
      const [red, g, b] = shot.getContext('2d')!.getImageData(sx, sy, 1, 1).data;
      return `#${((1 << 24) | (red << 16) | (g << 8) | b).toString(16).slice(1)}`;
    },
    { x, y },
  );
}

/** A coarse fingerprint of the view: mean color of each cell of a 32 × 20 grid. */
export async function fingerprint(page: Page): Promise<number[]> {
  await shootView(page);
  return page.evaluate(() => {
    const shot = (window as unknown as { __viewShot: HTMLCanvasElement }).__viewShot;
    const copy = document.createElement('canvas');
    copy.width = 32;
    copy.height = 20;
    const ctx = copy.getContext('2d')!;
    ctx.imageSmoothingQuality = 'high';
    ctx.drawImage(shot, 0, 0, 32, 20);
    return Array.from(ctx.getImageData(0, 0, 32, 20).data);
  });
}

export function expectSameFingerprint(a: number[], b: number[]): void {
  expect(a.length).toBe(b.length);
  let worst = 0;
  for (let i = 0; i < a.length; i++) worst = Math.max(worst, Math.abs(a[i] - b[i]));
  expect(worst, 'largest channel difference between the two canvases').toBeLessThanOrEqual(2);
}

export function fingerprintDistance(a: number[], b: number[]): number {
  let sum = 0;
  for (let i = 0; i < a.length; i++) sum += Math.abs(a[i] - b[i]);
  return sum / a.length;
}

/** Fill colors (#rrggbb, lower case) used in an SVG file's markup. */
export function colorsInFile(path: string): Set<string> {
  const text = readFileSync(path, 'utf8');
  return new Set(Array.from(text.matchAll(/#[0-9a-fA-F]{6}\b/g), (m) => m[0].toLowerCase()));
}

/**
 * Counts an SVG's `<path>` elements and their segments from the path data alone — an independent
 * reference for files made of paths (like oc_dog.svg): one segment per drawing command, plus one
 * for a closepath that does not end where the subpath started.
 */
export function referenceCounts(path: string): { elements: number; segments: number } {
  const text = readFileSync(path, 'utf8');
  const arity: Record<string, number> = { m: 2, l: 2, h: 1, v: 1, c: 6, s: 4, q: 4, t: 2, a: 7, z: 0 };
  let elements = 0, segments = 0;
  for (const m of text.matchAll(/<path\b[^>]*?\sd="([^"]*)"/g)) {
    elements++;
    const tokens = m[1].match(/[MmLlHhVvCcSsQqTtAaZz]|[-+]?(?:\d*\.\d+|\d+\.?)(?:[eE][-+]?\d+)?/g) ?? [];
    let x = 0, y = 0, sx = 0, sy = 0, command = '', args: number[] = [];
    const run = () => {
      if (!command) return;
      const k = command.toLowerCase(), relative = command === k;
      if (k === 'z') {
        if (Math.abs(x - sx) > 1e-9 || Math.abs(y - sy) > 1e-9) segments++;
        x = sx;
        y = sy;
        return;
      }
      const n = arity[k];
      for (let i = 0; i + n <= args.length; i += n) {
        const g = args.slice(i, i + n);
        let nx: number, ny: number;
        if (k === 'h') [nx, ny] = [relative ? x + g[0] : g[0], y];
        else if (k === 'v') [nx, ny] = [x, relative ? y + g[0] : g[0]];
        else [nx, ny] = relative ? [x + g[n - 2], y + g[n - 1]] : [g[n - 2], g[n - 1]];
        if (k === 'm' && i === 0) [sx, sy] = [nx, ny];
        else segments++;
        [x, y] = [nx, ny];
      }
    };
    for (const t of tokens) {
      if (/[a-z]/i.test(t)) {
        run();
        command = t;
        args = [];
      } else args.push(Number(t));
    }
    run();
  }
  return { elements, segments };
}
