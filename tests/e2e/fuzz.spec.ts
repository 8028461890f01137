// Generated hostile SVGs (tests/fuzz/svg-arbitrary.ts, fast-check) go through the editor in
// Chromium: open → draw → export. Each either opens, or ends with an error that names it while the
// previous drawing stays; nothing throws past the app, the page keeps answering, and what opened
// exports to an SVG the package reads back with the same splines. The failures found so far
// (tests/fuzz/regressions.json) go first. The seed is fixed so a failure here replays as it is.
import fc from 'fast-check';
import { readFileSync } from 'node:fs';
import { init, parseSVG } from '../../dist/index.js';
import { svgDocument } from '../fuzz/svg-arbitrary.js';
import { expect, test } from './fixtures.js';
import { collectErrors, editorState, frames, openEditor } from './helpers.js';

// SPLINEKIT_FUZZ_SEED explores other seeds; a failing one goes into tests/fuzz/regressions.json.
const SEED = Number(process.env.SPLINEKIT_FUZZ_SEED ?? 20261202);
const regressions = (JSON.parse(readFileSync(new URL('../fuzz/regressions.json', import.meta.url), 'utf8')) as { cases: { input: string }[] }).cases;

test('generated hostile SVGs open, draw and export, or end with an error naming them', async ({ page }) => {
  test.setTimeout(180_000);
  const errors = collectErrors(page);
  await openEditor(page);
  await init();
  const inputs = [...regressions.map((r) => r.input), ...fc.sample(svgDocument, { numRuns: 80, seed: SEED })];
  let opened = 0;
  for (const [i, text] of inputs.entries()) {
    const name = `fuzz-${i}.svg`;
    const before = await editorState(page);
    await page.getByTestId('file-input').setInputFiles({ name, mimeType: 'image/svg+xml', buffer: Buffer.from(text) });
    await expect
      .poll(async () => {
        const s = await editorState(page);
        return s.file === name || (s.error ?? '').includes(name);
      }, { message: `${name} neither opened nor failed with its name` })
      .toBe(true);
    await frames(page);
    const after = await editorState(page);
    if (after.file !== name) {
      // Refused: the document before it is still the one shown.
      expect({ file: after.file, splines: after.splines, segments: after.segments }, name).toEqual({ file: before.file, splines: before.splines, segments: before.segments });
      continue;
    }
    opened++;
    const [download] = await Promise.all([page.waitForEvent('download'), page.getByRole('button', { name: 'Export' }).click()]);
    const exported = parseSVG(readFileSync(await download.path(), 'utf8'), { name: `${name} exported` }).stats();
    expect([exported.splines, exported.segments], `${name} exported`).toEqual([after.splines, after.segments]);
  }
  // Both outcomes were exercised, and the app never threw past itself.
  expect(opened).toBeGreaterThan(5);
  expect(opened).toBeLessThan(inputs.length);
  expect(errors).toEqual([]);
});
