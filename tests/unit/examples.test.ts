// examples/node run as a user runs them: the packed tarball installed into a copy of the example,
// the scripts run by node, their output checked against what the numbers must be.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, expect, test } from 'vitest';
import { installExample, packTarball } from '../packed-example.js';
import { init, parseSVG } from '../../src/index.js';

const work = mkdtempSync(join(tmpdir(), 'splinekit-examples-'));
let dir = '';

beforeAll(async () => {
  await init();
  dir = installExample('node', packTarball(work), work);
}, 180_000);

afterAll(() => rmSync(work, { recursive: true, force: true }));

function run(script: string, ...args: string[]): string[] {
  const r = spawnSync(process.execPath, [script, ...args], { cwd: dir, encoding: 'utf8' });
  expect(r.stderr).toBe('');
  expect(r.status).toBe(0);
  return r.stdout.trim().split('\n');
}

test('examples/node/skin.mjs poses the character with two handles and writes it as splines', () => {
  const lines = run('skin.mjs', 'out.svg');
  const rest = parseSVG(readFileSync(join(dir, 'character.svg'), 'utf8'));
  const { elements, splines, segments } = rest.stats();
  expect(lines[0]).toBe(`character.svg: ${elements} shapes, ${splines} splines, ${segments} segments`);
  expect([elements, splines, segments]).toEqual([2, 2, 8]);

  // The fit is the paper's least-squares optimum; on this pose it is well under the naive
  // skinning of the control points.
  const m = /^posed with 2 handles: fit rms ([\d.]+), naive rms ([\d.]+); wrote out\.svg$/.exec(lines[1]);
  expect(m, lines[1]).not.toBeNull();
  const [fit, naive] = [Number(m![1]), Number(m![2])];
  expect(fit).toBeGreaterThan(0);
  expect(fit).toBeLessThan(naive / 2);

  // The written file is the same drawing posed: same shapes and splines, the tail (near the
  // identity handle) nearly in place, the eye (almost all head handle's weight) turned by −30°
  // about the head handle (160, 85) and raised by 20: its centre (165, 78) goes to
  // (160 + 5cos30° − 7sin30°, 85 − 5sin30° − 7cos30° − 20) ≈ (160.83, 56.44).
  expect(existsSync(join(dir, 'out.svg'))).toBe(true);
  const posed = parseSVG(readFileSync(join(dir, 'out.svg'), 'utf8'));
  expect(posed.stats()).toMatchObject({ elements, splines, segments });
  const centre = (pts: Float64Array) => {
    let x = 0, y = 0;
    for (let i = 0; i < pts.length; i += 2) [x, y] = [x + pts[i], y + pts[i + 1]];
    return [x / (pts.length / 2), y / (pts.length / 2)];
  };
  const eye = centre(posed.splines[1].points);
  expect(Math.hypot(eye[0] - 160.83, eye[1] - 56.44)).toBeLessThan(1);
  const body = posed.splines[0].points, restBody = rest.splines[0].points;
  expect(Math.hypot(body[0] - restBody[0], body[1] - restBody[1])).toBeLessThan(2); // the tail end (20, 70)

  // Both handles translated alike: an affine-reproducing rig moves every point by exactly that.
  const t = /^translation of both handles reproduced within (\S+)$/.exec(lines[2]);
  expect(t, lines[2]).not.toBeNull();
  expect(Number(t![1])).toBeLessThan(1e-9);
});

test('examples/node/geodesic.mjs: the geodesic on the generated flat grid is the straight segment', () => {
  const lines = run('geodesic.mjs');
  expect(lines[0]).toBe('grid.obj: 441 vertices, 800 faces'); // (20+1)² vertices, 2·20² triangles
  const m = /^geodesic \((\S+), (\S+), (\S+)\) → \((\S+), (\S+), (\S+)\): length (\S+), (\d+) points$/.exec(lines[1]);
  expect(m, lines[1]).not.toBeNull();
  const [x0, y0, z0, x1, y1, z1, length] = m!.slice(1, 8).map(Number);
  expect([x0, y0, z0, x1, y1, z1]).toEqual([0, 0, 0, 1, 0.35, 0]);
  expect(Math.abs(length - Math.hypot(1, 0.35))).toBeLessThan(1e-9);
  // The segment from (0,0) to (1, 0.35) crosses the 19 inner vertical grid lines at least, so
  // the path has more than 21 points with its ends.
  expect(Number(m![8])).toBeGreaterThan(21);
  const b = /^bezier: (\d+) points on the surface$/.exec(lines[2]);
  expect(b, lines[2]).not.toBeNull();
  expect(Number(b![1])).toBeGreaterThan(35); // OLR level 5 gives 35 points before edge crossings
});
