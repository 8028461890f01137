// `splinekit skin`: the command-line contract (acceptance checks use it exactly).
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, expect, test } from 'vitest';
import { init, parseSVG } from '../../src/index.js';
import { cli, readShared, sharedData } from './helpers.js';

const dir = mkdtempSync(join(tmpdir(), 'splinekit-skin-'));
const input = join(sharedData, 'svg/characters/oc_ballerina.svg');
const handles = [{ x: 40, y: 40 }, { x: 110, y: 40 }, { x: 40, y: 200 }, { x: 110, y: 200 }];
const ID = [1, 0, 0, 1, 0, 0];

function rotationAbout(deg: number, cx: number, cy: number): number[] {
  const a = (deg * Math.PI) / 180, c = Math.cos(a), s = Math.sin(a);
  return [c, s, -s, c, cx - (c * cx - s * cy), cy - (s * cx + c * cy)];
}

function write(name: string, value: unknown): string {
  const path = join(dir, name);
  writeFileSync(path, JSON.stringify(value));
  return path;
}

const handlesFile = write('handles.json', { handles });
const identityFile = write('identity.json', { transforms: [ID, ID, ID, ID] });
const bentFile = write('bent.json', { transforms: [ID, ID, rotationAbout(40, 40, 200), rotationAbout(-35, 110, 200)] });

beforeAll(async () => {
  await init();
});
afterAll(() => rmSync(dir, { recursive: true, force: true }));

interface SkinJSON {
  splines: { closed: boolean; points: number[][]; continuity: string[] }[];
  stats: { curves: number; precompute_ms: number; update_ms: number };
}

/** Wall-clock ms of the last run of the CLI, start of Node to exit: a bound on any time it reports. */
let lastRunMs = 0;

function run(pose: string, extra: string[] = []): SkinJSON {
  const out = join(dir, `out-${Math.random().toString(36).slice(2)}.json`);
  const t0 = performance.now();
  const r = cli(['skin', input, '--handles', handlesFile, '--pose', pose, '--json', out, ...extra]);
  lastRunMs = performance.now() - t0;
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  return JSON.parse(readFileSync(out, 'utf8'));
}

test('an identity pose gives the input back, in the schema of info', () => {
  const json = run(identityFile);
  const doc = parseSVG(readShared('svg/characters/oc_ballerina.svg'));
  expect(json.splines).toHaveLength(doc.splines.length);
  let worst = 0;
  json.splines.forEach((s, i) => {
    expect(s.closed).toBe(doc.splines[i].closed);
    expect(s.continuity).toEqual(doc.splines[i].continuity.map((t) => t.kind));
    s.points.flat().forEach((v, k) => (worst = Math.max(worst, Math.abs(v - doc.splines[i].points[k]))));
  });
  expect(worst).toBeLessThan(1e-9 * doc.size);
  expect(json.stats.curves).toBe(doc.stats().segments);
  // The precompute (weights, factorization) costs more than an update (one matrix-vector
  // product), and the command does both, the precompute once and 110 updates, within its own
  // wall-clock time: update_ms is the median of the last 100, so 50 of them took at least that.
  expect(json.stats.update_ms).toBeGreaterThan(0);
  expect(json.stats.update_ms).toBeLessThan(json.stats.precompute_ms);
  expect(json.stats.precompute_ms + 50 * json.stats.update_ms).toBeLessThan(lastRunMs);
});

test('--method naive moves every control point by the blended transforms', () => {
  const json = run(bentFile, ['--method', 'naive']);
  const doc = parseSVG(readShared('svg/characters/oc_ballerina.svg'));
  const T = [ID, ID, rotationAbout(40, 40, 200), rotationAbout(-35, 110, 200)];
  // Independent Shepard weights (power 2) and linear blend skinning of each control point.
  let worst = 0;
  doc.splines.forEach((s, i) => {
    for (let k = 0; k < s.points.length; k += 2) {
      const x = s.points[k], y = s.points[k + 1];
      const inv = handles.map((h) => 1 / ((x - h.x) ** 2 + (y - h.y) ** 2));
      const sum = inv.reduce((a, b) => a + b, 0);
      let px = 0, py = 0;
      T.forEach((t, h) => {
        const w = inv[h] / sum;
        px += w * (t[0] * x + t[2] * y + t[4]);
        py += w * (t[1] * x + t[3] * y + t[5]);
      });
      const [gx, gy] = json.splines[i].points[k / 2];
      worst = Math.max(worst, Math.hypot(gx - px, gy - py));
    }
  });
  expect(worst).toBeLessThan(1e-9 * doc.size);
});

test('the fit keeps continuity and writes a posed SVG; --flexible relaxes', () => {
  const svgOut = join(dir, 'posed.svg');
  const fit = run(bentFile, ['-o', svgOut]);
  const posed = parseSVG(readFileSync(svgOut, 'utf8'));
  // The written SVG parses back to the same splines (within export precision) and the same tags.
  posed.splines.forEach((s, i) => {
    s.points.forEach((v, k) => expect(Math.abs(v - fit.splines[i].points[Math.floor(k / 2)][k % 2])).toBeLessThan(1e-6 * posed.size));
  });
  const doc = parseSVG(readShared('svg/characters/oc_ballerina.svg'));
  const smooth = (d: { splines: { continuity: { kind: string }[] }[] }) => d.splines.flatMap((s) => s.continuity.map((t) => t.kind)).filter((k) => k !== 'C0').length;
  expect(smooth(posed)).toBeGreaterThanOrEqual(smooth(doc) - 2); // smooth junctions stay smooth after deformation
  const flexible = run(bentFile, ['--flexible']);
  expect(flexible.splines.flatMap((s) => s.points.flat())).not.toEqual(fit.splines.flatMap((s) => s.points.flat()));
});

test('bad handles, poses and options: one line, non-zero exit', () => {
  const cases: [string[], number, RegExp][] = [
    [['skin', input, '--handles', handlesFile], 2, /needs --handles and --pose/],
    [['skin', input, '--handles', write('h0.json', { handles: [] }), '--pose', write('p0.json', { transforms: [] })], 1, /at least one handle/],
    [['skin', input, '--handles', write('hbad.json', { handles: [{ x: 'a', y: 1 }] }), '--pose', identityFile], 1, /handle 0 needs finite numbers/],
    [['skin', input, '--handles', handlesFile, '--pose', write('p1.json', { transforms: [ID] })], 1, /1 transforms for 4 handles/],
    [['skin', input, '--handles', handlesFile, '--pose', write('p2.json', { transforms: [ID, ID, ID, [1, 0, 0, 1, 0]] })], 1, /transform 3 must be 6 finite numbers/],
    [['skin', input, '--handles', join(dir, 'missing.json'), '--pose', identityFile], 1, /cannot read handles/],
    [['skin', input, '--handles', write('junk.json', 'not json{') , '--pose', identityFile], 1, /expected \{"handles"/],
    [['skin', input, '--handles', handlesFile, '--pose', identityFile, '--weights', 'magic'], 2, /--weights must be/],
    [['skin', input, '--handles', handlesFile, '--pose', identityFile, '--samples', '2'], 1, /samples must be/],
  ];
  for (const [args, code, message] of cases) {
    const r = cli(args);
    expect(r.code, args.join(' ')).toBe(code);
    expect(r.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(r.stderr).toMatch(message);
  }
});

test('--weights harmonic and bbw: identity gives the input back, a pose moves it', () => {
  const icon = join(sharedData, 'svg/icons/fa_dragon.svg');
  const doc = parseSVG(readShared('svg/icons/fa_dragon.svg'));
  const [x0, y0, x1, y1] = doc.bounds!;
  const hs = write('icon-handles.json', { handles: [{ x: x0 + 0.2 * (x1 - x0), y: y0 + 0.3 * (y1 - y0) }, { x: x0 + 0.8 * (x1 - x0), y: y0 + 0.7 * (y1 - y0) }] });
  const id = write('icon-id.json', { transforms: [ID, ID] });
  const moved = write('icon-moved.json', { transforms: [ID, [1, 0, 0, 1, 30, -20]] });
  for (const weights of ['harmonic', 'bbw']) {
    const out = join(dir, `icon-${weights}.json`), out2 = join(dir, `icon-${weights}-2.json`);
    expect(cli(['skin', icon, '--handles', hs, '--pose', id, '--weights', weights, '--samples', '30', '--json', out]).code).toBe(0);
    const same = JSON.parse(readFileSync(out, 'utf8')) as SkinJSON;
    let worst = 0;
    same.splines.forEach((s, i) => s.points.flat().forEach((v, k) => (worst = Math.max(worst, Math.abs(v - doc.splines[i].points[k])))));
    expect(worst).toBeLessThan(1e-9 * doc.size);
    expect(cli(['skin', icon, '--handles', hs, '--pose', moved, '--weights', weights, '--samples', '30', '--json', out2]).code).toBe(0);
    const posed = JSON.parse(readFileSync(out2, 'utf8')) as SkinJSON & { stats: { weights: string } };
    expect(posed.stats.weights).toBe(weights);
    expect(posed.splines[0].points.flat()).not.toEqual(same.splines[0].points.flat());
  }
}, 120_000);
