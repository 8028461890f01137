// Skinning benchmarks (imported by bench/run.mjs): speed on the largest drawing and accuracy of
// the fit against the paper's baselines on every shared character.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { SkinRig, SkinWeights, buildDomain, domainWeights, memory, outlineSamples, parseSVG } from '../dist/index.js';
import { mulberry32 } from '../dist/core/random.js';

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

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
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
