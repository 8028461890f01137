// While a skin handle is dragged, the editor paints drawings of solid paint (fills, strokes with
// dashes, caps, joins and opacities, transformed groups, clip paths) on a 2D canvas from the
// splines instead of rewriting the SVG's paths per frame; drawings with paint it does not draw
// (gradients, patterns, masks, filters, markers, text, images) stay the browser's SVG, written with
// the digits the zoom shows. Either way, a frame of the drag must look as the still drawing of the
// same pose does once the handle is released: both are screenshotted at the same place and compared
// as fidelity.spec.ts compares (at most 1% of the pixels differ beyond anti-aliasing).
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Page } from '@playwright/test';
import { expect, test } from './fixtures.js';
import { frames, sharedData } from './helpers.js';
import { compareShots, hideOverlays, shoot } from './shots.js';
import { handleAt, rigFile, rigReady } from './skin-helpers.js';

const paint = fileURLToPath(new URL('./paint/', import.meta.url));
const MAX_DIFFERENT = 0.01;

/** What shows the drawing now: the live canvas or the browser's SVG (and whether the other is hidden). */
function shownBy(page: Page): Promise<{ canvas: boolean; svg: boolean; frame: string | null }> {
  return page.evaluate(() => {
    const root = document.querySelector('.view2d-drawing')!.shadowRoot!;
    const canvas = root.querySelector('canvas.live') as HTMLCanvasElement;
    const svg = root.querySelector('svg.drawing') as SVGSVGElement;
    return { canvas: !canvas.hidden, svg: getComputedStyle(svg).visibility !== 'hidden', frame: canvas.dataset.frame ?? null };
  });
}

for (const [label, path, canvas] of [
  ['paint/live-strokes-clips.svg', join(paint, 'live-strokes-clips.svg'), true],
  ['illustrations/oc_road_runner_car.svg (1,121 clipped paths)', sharedData('svg/illustrations/oc_road_runner_car.svg'), true],
  ['illustrations/ghostscript_tiger_inkscape.svg', sharedData('svg/illustrations/ghostscript_tiger_inkscape.svg'), true],
  ['paint/gradients.svg (the browser draws it live)', join(paint, 'gradients.svg'), false],
] as const) {
  test(`a frame of a drag looks as the still drawing of its pose: ${label}`, async ({ page }, testInfo) => {
    test.setTimeout(120_000);
    await rigFile(page, path);
    await page.keyboard.press('p');
    // Not relaxed on release, so the still pose is the last one dragged.
    await page.getByTestId('flexible').uncheck();
    await rigReady(page);
    expect((await rigReady(page)).tool).toBe('pose');
    const box = (await page.locator('canvas.view2d-canvas').boundingBox())!;
    const x = Math.round(box.x) + 20, y = Math.round(box.y) + 20, width = Math.floor(Math.min(box.width - 40, 700)), height = Math.floor(Math.min(box.height - 40, 600));
    await hideOverlays(page, true);
    const rest = await shoot(page, x, y, width, height);
    await hideOverlays(page, false);

    const leg = await handleAt(page, 2);
    await page.mouse.move(leg.x, leg.y);
    await page.mouse.down();
    for (let i = 1; i <= 8; i++) await page.mouse.move(leg.x + 8 * i, leg.y - 10 * i);
    await frames(page);
    const during = await shownBy(page);
    expect(during.canvas, 'the live canvas shows the drag').toBe(canvas);
    expect(during.svg, 'the SVG shows the drag').toBe(!canvas);
    if (canvas) expect(Number(during.frame)).toBeGreaterThan(0);
    await hideOverlays(page, true);
    const live = await shoot(page, x, y, width, height);
    await hideOverlays(page, false);

    await page.mouse.up();
    await rigReady(page);
    const after = await shownBy(page);
    expect(after).toMatchObject({ canvas: false, svg: true });
    await hideOverlays(page, true);
    const still = await shoot(page, x, y, width, height);
    await hideOverlays(page, false);

    const c = await compareShots(page, still, live);
    const moved = await compareShots(page, rest, still);
    testInfo.annotations.push({ type: 'fidelity', description: `drag frame vs still ${(100 * c.different).toFixed(3)}%, rest vs still ${(100 * moved.different).toFixed(1)}%` });
    expect(c.painted).toBeGreaterThan(0.01);
    expect(c.different, 'the drag frame against the still drawing').toBeLessThanOrEqual(MAX_DIFFERENT);
    expect(moved.different, 'the pose moved the drawing').toBeGreaterThan(0.003);
  });
}
