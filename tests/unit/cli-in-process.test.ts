// The CLI's commands imported and run in this process, without the entry (src/cli/splinekit.ts):
// importing a command must not start the CLI (the entry runs main() and calls process.exit on
// import, so a command that still imported it would end this test run), and each command's output
// is checked against what the drawing or mesh written here holds.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, afterEach, beforeAll, describe, expect, test, vi } from 'vitest';
import { init, SplinekitError } from '../../src/index.js';
import { UsageError } from '../../src/cli/common.js';
import { cubicAt } from './helpers.js';
import { info } from '../../src/cli/info.js';
import { skin } from '../../src/cli/skin.js';
import { geodesic, trace } from '../../src/cli/surface.js';

const dir = mkdtempSync(join(tmpdir(), 'splinekit-cli-in-process-'));
beforeAll(async () => {
  await init();
});
afterAll(() => rmSync(dir, { recursive: true, force: true }));
afterEach(() => vi.restoreAllMocks());

function write(name: string, text: string): string {
  const path = join(dir, name);
  writeFileSync(path, text);
  return path;
}

/** Runs `command.run(args)` and returns what it printed with console.log and wrote to stdout. */
async function run(command: { run(args: string[]): Promise<void> }, args: string[]): Promise<{ log: string; stdout: string }> {
  const log: string[] = [];
  const stdout: string[] = [];
  vi.spyOn(console, 'log').mockImplementation((...values: unknown[]) => void log.push(values.join(' ')));
  vi.spyOn(process.stdout, 'write').mockImplementation((chunk: string | Uint8Array) => (stdout.push(String(chunk)), true));
  await command.run(args);
  vi.restoreAllMocks();
  return { log: log.join('\n'), stdout: stdout.join('') };
}

// A rect (4 segments, 4 C0 corners), a circle (4 segments, 4 C1 junctions), an open polyline of two
// lines (2 segments, one C0 corner) and a text element the model keeps as it is (one warning).
const drawing = `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
  <rect width="10" height="10"/><circle cx="50" cy="50" r="5"/><path d="M0 0 L10 0 L20 10"/><text>t</text></svg>`;

describe('info', () => {
  test('prints the element, spline, segment and continuity counts of a hand-made drawing', async () => {
    const { log } = await run(info, [write('mix.svg', drawing)]);
    expect(log).toContain('mix.svg: 3 elements, 3 splines, 10 segments');
    expect(log).toContain('continuity: C0 5, C1 4, G1 0, angle 0, none 0');
    expect(log).toContain('warnings: 1');
  });

  test('--json - writes the counts and the geometry to stdout and prints nothing else', async () => {
    const { log, stdout } = await run(info, [write('mix.svg', drawing), '--json', '-']);
    expect(log).toBe('');
    const json = JSON.parse(stdout);
    expect(json.counts).toMatchObject({ elements: 3, splines: 3, segments: 10, warnings: 1 });
    expect(json.counts.continuity).toMatchObject({ C0: 5, C1: 4 });
    // The rect's spline: closed, 4 segments → 12 control points, the first at its corner (0, 0).
    expect(json.splines[0].closed).toBe(true);
    expect(json.splines[0].points).toHaveLength(12);
    expect(json.splines[0].points[0]).toEqual([0, 0]);
    // The polyline: open, 2 segments → 7 points ending at (20, 10).
    expect(json.splines[2].closed).toBe(false);
    expect(json.splines[2].points.at(-1)).toEqual([20, 10]);
  });

  test('bad usage throws UsageError, bad input SplinekitError', async () => {
    await expect(info.run([])).rejects.toBeInstanceOf(UsageError);
    await expect(info.run(['a.svg', 'b.svg'])).rejects.toBeInstanceOf(UsageError);
    await expect(info.run([write('x.svg', drawing), '--nope'])).rejects.toBeInstanceOf(UsageError);
    await expect(info.run([join(dir, 'missing.svg')])).rejects.toMatchObject({ code: 'invalid-input' });
    await expect(info.run([write('bad.svg', '<svg')])).rejects.toBeInstanceOf(SplinekitError);
  });
});

describe('skin', () => {
  test('needs --handles and --pose', async () => {
    await expect(skin.run([write('s.svg', drawing)])).rejects.toBeInstanceOf(UsageError);
  });

  test('one handle moved by a translation moves every control point by it', async () => {
    const handles = write('handles.json', JSON.stringify({ handles: [{ x: 5, y: 5 }] }));
    const pose = write('pose.json', JSON.stringify({ transforms: [[1, 0, 0, 1, 7, -3]] }));
    const out = join(dir, 'skinned.json');
    await run(skin, [write('s.svg', drawing), '--handles', handles, '--pose', pose, '--json', out]);
    const moved = JSON.parse(readFileSync(out, 'utf8'));
    const rest = JSON.parse((await run(info, [join(dir, 's.svg'), '--json', '-'])).stdout);
    expect(moved.splines).toHaveLength(rest.splines.length);
    moved.splines.forEach((s: { points: number[][] }, i: number) =>
      s.points.forEach(([x, y], k) => {
        expect(x).toBeCloseTo(rest.splines[i].points[k][0] + 7, 9);
        expect(y).toBeCloseTo(rest.splines[i].points[k][1] - 3, 9);
      }),
    );
  });
});

describe('geodesic and trace', () => {
  // A unit square in z = 0 cut along its diagonal 0–2: the shortest path between opposite
  // corners 1 and 3 crosses the diagonal and is the straight line of length √2.
  const square = () => write('square.obj', 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n');

  test('geodesic between opposite corners of a flat square is its diagonal', async () => {
    const out = join(dir, 'paths.json');
    await run(geodesic, [square(), '--pairs', write('pairs.json', JSON.stringify({ pairs: [[1, 3], [0, 1]] })), '--json', out]);
    const json = JSON.parse(readFileSync(out, 'utf8'));
    expect(json.paths[0].length).toBeCloseTo(Math.SQRT2, 9);
    expect(json.paths[0].points[0]).toEqual([1, 0, 0]);
    expect(json.paths[0].points.at(-1)).toEqual([0, 1, 0]);
    expect(json.paths[1].length).toBeCloseTo(1, 9);
  });

  test('a traced curve on a flat square is the planar Bézier curve, and bad usage throws', async () => {
    const out = join(dir, 'curves.json');
    const controls = [0, { face: 0, uv: [0.5, 0] }, { face: 1, uv: [0.5, 0.25] }, 2];
    await run(trace, [square(), '--curves', write('curves.json', JSON.stringify({ curves: [controls] })), '--json', out]);
    const json = JSON.parse(readFileSync(out, 'utf8'));
    const points: number[][] = json.curves[0].points.map((p: { xyz: number[] }) => p.xyz);
    expect(points.length).toBeGreaterThan(4);
    expect(points[0]).toEqual([0, 0, 0]);
    expect(points.at(-1)).toEqual([1, 1, 0]);
    // On a flat mesh geodesics are straight, so the subdivision converges to the planar Bézier curve
    // with controls (0,0), (0.5,0) (face 0 = vertices 0,1,2), (0.5,0.75) (face 1 = vertices 0,2,3), (1,1).
    const c = [0, 0, 0.5, 0, 0.5, 0.75, 1, 1];
    const curve = Array.from({ length: 2001 }, (_, i) => cubicAt(c, i / 2000));
    for (const p of points) {
      expect(p[2]).toBe(0);
      expect(Math.min(...curve.map(([x, y]) => Math.hypot(p[0] - x, p[1] - y)))).toBeLessThan(5e-3);
    }
    await expect(trace.run([square()])).rejects.toBeInstanceOf(UsageError);
    await expect(geodesic.run([])).rejects.toBeInstanceOf(UsageError);
  });
});
