// `splinekit info`: the counts it prints and the JSON schema the capability CLIs reuse.
import { mkdtempSync, rmSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, expect, test } from 'vitest';
import { init, parseSVG } from '../../src/index.js';
import { cli, readShared, sharedData } from './helpers.js';

const dir = mkdtempSync(join(tmpdir(), 'splinekit-info-'));

beforeAll(async () => {
  await init();
});

afterAll(() => rmSync(dir, { recursive: true, force: true }));

test('prints counts of a hand-made drawing', () => {
  const file = join(dir, 'mix.svg');
  writeFileSync(file, `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
    <rect width="10" height="10"/><circle cx="50" cy="50" r="5"/><path d="M0 0 L10 0 L20 10"/><text>t</text></svg>`);
  const r = cli(['info', file]);
  expect(r.code).toBe(0);
  expect(r.stdout).toContain('mix.svg: 3 elements, 3 splines, 10 segments');
  // rect: 4 corners (C0); circle: 4 smooth (C1); open polyline: one corner (C0).
  expect(r.stdout).toContain('continuity: C0 5, C1 4, G1 0, angle 0, none 0');
  expect(r.stdout).toContain('warnings: 1');
  expect(r.stdout).toContain('1 <text> element kept as it is');
});

test('--json holds counts and the geometry in the shared schema', () => {
  const rel = 'svg/characters/twemoji_1f419_octopus.svg';
  const out = join(dir, 'octopus.json');
  const r = cli(['info', join(sharedData, rel), '--json', out]);
  expect(r.code).toBe(0);
  const json = JSON.parse(readFileSync(out, 'utf8'));
  const doc = parseSVG(readShared(rel));
  expect(json.counts).toEqual(doc.stats());
  expect(json.splines).toHaveLength(doc.splines.length);
  json.splines.forEach((s: { closed: boolean; points: number[][]; continuity: string[] }, i: number) => {
    const n = s.points.length;
    expect(n % 3).toBe(s.closed ? 0 : 1); // 3n closed, 3n+1 open
    expect(s.continuity).toHaveLength(s.closed ? n / 3 : Math.max(0, (n - 1) / 3 - 1));
    expect(s.points.flat()).toEqual(Array.from(doc.splines[i].points));
    expect(s.continuity).toEqual(doc.splines[i].continuity.map((t) => t.kind));
  });
});

test('--json - writes JSON alone to stdout', () => {
  const file = join(dir, 'tri.svg');
  writeFileSync(file, '<svg xmlns="http://www.w3.org/2000/svg"><g transform="translate(1 2)"><polygon points="0,0 3,0 0,3"/></g></svg>');
  const r = cli(['info', file, '--json', '-']);
  expect(r.code).toBe(0);
  const json = JSON.parse(r.stdout);
  expect(json.splines).toEqual([
    { closed: true, points: [[1, 2], [2, 2], [3, 2], [4, 2], [3, 3], [2, 4], [1, 5], [1, 4], [1, 3]], continuity: ['C0', 'C0', 'C0'] },
  ]);
});
