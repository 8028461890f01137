import { readFileSync } from 'node:fs';
import type { Page } from '@playwright/test';
import type { Mesh } from 'three';
import { GLTFLoader, type GLTF } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { expect, test } from './fixtures.js';
import { docsScreenshot, frames, openEditor } from './helpers.js';

/**
 * 3D Skin mode end to end: the gingerbread sample cage opens with its refined surface; clicks on
 * the surface add handles; a real pointer drag on the gizmo's X arrow moves the selected handle,
 * and the surface follows it near the handle and stays put far away; undo gives back the rest
 * cage exactly; keyframes; the posed cage as OBJ and the animation as glTF, loaded back with
 * three.js's GLTFLoader; a bad cage file keeps the cage shown; BBW weights come from the worker.
 */

type Skin3DState = ReturnType<NonNullable<Window['splinekitEditor']>['skin3d']['state']>;
type XY = { x: number; y: number };
type V3 = [number, number, number];

function skin3d(page: Page): Promise<Skin3DState> {
  return page.evaluate(() => window.splinekitEditor!.skin3d.state());
}

/** Waits until no load or rig build is under way, and the view has drawn. */
async function settled(page: Page): Promise<Skin3DState> {
  await page.evaluate(() => window.splinekitEditor!.skin3d.ready());
  await frames(page);
  return skin3d(page);
}

async function projected(page: Page, p: V3): Promise<XY> {
  const at = await page.evaluate((q) => window.splinekitEditor!.skin3d.project(q[0], q[1], q[2]), p);
  expect(at, 'the point projects in front of the camera').not.toBeNull();
  return at!;
}

const vertex = (a: number[], i: number): V3 => [a[3 * i], a[3 * i + 1], a[3 * i + 2]];
const dist = (a: V3, b: V3) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);

/** The refined vertex nearest to `p` at rest (aim at the front face, +z, which the camera sees). */
function nearest(surface: number[], p: V3): V3 {
  let best: V3 = [0, 0, 0];
  for (let i = 0; i < surface.length / 3; i++) {
    const v = vertex(surface, i);
    if (dist(v, p) < dist(best, p)) best = v;
  }
  return best;
}

/** Spots on the gingerbread's front face (its cells are unit squares, the slab 0.7 thick). */
const RIGHT_HAND: V3 = [2.5, 5, 0.4], LEFT_HAND: V3 = [-2.5, 5, 0.4], RIGHT_FOOT: V3 = [1.5, 0.7, 0.4], HEAD: V3 = [0, 7, 0.4];

/** Mean displacement of the surface vertices whose rest position passes `where`. */
function meanMove(rest: number[], posed: number[], where: (v: V3) => boolean): { mean: V3; count: number } {
  const sum: V3 = [0, 0, 0];
  let count = 0;
  for (let i = 0; i < rest.length / 3; i++) {
    const r = vertex(rest, i);
    if (!where(r)) continue;
    const p = vertex(posed, i);
    for (let k = 0; k < 3; k++) sum[k] += p[k] - r[k];
    count++;
  }
  return { mean: sum.map((s) => s / Math.max(count, 1)) as V3, count };
}

async function nextFrame(page: Page): Promise<void> {
  await page.evaluate(() => new Promise<void>((r) => requestAnimationFrame(() => r())));
}

test('3D Skin: handles on the surface, a gizmo drag poses it, undo restores the rest cage exactly, keyframes, OBJ and glTF export', async ({ page }) => {
  await openEditor(page);
  await page.getByRole('button', { name: '3D Skin', exact: true }).click();
  await expect.poll(async () => (await skin3d(page)).file).toBe('gingerbread.obj');
  let s = await settled(page);
  expect(s.active).toBe(true);
  expect(s.cage).toEqual({ vertices: 90, faces: 88, creases: 4 });
  expect(s.refinedVertices).toBeGreaterThan(s.cage!.vertices);
  expect(s.surface.length).toBe(3 * s.refinedVertices);
  expect(s.posedCage).toEqual(s.restCage);
  const rest = s.surface;
  await expect(page.getByTestId('skin3d-hint')).toContainText('Click on the surface');

  // Three handles: the right hand, the left hand, the feet (clicked where the surface is).
  for (const [i, at] of [RIGHT_HAND, LEFT_HAND, RIGHT_FOOT].map((p) => nearest(rest, p)).entries()) {
    const xy = await projected(page, at);
    await page.mouse.click(xy.x, xy.y);
    s = await settled(page);
    expect(s.handles).toHaveLength(i + 1);
    expect(s.selected).toBe(i);
    // The handle sits on the rest surface, near the vertex aimed at.
    expect(dist([s.handles[i].x, s.handles[i].y, s.handles[i].z], at)).toBeLessThan(0.3);
  }
  expect(s.rig.ready).toBe(true);
  expect(s.posedCage).toEqual(s.restCage);

  // Select the right hand by clicking its marker: the gizmo comes up on it.
  const hand = await projected(page, [s.handles[0].x, s.handles[0].y, s.handles[0].z]);
  await page.mouse.click(hand.x, hand.y);
  s = await settled(page);
  expect(s.selected).toBe(0);
  expect(s.handles).toHaveLength(3);
  const arrow = await page.evaluate(() => window.splinekitEditor!.skin3d.gizmoAxis('X'));
  expect(arrow, 'the gizmo shows an X arrow').not.toBeNull();

  // A real drag on the X arrow, 90 pixels along its screen direction.
  await page.mouse.move(arrow!.x, arrow!.y);
  await page.mouse.down();
  for (let i = 1; i <= 9; i++) {
    await page.mouse.move(arrow!.x + arrow!.dx * 10 * i, arrow!.y + arrow!.dy * 10 * i);
    await nextFrame(page);
  }
  await page.mouse.up();
  s = await settled(page);
  const t = s.pose[0].t;
  expect(t[0], 'the hand moved along +x').toBeGreaterThan(0.3);
  expect(Math.abs(t[1]) + Math.abs(t[2])).toBeLessThan(1e-9);
  expect(s.pose[0].q).toEqual([0, 0, 0, 1]);
  expect(s.pose[1].t).toEqual([0, 0, 0]);

  // The surface follows: around the right hand by about the handle's move, the feet barely.
  const near = meanMove(rest, s.surface, (v) => v[0] > 2.2);
  const far = meanMove(rest, s.surface, (v) => v[1] < 1.5);
  expect(near.count).toBeGreaterThan(5);
  expect(far.count).toBeGreaterThan(5);
  expect(near.mean[0]).toBeGreaterThan(0.5 * t[0]);
  expect(near.mean[0]).toBeLessThan(1.3 * t[0]);
  expect(Math.hypot(...far.mean)).toBeLessThan(0.25 * t[0]);
  expect(s.posedCage).not.toEqual(s.restCage);
  const posedSurface = s.surface, posedCage = s.posedCage;

  // The overlays: the error colours with their legend (the README's picture), the naive numbers.
  await page.keyboard.press('e');
  await settled(page);
  await docsScreenshot(page, 'skin3d.png');
  await page.keyboard.press('n');
  s = await settled(page);
  expect(s.overlays.errors && s.overlays.naive).toBe(true);
  await expect(page.getByTestId('skin3d-legend')).toBeVisible();
  expect(s.errors!.fitRms).toBeGreaterThanOrEqual(0);
  expect(s.errors!.fitRms).toBeLessThanOrEqual(s.errors!.naiveRms + 1e-12);
  await page.keyboard.press('e');
  await page.keyboard.press('n');

  // Undo: the rest cage and surface exactly; redo: the same pose again.
  await page.keyboard.press('Control+z');
  s = await settled(page);
  expect(s.pose[0].t).toEqual([0, 0, 0]);
  expect(s.posedCage).toEqual(s.restCage);
  expect(s.surface).toEqual(rest);
  await page.keyboard.press('Control+Shift+z');
  s = await settled(page);
  expect(s.pose[0].t).toEqual(t);
  expect(s.surface).toEqual(posedSurface);

  // Keyframes: this pose at 0 s, the rest pose at 1 s.
  await page.keyboard.press('i');
  const track = (await page.getByTestId('timeline-track').boundingBox())!;
  await page.mouse.click(track.x + track.width / 2, track.y + track.height / 2);
  s = await settled(page);
  expect(s.time).toBeGreaterThan(0.8);
  expect(s.time).toBeLessThan(1.2);
  await page.getByTestId('skin3d-reset').click(); // the selected handle (the right hand) back to rest
  await page.keyboard.press('i');
  s = await settled(page);
  const keyTimes = s.keyframes;
  expect(keyTimes).toHaveLength(2);
  expect(keyTimes[0]).toBe(0);
  expect(s.posedCage).toEqual(s.restCage);

  // Back to 0 s: the keyed pose.
  await page.keyboard.press('[');
  s = await settled(page);
  expect(s.time).toBe(0);
  expect(s.posedCage).toEqual(posedCage);

  // The posed cage as OBJ: the same faces and crease tags, the posed positions.
  const [objDownload] = await Promise.all([page.waitForEvent('download'), page.getByTestId('skin3d-export-obj').click()]);
  expect(objDownload.suggestedFilename()).toBe('gingerbread-posed.obj');
  const obj = readFileSync((await objDownload.path())!, 'utf8').split('\n');
  const vs = obj.filter((l) => l.startsWith('v ')).flatMap((l) => l.slice(2).trim().split(/\s+/).map(Number));
  expect(obj.filter((l) => l.startsWith('f '))).toHaveLength(88);
  expect(obj.filter((l) => l.startsWith("t crease"))).toHaveLength(4);
  expect(vs).toHaveLength(posedCage.length);
  expect(Math.max(...vs.map((v, i) => Math.abs(v - posedCage[i])))).toBeLessThan(1e-6);

  // The animation as glTF: loaded back with three.js. One morph target per frame: the keyframes
  // and, between them, a frame every tenth of a second; the weights track switches them on at
  // their times. The first frame is the posed surface, the last the rest surface, and (the pose
  // being a translation, which the rig fits linearly) frame k at time t the blend of the two.
  const [glbDownload] = await Promise.all([page.waitForEvent('download'), page.getByTestId('skin3d-export-gltf').click()]);
  expect(glbDownload.suggestedFilename()).toBe('gingerbread-animated.glb');
  const bytes = readFileSync((await glbDownload.path())!);
  const gltf = await new Promise<GLTF>((resolve, reject) => new GLTFLoader().parse(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength), '', resolve, reject));
  const meshes: Mesh[] = [];
  gltf.scene.traverse((o) => {
    if ((o as Mesh).isMesh) meshes.push(o as Mesh);
  });
  expect(meshes).toHaveLength(1);
  const geometry = meshes[0].geometry;
  expect(geometry.getAttribute('position').count).toBe(s.refinedVertices);
  expect(gltf.animations).toHaveLength(1);
  const tracks = gltf.animations[0].tracks;
  expect(tracks).toHaveLength(1);
  expect(tracks[0].name).toMatch(/morphTargetInfluences$/);
  const times = [...tracks[0].times];
  const n = times.length;
  expect(n).toBe(Math.ceil(keyTimes[1] * 10 - 1e-9) + 1);
  expect(times[0]).toBe(0);
  expect(times[n - 1]).toBeCloseTo(keyTimes[1], 5);
  for (let k = 1; k < n; k++) expect(times[k] - times[k - 1]).toBeLessThanOrEqual(0.1 + 1e-6);
  const values = [...tracks[0].values];
  expect(values).toEqual(Array.from({ length: n * n }, (_, i) => (Math.floor(i / n) === i % n ? 1 : 0)));
  const targets = geometry.morphAttributes.position ?? [];
  expect(targets).toHaveLength(n);
  const absolute = (k: number, i: number) => {
    const base = geometry.getAttribute('position'), d = targets[k];
    // GLTFLoader reads glTF's morph targets as offsets from the base.
    return [base.getX(i) + d.getX(i), base.getY(i) + d.getY(i), base.getZ(i) + d.getZ(i)];
  };
  // Largest deviations over all vertices (one expect each: Playwright's expect is not free).
  const u = times[n >> 1] / times[n - 1];
  let offFirst = 0, offLast = 0, offMid = 0;
  for (let i = 0; i < s.refinedVertices; i++) {
    const first = absolute(0, i), last = absolute(n - 1, i), mid = absolute(n >> 1, i);
    for (let c = 0; c < 3; c++) {
      offFirst = Math.max(offFirst, Math.abs(first[c] - posedSurface[3 * i + c]));
      offLast = Math.max(offLast, Math.abs(last[c] - rest[3 * i + c]));
      offMid = Math.max(offMid, Math.abs(mid[c] - ((1 - u) * first[c] + u * last[c])));
    }
  }
  expect(offFirst, 'first frame = the posed surface').toBeLessThan(1e-4);
  expect(offLast, 'last frame = the rest surface').toBeLessThan(1e-4);
  expect(offMid, 'the middle frame = the rig at its time').toBeLessThan(1e-4);
});

test('3D Skin: a bad cage keeps the cage shown; BBW weights come from the worker with progress; another sample and undo; the autosave after a reload', async ({ page }) => {
  await openEditor(page);
  await page.getByRole('button', { name: '3D Skin', exact: true }).click();
  await expect.poll(async () => (await skin3d(page)).file).toBe('gingerbread.obj');
  await settled(page);

  // An edge shared by three faces: parseCage names the problem, the gingerbread stays.
  const bad = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n';
  await page.getByTestId('skin3d-cage-input').setInputFiles({ name: 'fan.obj', mimeType: 'text/plain', buffer: Buffer.from(bad) });
  await expect(page.getByTestId('status-error')).toBeVisible();
  await expect(page.getByTestId('status-error')).toContainText(/manifold/i);
  let s = await settled(page);
  expect(s.file).toBe('gingerbread.obj');
  expect(s.cage!.vertices).toBe(90);
  await page.getByTestId('status-error').getByRole('button').click();

  // A handle, then BBW: solved in the worker, with progress, then the rig is ready.
  for (const p of [HEAD, RIGHT_FOOT]) {
    const at = await projected(page, nearest(s.surface, p));
    await page.mouse.click(at.x, at.y);
    await settled(page);
  }
  s = await skin3d(page);
  expect(s.handles).toHaveLength(2);
  await page.getByRole('button', { name: 'BBW', exact: true }).click();
  s = await settled(page);
  expect(s.rig.phase).toBe('ready');
  expect(s.rig.ready).toBe(true);
  expect(s.progressReports).toBeGreaterThan(0);

  // The bar sample, then undo: the gingerbread with its two handles again.
  await page.getByTestId('skin3d-sample').selectOption('bar.obj');
  await expect.poll(async () => (await skin3d(page)).file).toBe('bar.obj');
  s = await settled(page);
  expect(s.cage).toEqual({ vertices: 72, faces: 66, creases: 8 });
  expect(s.handles).toHaveLength(0);
  await page.keyboard.press('Control+z');
  await expect.poll(async () => (await skin3d(page)).file).toBe('gingerbread.obj');
  s = await settled(page);
  expect(s.handles).toHaveLength(2);
  expect(s.rig.ready).toBe(true);

  // Reload: 3D Skin mode, the gingerbread, its handles and BBW weights come back from the autosave.
  await expect.poll(async () => (await skin3d(page)).saved).toBe(true);
  const handles = s.handles;
  await page.reload();
  await page.waitForFunction(() => window.splinekitEditor !== undefined);
  await page.evaluate(() => window.splinekitEditor!.ready);
  await expect.poll(async () => (await skin3d(page)).file).toBe('gingerbread.obj');
  s = await settled(page);
  expect(s.active).toBe(true);
  expect(s.handles).toEqual(handles);
  await expect(page.getByRole('button', { name: 'BBW', exact: true })).toHaveAttribute('aria-pressed', 'true');
  expect(s.rig.ready).toBe(true);
});
