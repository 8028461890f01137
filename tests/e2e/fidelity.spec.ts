// The editor draws what the browser draws: every SVG of the shared data, the app's samples and
// the paint fixtures (gradients, dashes, markers, clip paths, masks, opacity, patterns, text,
// images, filters) is rendered twice in Chromium — natively, as an <img> of the file, and in the
// editor's view with the document's frame placed at the same size — and the two must agree on all
// but 1% of the pixels, beyond anti-aliasing. A posed skin drawing is compared the same way with
// the posed SVG the editor exports. Per-file figures are written to build/fidelity.json (and
// written into BENCHMARKS.md by `node bench/run.mjs --only=fidelity`). FIDELITY_DEBUG=1 keeps the
// screenshots of failing files and posed drawings in the test's output folder.
import { mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures.js';
import { editorState, frames, openEditor, publicFile, sharedData, waitForFile } from './helpers.js';
import { compareShots as compare, hideOverlays, shoot, type Comparison } from './shots.js';
import { drag, handleAt, rigFile, rigReady } from './skin-helpers.js';

/** The frame's width on screen (its height follows its aspect; tall frames are 400 high). */
const SIZE = 400;
/** Where the frame's top-left corner goes, in pixels from the view's corner. */
const INSET = 24;
/** At most this fraction of the pixels may differ beyond anti-aliasing. */
const MAX_DIFFERENT = 0.01;

const paint = fileURLToPath(new URL('./paint/', import.meta.url));
const sharedSvg = sharedData('svg');
const FILES = [
  ...readdirSync(sharedSvg).flatMap((dir) => readdirSync(join(sharedSvg, dir)).filter((f) => f.endsWith('.svg')).map((f) => join(sharedSvg, dir, f))),
  ...readdirSync(publicFile('samples')).filter((f) => f.endsWith('.svg')).map((f) => publicFile(`samples/${f}`)),
  ...readdirSync(paint).filter((f) => f.endsWith('.svg')).map((f) => join(paint, f)),
  // More files to try (drawings nobody here tuned on), e.g. SPLINEKIT_FIDELITY_DIR=~/Downloads/svgs.
  ...(process.env.SPLINEKIT_FIDELITY_DIR ? readdirSync(process.env.SPLINEKIT_FIDELITY_DIR).filter((f) => f.endsWith('.svg')).map((f) => join(process.env.SPLINEKIT_FIDELITY_DIR!, f)) : []),
].sort();


/** The size (pixels) the frame [x, y, w, h] is shown at. */
function shownSize(frame: number[]): { width: number; height: number } {
  const [, , w, h] = frame;
  return w >= h ? { width: SIZE, height: (SIZE * h) / w } : { width: (SIZE * w) / h, height: SIZE };
}

/**
 * How the editor shows the open document: its frame placed at (INSET, INSET) of the view,
 * `width` pixels wide, with the overlays hidden (they draw handles and guides, not the drawing).
 */
async function editorShot(page: Page, width: number, height: number): Promise<string> {
  const box = (await page.locator('canvas.view2d-canvas').boundingBox())!;
  const x = Math.round(box.x) + INSET, y = Math.round(box.y) + INSET;
  await page.evaluate(([x, y, w]) => window.splinekitEditor!.placeFrame(x, y, w), [x, y, width]);
  await hideOverlays(page, true);
  await frames(page);
  const shot = await shoot(page, x, y, width, height);
  await hideOverlays(page, false);
  return shot;
}

/** How Chromium draws `markup` as an image of `width` × `height` pixels on white. */
async function nativeShot(page: Page, markup: string, width: number, height: number): Promise<string> {
  await page.setContent('<body style="margin:0;background:#fff"><img id="native" style="display:block"></body>');
  await page.evaluate(
    async ([svg, w, h]) => {
      const img = document.getElementById('native') as HTMLImageElement;
      img.style.width = `${w}px`;
      img.style.height = `${h}px`;
      img.src = URL.createObjectURL(new Blob([svg], { type: 'image/svg+xml' }));
      await img.decode();
    },
    [markup, width, height] as const,
  );
  return shoot(page, 0, 0, width, height);
}

function record(name: string, figures: Record<string, Comparison>): void {
  const out = fileURLToPath(new URL('../../build/', import.meta.url));
  mkdirSync(out, { recursive: true });
  writeFileSync(join(out, name), `${JSON.stringify(figures, null, 2)}\n`);
}

test('every SVG draws in the editor as Chromium draws the file', async ({ page, browser }, testInfo) => {
  test.setTimeout(300_000);
  // Its own context (window): a second tab of the editor's would be in the background, and wait for frames.
  const native = await (await browser.newContext()).newPage();
  await openEditor(page);
  const figures: Record<string, Comparison> = {};
  const failures: string[] = [];
  for (const path of FILES) {
    const name = basename(path);
    // The first sample is also the editor's starting drawing: wait for the copy opened here.
    const shownBefore = (await editorState(page)).documentsShown;
    await page.getByTestId('file-input').setInputFiles(path);
    const state = await waitForFile(page, name, shownBefore);
    expect(state.error, name).toBeNull();
    const frame = await page.evaluate(() => window.splinekitEditor!.frame());
    const { width, height } = shownSize(frame!);
    const shown = await editorShot(page, width, height);
    const reference = await nativeShot(native, readFileSync(path, 'utf8'), width, height);
    const c = await compare(native, reference, shown);
    figures[path.includes('/shared/') ? path.slice(path.indexOf('svg/')) : path.includes('/paint/') ? `paint/${name}` : path.includes('/public/') ? `samples/${name}` : path] = c;
    if (process.env.FIDELITY_DEBUG && c.different > MAX_DIFFERENT) for (const [n, b] of [['shown', shown], ['native', reference]]) writeFileSync(testInfo.outputPath(`${name}-${n}.png`), Buffer.from(b, 'base64'));
    if (!(c.painted > 0.002 && c.different <= MAX_DIFFERENT)) failures.push(`${name}: ${(100 * c.different).toFixed(2)}% differ, ${(100 * c.painted).toFixed(1)}% painted`);
  }
  record('fidelity.json', figures);
  expect(FILES.length).toBeGreaterThan(40);
  expect(failures).toEqual([]);
});

for (const [label, path] of [
  ['characters/oc_ballerina.svg', sharedData('svg/characters/oc_ballerina.svg')],
  ['paint/gradients.svg', join(paint, 'gradients.svg')],
]) {
  test(`a posed drawing shows as its exported SVG draws: ${label}`, async ({ page, browser }, testInfo) => {
    await rigFile(page, path);
    await page.keyboard.press('p');
    const leg = await handleAt(page, 2);
    await drag(page, leg, { x: leg.x + 70, y: leg.y - 90 });
    await rigReady(page);
    const [posed] = await Promise.all([page.waitForEvent('download'), page.getByTestId('export-posed').click()]);
    const file = testInfo.outputPath('posed.svg');
    await posed.saveAs(file);

    const frame = await page.evaluate(() => window.splinekitEditor!.frame());
    const { width, height } = shownSize(frame!);
    const shown = await editorShot(page, width, height);
    const native = await (await browser.newContext()).newPage();
    const posedShot = await nativeShot(native, readFileSync(file, 'utf8'), width, height);
    const restShot = await nativeShot(native, readFileSync(path, 'utf8'), width, height);
    const c = await compare(native, posedShot, shown);
    if (process.env.FIDELITY_DEBUG) for (const [n, b] of [['shown', shown], ['posed', posedShot]]) writeFileSync(testInfo.outputPath(`${n}.png`), Buffer.from(b, 'base64'));
    // The view is the pose (not the rest drawing): the rest differs from it where the drawing moved.
    const rest = await compare(native, restShot, shown);
    record(`fidelity-posed-${basename(path, '.svg')}.json`, { [`${label} posed`]: c, [`${label} rest vs posed view`]: rest });
    expect(c.painted).toBeGreaterThan(0.01);
    expect(c.different).toBeLessThanOrEqual(MAX_DIFFERENT);
    expect(rest.different, 'the rest drawing differs from the posed view').toBeGreaterThan(0.005);
    if (label.startsWith('paint/')) expect(readFileSync(file, 'utf8'), 'the posed export carries its own copies of the paint').toContain('-splinekit-');
  });
}

test('a hostile file cannot run script in the editor, and opening a file fetches nothing', async ({ page }, testInfo) => {
  await openEditor(page);
  const fetched: string[] = [];
  page.on('request', (r) => {
    if (!r.url().startsWith('data:') && !r.url().startsWith('blob:')) fetched.push(r.url());
  });
  const file = testInfo.outputPath('hostile.svg');
  writeFileSync(
    file,
    `<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 100 100" onload="window.pwned = 1">
      <script>window.pwned = 2</script>
      <rect width="50" height="50" fill="#0c8" onmouseover="window.pwned = 3"/>
      <image href="x" onerror="window.pwned = 4" width="10" height="10"/>
      <foreignObject width="100" height="100"><iframe xmlns="http://www.w3.org/1999/xhtml" src="javascript:parent.pwned=5"></iframe></foreignObject>
      <a xlink:href="javascript:window.pwned = 6"><circle cx="70" cy="70" r="20"/></a>
      <style>@import url(http://127.0.0.1:9/x.css); rect { stroke: url(http://127.0.0.1:9/p.svg#p) }</style>
      <image href="http://127.0.0.1:9/x.png" width="10" height="10"/>
      <circle cx="20" cy="80" r="5" style="fill: url('http://127.0.0.1:9/g.svg#g')"/>
    </svg>`,
  );
  await page.getByTestId('file-input').setInputFiles(file);
  const state = await waitForFile(page, 'hostile.svg');
  expect(state.error).toBeNull();
  await page.waitForTimeout(300);
  expect(await page.evaluate(() => (window as unknown as { pwned?: number }).pwned ?? 0)).toBe(0);
  // The shapes are drawn all the same; nothing was asked of the network.
  expect(state.elements).toBe(3);
  expect(fetched).toEqual([]);
});

test('a drawing the browser cannot show is named in the warnings, and the editor keeps working', async ({ page }) => {
  await openEditor(page);
  // The page's XML parser fails on the view's markup, as it would on markup it cannot read.
  await page.evaluate(() => {
    const real = DOMParser.prototype.parseFromString;
    (window as unknown as { restoreParser: () => void }).restoreParser = () => (DOMParser.prototype.parseFromString = real);
    DOMParser.prototype.parseFromString = function (this: DOMParser, text: string, type: DOMParserSupportedType) {
      if (!text.includes('data-splinekit-shape')) return real.call(this, text, type);
      throw new Error('parser exploded');
    } as DOMParser['parseFromString'];
  });
  await page.getByTestId('file-input').setInputFiles(sharedData('svg/characters/oc_dog.svg'));
  const state = await waitForFile(page, 'oc_dog.svg');
  expect(state.elements).toBe(8);
  await expect(page.getByTestId('warnings')).toContainText('<svg>: not drawn (the drawing could not be shown: parser exploded)');
  // With the parser back, the next file is drawn.
  await page.evaluate(() => (window as unknown as { restoreParser: () => void }).restoreParser());
  await page.getByTestId('file-input').setInputFiles(sharedData('svg/characters/oc_stick_man.svg'));
  await waitForFile(page, 'oc_stick_man.svg');
  await expect(page.getByTestId('warnings')).not.toContainText('not drawn');
  expect(await page.locator('.view2d-drawing').evaluate((h) => h.shadowRoot!.querySelectorAll('svg.drawing path').length)).toBeGreaterThan(0);
});
