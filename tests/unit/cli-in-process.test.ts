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
import { morph } from '../../src/cli/morph.js';

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

  test('a mesh: what building it found and repaired, the warnings, and --json the same as SurfaceMesh.info', async () => {
    // A square of two triangles written twice, the second time with the other winding (double-sided),
    // and a fifth vertex no face uses.
    const obj = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\nf 1 3 4\nf 1 3 2\nf 1 4 3\n';
    const { log } = await run(info, [write('square.obj', obj)]);
    expect(log).toContain('square.obj: 5 vertices, 4 faces, 1 parts, 1 boundary loops');
    expect(log).toContain('repairs: welded 0, unused 1, degenerate 0, repeated 2, non-manifold 0 edges / 0 vertices, flipped 0');
    expect(log).toContain('warnings: 2');
    expect(log).toContain('  - 2 faces repeat an earlier face (a double-sided mesh?): taken as that face');
    const { stdout } = await run(info, [write('square.obj', obj), '--json', '-']);
    expect(JSON.parse(stdout)).toMatchObject({ file: 'square.obj', vertices: 5, faces: 4, duplicateFaces: 2, components: 1, unreferencedVertices: 1 });
    await expect(info.run([write('bad.obj', 'v 0 0 0\nf 1 2 3\n')])).rejects.toBeInstanceOf(SplinekitError);
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

describe('morph', () => {
  // A square and a diamond of the same size: one closed contour each, all corners.
  const squareSvg = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><path d="M10 10 H90 V90 H10 Z"/></svg>';
  const diamondSvg = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100"><path d="M50 0 L100 50 L50 100 L0 50 Z"/></svg>';

  test('--json - writes N frames at t = i/(N-1) in the info schema, the work and the timings', async () => {
    const { log, stdout } = await run(morph, [write('sq.svg', squareSvg), write('di.svg', diamondSvg), '--frames', '5', '--json', '-']);
    expect(log).toBe('');
    const json = JSON.parse(stdout);
    expect(json.frames.map((f: { t: number }) => f.t)).toEqual([0, 0.25, 0.5, 0.75, 1]);
    expect(json.work).toBeGreaterThan(0);
    expect(json.stats.correspondence_ms).toBeGreaterThan(0);
    expect(json.stats.frame_ms).toBeGreaterThanOrEqual(0);
    for (const frame of json.frames) {
      expect(frame.splines).toHaveLength(1);
      const s = frame.splines[0];
      expect(s.closed).toBe(true);
      expect(s.points.length % 3).toBe(0);
      expect(s.continuity).toHaveLength(s.points.length / 3);
    }
    // The first frame is the square: its corners are among its anchors, all points on its sides.
    const first = json.frames[0].splines[0].points as [number, number][];
    for (const [x, y] of first) expect(Math.min(Math.abs(x - 10), Math.abs(x - 90), Math.abs(y - 10), Math.abs(y - 90))).toBeLessThan(1e-9);
    const last = json.frames[4].splines[0].points as [number, number][];
    for (const [x, y] of last) expect(Math.abs(Math.abs(x - 50) + Math.abs(y - 50) - 50)).toBeLessThan(1e-9);
  });

  test('default 11 frames; --out-dir writes one SVG per frame that reads back', async () => {
    const out = join(dir, 'frames');
    const { log } = await run(morph, [write('sq.svg', squareSvg), write('di.svg', diamondSvg), '--out-dir', out, '--json', join(dir, 'm.json'), '--interpolation', 'intrinsic']);
    expect(log).toContain('sq.svg → di.svg: 1 contours');
    const json = JSON.parse(readFileSync(join(dir, 'm.json'), 'utf8'));
    expect(json.frames).toHaveLength(11);
    const svg = readFileSync(join(out, 'frame-005.svg'), 'utf8');
    expect(svg).toContain('<path');
    expect(readFileSync(join(out, 'frame-010.svg'), 'utf8')).toContain('fill-rule="nonzero"');
  });

  test('--pins holds the given points together', async () => {
    const pins = write('pins.json', JSON.stringify({ pins: [{ a: [90, 10], b: [50, 100] }] }));
    const { stdout } = await run(morph, [write('sq.svg', squareSvg), write('di.svg', diamondSvg), '--frames', '2', '--pins', pins, '--json', '-']);
    const json = JSON.parse(stdout);
    const a = json.frames[0].splines[0].points as [number, number][], b = json.frames[1].splines[0].points as [number, number][];
    expect(a.some(([x, y], i) => x === 90 && y === 10 && b[i][0] === 50 && b[i][1] === 100)).toBe(true);
  });

  test('bad usage throws UsageError, bad or empty input a SplinekitError naming it', async () => {
    const sq = write('sq.svg', squareSvg);
    await expect(morph.run([sq])).rejects.toBeInstanceOf(UsageError);
    await expect(morph.run([sq, sq, '--frames', '1'])).rejects.toBeInstanceOf(UsageError);
    await expect(morph.run([sq, sq, '--frames', 'x'])).rejects.toBeInstanceOf(UsageError);
    await expect(morph.run([sq, sq, '--interpolation', 'cubic'])).rejects.toBeInstanceOf(UsageError);
    const empty = write('empty.svg', '<svg xmlns="http://www.w3.org/2000/svg"><text>t</text></svg>');
    await expect(morph.run([empty, sq])).rejects.toThrow(/empty.svg: no path or shape to morph/);
    await expect(morph.run([sq, write('bad.svg', '<svg><path d="M0 0 L"/>')])).rejects.toBeInstanceOf(SplinekitError);
    await expect(morph.run([sq, join(dir, 'missing.svg')])).rejects.toMatchObject({ code: 'invalid-input' });
    const dot = write('dot.svg', '<svg xmlns="http://www.w3.org/2000/svg"><path d="M5 5 L5 5 L5 5 Z"/></svg>');
    await expect(morph.run([dot, sq])).rejects.toThrow(/zero/);
    await expect(morph.run([sq, sq, '--pins', write('p.json', '{"pins":[{"a":[1]}]}')])).rejects.toThrow(/pin 0/);
  });
});
