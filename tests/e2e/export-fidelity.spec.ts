// Export draws the same picture: Chromium renders each shared SVG as the file has it and as
// splinekit writes it back with every shape rewritten from the splines (rewrite: 'all'), and the
// two renderings must match pixel for pixel up to anti-aliasing.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { init, parseSVG } from '../../dist/index.js';

const data = new URL('../../../shared/data/svg/', import.meta.url).pathname;
const files = readdirSync(data)
  .flatMap((dir) => readdirSync(join(data, dir)).map((f) => `${dir}/${f}`))
  .filter((f) => f.endsWith('.svg'))
  .sort();

/**
 * Draws two SVGs as images in Chromium, 400 px on their longer side on white, and compares them:
 * `bad` is the fraction of pixels whose channels differ by more than anti-aliasing does (96),
 * `painted` the fraction the first one paints.
 */
async function diffImages(page: Page, a: string, b: string): Promise<{ bad: number; painted: number; size: number }> {
return page.evaluate(
    async ([a, b]) => {
      const load = (svg: string) =>
        new Promise<HTMLImageElement>((resolve, reject) => {
          const img = new Image();
          img.onload = () => resolve(img);
          img.onerror = () => reject(new Error('image failed to load'));
          img.src = `data:image/svg+xml;base64,${btoa(unescape(encodeURIComponent(svg)))}`;
        });
      const draw = (img: HTMLImageElement, id: string) => {
        const c = document.getElementById(id) as HTMLCanvasElement;
        const scale = 400 / Math.max(img.naturalWidth || 400, img.naturalHeight || 400);
        c.width = Math.round((img.naturalWidth || 400) * scale);
        c.height = Math.round((img.naturalHeight || 400) * scale);
        const ctx = c.getContext('2d', { willReadFrequently: true })!;
        ctx.fillStyle = '#fff';
        ctx.fillRect(0, 0, c.width, c.height);
        ctx.drawImage(img, 0, 0, c.width, c.height);
        return ctx.getImageData(0, 0, c.width, c.height).data;
      };
      const pa = draw(await load(a), 'a');
      const pb = draw(await load(b), 'b');
      if (pa.length !== pb.length) return { bad: 1, painted: 0, size: -1 };
      let bad = 0, painted = 0;
      for (let i = 0; i < pa.length; i += 4) {
        const d = Math.max(Math.abs(pa[i] - pb[i]), Math.abs(pa[i + 1] - pb[i + 1]), Math.abs(pa[i + 2] - pb[i + 2]));
        if (d > 96) bad++;
        if (pa[i] < 250 || pa[i + 1] < 250 || pa[i + 2] < 250) painted++;
      }
      return { bad: bad / (pa.length / 4), painted: painted / (pa.length / 4), size: pa.length / 4 };
    },
  [a, b],
);
}

test('every shared SVG renders the same after export', async ({ page }) => {
  test.setTimeout(180_000);
  await init();
  await page.setContent('<canvas id="a"></canvas><canvas id="b"></canvas>');
  const failures: string[] = [];
  for (const file of files) {
    const original = readFileSync(join(data, file), 'utf8');
    const exported = parseSVG(original, { name: file }).toSVG({ rewrite: 'all' });
    const diff = await diffImages(page, original, exported);
    // Something was drawn, and at most 0.2% of the pixels differ by more than anti-aliasing does.
    if (!(diff.painted > 0.001 && diff.bad <= 0.002)) failures.push(`${file}: ${JSON.stringify(diff)}`);
  }
  expect(failures).toEqual([]);
});

test('deformed shapes keep their paint: user-space gradients and patterns follow the shape', async ({ page }) => {
  await init();
  await page.setContent('<canvas id="a"></canvas><canvas id="b"></canvas>');
  const paint = new URL('./paint/', import.meta.url).pathname;
  const patterned = `<svg xmlns="http://www.w3.org/2000/svg" width="400" height="300" viewBox="0 0 400 300">
    <defs><pattern id="p" patternUnits="userSpaceOnUse" width="24" height="24" patternTransform="rotate(15)">
      <rect width="24" height="24" fill="#fff3bf"/><rect width="12" height="12" fill="#e8590c"/><circle cx="18" cy="18" r="5" fill="#1971c2"/></pattern></defs>
    <path d="M60 40 C200 0 300 120 340 260 L60 260 Z" fill="url(#p)" stroke="#333" stroke-width="3"/></svg>`;
  // Every shape moved by one affine map of the document: the picture must be the file drawn under that map.
  const m = { a: 0.9 * Math.cos(0.35), b: 0.9 * Math.sin(0.35), c: -0.8 * Math.sin(0.35), d: 0.8 * Math.cos(0.35), e: 110, f: -30 };
  const matrix = `matrix(${m.a} ${m.b} ${m.c} ${m.d} ${m.e} ${m.f})`;
  for (const [name, original] of [['gradients.svg', readFileSync(join(paint, 'gradients.svg'), 'utf8')], ['pattern', patterned]]) {
    const doc = parseSVG(original, { name });
    for (const s of doc.splines) {
      for (let i = 0; i < s.points.length; i += 2) {
        const x = s.points[i], y = s.points[i + 1];
        s.points[i] = m.a * x + m.c * y + m.e;
        s.points[i + 1] = m.b * x + m.d * y + m.f;
      }
    }
    const moved = doc.toSVG();
    const reference = original.replace(/<svg[^>]*>/, (open) => `${open}<g transform="${matrix}">`).replace(/<\/svg>\s*$/, '</g></svg>');
    // The control: the same shapes painted by the paint as the file placed it.
    const unfollowed = moved.replace(/url\(#([^)]*?)-splinekit-\d+-(fill|stroke)\)/g, 'url(#$1)');
    expect(unfollowed).not.toBe(moved);
    const follows = await diffImages(page, reference, moved);
    const stays = await diffImages(page, reference, unfollowed);
    expect(follows.painted, name).toBeGreaterThan(0.05);
    expect(follows.bad, `${name}: pixels that differ with the paint following`).toBeLessThanOrEqual(0.002);
    expect(stays.bad, `${name}: pixels that differ with the paint left in place`).toBeGreaterThan(0.02);
  }
});
