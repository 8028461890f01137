import { readFileSync } from 'node:fs';
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures.js';
import { docsScreenshot, fingerprint, fingerprintDistance, frames, openEditor, sharedData } from './helpers.js';

/**
 * Morph mode end to end: two keys (the mode's own sample and a glyph from the shared data opened
 * as a file) blend; t is scrubbed; a pin is dragged from one key to the other and undone; the
 * animated SVG export moves in Chromium with no script.
 */

type MorphState = ReturnType<NonNullable<Window['splinekitEditor']>['morph']>;

function morph(page: Page): Promise<MorphState> {
  return page.evaluate(() => window.splinekitEditor!.morph());
}

async function openMorph(page: Page): Promise<MorphState> {
  await openEditor(page);
  await page.getByRole('button', { name: 'Morph', exact: true }).click();
  await page.waitForFunction(() => window.splinekitEditor!.morph().contours > 0);
  await frames(page);
  return morph(page);
}

test('loads two shapes, scrubs t, pins an anchor with undo, and exports an animated SVG that moves without script', async ({ page, context }, testInfo) => {
  const start = await openMorph(page);
  expect(start).toMatchObject({ active: true, keyA: 'blob', keyB: 'star', error: null, pins: 0 });
  expect(start.lines).toBeGreaterThan(10);
  await expect(page.getByTestId('morph-correspondence')).toHaveAttribute('data-count', String(start.lines));

  // A glyph from a file as the second key: the Fig. 7 G of the paper.
  await page.getByTestId('morph-open-b').setInputFiles(sharedData('svg/morph/NimbusRoman-Bold_G.svg'));
  await page.waitForFunction(() => window.splinekitEditor!.morph().keyB === 'file');
  const glyph = await morph(page);
  expect(glyph.error).toBeNull();
  expect(glyph.work).not.toBe(start.work);
  // and the Courier-like G as the first: the two keys of Fig. 7.
  await page.getByTestId('morph-open-a').setInputFiles(sharedData('svg/morph/NimbusMonoPS-Bold_G.svg'));
  await page.waitForFunction(() => window.splinekitEditor!.morph().keyA === 'file');
  expect(await morph(page)).toMatchObject({ error: null, contours: 1 });

  // Scrubbing t changes the in-between; t = 0 and t = 1 differ.
  const slider = page.getByTestId('morph-slider');
  await slider.fill('400');
  await page.waitForFunction(() => window.splinekitEditor!.morph().t === 0.4);
  await frames(page);
  await docsScreenshot(page, 'morph.png');
  await slider.fill('0');
  await page.waitForFunction(() => window.splinekitEditor!.morph().t === 0);
  const at0 = (await morph(page)).checksum;
  await frames(page);
  const drawn0 = await fingerprint(page);
  await slider.fill('1000');
  await page.waitForFunction(() => window.splinekitEditor!.morph().t === 1);
  const at1 = (await morph(page)).checksum;
  expect(at1).not.toBe(at0);
  // The view draws the new in-between (its paths are rewritten in place, not remounted).
  await frames(page);
  expect(fingerprintDistance(drawn0, await fingerprint(page)), 'the drawing changed with t').toBeGreaterThan(1);
  await expect(page.getByTestId('morph-t')).toHaveText('1.000');

  // A pin: drag from an anchor of the first key to a far anchor of the second.
  const from = await page.evaluate(() => window.splinekitEditor!.morphAnchorOnScreen('a', 0));
  const far = await page.evaluate(() => {
    const e = window.splinekitEditor!;
    const a = e.morphAnchorOnScreen('a', 0)!;
    let best = null as { x: number; y: number } | null, bestD = -1;
    for (let k = 0; ; k++) {
      const b = e.morphAnchorOnScreen('b', k);
      if (!b) break;
      const d = Math.hypot(b.x - a.x, b.y - a.y);
      if (d > bestD) {
        bestD = d;
        best = b;
      }
    }
    return best;
  });
  expect(from).not.toBeNull();
  expect(far).not.toBeNull();
  const before = await morph(page);
  await page.mouse.move(from!.x, from!.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) await page.mouse.move(from!.x + ((far!.x - from!.x) * i) / 10, from!.y + ((far!.y - from!.y) * i) / 10);
  await page.mouse.up();
  await page.waitForFunction(() => window.splinekitEditor!.morph().pins === 1);
  const pinned = await morph(page);
  expect(pinned.work).toBeGreaterThan(before.work!); // a pin against the least-work match costs work
  await expect(page.getByTestId('morph-pins')).toHaveAttribute('data-count', '1');
  await page.keyboard.press('Control+z');
  await page.waitForFunction(() => window.splinekitEditor!.morph().pins === 0);
  expect((await morph(page)).work).toBeCloseTo(before.work!, 9);
  await page.keyboard.press('Control+Shift+z');
  await page.waitForFunction(() => window.splinekitEditor!.morph().pins === 1);

  // The animated SVG plays as an image, where no script runs.
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('morph-export-animated').click()]);
  expect(download.suggestedFilename()).toBe('NimbusMonoPS-Bold_G-to-NimbusRoman-Bold_G-animated.svg');
  const file = testInfo.outputPath('morph-animated.svg');
  await download.saveAs(file);
  const svg = readFileSync(file, 'utf8');
  expect(svg).toContain('<animate attributeName="d"');
  expect(svg).not.toMatch(/<script/i);
  const viewer = await context.newPage();
  await viewer.setContent(`<body style="margin:0;background:#fff"><img id="anim" style="height:400px" src="data:image/svg+xml;base64,${Buffer.from(svg).toString('base64')}"></body>`);
  await viewer.waitForFunction(() => (document.getElementById('anim') as HTMLImageElement).complete);
  const img = viewer.locator('#anim');
  const first = await img.screenshot();
  await expect.poll(async () => (await img.screenshot()).equals(first), { message: 'a later frame of the animated SVG differs from the first' }).toBe(false);
  await viewer.close();
});

test('a glyph of a local font file is a key; the set-up comes back after a reload; a bad key file leaves the morph as it was', async ({ page }) => {
  await openMorph(page);
  await page.getByTestId('morph-key-b').selectOption('ring');
  await page.getByRole('button', { name: 'Intrinsic' }).click();
  await page.waitForFunction(() => {
    const s = window.splinekitEditor!.morph();
    return s.keyB === 'ring' && s.interpolation === 'intrinsic' && s.contours === 2;
  });
  const ring = await morph(page);
  await page.getByTestId('morph-open-b').setInputFiles({ name: 'broken.svg', mimeType: 'image/svg+xml', buffer: Buffer.from('<svg><path d="M0 0 L"') });
  await expect.poll(async () => (await page.evaluate(() => window.splinekitEditor!.state().error)) ?? '').toContain('broken.svg');
  expect(await morph(page)).toMatchObject({ keyB: 'ring', work: ring.work });
  await page.waitForTimeout(400); // the autosave runs 300 ms after the last change
  await page.reload();
  await page.evaluate(() => window.splinekitEditor!.ready);
  await page.getByRole('button', { name: 'Morph', exact: true }).click();
  await page.waitForFunction(() => window.splinekitEditor!.morph().contours > 0);
  expect(await morph(page)).toMatchObject({ keyB: 'ring', interpolation: 'intrinsic', contours: 2 });

  // The "a" of a TrueType font (two contours: the bowl is a hole) blends into the ring.
  await page.getByTestId('morph-char-a').fill('a');
  await page.getByTestId('morph-font-a').setInputFiles(sharedData('fonts/LiberationSerif-Bold.ttf'));
  await page.waitForFunction(() => window.splinekitEditor!.morph().keyA === 'file');
  expect(await morph(page)).toMatchObject({ keyA: 'file', keyB: 'ring', contours: 2, error: null });
  await expect(page.getByTestId('morph-key-a').locator('option:checked')).toHaveText(/“a”/);
});
