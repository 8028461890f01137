// Screenshots of the editor's view and their comparison beyond anti-aliasing, shared by the
// fidelity tests (the editor against Chromium's own rendering of a file) and the live-canvas test
// (a frame of a drag against the still drawing of its pose).
import type { Page } from '@playwright/test';

/** A channel difference up to this is anti-aliasing or colour rounding. */
const CHANNEL_TOLERANCE = 40;

export interface Comparison {
  /** Fraction of pixels that differ beyond anti-aliasing. */
  different: number;
  /** Fraction of pixels the first image paints (not white): something must be drawn. */
  painted: number;
  width: number;
  height: number;
}

/** Screenshot (PNG, base64) of the region of the page, the region's size rounded down to pixels. */
export async function shoot(page: Page, x: number, y: number, width: number, height: number): Promise<string> {
  const png = await page.screenshot({ clip: { x, y, width: Math.floor(width), height: Math.floor(height) }, animations: 'disabled', caret: 'hide' });
  return png.toString('base64');
}

/** Hides (or shows again) what the view draws over the document: handles, guides, control points. */
export async function hideOverlays(page: Page, hidden: boolean): Promise<void> {
  await page.evaluate((hidden) => {
    for (const el of Array.from(document.querySelector('.stage')!.children) as HTMLElement[]) {
      if (!el.classList.contains('view2d-drawing')) el.style.visibility = hidden ? 'hidden' : '';
    }
  }, hidden);
}

/**
 * Compares two screenshots: a pixel differs when every pixel of the other image's 3 × 3
 * neighbourhood is further than the tolerance from it on some channel (so edges that moved by
 * less than a pixel, as anti-aliasing does, do not count), in either direction.
 */
export async function compareShots(page: Page, a: string, b: string): Promise<Comparison> {
  return page.evaluate(
    async ([a, b, tolerance]) => {
      const decode = async (b64: string) => {
        const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
        const c = document.createElement('canvas');
        c.width = bitmap.width;
        c.height = bitmap.height;
        const ctx = c.getContext('2d', { willReadFrequently: true })!;
        ctx.drawImage(bitmap, 0, 0);
        return { w: c.width, h: c.height, data: ctx.getImageData(0, 0, c.width, c.height).data };
      };
      const A = await decode(a), B = await decode(b);
      if (A.w !== B.w || A.h !== B.h) return { different: 1, painted: 0, width: A.w, height: A.h };
      const { w, h } = A;
      const near = (p: Uint8ClampedArray, i: number, q: Uint8ClampedArray, x: number, y: number) => {
        for (let dy = -1; dy <= 1; dy++) {
          for (let dx = -1; dx <= 1; dx++) {
            const xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
            const j = 4 * (yy * w + xx);
            if (Math.abs(p[i] - q[j]) <= tolerance && Math.abs(p[i + 1] - q[j + 1]) <= tolerance && Math.abs(p[i + 2] - q[j + 2]) <= tolerance) return true;
          }
        }
        return false;
      };
      let different = 0, painted = 0;
      for (let y = 0; y < h; y++) {
        for (let x = 0; x < w; x++) {
          const i = 4 * (y * w + x);
          if (A.data[i] < 245 || A.data[i + 1] < 245 || A.data[i + 2] < 245) painted++;
          if (!near(A.data, i, B.data, x, y) || !near(B.data, i, A.data, x, y)) different++;
        }
      }
      return { different: different / (w * h), painted: painted / (w * h), width: w, height: h };
    },
    [a, b, CHANNEL_TOLERANCE] as const,
  );
}

