// Skin mode steps shared by the end-to-end tests: rig the ballerina, wait for the rig, drag.
import type { Page } from '@playwright/test';
import { expect } from './fixtures.js';
import { frames, openEditor, sharedData, waitForFile } from './helpers.js';

export const BALLERINA = sharedData('svg/characters/oc_ballerina.svg');
export const BALLERINA_FILE = 'oc_ballerina.svg';
/** Where the handles go, as fractions of the drawing's bounds: chest, hip, lower leg. */
const HANDLE_SPOTS: [number, number][] = [
  [0.5, 0.2],
  [0.5, 0.55],
  [0.78, 0.88],
];

export type SkinState = ReturnType<NonNullable<Window['splinekitEditor']>['skin']>;

export function skin(page: Page): Promise<SkinState> {
  return page.evaluate(() => window.splinekitEditor!.skin());
}

/** Waits until the rig matches the handles and the drawing is posed with it. */
export async function rigReady(page: Page): Promise<SkinState> {
  await page.waitForFunction(() => {
    const s = window.splinekitEditor!.skin();
    return s.ready && s.phase === 'ready';
  });
  await frames(page);
  return skin(page);
}

export async function handleAt(page: Page, index: number): Promise<{ x: number; y: number }> {
  const at = await page.evaluate((i) => window.splinekitEditor!.skinHandleOnScreen(i), index);
  expect(at, `handle ${index} is drawn`).not.toBeNull();
  return at!;
}

/** Presses at `from` and moves in `steps` to `to` (a drag as a user does it), then releases. */
export async function drag(page: Page, from: { x: number; y: number }, to: { x: number; y: number }, steps = 12): Promise<void> {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) await page.mouse.move(from.x + ((to.x - from.x) * i) / steps, from.y + ((to.y - from.y) * i) / steps);
  await page.mouse.up();
}

/** Opens the ballerina, switches to Skin and places the three handles by clicking on the canvas. */
export function rigBallerina(page: Page): Promise<SkinState> {
  return rigFile(page, BALLERINA);
}

/** Opens the SVG at `path`, switches to Skin and places the three handles by clicking on the canvas. */
export async function rigFile(page: Page, path: string): Promise<SkinState> {
  await openEditor(page);
  await page.getByTestId('file-input').setInputFiles(path);
  await waitForFile(page, path.split('/').pop()!);
  await page.getByRole('button', { name: 'Skin', exact: true }).click();
  await frames(page);
  let s = await skin(page);
  expect(s.active).toBe(true);
  expect(s.tool).toBe('rig');
  expect(s.handles).toBe(0);
  await expect(page.getByTestId('skin-hint')).toContainText('Click on the drawing');

  const b = (await page.evaluate(() => window.splinekitEditor!.bounds()))!;
  for (const [fx, fy] of HANDLE_SPOTS) {
    const p = await page.evaluate(([x, y]) => window.splinekitEditor!.docToScreen(x, y), [b[0] + fx * (b[2] - b[0]), b[1] + fy * (b[3] - b[1])]);
    await page.mouse.click(p.x, p.y);
  }
  s = await rigReady(page);
  expect(s.handles).toBe(3);
  expect(s.selected).toBe(2); // the last one placed
  expect(s.nan).toBe(false);
  return s;
}
