// `splinekit edit`: the command-line contract of issue 16 (acceptance checks use it exactly).
// Closed forms on a straight line of evenly spaced points, where arc lengths are the chords.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, test, vi } from 'vitest';
import { init, parseSVG } from '../../src/index.js';
import { cli, cubicAt } from './helpers.js';
import { edit } from '../../src/cli/edit.js';
import { UsageError } from '../../src/cli/common.js';

const dir = mkdtempSync(join(tmpdir(), 'splinekit-edit-'));
beforeAll(async () => {
  await init();
});
afterAll(() => rmSync(dir, { recursive: true, force: true }));

function write(name: string, value: unknown): string {
  const path = join(dir, name);
  writeFileSync(path, typeof value === 'string' ? value : JSON.stringify(value));
  return path;
}

interface EditJSON {
  points: [number, number][];
  bezier: { closed: boolean; points: [number, number][]; continuity: string[] };
  stats: { count: number; moved: number; window: { left: number; right: number; first: number; last: number }; parameterization: string };
}

function run(curve: string, args: string[]): EditJSON {
  const out = join(dir, `out-${Math.random().toString(36).slice(2)}.json`);
  const r = cli(['edit', curve, ...args, '--json', out]);
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  return JSON.parse(readFileSync(out, 'utf8'));
}

const line = Array.from({ length: 11 }, (_, i) => [i, 0]);
const lineFile = write('line.json', { closed: false, points: line });
const loop = Array.from({ length: 10 }, (_, i) => [Math.cos((2 * Math.PI * i) / 10) * 10, Math.sin((2 * Math.PI * i) / 10) * 10]);
const loopFile = write('loop.json', { closed: true, points: loop });

describe('splinekit edit', () => {
  test('a linear drop-off over an asymmetric window: the closed form 1 - d/W on each side', () => {
    const json = run(lineFile, ['--drag', '5', '0', '2', '--window', '3', '2', '--falloff', 'linear']);
    const y = json.points.map((p) => p[1]);
    // Left: W = 3, points 4, 3 at d = 1, 2; right: W = 2, point 6 at d = 1.
    expect(y[5]).toBe(2);
    expect(y[4]).toBeCloseTo((2 * 2) / 3, 12);
    expect(y[3]).toBeCloseTo(2 / 3, 12);
    expect(y[6]).toBeCloseTo(1, 12);
    // The window's ends (2 and 7) and everything outside stay exactly; x never changes.
    for (const i of [0, 1, 2, 7, 8, 9, 10]) expect(json.points[i]).toEqual(line[i]);
    json.points.forEach((p, i) => expect(p[0]).toBe(line[i][0]));
    expect(json.stats.window).toEqual({ left: 3, right: 2, first: 2, last: 7 });
    expect(json.stats.moved).toBe(4);
  });

  test('the exact Bézier form, in the schema of info: anchors at the control points, uniform handles at ±(P[i+1]−P[i−1])/6', () => {
    const json = run(lineFile, ['--drag', '4', '1', '-3', '--param', 'uniform']);
    const { bezier, points } = json;
    expect(bezier.closed).toBe(false);
    expect(bezier.points).toHaveLength(3 * 10 + 1);
    expect(bezier.continuity).toEqual(Array(9).fill('C1'));
    for (let i = 0; i < points.length; i++) expect(bezier.points[3 * i]).toEqual(points[i]);
    for (let i = 1; i < points.length - 1; i++) {
      for (const a of [0, 1]) {
        const t = (points[i + 1][a] - points[i - 1][a]) / 6;
        expect(bezier.points[3 * i + 1][a]).toBeCloseTo(points[i][a] + t, 12);
        expect(bezier.points[3 * i - 1][a]).toBeCloseTo(points[i][a] - t, 12);
      }
    }
    // The cubic through the handles passes through the Catmull-Rom midpoint (P1+P2)·9/16 − (P0+P3)/16.
    const seg = [3, 4, 5, 6].flatMap((k) => bezier.points[k]);
    const mid = cubicAt(seg, 0.5);
    for (const a of [0, 1]) expect(mid[a]).toBeCloseTo((9 * (points[1][a] + points[2][a]) - (points[0][a] + points[3][a])) / 16, 12);
  });

  test('a closed curve wraps its window across the seam; centripetal gives G1 or C1 tags; -o writes the curve as SVG', () => {
    const svg = join(dir, 'loop.svg');
    const out = join(dir, 'loop-out.json');
    const r = cli(['edit', loopFile, '--drag', '0', '3', '0', '--window', '2', '2', '--normals', '--json', out, '-o', svg]);
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    expect(r.stdout).toContain('loop.json: 10 control points (closed, centripetal)');
    const json = JSON.parse(readFileSync(out, 'utf8')) as EditJSON;
    expect(json.stats.window).toEqual({ left: 2, right: 2, first: 8, last: 2 });
    for (const i of [2, 3, 4, 5, 6, 7, 8]) expect(json.points[i]).toEqual(loop[i]);
    for (const i of [9, 0, 1]) expect(json.points[i]).not.toEqual(loop[i]);
    expect(json.points[0]).toEqual([loop[0][0] + 3, loop[0][1]]);
    expect(json.bezier.closed).toBe(true);
    expect(json.bezier.points).toHaveLength(30);
    expect(json.bezier.continuity).toHaveLength(10);
    expect(json.bezier.continuity.every((k) => k === 'G1' || k === 'C1')).toBe(true);
    const doc = parseSVG(readFileSync(svg, 'utf8'));
    expect(doc.splines).toHaveLength(1);
    expect(doc.splines[0].closed).toBe(true);
    json.bezier.points.flat().forEach((v, k) => expect(doc.splines[0].points[k]).toBeCloseTo(v, 9));
  });

  test('runs in-process: --json - writes the JSON to stdout and nothing else; usage errors are UsageErrors', async () => {
    const chunks: string[] = [];
    const log = vi.spyOn(console, 'log').mockImplementation(() => {});
    const out = vi.spyOn(process.stdout, 'write').mockImplementation((c: string | Uint8Array) => (chunks.push(String(c)), true));
    try {
      await edit.run([lineFile, '--drag', '5', '0', '1', '--window', '0', '0', '--json', '-']);
    } finally {
      out.mockRestore();
      log.mockRestore();
    }
    expect(log).not.toHaveBeenCalled();
    const json = JSON.parse(chunks.join('')) as EditJSON;
    // A window of zero is a plain control-point move.
    json.points.forEach((p, i) => expect(p).toEqual(i === 5 ? [5, 1] : line[i]));
    await expect(edit.run([lineFile, '--drag', '5', '0'])).rejects.toThrow(UsageError);
  });

  test('bad input ends with one line naming the problem: exit 1 for the data, 2 for the usage', () => {
    const cases: [string[], number, string][] = [
      [[write('bad.json', '{"closed":false,"points":[[0,0],'), '--drag', '0', '1', '1'], 1, 'not valid JSON'],
      [[write('one.json', { closed: false, points: [[0, 0]] }), '--drag', '0', '1', '1'], 1, 'at least 2 control points'],
      [[write('nan.json', { closed: false, points: [[0, 0], [1, 'x']] }), '--drag', '0', '1', '1'], 1, 'point 1 must be [x, y]'],
      [[write('shape.json', { curve: [] }), '--drag', '0', '1', '1'], 1, 'expected {"closed":bool,"points"'],
      [[lineFile, '--drag', '11', '1', '1'], 1, 'control point 11 is out of range'],
      [[write('huge.json', { closed: true, points: [[0, 0], [1e300, 0], [0, 1]] }), '--drag', '0', '1', '1'], 1, 'beyond ±1e150'],
      [[lineFile, '--drag', '1', '1e200', '0'], 1, 'within ±1e150'],
      [[lineFile], 2, 'needs --drag I DX DY'],
      [[lineFile, '--drag', '1', 'NaN', '0'], 2, '--drag DX must be a finite number'],
      [[lineFile, '--drag', '1', '0', '0', '--falloff', 'box'], 2, '--falloff must be linear, gaussian or cosine'],
      [[lineFile, '--drag', '1', '0', '0', '--window', '2'], 2, '--window takes 2 values'],
    ];
    for (const [args, code, message] of cases) {
      const r = cli(['edit', ...args]);
      expect(r.code, args.join(' ')).toBe(code);
      expect(r.stderr.trim().split('\n')).toHaveLength(1);
      expect(r.stderr).toContain(message);
    }
  });
});
