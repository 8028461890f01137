// Export draws the same picture: Chromium renders each shared SVG as the file has it and as
// splinekit writes it back with every shape rewritten from the splines (rewrite: 'all'), and the
// two renderings must match pixel for pixel up to anti-aliasing.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test } from '@playwright/test';
import { init, parseSVG } from '../../dist/index.js';

const data = new URL('../../../shared/data/svg/', import.meta.url).pathname;
const files = readdirSync(data)
  .flatMap((dir) => readdirSync(join(data, dir)).map((f) => `${dir}/${f}`))
  .filter((f) => f.endsWith('.svg'))
  .sort();

test('every shared SVG renders the same after export', async ({ page }) => {
  test.setTimeout(180_000);
  await init();
  await page.setContent('<canvas id="a"></canvas><canvas id="b"></canvas>');
  const failures: string[] = [];
  for (const file of files) {
    const original = readFileSync(join(data, file), 'utf8');
    const exported = parseSVG(original, { name: file }).toSVG({ rewrite: 'all' });
    const diff = await page.evaluate(
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
      [original, exported],
    );
    // Something was drawn, and at most 0.2% of the pixels differ by more than anti-aliasing does.
    if (!(diff.painted > 0.001 && diff.bad <= 0.002)) failures.push(`${file}: ${JSON.stringify(diff)}`);
  }
  expect(failures).toEqual([]);
});
