// Localized editing benchmarks (imported by bench/run.mjs; `node bench/run.mjs --only=edit`):
// one drag update on a 10,000-point Catmull-Rom curve and the capture of a 2,000-sample stroke,
// through the package as an embedder calls it (wasm in Node). Medians after warm-up.
import { CatmullRom, LocalEdit, memory } from '../dist/index.js';
import { median } from './stats.mjs';


/** Median ms per call of fn, timed in batches of `batch` calls (sub-microsecond calls need it). */
function perCall(fn, batches = 200, batch = 50, warmup = 20) {
  for (let i = 0; i < warmup * batch; i++) fn(i);
  const t = [];
  let k = 0;
  for (let b = 0; b < batches; b++) {
    const t0 = performance.now();
    for (let i = 0; i < batch; i++) fn(k++);
    t.push((performance.now() - t0) / batch);
  }
  return median(t);
}

/** Median ms of fn over `repeats` runs after `warmup` runs. */
function time(fn, repeats, warmup = 5) {
  for (let i = 0; i < warmup; i++) fn();
  const t = [];
  for (let i = 0; i < repeats; i++) {
    const t0 = performance.now();
    fn();
    t.push(performance.now() - t0);
  }
  return median(t);
}

/** A pen stroke of n samples: a wandering wave drawn at varying speed, with pressure and time. */
function stroke(n) {
  const samples = [];
  for (let i = 0; i < n; i++) {
    const t = i / (n - 1), s = t + 0.15 * Math.sin(9 * t); // speed varies along the stroke
    samples.push({ x: 1000 * s, y: 120 * Math.sin(14 * s) + 30 * Math.sin(51 * s), pressure: 0.3 + 0.5 * t, time: 4 * i });
  }
  return samples;
}

export function editBenchmarks() {
  const out = {};
  // ---- drag updates on a 10,000-point curve ----------------------------------------------------
  const curve = CatmullRom.fromStroke(stroke(10000), { resample: true });
  out.points = curve.count;
  const center = 5000;
  const drag = (options) => {
    const beginMs = time(() => LocalEdit.begin(curve, center, options).dispose(), 20);
    const e = LocalEdit.begin(curve, center, options);
    const update = perCall((i) => e.move(3 * Math.sin(i * 0.01), 2 * Math.cos(i * 0.013)));
    const heap = memory();
    for (let i = 0; i < 1000; i++) e.move(i * 0.01, -i * 0.02);
    const after = memory();
    const moveApply = perCall((i) => {
      e.move(Math.sin(i * 0.01), 1);
      e.apply();
    }, 50, 10, 5);
    e.cancel();
    return { window: e.window.indices.length, begin_ms: beginMs, update_ms: update, move_and_apply_ms: moveApply, heap_grew_by: after.heap - heap.heap, malloc_grew_by: after.used - heap.used };
  };
  out.plain = drag({ left: 0, right: 0 });
  out.window100 = drag({ left: 50, right: 50 });
  out.window100_normals = drag({ left: 50, right: 50, normals: true });
  out.whole = drag({ left: 10000, right: 10000 });
  out.whole_normals = drag({ left: 10000, right: 10000, normals: true });
  out.to_bezier_ms = time(() => curve.toBezier(), 20);
  curve.dispose();

  // ---- sketch capture of a 2,000-sample stroke -------------------------------------------------
  const samples = stroke(2000);
  out.capture_samples = samples.length;
  out.capture_ms = time(() => CatmullRom.fromStroke(samples).dispose(), 50);
  out.capture_resample_ms = time(() => CatmullRom.fromStroke(samples, { resample: true }).dispose(), 50);
  return out;
}

/** The BENCHMARKS.md section for editBenchmarks. */
export function editSection(r, { date, machine, load }) {
  const f = (x, d = 4) => x.toFixed(d);
  const row = (label, k) => `| ${label} | ${k.window} | ${f(k.begin_ms, 3)} | **${f(k.update_ms)}** | ${f(k.move_and_apply_ms, 3)} | ${k.heap_grew_by} / ${k.malloc_grew_by} |`;
  return `## Edit (Eyiyurekli & Breen: localized editing of Catmull-Rom splines)

Measured by \`node bench/run.mjs --only=edit\` (bench/edit.mjs) on ${date}, load ${load}.
Machine: ${machine}. wasm in Node through the package (CatmullRom, LocalEdit), medians after warm-up.

One drag update (\`LocalEdit.move\`: every window point placed from the positions at begin) on a
${r.points}-point centripetal curve (a 10,000-sample stroke resampled evenly), dragging point 5000.
Updates are timed in batches of 50 calls; "begin" fixes the window, arc lengths and weights; "move
+ apply" also hands the points to the curve, which recomputes its tangents (what the editor does
per pointer move to draw the curve mid-drag).

| window | points in it | begin ms | update ms | move + apply ms | heap / malloc bytes grown by 1,000 updates |
|---|---:|---:|---:|---:|---:|
${row('none (a plain control-point move)', r.plain)}
${row('50 + 50, cosine', r.window100)}
${row('50 + 50, cosine, normals (§3.4)', r.window100_normals)}
${row('whole curve, cosine', r.whole)}
${row('whole curve, cosine, normals', r.whole_normals)}

Budget: one drag update on a 10,000-point curve ≤ 0.1 ms, in every row, the whole-curve window with
normals included: there every point turns by its own angle, carried from point to point by small
rotation steps (a short series, an exact sine and cosine every 64 points) rather than a sine and a
cosine per point. The plain move is the baseline: a window of 100 costs about as much as moving one
point through the API. The exact Bézier form of the whole curve (\`toBezier\`, copied out of wasm):
${f(r.to_bezier_ms, 3)} ms.

Sketch capture of a ${r.capture_samples}-sample pen stroke (\`CatmullRom.fromStroke\`: samples with pressure and
time into wasm, repeats dropped, the curve built): **${f(r.capture_ms, 3)} ms**; with §3.2's even
resampling by arc length (same count): **${f(r.capture_resample_ms, 3)} ms**. Budget ≤ 2 ms.
`;
}
