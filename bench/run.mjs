#!/usr/bin/env node
// `npm run bench`: speed of the foundation on ../shared/data, as medians after warm-up, printed as
// a table and written to build/bench/results.json and BENCHMARKS.md (with machine and date).
// Ratios compare work done in the same run: wasm vs native for the core kernels.
//
// `node bench/run.mjs --only=<section>[,<section>]` runs only the named sections (editor,
// editor-drag, fidelity, skin-weight-steps, edit, morph, skin3d, surface, surface-scale) and replaces just their text in BENCHMARKS.md (and their entries in
// build/bench/results.json), leaving the rest as the last full run wrote it.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { SplineSet, init, memory, parseSVG } from '../dist/index.js';
import { editBenchmarks, editSection } from './edit.mjs';
import { editorBenchmarks, editorSection } from './editor.mjs';
import { dragBenchmarks, dragSection } from './editor-drag.mjs';
import { fidelityFigures, fidelitySection } from './fidelity.mjs';
import { morphBenchmarks, morphSection } from './morph.mjs';
import { skinAccuracy, skinSpeed, skinWeightSteps, skinWeightStepsSection, skinWeightsSpeed } from './skin.mjs';
import { skin3dBenchmarks, skin3dSection } from './skin3d.mjs';
import { surfaceBenchmarks, surfaceSection } from './surface.mjs';
import { surfaceScaleBenchmarks, surfaceScaleSection } from './surface-scale.mjs';
import { time } from './stats.mjs';

const root = new URL('..', import.meta.url).pathname;
const data = join(root, '../shared/data');
mkdirSync(join(root, 'build/bench'), { recursive: true });



await init();

const machine = `${os.cpus()[0]?.model ?? 'unknown CPU'}, ${os.cpus().length} cores, ${(os.totalmem() / 2 ** 30).toFixed(0)} GiB, Node ${process.version}, ${os.platform()} ${os.release()}`;
const date = new Date().toISOString().slice(0, 10);
/** The machine's 1-minute load average now, for sections that say how busy the machine was. */
const load = () => os.loadavg()[0].toFixed(1);

/**
 * Sections that can run alone (--only): each writes its own part of BENCHMARKS.md, found again by
 * its heading (up to the next heading of the same or a higher level), and its key in results.json.
 */
const sections = {
  editor: { key: 'editor', heading: '## Editor (Chromium)', before: '## Memory and size', run: () => editorBenchmarks(root, data, { log: console.log }), markdown: editorSection },
  fidelity: { key: 'fidelity', heading: '## Editor fidelity (Chromium)', before: '## Memory and size', run: () => fidelityFigures(root), markdown: fidelitySection },
  'editor-drag': { key: 'editor_drag', heading: '## Dragging in the editor (Chromium)', before: '## Memory and size', run: () => dragBenchmarks(root, data, { log: console.log }), markdown: dragSection },
  edit: { key: 'edit', heading: '## Edit (', before: '## Memory and size', run: () => editBenchmarks(), markdown: editSection },
  'skin-weight-steps': { key: 'skin_weight_steps', heading: '### Automatic weights step by step', before: '## Surface', run: () => skinWeightSteps(data), markdown: skinWeightStepsSection },
  morph: { key: 'morph', heading: '## Morph', before: '## Editor (Chromium)', run: () => morphBenchmarks(data), markdown: morphSection },
  skin3d: { key: 'skin3d', heading: '## Skin 3D', before: '## Surface', run: () => skin3dBenchmarks(data), markdown: skin3dSection },
  surface: { key: 'surface', heading: '## Surface (b/Surf)', before: '## Surface at scale', run: () => surfaceBenchmarks(root, data, { log: console.log }), markdown: surfaceSection },
  'surface-scale': { key: 'surface_scale', heading: '## Surface at scale', before: '## Morph', run: () => surfaceScaleBenchmarks(root, data, { log: console.log }), markdown: surfaceScaleSection },
};

/**
 * Replaces the part of `md` under the heading that starts with `heading` by `text`; a section
 * the file does not have yet goes where the full run puts it, before the heading `before`.
 */
function spliceSection(md, { heading, before }, text) {
  const lines = md.split('\n');
  const level = heading.indexOf(' ');
  let start = lines.findIndex((l) => l.startsWith(heading)), end = start + 1;
  if (start < 0) {
    start = end = lines.findIndex((l) => l.startsWith(before));
    if (start < 0) throw new Error(`BENCHMARKS.md has neither "${heading}" nor "${before}": run the full benchmark once`);
  } else {
    while (end < lines.length && !(/^#+ /.test(lines[end]) && lines[end].indexOf(' ') <= level)) end++;
  }
  return [...lines.slice(0, start), ...text.replace(/\n$/, '').split('\n'), '', ...lines.slice(end)].join('\n');
}

const only = process.argv.find((a) => a.startsWith('--only='))?.slice('--only='.length).split(',');
if (only) {
  for (const name of only) if (!sections[name]) throw new Error(`unknown section "${name}" (known: ${Object.keys(sections).join(', ')})`);
  let md = readFileSync(join(root, 'BENCHMARKS.md'), 'utf8');
  const resultsFile = join(root, 'build/bench/results.json');
  const results = existsSync(resultsFile) ? JSON.parse(readFileSync(resultsFile, 'utf8')) : {};
  for (const name of only) {
    const section = sections[name];
    const result = { ...(await section.run()), load: load() };
    console.log(`${name}: ${JSON.stringify(result)}`);
    results[section.key] = { date, machine, ...result };
    md = spliceSection(md, section, section.markdown(result, { date, machine, load: result.load }));
  }
  writeFileSync(resultsFile, `${JSON.stringify(results, null, 2)}\n`);
  writeFileSync(join(root, 'BENCHMARKS.md'), md);
  console.log(`wrote the ${only.join(', ')} section(s) of BENCHMARKS.md and build/bench/results.json`);
  process.exit(0);
}

// ---- import / export of every shared SVG ------------------------------------------------------
const files = [];
for (const dir of readdirSync(join(data, 'svg')).sort()) {
  for (const f of readdirSync(join(data, 'svg', dir)).sort()) if (f.endsWith('.svg')) files.push(`svg/${dir}/${f}`);
}
const rows = [];
for (const rel of files) {
  const text = readFileSync(join(data, rel), 'utf8');
  const t0 = performance.now();
  const doc = parseSVG(text, { name: rel });
  const cold = performance.now() - t0;
  const stats = doc.stats();
  const repeats = stats.segments > 5000 ? 15 : stats.segments > 1000 ? 25 : 50;
  const importMs = time(() => parseSVG(text, { name: rel }), repeats);
  const exportMs = time(() => doc.toSVG({ rewrite: 'all' }), repeats);
  rows.push({ file: rel, kB: text.length / 1024, elements: stats.elements, segments: stats.segments, cold_ms: cold, import_ms: importMs, export_ms: exportMs, segments_per_ms: stats.segments / importMs });
}

// ---- core kernels: wasm (through SplineSet) vs native, on the largest drawing -----------------
const bigRel = 'svg/illustrations/oc_road_runner_car.svg';
const big = parseSVG(readFileSync(join(data, bigRel), 'utf8'));
const set = SplineSet.from(big.splines);
const wasm = {
  bounds_ms: time(() => set.bounds(), 50),
  classify_ms: time(() => set.classify(big.size), 50),
  sample16_ms: time(() => set.sample(16), 50),
};
set.dispose();
const points = big.splines.reduce((n, s) => n + s.points.length / 2, 0);
const header = new Int32Array([big.splines.length, points]);
const meta = new Int32Array(3 * big.splines.length);
const coords = new Float64Array(2 * points);
let at = 0;
big.splines.forEach((s, i) => {
  meta[i] = at;
  meta[big.splines.length + i] = s.points.length / 2;
  meta[2 * big.splines.length + i] = s.closed ? 1 : 0;
  coords.set(s.points, 2 * at);
  at += s.points.length / 2;
});
const dump = join(root, 'build/bench/roadrunner-splines.bin');
writeFileSync(dump, Buffer.concat([Buffer.from(header.buffer), Buffer.from(meta.buffer), Buffer.from(coords.buffer)]));
const native = JSON.parse(execFileSync(join(root, 'build/native/spline_bench'), [dump, '50'], { encoding: 'utf8' }));

// ---- memory and module size -------------------------------------------------------------------
const text = readFileSync(join(data, bigRel), 'utf8');
parseSVG(text);
const before = memory().used;
for (let i = 0; i < 20; i++) parseSVG(text);
const leak = memory().used - before;
const moduleText = readFileSync(join(root, 'dist/core/splinekit-core.mjs'));
const wasmBase64 = /data:application\/octet-stream;base64,([A-Za-z0-9+/=]+)/.exec(moduleText.toString())?.[1] ?? '';
const wasmBytes = Buffer.from(wasmBase64, 'base64');
const size = {
  module_kB: moduleText.length / 1024,
  module_gzip_kB: gzipSync(moduleText).length / 1024,
  wasm_kB: wasmBytes.length / 1024,
  wasm_gzip_kB: gzipSync(wasmBytes).length / 1024,
};

// ---- skinning ---------------------------------------------------------------------------------
const skin = skinSpeed(data, time);
const accuracy = skinAccuracy(data);
const weightsSpeed = skinWeightsSpeed(data);
const weightSteps = { ...skinWeightSteps(data), load: load() };
console.log(`skin weight steps: ${JSON.stringify(weightSteps)}`);

// ---- skinning subdivision surfaces (3D) ----------------------------------------------------------
const skin3d = { ...skin3dBenchmarks(data), load: load() };
console.log(`skin3d: ${JSON.stringify(skin3d.speed)}`);

// ---- the editor in Chromium -------------------------------------------------------------------
const editor = { ...(await editorBenchmarks(root, data, { log: console.log })), load: load() };
const drag = { ...(await dragBenchmarks(root, data, { log: console.log })), load: load() };
const fidelity = fidelityFigures(root);

// ---- localized editing (Catmull-Rom) ----------------------------------------------------------
const edit = { ...editBenchmarks(), load: load() };
console.log(`edit: ${JSON.stringify(edit)}`);

// ---- surface (b/Surf) -------------------------------------------------------------------------
const surface = await surfaceBenchmarks(root, data, { log: console.log });
const surfaceScale = await surfaceScaleBenchmarks(root, data, { log: console.log });

// ---- morph (Sederberg & Greenwood) vs flubber ---------------------------------------------------
const morph = morphBenchmarks(data);
console.log(`morph: ${JSON.stringify(morph.speed)}`);

// ---- report -----------------------------------------------------------------------------------
const results = { date, machine, svg: rows, skin: { speed: skin, accuracy, weights: weightsSpeed }, skin_weight_steps: weightSteps, skin3d, editor, morph, editor_drag: drag, fidelity, edit, surface, surface_scale: surfaceScale, kernels: { file: bigRel, splines: big.splines.length, segments: big.stats().segments, wasm, native }, memory: { leak_bytes_after_20_parses: leak }, size };
writeFileSync(join(root, 'build/bench/results.json'), `${JSON.stringify(results, null, 2)}\n`);

const f = (x, d = 2) => x.toFixed(d);
const table = [
  '| file | kB | elements | segments | import ms (cold) | import ms | export ms | segments/ms |',
  '|---|---:|---:|---:|---:|---:|---:|---:|',
  ...rows.map((r) => `| ${r.file.replace('svg/', '')} | ${f(r.kB, 1)} | ${r.elements} | ${r.segments} | ${f(r.cold_ms, 1)} | ${f(r.import_ms)} | ${f(r.export_ms)} | ${f(r.segments_per_ms, 0)} |`),
];
const kernelTable = [
  '| kernel (all splines at once) | wasm ms | native ms | wasm / native |',
  '|---|---:|---:|---:|',
  ...Object.keys(wasm).map((k) => `| ${k.replace('_ms', '')} | ${f(wasm[k], 3)} | ${f(native[k], 3)} | ${f(wasm[k] / native[k])} |`),
];
const bigRow = rows.find((r) => r.file === bigRel);
const e = (x) => x.toExponential(2);
const accuracyTable = [
  '| character | handles | fit | all control points | interpolated | Jacobian | all / fit |',
  '|---|---:|---:|---:|---:|---:|---:|',
  ...accuracy.map((r) => `| ${r.file} | ${r.handles} | ${e(r.fit)} | ${e(r.naive)} | ${e(r.interpolated)} | ${e(r.jacobian)} | ${f(r.naive_over_fit, 1)} |`),
];
const meanRatio = accuracy.reduce((n, r) => n + r.naive_over_fit, 0) / accuracy.length;
const worstRatio = Math.min(...accuracy.map((r) => r.naive_over_fit));
const geoRatio = Math.exp(accuracy.reduce((n, r) => n + Math.log(r.naive_over_fit), 0) / accuracy.length);
const md = `# Benchmarks

Measured by \`npm run bench\` (bench/run.mjs) on ${date}.
Machine: ${machine}.
Times are medians over repeated runs after 3 warm-up runs (15–50 runs by file size), wasm in Node;
"cold" is the first import in the process (JIT not warmed). Raw numbers: build/bench/results.json.

## SVG import and export (every file in ../shared/data/svg)

Import = parseSVG: XML parse, path data, transforms, styles, splines, bounds and continuity in wasm.
Export = toSVG({ rewrite: 'all' }): every shape written back as a path.

${table.join('\n')}

Budget: the largest file (${bigRel.replace('svg/', '')}, ${bigRow.segments} segments) imports in
≤ 300 ms: **${f(bigRow.import_ms, 1)} ms** warm, ${f(bigRow.cold_ms, 1)} ms cold.

## Core kernels, wasm vs native (same splines: ${big.splines.length} splines, ${big.stats().segments} segments of ${bigRel.replace('svg/', '')})

The wasm column goes through the TS wrapper (SplineSet: validation and copy of the result out of
wasm memory included); native calls the same C++ functions directly (bench/native/spline_bench.cpp).

${kernelTable.join('\n')}

## Skinning (Liu, Jacobson & Gingold 2014)

Speed on ${skin.file.replace('svg/', '')} (${skin.curves} curves), ${skin.handles} handles, Shepard weights, 100 samples per curve:

| precompute ms | update ms | flexible relax ms | bytes allocated by 1,000 updates |
|---:|---:|---:|---:|
| ${f(skin.precompute_ms, 0)} | ${f(skin.update_ms, 3)} | ${f(skin.relax_ms, 0)} | ${skin.bytes_allocated_by_1000_updates} |

Budgets: precompute ≤ 1 s, update ≤ 2 ms, relax ≤ 300 ms (the paper, Python, 9.5k curves: 42 s, 0.1 s, 16 s).

Automatic weights on the same drawing, ${weightsSpeed.handles} handles, a ${weightsSpeed.triangles}-triangle domain (built in
${f(weightsSpeed.domain_ms, 0)} ms). Solve alone (median of 3): harmonic **${f(weightsSpeed.harmonic_solve_ms, 0)} ms**,
BBW **${f(weightsSpeed.bbw_solve_ms, 0)} ms** (budget for BBW on 20k triangles with 8 handles: 5 s). End to end
(domain, solve, evaluation at the ${skin.curves * 100} curve samples and the control points): harmonic
${f(weightsSpeed.harmonic_total_ms, 0)} ms, BBW ${f(weightsSpeed.bbw_total_ms, 0)} ms.

Accuracy on every shared character: handles spread over the artwork (farthest points), 5 random
poses each (every handle rotated about itself by up to ±60°), Shepard weights. RMS distance to
the linear-blend-skinned target, integrated along the curves, over the bounding-box diagonal
(mean over the poses), for the fit and the paper's three baselines:

${accuracyTable.join('\n')}

All control points / fit: **${f(meanRatio, 1)}×** on average (geometric mean ${f(geoRatio, 1)}×), **${f(worstRatio, 1)}×** at worst
(the fit must beat that baseline on every file and by ≥ 2× on average).

${skinWeightStepsSection(weightSteps, { date, machine, load: weightSteps.load })}
${skin3dSection(skin3d, { date, machine, load: skin3d.load })}
${surfaceSection(surface)}
${surfaceScaleSection(surfaceScale, { date, machine })}
${morphSection(morph, { date, machine, load: load() })}
${editorSection(editor, { date, machine, load: editor.load })}
${dragSection(drag, { date, machine, load: drag.load })}
${fidelitySection(fidelity, { date, machine })}
${editSection(edit, { date, machine, load: edit.load })}
## Memory and size

- malloc'd bytes in the wasm heap after 20 more imports of ${bigRel.replace('svg/', '')}: **${leak}** more than before (0 = nothing leaked).
- Module (dist/core/splinekit-core.mjs, wasm inlined as base64): ${f(size.module_kB, 1)} kB, ${f(size.module_gzip_kB, 1)} kB gzipped;
  the wasm itself: ${f(size.wasm_kB, 1)} kB, ${f(size.wasm_gzip_kB, 1)} kB gzipped (budget 1.5 MB / 500 kB).
`;
writeFileSync(join(root, 'BENCHMARKS.md'), md);
console.log(table.join('\n'));
console.log();
console.log(kernelTable.join('\n'));
console.log(`\nleak after 20 imports: ${leak} bytes; module ${f(size.module_kB, 1)} kB (${f(size.module_gzip_kB, 1)} kB gz), wasm ${f(size.wasm_kB, 1)} kB (${f(size.wasm_gzip_kB, 1)} kB gz)`);
console.log(`\nskin: ${JSON.stringify(skin)}`);
console.log(accuracyTable.join('\n'));
console.log(`all/fit: mean ${f(meanRatio, 2)}x, geometric ${f(geoRatio, 2)}x, worst ${f(worstRatio, 2)}x`);
console.log('wrote BENCHMARKS.md and build/bench/results.json');
