#!/usr/bin/env node
// `npm run bench:ab -- [ref] [--mesh file]... [--curves N] [--rounds R]`: whether the working
// tree's surface core traces the benchmark's curves faster or slower than `ref`'s (default HEAD).
// Whole `npm run bench` runs on this 2-core VM drift by up to 25%, more than most changes are
// worth; here both cores are linked into one wasm module (each in its own namespace) and trace
// every curve in turn, so the ratio holds up to about 1% (a tree against itself: 0.99-1.01).
// Curves: the random polygons of BENCHMARKS.md (OLR, 5 levels, the same generator and seed).
// --mesh: a file of ../shared/data/meshes, or any path to a mesh file. Meshes of 65,536 faces or
// more get the coarse guide and landmarks the library gives them (SurfaceMesh's defaults), so that
// the A/B runs what `npm run bench`'s "Surface at scale" measures.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import { SurfaceMesh, init, randomMeshPoints } from '../dist/index.js';
import { GUIDE_MIN_FACES, guideTriangles } from '../dist/surface/coarse-guide.js';
import { DEFAULT_LANDMARKS, GUIDED_LANDMARKS } from '../dist/surface/mesh.js';

const root = new URL('..', import.meta.url).pathname;
const data = join(root, '../shared/data');
const out = join(root, 'build/ab');

const { values, positionals } = parseArgs({
  allowPositionals: true,
  options: {
    mesh: { type: 'string', multiple: true, default: ['spot_loop2_369k.ply', 'nefertiti.obj'] },
    curves: { type: 'string', default: '200' },
    rounds: { type: 'string', default: '3' },
  },
});
const ref = positionals[0] ?? 'HEAD';
const run = (cmd, args, options = {}) => execFileSync(cmd, args, { cwd: root, encoding: 'utf8', ...options });

// ---- the two source trees: `ref` from git, B the working tree ---------------------------------
const refTree = join(out, 'ref');
rmSync(refTree, { recursive: true, force: true });
mkdirSync(refTree, { recursive: true });
const commit = run('git', ['rev-parse', '--short', ref]).trim();
run('bash', ['-c', `git archive ${commit} wasm/core | tar -x -C "${refTree}"`]);

// ---- one module: each tree's core with its namespace renamed, and the driver -------------------
const env = { ...process.env, NODE_PATH: '/usr/share/nodejs' }; // em++ 3.1.6 needs Debian's acorn
const flags = ['-O3', '-DNDEBUG', '-std=c++17', '-msimd128', '-I/usr/include/eigen3'];
const objects = [];
for (const [side, tree] of [['A', refTree], ['B', root]]) {
  const dir = join(out, `obj_${side}`);
  rmSync(dir, { recursive: true, force: true });
  mkdirSync(dir, { recursive: true });
  const sources = ['common', 'surface'].flatMap((d) =>
    readdirSync(join(tree, 'wasm/core', d)).filter((f) => f.endsWith('.cpp')).map((f) => join(tree, 'wasm/core', d, f)));
  sources.push(join(root, 'bench/ab/variant.cpp'));
  for (const src of sources) {
    const obj = join(dir, src.split('/').pop().replace(/\.cpp$/, '.o'));
    run('em++', [...flags, `-I${join(tree, 'wasm/core')}`, `-Dsplinekit=splinekit_ab_${side}`, `-DSPLINEKIT_AB_SIDE=${side}`, '-c', src, '-o', obj], { env });
    objects.push(obj);
  }
}
const module = join(out, 'ab.js');
writeFileSync(join(out, 'package.json'), '{"type": "commonjs"}\n'); // (emscripten's node output requires)
run('em++', ['-O3', '-msimd128', join(root, 'bench/ab/main.cpp'), ...objects, '-o', module,
  '-sNODERAWFS=1', '-sALLOW_MEMORY_GROWTH=1', '-sMAXIMUM_MEMORY=4GB', '-sENVIRONMENT=node'], { env, stdio: ['ignore', 'pipe', 'pipe'] });

// ---- the curves, and the runs ------------------------------------------------------------------
await init();
const curves = Number(values.curves);
console.log(`A = ${ref} (${commit}), B = the working tree; ${curves} random curves per mesh, best of ${values.rounds} rounds`);
for (const file of values.mesh) {
  const path = existsSync(file) ? file : join(data, 'meshes', file);
  const mesh = await SurfaceMesh.load(readFileSync(path), path.split('/').pop());
  const points = randomMeshPoints(mesh, 4 * curves, 1);
  const meshBin = Buffer.alloc(8 + 8 * mesh.positions.length + 4 * mesh.triangles.length);
  meshBin.writeInt32LE(mesh.positions.length / 3, 0);
  meshBin.writeInt32LE(mesh.triangles.length / 3, 4);
  Buffer.from(mesh.positions.buffer, mesh.positions.byteOffset, 8 * mesh.positions.length).copy(meshBin, 8);
  Buffer.from(mesh.triangles.buffer, mesh.triangles.byteOffset, 4 * mesh.triangles.length).copy(meshBin, 8 + 8 * mesh.positions.length);
  const pointsBin = Buffer.alloc(4 + 20 * points.length);
  pointsBin.writeInt32LE(points.length, 0);
  points.forEach((p, i) => {
    pointsBin.writeInt32LE(p.face, 4 + 20 * i);
    pointsBin.writeDoubleLE(p.uv[0], 8 + 20 * i);
    pointsBin.writeDoubleLE(p.uv[1], 16 + 20 * i);
  });
  // The search's landmarks and the guide's triangles (mesh vertex indices), as SurfaceMesh chooses
  // and builds them: int32 landmarks, int32 #faces, then 3 indices per face.
  const guide = mesh.faceCount >= GUIDE_MIN_FACES ? guideTriangles(mesh.positions, mesh.triangles) : null;
  const guideBin = Buffer.alloc(8 + 4 * (guide?.length ?? 0));
  guideBin.writeInt32LE(guide ? GUIDED_LANDMARKS : DEFAULT_LANDMARKS, 0);
  guideBin.writeInt32LE(guide ? guide.length / 3 : 0, 4);
  if (guide) Buffer.from(Int32Array.from(guide).buffer).copy(guideBin, 8);
  mesh.dispose();
  writeFileSync(join(out, 'guide.bin'), guideBin);
  writeFileSync(join(out, 'mesh.bin'), meshBin);
  writeFileSync(join(out, 'points.bin'), pointsBin);
  const r = JSON.parse(run('node', ['--no-experimental-fetch', module, join(out, 'mesh.bin'), join(out, 'points.bin'), String(curves), values.rounds, join(out, 'guide.bin')]));
  const change = (r.median_ratio - 1) * 100;
  console.log(`${file}${guide ? ` (guide of ${guide.length / 3} faces)` : ''}: median ${r.median_a_ms.toFixed(2)} -> ${r.median_b_ms.toFixed(2)} ms; per curve B/A median ${r.median_ratio.toFixed(3)} ` +
    `(${change >= 0 ? '+' : ''}${change.toFixed(1)}%), total ${r.total_ratio.toFixed(3)}; mean length ${r.mean_length_a.toFixed(5)} -> ` +
    `${r.mean_length_b.toFixed(5)}, ${r.curves_changed} of ${r.curves} curves changed`);
}
