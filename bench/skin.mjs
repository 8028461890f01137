// Skinning benchmarks (imported by bench/run.mjs): speed on the largest drawing and accuracy of
// the fit against the paper's baselines on every shared character.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { SkinRig, SkinWeights, SplineSet, buildDomain, domainWeights, memory, outlineSamples, parseSVG } from '../dist/index.js';
import { mulberry32 } from '../dist/core/random.js';
import { farthestPoints } from '../dist/core/farthest-points.js';
import { median } from './stats.mjs';

/** `count` handles spread over the artwork: farthest-point sampling of on-curve points. */
export function spreadHandles(doc, count) {
  const pts = [];
  for (const s of doc.splines) for (let i = 0; i < s.points.length; i += 6) pts.push([s.points[i], s.points[i + 1]]);
  const [x0, y0, x1] = doc.bounds;
  let first = 0, best = Infinity;
  pts.forEach((p, i) => {
    const d = Math.hypot(p[0] - (x0 + x1) / 2, p[1] - y0); // start near the top centre
    if (d < best) {
      best = d;
      first = i;
    }
  });
  const chosen = [pts[first]];
  const dist = pts.map((p) => Math.hypot(p[0] - pts[first][0], p[1] - pts[first][1]));
  while (chosen.length < count) {
    let k = 0;
    dist.forEach((d, i) => { if (d > dist[k]) k = i; });
    chosen.push(pts[k]);
    pts.forEach((p, i) => { dist[i] = Math.min(dist[i], Math.hypot(p[0] - pts[k][0], p[1] - pts[k][1])); });
  }
  return chosen.map(([x, y]) => ({ x, y }));
}

/** A random pose: each handle rotates about itself by up to ±maxDeg. */
export function randomPose(handles, random, maxDeg = 60) {
  return handles.map((h) => {
    const a = ((random() * 2 - 1) * maxDeg * Math.PI) / 180, c = Math.cos(a), s = Math.sin(a);
    return [c, s, -s, c, h.x - (c * h.x - s * h.y), h.y - (s * h.x + c * h.y)];
  });
}


export function skinSpeed(data, time) {
  const rel = 'svg/illustrations/oc_road_runner_car.svg';
  const doc = parseSVG(readFileSync(join(data, rel), 'utf8'));
  const handles = spreadHandles(doc, 4);
  const pose = randomPose(handles, mulberry32(1));
  const precompute = [];
  let rig;
  for (let i = 0; i < 3; i++) {
    rig?.dispose();
    const t0 = performance.now();
    rig = SkinRig.create(doc, { handles });
    precompute.push(performance.now() - t0);
  }
  const flat = new Float64Array(pose.flat());
  const update = time(() => rig.pose(flat), 100, 10);
  const before = memory().used;
  for (let i = 0; i < 1000; i++) rig.pose(flat);
  const allocated = memory().used - before;
  const relax = [];
  for (let i = 0; i < 3; i++) {
    rig.pose(flat);
    const t0 = performance.now();
    rig.relax();
    relax.push(performance.now() - t0);
  }
  const result = { file: rel, curves: rig.curveCount, handles: 4, precompute_ms: median(precompute), update_ms: update, relax_ms: median(relax), bytes_allocated_by_1000_updates: allocated };
  rig.dispose();
  return result;
}

export function skinAccuracy(data, poses = 5) {
  const dir = join(data, 'svg/characters');
  const rows = [];
  for (const f of readdirSync(dir).filter((f) => f.endsWith('.svg')).sort()) {
    const doc = parseSVG(readFileSync(join(dir, f), 'utf8'));
    const diag = doc.size;
    for (const count of [4, 8]) {
      const handles = spreadHandles(doc, count);
      const rig = SkinRig.create(doc, { handles });
      const random = mulberry32(count * 1000 + f.length);
      const sums = { fit: 0, naive: 0, interpolated: 0, jacobian: 0 };
      for (let p = 0; p < poses; p++) {
        rig.pose(randomPose(handles, random));
        for (const m of Object.keys(sums)) sums[m] += rig.error(m).rms / diag;
      }
      for (const m of Object.keys(sums)) sums[m] /= poses;
      rows.push({ file: f, handles: count, ...sums, naive_over_fit: sums.naive / sums.fit });
      rig.dispose();
    }
  }
  return rows;
}

/** BBW and harmonic weights on a ~20k-triangle domain of the road runner with 8 handles. */
export function skinWeightsSpeed(data) {
  const rel = 'svg/illustrations/oc_road_runner_car.svg';
  const doc = parseSVG(readFileSync(join(data, rel), 'utf8'));
  const handles = spreadHandles(doc, 8);
  const out = { file: rel, handles: 8 };
  let t0 = performance.now();
  const domain = buildDomain(outlineSamples(doc), handles, { targetTriangles: 20000 });
  out.domain_ms = performance.now() - t0;
  out.triangles = domain.triangles.length / 3;
  for (const kind of ['harmonic', 'bbw']) {
    const solves = [];
    for (let i = 0; i < 3; i++) {
      t0 = performance.now();
      SkinWeights.solve(domain, kind).dispose();
      solves.push(performance.now() - t0);
    }
    out[`${kind}_solve_ms`] = median(solves);
    t0 = performance.now();
    domainWeights(doc, handles, kind, { targetTriangles: 20000 });
    out[`${kind}_total_ms`] = performance.now() - t0;
  }
  return out;
}

/**
 * Median wall-clock and CPU ms (user + system, this process) of `repeats` runs of fn (each given
 * the run's index), with the last run's result. On a shared machine the CPU time is the steadier.
 */
function timed(fn, repeats) {
  const wall = [], cpu = [];
  let last;
  for (let i = 0; i < repeats; i++) {
    const c0 = process.cpuUsage(), t0 = performance.now();
    last = fn(i);
    wall.push(performance.now() - t0);
    const used = process.cpuUsage(c0);
    cpu.push((used.user + used.system) / 1000);
  }
  return { ms: median(wall), cpu_ms: median(cpu), last };
}

/**
 * Cost of automatic weights step by step, on the curve samples of oc_dog.svg (8 per segment)
 * with 8 handles spread over them, a ~20k-triangle domain (formerly printed by the unit tests):
 * building the domain, harmonic and BBW weights, and evaluating the BBW weights at 1M points.
 * Medians of `repeats` runs, each step warmed up first, as wall-clock and CPU time; ratios to the
 * harmonic solve of the same run, in CPU time (the machines are shared: wall time includes
 * waiting for a core, CPU time does not; a CPU / wall ratio above 1 would mean threads).
 */
export function skinWeightSteps(data, repeats = 3) {
  const rel = 'svg/characters/oc_dog.svg';
  const doc = parseSVG(readFileSync(join(data, rel), 'utf8'));
  const set = SplineSet.from(doc.splines);
  const samples = set.sample(8);
  set.dispose();
  const handles = farthestPoints(samples, 8);
  const small = buildDomain(samples, handles, { targetTriangles: 500 });
  SkinWeights.harmonic(small).dispose(); // warm-up of the solver paths
  SkinWeights.bbw(small).dispose();
  buildDomain(samples, handles, { targetTriangles: 20000 });
  const domain = timed(() => buildDomain(samples, handles, { targetTriangles: 20000 }), repeats);
  const big = domain.last;
  const harmonic = timed(() => SkinWeights.harmonic(big).dispose(), repeats);
  const bbw = timed((i) => {
    const w = SkinWeights.bbw(big);
    if (i < repeats - 1) w.dispose();
    return w;
  }, repeats);
  const weights = bbw.last;
  const points = 1_000_000;
  const query = new Float64Array(2 * points);
  for (let k = 0; k < query.length; k++) query[k] = samples[k % samples.length];
  const out = new Float64Array(points * 8);
  weights.weightsAt(query, out);
  const interpolate = timed(() => weights.weightsAt(query, out), repeats);
  const steps = { domain, harmonic, bbw, weights_at_1M_points: interpolate };
  const result = {
    file: rel,
    handles: 8,
    samples: samples.length / 2,
    triangles: big.triangles.length / 3,
    vertices: big.vertices.length / 2,
    repeats,
    bbw_solves_per_handle: Array.from(weights.iterations),
    bbw_converged: weights.converged,
    bbw_pinned: weights.pinned,
  };
  weights.dispose();
  for (const [name, t] of Object.entries(steps)) {
    result[`${name}_ms`] = t.ms;
    result[`${name}_cpu_ms`] = t.cpu_ms;
    result[`${name}_over_harmonic`] = t.cpu_ms / harmonic.cpu_ms;
  }
  result.weights_at_ns_per_point = (interpolate.cpu_ms * 1e6) / points;
  return result;
}

/** The subsection of BENCHMARKS.md's skinning section for skinWeightSteps. */
export function skinWeightStepsSection(r, { date, machine, load }) {
  const f = (x, d = 0) => x.toFixed(d);
  const row = (label, key) => `| ${label} | ${f(r[`${key}_ms`])} | ${f(r[`${key}_cpu_ms`])} | ${f(r[`${key}_over_harmonic`], 1)} |`;
  return `### Automatic weights step by step (${r.file.replace('svg/', '')})

Measured by bench/skin.mjs (skinWeightSteps) on ${date} (${machine}; load average ${load} at the end): the ${r.samples} curve samples of
${r.file.replace('svg/', '')} (8 per segment), ${r.handles} handles spread over them (farthest points), a
${r.triangles}-triangle domain (${r.vertices} vertices). Medians of ${r.repeats} runs after a warm-up; the ratio is
of CPU times (on a shared machine the wall clock also counts the wait for a core):

| step | wall ms | CPU ms | CPU / harmonic |
|---|---:|---:|---:|
${row('domain (triangulation)', 'domain')}
${row('harmonic weights', 'harmonic')}
${row('BBW weights', 'bbw')}
${row('BBW weights at 1M points (weightsAt, 8 weights each)', 'weights_at_1M_points')}

BBW: ${r.bbw_solves_per_handle.join(' ')} solves per handle, converged ${r.bbw_converged}, ${r.bbw_pinned} vertices pinned to a bound;
weightsAt ${f(r.weights_at_ns_per_point, 0)} ns of CPU per point.
`;
}
