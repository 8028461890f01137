// `splinekit morph` as a process: exit codes and one-line errors (the in-process tests in
// cli-in-process.test.ts check its output), on a glyph pair of the shared data.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, expect, test } from 'vitest';
import { cli, sharedData } from './helpers.js';

const dir = mkdtempSync(join(tmpdir(), 'splinekit-cli-morph-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));
const g = (font: string) => join(sharedData, 'svg/morph', `${font}_G.svg`);

test('the paper’s Fig. 7 pair blends into 3 frames on stdout and exits 0', () => {
  const r = cli(['morph', g('NimbusMonoPS-Bold'), g('NimbusRoman-Bold'), '--frames', '3', '--json', '-']);
  expect(r.code).toBe(0);
  const json = JSON.parse(r.stdout);
  expect(json.frames).toHaveLength(3);
  expect(json.frames[1].t).toBe(0.5);
  expect(json.stats.frame_ms).toBeLessThan(json.stats.correspondence_ms);
});

test('bad input exits 1 and bad usage 2, each with one line on stderr naming the problem', () => {
  const empty = join(dir, 'empty.svg');
  writeFileSync(empty, '<svg xmlns="http://www.w3.org/2000/svg"/>');
  const bad = cli(['morph', empty, g('NimbusRoman-Bold')]);
  expect(bad.code).toBe(1);
  expect(bad.stderr.trim().split('\n')).toEqual(['splinekit: empty.svg: no path or shape to morph']);
  const usage = cli(['morph', g('NimbusRoman-Bold')]);
  expect(usage.code).toBe(2);
  expect(usage.stderr.trim().split('\n')).toHaveLength(1);
  expect(cli(['morph', '--help']).stdout).toContain('--interpolation linear|intrinsic');
});
