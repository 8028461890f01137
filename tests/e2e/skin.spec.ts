import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test } from './fixtures.js';
import { countColors, fingerprint, fingerprintDistance, frames, waitForFile } from './helpers.js';
import { BALLERINA_FILE as FILE, drag, handleAt, rigBallerina, rigReady, skin } from './skin-helpers.js';

/** Heat map ends (web/modes/skin/colors.ts): purple at the least error, red at the most; the naive outline. */
const HEAT_MIN = '#7b2ff7';
const HEAT_MAX = '#f03e3e';
const NAIVE = '#15aabf';

/**
 * Skin mode end to end: a character from the shared data gets three handles, is posed by dragging
 * and by the gizmo, undone, reloaded from the autosave, keyframed, and exported as an animated SVG
 * that plays in the browser with no script.
 */

test('rigs a character, poses it by dragging and with the gizmo, undoes, and reloads it from the autosave', async ({ page }, testInfo) => {
  const rest = await rigBallerina(page);
  expect(rest.points).toBe(2 * 1333); // every control point of the drawing
  expect(rest.pose.every((m) => m.join() === '1,0,0,1,0,0')).toBe(true);

  // Pose: drag the lower-leg handle up and to the side.
  await page.keyboard.press('p');
  await frames(page);
  expect((await skin(page)).tool).toBe('pose');
  const before = await fingerprint(page);
  const leg = await handleAt(page, 2);
  await drag(page, leg, { x: leg.x + 70, y: leg.y - 90 });
  const moved = await rigReady(page);
  expect(moved.nan).toBe(false);
  expect(Math.abs(moved.checksum - rest.checksum), 'the posed path data changed').toBeGreaterThan(1);
  expect(moved.pose[2][4]).not.toBe(0);
  expect(fingerprintDistance(before, await fingerprint(page)), 'canvas pixels changed').toBeGreaterThan(0.5);
  // The fit follows the target more closely than moving the control points (the paper's claim).
  expect(moved.fitRms!).toBeLessThan(moved.naiveRms!);
  expect(moved.layers.target).toBeGreaterThan(1000); // the dashed target is drawn, as a heat map
  // The target is 1 px wide: its anti-aliased pixels are near the ramp's ends, not on them.
  const [purple, red] = await countColors(page, [HEAT_MIN, HEAT_MAX], 36);
  expect(purple, 'target pixels at the least error (1 px dashed lines)').toBeGreaterThan(100);
  expect(red, 'target pixels at the most error').toBeGreaterThan(5);
  await expect(page.getByTestId('skin-errors')).toContainText('closer than naive');

  // Turn the chest handle with its gizmo ring: select it, grab the ring, sweep 50°.
  const chest = await handleAt(page, 0);
  await page.mouse.click(chest.x, chest.y);
  await frames(page);
  const g = (await page.evaluate(() => window.splinekitEditor!.skinGizmoOnScreen()))!;
  expect(g).not.toBeNull();
  await page.mouse.move(g.center.x + g.ring, g.center.y);
  await page.mouse.down();
  for (let i = 1; i <= 10; i++) {
    const a = (-i / 10) * (50 * Math.PI) / 180;
    await page.mouse.move(g.center.x + g.ring * Math.cos(a), g.center.y + g.ring * Math.sin(a));
  }
  await page.mouse.up();
  const turned = await rigReady(page);
  const angle = (Math.atan2(turned.pose[0][1] - turned.pose[0][2], turned.pose[0][0] + turned.pose[0][3]) * 180) / Math.PI;
  expect(angle).toBeCloseTo(-50, 0);
  expect(turned.nan).toBe(false);
  expect(Math.abs(turned.checksum - moved.checksum)).toBeGreaterThan(1);
  await page.keyboard.press('n'); // the naive result too, for the picture
  await frames(page);
  expect((await skin(page)).layers.naive).toBeGreaterThan(100);
  expect((await countColors(page, [NAIVE], 6))[0], 'naive outline pixels').toBeGreaterThan(100);
  await page.screenshot({ path: join(testInfo.project.outputDir, 'skin.png') });
  await page.keyboard.press('n');

  // Undo takes back the turn (one step per drag); redo brings it back.
  await page.keyboard.press('Control+z');
  const undone = await rigReady(page);
  expect(undone.checksum).toBeCloseTo(moved.checksum, 6);
  expect(undone.pose).toEqual(moved.pose);
  await page.keyboard.press('Control+Shift+z');
  expect((await rigReady(page)).checksum).toBeCloseTo(turned.checksum, 6);

  // A reload brings back the document, the mode, the handles and the pose.
  await page.waitForFunction(() => window.splinekitEditor!.skin().saved);
  await page.reload();
  await page.waitForFunction(() => window.splinekitEditor !== undefined);
  await page.evaluate(() => window.splinekitEditor!.ready);
  expect((await page.evaluate(() => window.splinekitEditor!.state())).file).toBe(FILE);
  const restored = await rigReady(page);
  expect(restored.active).toBe(true);
  expect(restored.handles).toBe(3);
  expect(restored.pose).toEqual(turned.pose);
  expect(restored.checksum).toBeCloseTo(turned.checksum, 6);
  expect(restored.nan).toBe(false);
});

test('edits the rig at rest, shows a weight field, saves the rig in the SVG, removes and restores a handle', async ({ page }, testInfo) => {
  const rest = await rigBallerina(page);
  // Rig tool: dragging a handle moves its rest position and rebuilds the rig; the drawing stays.
  const hip = await handleAt(page, 1);
  await drag(page, hip, { x: hip.x + 30, y: hip.y + 20 });
  const moved = await rigReady(page);
  expect(moved.handles).toBe(3);
  expect(moved.checksum).toBeCloseTo(rest.checksum, 6); // at rest the drawing is exact
  const at = await handleAt(page, 1);
  expect(at.x).toBeCloseTo(hip.x + 30, 0);

  // The selected handle's weight field colors the curves.
  await page.keyboard.press('w');
  await frames(page);
  expect((await skin(page)).layers.field).toBeGreaterThan(1000);
  await page.keyboard.press('w');

  // Export (Ctrl+S) writes the document with the rig in its metadata; opening that file (here
  // as another name, so no autosave matches it) brings the rig back.
  const [saved] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('Control+s')]);
  const exported = testInfo.outputPath('rigged.svg');
  await saved.saveAs(exported);
  expect(readFileSync(exported, 'utf8')).toContain('<metadata id="splinekit-rig">');
  await page.getByTestId('file-input').setInputFiles(exported);
  await waitForFile(page, 'rigged.svg');
  const reopened = await rigReady(page);
  expect(reopened.handles).toBe(3);
  expect(reopened.checksum).toBeCloseTo(rest.checksum, 6);
  await page.keyboard.press('Control+z'); // back to the ballerina, with its session
  await waitForFile(page, FILE);
  await rigReady(page);
  await page.keyboard.press('r');
  const hip2 = await handleAt(page, 1);
  await page.mouse.click(hip2.x, hip2.y); // select it again

  // Delete removes the selected handle; undo brings it back where it was.
  expect((await skin(page)).selected).toBe(1);
  await page.keyboard.press('Delete');
  expect((await rigReady(page)).handles).toBe(2);
  await page.keyboard.press('Control+z');
  const back = await rigReady(page);
  expect(back.handles).toBe(3);
  expect((await handleAt(page, 1)).x).toBeCloseTo(hip2.x, 0);
});

test('keys poses on the timeline, plays them, and exports an animated SVG that moves without script', async ({ page, context }, testInfo) => {
  await rigBallerina(page);
  await page.keyboard.press('p');
  // Key the rest pose at 0 s.
  await page.getByTestId('keyframe-add').click();
  expect((await skin(page)).keyframes).toBe(1);

  // At 1 s (the middle of the 2 s track), pose the chest and key it.
  const track = (await page.getByTestId('timeline-track').boundingBox())!;
  await page.mouse.click(track.x + track.width / 2, track.y + track.height / 2);
  expect((await skin(page)).time).toBeCloseTo(1, 1);
  const chest = await handleAt(page, 0);
  await drag(page, chest, { x: chest.x + 80, y: chest.y + 30 });
  await rigReady(page);
  await page.keyboard.press('i');
  const keyed = await skin(page);
  expect(keyed.keyframes).toBe(2);
  await expect(page.getByTestId('timeline').locator('.tl-key')).toHaveCount(2);

  // Drag the second keyframe's diamond from 1 s to 1.5 s; undo puts it back.
  const diamond = (await page.getByTestId('timeline').locator('.tl-key').nth(1).boundingBox())!;
  await drag(page, { x: diamond.x + diamond.width / 2, y: diamond.y + diamond.height / 2 }, { x: track.x + track.width * 0.75, y: track.y + track.height / 2 }, 6);
  const retimed = (await skin(page)).keyTimes;
  expect(retimed[0]).toBe(0);
  expect(retimed[1]).toBeCloseTo(1.5, 1);
  await page.keyboard.press('Control+z');
  expect((await skin(page)).keyTimes[1]).toBeCloseTo(1, 1);

  // Scrubbing to 0 s poses the rest again; playing changes the pose over time.
  await page.mouse.click(track.x + 1, track.y + track.height / 2);
  const start = await rigReady(page);
  expect(start.pose.every((m) => m.join() === '1,0,0,1,0,0')).toBe(true);
  await page.keyboard.press('k');
  expect((await skin(page)).playing).toBe(true);
  // Playback poses the rig on animation frames: wait until a frame has moved the drawing away
  // from the rest pose (the keyframe at 1 s bends the chest), however fast frames come.
  await expect
    .poll(async () => {
      const s = await skin(page);
      return s.playing && Math.abs(s.checksum - start.checksum) > 1;
    }, { message: 'playing moves the drawing away from the rest pose' })
    .toBe(true);
  await page.keyboard.press('k');
  expect((await skin(page)).playing).toBe(false);

  // Export the deformed drawing and the animation.
  const [posed] = await Promise.all([page.waitForEvent('download'), page.getByTestId('export-posed').click()]);
  expect(posed.suggestedFilename()).toBe('oc_ballerina-posed.svg');
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('export-animated').click()]);
  expect(download.suggestedFilename()).toBe('oc_ballerina-animated.svg');
  const file = testInfo.outputPath('animated.svg');
  await download.saveAs(file);
  const svg = readFileSync(file, 'utf8');
  expect(svg).toContain('<animate attributeName="d"');
  expect(svg).not.toMatch(/<script/i);
  expect(svg).not.toMatch(/\bon[a-z]+\s*=/i); // no event handler attributes either

  // Shown as an image (where scripts never run), the drawing moves.
  const viewer = await context.newPage();
  await viewer.setContent(`<body style="margin:0;background:#fff"><img id="anim" style="height:600px" src="data:image/svg+xml;base64,${Buffer.from(svg).toString('base64')}"></body>`);
  await viewer.waitForFunction(() => (document.getElementById('anim') as HTMLImageElement).complete);
  const img = viewer.locator('#anim');
  // SMIL runs on the image's own clock: take frames until one differs from the first.
  const first = await img.screenshot();
  await expect.poll(async () => (await img.screenshot()).equals(first), { message: 'a later frame of the animated SVG differs from the first' }).toBe(false);
  await viewer.close();
});

test('switches to BBW weights computed in a worker, with progress', async ({ page }) => {
  await rigBallerina(page);
  const shepard = await skin(page);
  await page.keyboard.press('p');
  const leg = await handleAt(page, 2);
  await drag(page, leg, { x: leg.x + 60, y: leg.y - 60 });
  const posed = await rigReady(page);

  await page.getByRole('button', { name: 'BBW', exact: true }).click();
  await expect(page.getByTestId('weights-progress')).toBeVisible();
  // Posing keeps working on the previous rig while the worker computes.
  const s = await skin(page);
  expect(s.weights).toBe('bbw');
  const bbw = await rigReady(page);
  expect(bbw.weights).toBe('bbw');
  expect(bbw.nan).toBe(false);
  expect(bbw.checksum).not.toBeCloseTo(posed.checksum, 3); // other weights, other deformation
  await expect(page.getByTestId('weights-progress')).toBeHidden();
  expect(shepard.weights).toBe('shepard');
  // Undo goes back to Shepard.
  await page.keyboard.press('Control+z');
  expect((await rigReady(page)).weights).toBe('shepard');
});

test('Shift+drag turns a handle, Alt+drag and the gizmo knob scale it, Shift+click adds one on the pose', async ({ page }) => {
  await rigBallerina(page);
  await page.keyboard.press('p');
  const hip = await handleAt(page, 1);

  await page.keyboard.down('Shift');
  await drag(page, hip, { x: hip.x + 60, y: hip.y });
  await page.keyboard.up('Shift');
  let s = await rigReady(page);
  const [a, b, c, d, e, f] = s.pose[1];
  expect(Math.atan2(b - c, a + d)).toBeGreaterThan(0.2); // turned (clockwise on screen)
  expect(Math.hypot(a, b)).toBeCloseTo(1, 6); // not scaled
  // The handle turns about itself: it stays where it was.
  const h1 = await handleAt(page, 1);
  expect(h1.x).toBeCloseTo(hip.x, 0);
  expect(h1.y).toBeCloseTo(hip.y, 0);
  expect([e, f].every(Number.isFinite)).toBe(true);

  await page.keyboard.down('Alt');
  await drag(page, hip, { x: hip.x, y: hip.y - 60 });
  await page.keyboard.up('Alt');
  s = await rigReady(page);
  const grown = Math.sqrt(Math.abs(s.pose[1][0] * s.pose[1][3] - s.pose[1][1] * s.pose[1][2]));
  expect(grown).toBeGreaterThan(1.2);

  // The knob scales by the ratio of distances to the handle: drag it halfway in.
  const g = (await page.evaluate(() => window.splinekitEditor!.skinGizmoOnScreen()))!;
  await drag(page, g.knob, { x: (g.knob.x + g.center.x) / 2, y: (g.knob.y + g.center.y) / 2 });
  s = await rigReady(page);
  const half = Math.sqrt(Math.abs(s.pose[1][0] * s.pose[1][3] - s.pose[1][1] * s.pose[1][2]));
  expect(half / grown).toBeCloseTo(0.5, 1);
  expect(s.nan).toBe(false);

  // Shift+click on the posed drawing adds a handle right there, posed like its nearest neighbour:
  // the drawing does not jump.
  const near = { x: hip.x + 30, y: hip.y + 95 };
  await page.keyboard.down('Shift');
  await page.mouse.click(near.x, near.y);
  await page.keyboard.up('Shift');
  const added = await rigReady(page);
  expect(added.handles).toBe(4);
  expect(added.pose[3]).toEqual(added.pose[1]);
  const h4 = await handleAt(page, 3);
  expect(h4.x).toBeCloseTo(near.x, 0);
  expect(h4.y).toBeCloseTo(near.y, 0);
  expect(Math.abs(added.checksum - s.checksum) / Math.abs(s.checksum), 'the drawing barely moves').toBeLessThan(0.01);
  await page.keyboard.press('Control+z');
  expect((await rigReady(page)).handles).toBe(3);
  // "0" resets the selected handle to rest.
  await page.keyboard.press('0');
  expect((await rigReady(page)).pose[1]).toEqual([1, 0, 0, 1, 0, 0]);
});

test('a rig that cannot be built shows an error and keeps the page working', async ({ page }) => {
  await rigBallerina(page);
  await page.waitForFunction(() => window.splinekitEditor!.skin().saved);
  // Make the autosaved rig ask for BBW weights with two handles on the same spot: the domain
  // cannot have both as vertices, so the worker fails.
  await page.evaluate(() => {
    for (let i = 0; i < localStorage.length; i++) {
      const key = localStorage.key(i)!;
      if (!key.startsWith('splinekit:skin:')) continue;
      const entry = JSON.parse(localStorage.getItem(key)!);
      entry.rig.weights = 'bbw';
      entry.rig.handles[1] = { ...entry.rig.handles[0], id: entry.rig.handles[1].id };
      localStorage.setItem(key, JSON.stringify(entry));
    }
  });
  await page.reload();
  await page.waitForFunction(() => window.splinekitEditor !== undefined);
  await page.evaluate(() => window.splinekitEditor!.ready);
  await page.waitForFunction(() => window.splinekitEditor!.skin().phase === 'error');
  await expect(page.getByTestId('status-error')).toContainText('The rig could not be built');
  await expect(page.getByTestId('rig-error')).toBeVisible();
  const broken = await skin(page);
  expect(broken.handles).toBe(3); // the handles are kept
  expect(broken.nan).toBe(false);
  // Shepard weights take coincident handles: choosing them builds the rig again.
  await page.getByRole('button', { name: 'Shepard', exact: true }).click();
  const fixed = await rigReady(page);
  expect(fixed.weights).toBe('shepard');
  expect(fixed.handles).toBe(3);
  await expect(page.getByTestId('rig-error')).toBeHidden();
  await expect(page.getByTestId('status-error')).toBeHidden();
});

test('a continuity override in Document mode rebuilds the rig with the new tag', async ({ page }) => {
  await rigBallerina(page);
  await page.keyboard.press('p');
  const leg = await handleAt(page, 2);
  await drag(page, leg, { x: leg.x + 60, y: leg.y - 80 });
  const before = await rigReady(page);

  // Document mode: the control points are back; override the tag at a junction.
  await page.getByRole('button', { name: 'Document', exact: true }).click();
  const at = (await page.evaluate(() => window.splinekitEditor!.anchorOnScreen(0, 3)))!;
  await page.mouse.click(at.x, at.y);
  const sel = (await page.evaluate(() => window.splinekitEditor!.state().selection))!;
  expect(sel.kind).not.toBeNull();
  const kind = sel.kind === 'C0' ? 'G1' : 'C0';
  await page.getByTestId('junction').locator(`button[data-kind="${kind}"]`).click();
  expect((await page.evaluate(() => window.splinekitEditor!.state().selection))!.kind).toBe(kind);

  await page.getByRole('button', { name: 'Skin', exact: true }).click();
  const after = await rigReady(page);
  expect(after.pose).toEqual(before.pose);
  expect(after.nan).toBe(false);
  expect(Math.abs(after.checksum - before.checksum), 'the fit keeps the new tag').toBeGreaterThan(1e-9);
});
