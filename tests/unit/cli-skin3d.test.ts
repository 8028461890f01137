// `splinekit skin3d`: the command-line contract (acceptance checks use it exactly).
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, expect, test } from 'vitest';
import { init, parseCage } from '../../src/index.js';
import { cli, readShared, sharedData } from './helpers.js';

const dir = mkdtempSync(join(tmpdir(), 'splinekit-skin3d-'));
const spot = join(sharedData, 'meshes/quad/spot_control_mesh.obj');
const creased = join(sharedData, 'meshes/quad/catmark_cube_creases1.obj');
const ID = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0];

function write(name: string, text: string): string {
  const path = join(dir, name);
  writeFileSync(path, text);
  return path;
}

/** Rotation by `deg` about the z axis through (cx, cy, 0), as a row-major 3×4. */
function rotationZ(deg: number, cx: number, cy: number): number[] {
  const a = (deg * Math.PI) / 180, c = Math.cos(a), s = Math.sin(a);
  return [c, -s, 0, cx - (c * cx - s * cy), s, c, 0, cy - (s * cx + c * cy), 0, 0, 1, 0];
}

const spotCage = parseCage(readShared('meshes/quad/spot_control_mesh.obj'));
const P = spotCage.positions;
const handleVertices = [0, 40, 90, 150];
const handles = handleVertices.map((v) => ({ x: P[3 * v], y: P[3 * v + 1], z: P[3 * v + 2] }));
const handlesFile = write('handles.json', JSON.stringify({ handles }));
const identityFile = write('identity.json', JSON.stringify({ transforms: [ID, ID, ID, ID] }));
const bent = [ID, ID, rotationZ(35, handles[2].x, handles[2].y), rotationZ(-50, handles[3].x, handles[3].y)];
const bentFile = write('bent.json', JSON.stringify({ transforms: bent }));
const shared = [0.8, -0.6, 0, 0.3, 0.6, 0.8, 0, -0.2, 0, 0, 1, 0.5];
const sharedFile = write('shared.json', JSON.stringify({ transforms: [shared, shared, shared, shared] }));

beforeAll(async () => {
  await init();
});
afterAll(() => rmSync(dir, { recursive: true, force: true }));

interface Skin3dJSON {
  cage: number[][];
  stats: { precompute_ms: number; update_ms: number; error_rms: number; refined_vertices: number; levels: number };
}

function run(cage: string, pose: string, extra: string[] = [], handlesPath = handlesFile): Skin3dJSON {
  const out = join(dir, `out-${Math.random().toString(36).slice(2)}.json`);
  const r = cli(['skin3d', cage, '--handles', handlesPath, '--pose', pose, '--json', out, ...extra]);
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  return JSON.parse(readFileSync(out, 'utf8'));
}

function worstDistance(cage: number[][], expected: (v: number) => number[]): number {
  let worst = 0;
  cage.forEach((p, v) => {
    const q = expected(v);
    worst = Math.max(worst, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
  });
  return worst;
}

test('an identity pose gives the cage back in file order; a transform shared by every handle moves it rigidly', () => {
  const id = run(spot, identityFile);
  expect(id.cage).toHaveLength(P.length / 3);
  expect(worstDistance(id.cage, (v) => [P[3 * v], P[3 * v + 1], P[3 * v + 2]])).toBeLessThan(1e-9);
  expect(id.stats.levels).toBe(3);
  expect(id.stats.update_ms).toBeGreaterThan(0);
  expect(id.stats.update_ms).toBeLessThan(id.stats.precompute_ms);
  const moved = run(spot, sharedFile, ['--levels', '2']);
  expect(moved.stats.levels).toBe(2);
  expect(worstDistance(moved.cage, (v) => [0, 1, 2].map((r) => shared[4 * r] * P[3 * v] + shared[4 * r + 1] * P[3 * v + 1] + shared[4 * r + 2] * P[3 * v + 2] + shared[4 * r + 3]))).toBeLessThan(1e-9);
});

test('--method naive skins the cage vertices with Shepard weights; the fit is closer to the target', () => {
  const naive = run(spot, bentFile, ['--method', 'naive', '--levels', '2']);
  // Independent Shepard weights (power 2) and linear blend skinning of each cage vertex.
  const expected = (v: number) => {
    const p = [P[3 * v], P[3 * v + 1], P[3 * v + 2]];
    const d2 = handles.map((h) => (p[0] - h.x) ** 2 + (p[1] - h.y) ** 2 + (p[2] - h.z) ** 2);
    const at = d2.findIndex((d) => d === 0);
    const w = at >= 0 ? d2.map((_, i) => (i === at ? 1 : 0)) : d2.map((d) => 1 / d);
    const sum = w.reduce((a, b) => a + b, 0);
    return [0, 1, 2].map((r) => w.reduce((acc, wi, i) => acc + (wi / sum) * (bent[i][4 * r] * p[0] + bent[i][4 * r + 1] * p[1] + bent[i][4 * r + 2] * p[2] + bent[i][4 * r + 3]), 0));
  };
  expect(worstDistance(naive.cage, expected)).toBeLessThan(1e-12);
  const fit = run(spot, bentFile, ['--levels', '2']);
  expect(fit.stats.error_rms).toBeGreaterThan(0);
  expect(fit.stats.error_rms).toBeLessThan(naive.stats.error_rms);
});

test('without --json the JSON goes to stdout; -o writes the posed cage as OBJ with its crease tags', () => {
  const cube = parseCage(readShared('meshes/quad/catmark_cube_creases1.obj'));
  const h = write('cube-handles.json', JSON.stringify({ handles: [{ x: 0, y: 0, z: 1 }, { x: 0, y: 0, z: -1 }] }));
  const pose = write('cube-pose.json', JSON.stringify({ transforms: [ID, rotationZ(30, 0, 0)] }));
  const obj = join(dir, 'posed.obj');
  const r = cli(['skin3d', creased, '--handles', h, '--pose', pose, '--levels', '2', '-o', obj]);
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  const json = JSON.parse(r.stdout) as Skin3dJSON;
  const posed = parseCage(readFileSync(obj, 'utf8'));
  expect(Array.from(posed.positions)).toEqual(json.cage.flat());
  expect(Array.from(posed.faceIndices)).toEqual(Array.from(cube.faceIndices));
  expect(posed.creases).toEqual(cube.creases);
  expect(posed.creases).toHaveLength(12);
});

test('bad input: one line naming the problem, non-zero exit', () => {
  const bad = (cageText: string, pose = identityFile, handlesPath = handlesFile) => {
    const r = cli(['skin3d', write(`bad-${Math.random().toString(36).slice(2)}.obj`, cageText), '--handles', handlesPath, '--pose', pose]);
    expect(r.code).not.toBe(0);
    expect(r.stdout).toBe('');
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    return r.stderr;
  };
  const quad = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\n';
  expect(bad(`${quad}f 1 2 3\nf 2 1 4\nf 1 2 5\n`)).toMatch(/non-manifold edge 1-2/);
  expect(bad(`${quad}f 1 2 3 2\n`)).toMatch(/repeats vertex 2/);
  expect(bad('v 0 0 0\nv 1 nan 0\nv 1 1 0\nf 1 2 3\n')).toMatch(/vertex 2 needs 3 finite coordinates/);
  expect(bad('v 0 0 0\nv 1 0 0\nv 1 1 0\n')).toMatch(/no faces/);
  const three = write('three.json', JSON.stringify({ transforms: [ID, ID, ID] }));
  const r = cli(['skin3d', spot, '--handles', handlesFile, '--pose', three]);
  expect(r.code).toBe(1);
  expect(r.stderr).toMatch(/3 transforms for 4 handles/);
  const nanPose = write('nan.json', '{"transforms":[[1,0,0,0,0,1,0,0,0,0,1,0],[1,0,0,0,0,1,0,0,0,0,1,0],[1,0,0,0,0,1,0,0,0,0,1,0],[1,0,0,0,0,1,0,0,0,0,1]]}');
  expect(cli(['skin3d', spot, '--handles', handlesFile, '--pose', nanPose]).stderr).toMatch(/transform 3 must be 12 finite numbers/);
  expect(cli(['skin3d', spot, '--handles', handlesFile, '--pose', identityFile, '--levels', '7']).code).toBe(2);
});
