// The tracing defaults have one home (src/surface/trace-options.ts): a call that omits an option
// traces exactly what the call that names the default traces, and not what a neighbouring value
// traces; the benchmarks' table and the CLI's help state the same numbers.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, expect, test } from 'vitest';
import { DEFAULT_TRACE_LEVELS, DEFAULT_TRACE_SCHEME, init, SurfaceMesh, traceBezier, type MeshPointLike } from '../../src/index.js';
import { trace } from '../../src/cli/surface.js';
import { repoRoot } from './helpers.js';

let mesh: SurfaceMesh;
beforeAll(async () => {
  await init();
  // A bumpy 12×12 grid: curved, so that every subdivision level gives a different polyline.
  const n = 12, positions: number[] = [], triangles: number[] = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) positions.push(i, j, Math.sin(i / 2) * Math.cos(j / 3));
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) {
      const v = j * (n + 1) + i;
      triangles.push(v, v + 1, v + n + 2, v, v + n + 2, v + n + 1);
    }
  mesh = SurfaceMesh.fromArrays(positions, triangles);
  return () => mesh.dispose();
});

const controls: MeshPointLike[] = [14, 40 + 13 * 9, 13 * 11 + 2, 13 * 12 + 11];
const xyz = (options?: Parameters<typeof traceBezier>[2]) => Array.from(traceBezier(mesh, controls, options).xyz);

test('the defaults are OLR with 5 levels and RDC with 4', () => {
  expect(DEFAULT_TRACE_SCHEME).toBe('olr');
  expect({ ...DEFAULT_TRACE_LEVELS }).toEqual({ olr: 5, rdc: 4 });
});

test('omitted options trace what the named defaults trace, and not their neighbours', () => {
  const omitted = xyz();
  expect(omitted).toEqual(xyz({ scheme: DEFAULT_TRACE_SCHEME, levels: DEFAULT_TRACE_LEVELS[DEFAULT_TRACE_SCHEME] }));
  expect(xyz({ scheme: 'olr' })).toEqual(xyz({ scheme: 'olr', levels: DEFAULT_TRACE_LEVELS.olr }));
  expect(xyz({ scheme: 'rdc' })).toEqual(xyz({ scheme: 'rdc', levels: DEFAULT_TRACE_LEVELS.rdc }));
  for (const scheme of ['olr', 'rdc'] as const) {
    const d = DEFAULT_TRACE_LEVELS[scheme];
    expect(xyz({ scheme })).not.toEqual(xyz({ scheme, levels: d - 1 }));
    expect(xyz({ scheme })).not.toEqual(xyz({ scheme, levels: d + 1 }));
  }
  expect(xyz({ scheme: 'rdc' })).not.toEqual(omitted);
});

test('BENCHMARKS.md and the CLI help state the same defaults', () => {
  const bench = readFileSync(join(repoRoot, 'BENCHMARKS.md'), 'utf8');
  expect(bench).toContain(`OLR uniform (${DEFAULT_TRACE_LEVELS.olr} levels)`);
  expect(bench).toContain(`RDC uniform (${DEFAULT_TRACE_LEVELS.rdc} levels)`);
  expect(trace.usage).toContain(`OLR (default, ${DEFAULT_TRACE_LEVELS.olr} levels)`);
  expect(trace.usage).toContain(`RDC (${DEFAULT_TRACE_LEVELS.rdc} levels)`);
});
