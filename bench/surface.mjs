// Surface benchmarks (b/Surf; imported by bench/run.mjs): validity of traced curves on every shared
// mesh, per-curve trace time and dragging speed against the interactive budgets (wasm in Node), and
// locally shortest paths against the exact geodesic distance with memory and precompute time
// (native, bench/native/surface_bench.cpp).
import { execFileSync } from 'node:child_process';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import os from 'node:os';
import { join } from 'node:path';
import { SurfaceMesh, SurfaceSpline, randomMeshPoints, traceBezier } from '../dist/index.js';
import { mulberry32 as generator } from '../dist/core/random.js';

const randomPoints = randomMeshPoints; // the same polygons as `splinekit trace --random`

export function percentile(xs, p) {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.max(0, Math.ceil(p * s.length) - 1))];
}

/** The shared meshes (top level of ../shared/data/meshes), smallest file first. */
export function sharedMeshes(data) {
  const dir = join(data, 'meshes');
  return readdirSync(dir)
    .filter((f) => /\.(obj|ply|off|stl|gltf|glb)$/i.test(f) && statSync(join(dir, f)).isFile())
    .sort((a, b) => statSync(join(dir, a)).size - statSync(join(dir, b)).size);
}

export async function loadMesh(data, file) {
  const t0 = performance.now();
  const mesh = await SurfaceMesh.load(readFileSync(join(data, 'meshes', file)), file);
  return { mesh, load_ms: performance.now() - t0 };
}

// ---- (1) validity ---------------------------------------------------------------------------------

export const CONFIGS = [
  { key: 'olr', label: 'OLR uniform (5 levels)', options: { scheme: 'olr' } },
  { key: 'olr_adaptive', label: 'OLR adaptive 5°', options: { scheme: 'olr', adaptive: 5 } },
  { key: 'rdc', label: 'RDC uniform (4 levels)', options: { scheme: 'rdc' } },
  { key: 'rdc_adaptive', label: 'RDC adaptive 5°', options: { scheme: 'rdc', adaptive: 5 } },
];

/**
 * Continuity checker in file space. A point's support is the set of its face's vertices with a
 * nonzero barycentric weight; two points share a face when they lie on the same face or the support
 * of one is contained in the other's face. Vertices at the same position count as one (the core
 * welds them), so the check does not depend on how the file splits vertices.
 */
export function continuityChecker(mesh, eps = 1e-12) {
  const x = mesh.positions, t = mesh.triangles, nv = x.length / 3;
  const canonical = new Int32Array(nv);
  const seen = new Map();
  for (let v = 0; v < nv; v++) {
    const key = `${x[3 * v]},${x[3 * v + 1]},${x[3 * v + 2]}`;
    const first = seen.get(key);
    if (first === undefined) {
      seen.set(key, v);
      canonical[v] = v;
    } else canonical[v] = first;
  }
  const support = (p) => {
    const w = [1 - p.uv[0] - p.uv[1], p.uv[0], p.uv[1]];
    const out = [];
    for (let k = 0; k < 3; k++) if (Math.abs(w[k]) > eps) out.push(canonical[t[3 * p.face + k]]);
    return out;
  };
  const inFace = (vs, f) => {
    const a = canonical[t[3 * f]], b = canonical[t[3 * f + 1]], c = canonical[t[3 * f + 2]];
    return vs.every((v) => v === a || v === b || v === c);
  };
  return (p, q) => p.face === q.face || inFace(support(p), q.face) || inFace(support(q), p.face);
}

/**
 * Traces `count` random polygons (control points uniform over the area, seed 1) with every
 * configuration. A curve is valid when tracing terminates without error and every pair of
 * consecutive polyline points shares a face. Also checks that the polyline starts at P0 and ends
 * at P3 (within 1e-9 of the bounding-box diagonal).
 */
export function surfaceValidity(mesh, count, seed = 1) {
  const shares = continuityChecker(mesh);
  const points = randomPoints(mesh, 4 * count, seed);
  const tol = 1e-9 * mesh.scale;
  const out = {};
  // Warm-up (wasm tier-up) so that the per-curve times below are representative.
  for (let i = 0; i < Math.min(5, count); i++) traceBezier(mesh, points.slice(4 * i, 4 * i + 4));
  for (const config of CONFIGS) {
    const r = { curves: count, terminated: 0, continuous: 0, valid: 0, ends_interpolated: 0, errors: [], first_break: null };
    const ms = [], sizes = [];
    for (let i = 0; i < count; i++) {
      const controls = points.slice(4 * i, 4 * i + 4);
      let traced;
      try {
        traced = traceBezier(mesh, controls, config.options);
      } catch (err) {
        if (r.errors.length < 5) r.errors.push(`curve ${i}: ${err.message}`);
        continue;
      }
      r.terminated++;
      ms.push(traced.ms);
      sizes.push(traced.points.length);
      let ok = true;
      for (let k = 0; k + 1 < traced.points.length && ok; k++) {
        if (!shares(traced.points[k], traced.points[k + 1])) {
          ok = false;
          r.first_break ??= { curve: i, at: k, a: traced.points[k], b: traced.points[k + 1] };
        }
      }
      if (ok) {
        r.continuous++;
        r.valid++;
      }
      const n = traced.points.length, xyz = traced.xyz;
      const p0 = mesh.xyz(controls[0]), p3 = mesh.xyz(controls[3]);
      const d0 = Math.hypot(xyz[0] - p0[0], xyz[1] - p0[1], xyz[2] - p0[2]);
      const d3 = Math.hypot(xyz[3 * n - 3] - p3[0], xyz[3 * n - 2] - p3[1], xyz[3 * n - 1] - p3[2]);
      if (d0 <= tol && d3 <= tol) r.ends_interpolated++;
    }
    r.valid_pct = (100 * r.valid) / count;
    r.median_ms = ms.length ? percentile(ms, 0.5) : null;
    r.max_ms = ms.length ? Math.max(...ms) : null;
    r.median_points = sizes.length ? percentile(sizes, 0.5) : null;
    out[config.key] = r;
  }
  return out;
}

// ---- (2) per-curve trace time ---------------------------------------------------------------------

/** A unit tangent at p at angle θ in its face's plane (file winding; the sign does not matter). */
function tangentAt(mesh, p, theta) {
  const n = mesh.normal(p);
  const t = mesh.triangles, x = mesh.positions, f = 3 * p.face;
  const a = 3 * t[f], b = 3 * t[f + 1];
  let e = [x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]];
  const d = e[0] * n[0] + e[1] * n[1] + e[2] * n[2];
  e = [e[0] - d * n[0], e[1] - d * n[1], e[2] - d * n[2]];
  const len = Math.hypot(...e) || 1;
  e = e.map((c) => c / len);
  const g = [n[1] * e[2] - n[2] * e[1], n[2] * e[0] - n[0] * e[2], n[0] * e[1] - n[1] * e[0]];
  const c = Math.cos(theta), s = Math.sin(theta);
  return [c * e[0] + s * g[0], c * e[1] + s * g[1], c * e[2] + s * g[2]];
}

/** The end of the straightest geodesic from p at angle θ for `length`. */
function walk(mesh, p, theta, length) {
  if (length <= 0) return p;
  const path = mesh.straightest(p, tangentAt(mesh, p, theta), length);
  return path.points[path.points.length - 1];
}

/**
 * "Moderate" control polygons: a random centre (uniform over the area) and 4 control points at the
 * ends of straightest geodesics from it, in random directions, of random lengths up to
 * `radius` × the bounding-box diagonal: every control point lies in the geodesic disc of that radius.
 */
export function moderatePolygons(mesh, count, seed, radius = 0.05) {
  const random = generator(seed + 1000);
  const centres = randomPoints(mesh, count, seed);
  return centres.map((c) => [0, 1, 2, 3].map(() => walk(mesh, c, 2 * Math.PI * random(), radius * mesh.scale * random())));
}

function stats(ms) {
  return { curves: ms.length, median_ms: percentile(ms, 0.5), p90_ms: percentile(ms, 0.9), p99_ms: percentile(ms, 0.99), max_ms: Math.max(...ms) };
}

/**
 * Per-curve ms (traceBezier's `ms`: the wasm work) of OLR uniform 5 levels, random and moderate
 * polygons. Every list is traced `passes` times over: the first pass as it came, and per curve the
 * best of the passes (the work is identical; the spread is other load on the machine, as for dragging).
 */
export function surfaceTraceSpeed(mesh, count, seed = 1, passes = 3) {
  const points = randomPoints(mesh, 4 * count, seed);
  const random = Array.from({ length: count }, (_, i) => points.slice(4 * i, 4 * i + 4));
  const moderate = moderatePolygons(mesh, count, seed);
  const options = { scheme: 'olr', levels: 5 };
  for (let i = 0; i < 10; i++) traceBezier(mesh, moderate[i % count], options); // warm-up
  const time = (polygons) => {
    const rows = Array.from({ length: passes }, () => polygons.map((p) => traceBezier(mesh, p, options).ms));
    const best = rows[0].map((_, i) => Math.min(...rows.map((r) => r[i])));
    return { ...stats(rows[0]), passes, best: stats(best) };
  };
  return { random: time(random), moderate: time(moderate) };
}

// ---- (3) dragging -----------------------------------------------------------------------------------

/**
 * A moderate 2-segment spline (3 anchors within a 5% disc, straight handles, smooth middle anchor);
 * its middle anchor is dragged by `moves` successive steps of 0.2% of the diagonal along a
 * straightest geodesic (the drag targets are computed beforehand: picking is the viewer's job).
 * Each step is timed as moveAnchor + trace() (wall clock in Node, wrapper included).
 */
export function surfaceDrag(mesh, moves = 60, seed = 3, passes = 3, options = { scheme: 'olr', levels: 5 }) {
  const random = generator(seed);
  const centre = randomPoints(mesh, 1, seed)[0];
  const r = 0.05 * mesh.scale;
  const anchors = [walk(mesh, centre, Math.PI, r * 0.8), centre, walk(mesh, centre, 0.3 * random(), r * 0.8)];
  const spline = SurfaceSpline.fromPolygon(mesh, anchors);
  spline.setSmooth(3, true);
  const targets = [];
  let at = spline.points[3];
  const heading = Math.PI / 2 + 0.5 * random();
  for (let i = 0; i < moves; i++) targets.push((at = walk(mesh, at, heading, 0.002 * mesh.scale)));
  // Warm-up on a copy: the same first moves (the very first one is reported as the cold move).
  const start = spline.toJSON();
  const copy = SurfaceSpline.fromJSON(mesh, start);
  const cold = [];
  for (const target of targets.slice(0, 5)) {
    const t0 = performance.now();
    copy.moveAnchor(3, target);
    copy.trace(options);
    cold.push(performance.now() - t0);
  }
  // The same drag replayed `passes` times from the same start: the first pass as it came, and per
  // move the best of the passes (the work is identical; the spread is other load on the machine).
  const wall = [], move = [], wasm = [];
  let points = 0;
  for (let pass = 0; pass < passes; pass++) {
    const s = SurfaceSpline.fromJSON(mesh, start);
    const w = [], m = [], x = [];
    for (const target of targets) {
      const t0 = performance.now();
      s.moveAnchor(3, target);
      const t1 = performance.now();
      const traced = s.trace(options);
      w.push(performance.now() - t0);
      m.push(t1 - t0);
      x.push(traced.ms);
      if (pass === 0) points += traced.points.length;
    }
    wall.push(w);
    move.push(m);
    wasm.push(x);
  }
  const best = (rows) => rows[0].map((_, i) => Math.min(...rows.map((r) => r[i])));
  const bestWall = best(wall);
  return {
    moves, passes, step: 0.002, median_ms: percentile(wall[0], 0.5), p99_ms: percentile(wall[0], 0.99),
    best_of_passes_median_ms: percentile(bestWall, 0.5), best_of_passes_p99_ms: percentile(bestWall, 0.99),
    move_anchor_median_ms: percentile(move[0], 0.5), trace_wasm_median_ms: percentile(wasm[0], 0.5), trace_wasm_max_ms: Math.max(...wasm[0]),
    first_cold_move_ms: cold[0], mean_points: points / moves, per_pass_max_ms: wall.map((w) => Math.max(...w)),
  };
}

// ---- (4) shortest paths vs exact geodesics (native) -----------------------------------------------

export function surfaceGeodesics(root, data, file, sources, targets = 20, seed = 1) {
  const out = execFileSync(join(root, 'build/native/surface_bench'), [join(data, 'meshes', file), String(sources), String(targets), String(seed)], {
    encoding: 'utf8',
    maxBuffer: 1 << 20,
  });
  return JSON.parse(out);
}

// ---- everything --------------------------------------------------------------------------------------

export const TRACE_SPEED_MESHES = ['nefertiti.obj', 'spot_loop2_369k.ply'];
export const DRAG_MESH = 'spot_loop2_369k.ply';

/**
 * All surface benchmarks. options: curves per mesh and configuration for validity (default 100),
 * curves per kind for trace speed (200), sources for the exact comparison (5; 1 on meshes of more
 * than 200k triangles), log (progress).
 */
export async function surfaceBenchmarks(root, data, options = {}) {
  const { validityCurves = 100, speedCurves = 200, sources = 5, bigSources = 1, targets = 20, files = sharedMeshes(data), log = () => {} } = options;
  const meshes = [];
  const speed = {};
  let drag = null;
  const load_before = os.loadavg()[0];
  const t_start = performance.now();
  for (const file of files) {
    const { mesh, load_ms } = await loadMesh(data, file);
    const t0 = performance.now();
    const row = { file, faces: mesh.faceCount, vertices: mesh.info.vertices, load_ms, wasm_bytes_per_triangle: mesh.info.bytes / mesh.faceCount, warnings: mesh.info.warnings };
    row.validity = surfaceValidity(mesh, validityCurves);
    if (TRACE_SPEED_MESHES.includes(file)) speed[file] = { faces: mesh.faceCount, ...surfaceTraceSpeed(mesh, speedCurves) };
    if (file === DRAG_MESH) drag = { file, faces: mesh.faceCount, ...surfaceDrag(mesh) };
    mesh.dispose();
    row.wasm_seconds = (performance.now() - t0) / 1000;
    log(`surface ${file}: ${row.faces} faces, validity ${CONFIGS.map((c) => `${c.key} ${row.validity[c.key].valid_pct}%`).join(', ')} (${row.wasm_seconds.toFixed(1)} s)`);
    const t1 = performance.now();
    row.geodesics = surfaceGeodesics(root, data, file, row.faces > 200000 ? bigSources : sources, targets);
    row.native_seconds = (performance.now() - t1) / 1000;
    log(`surface ${file}: refined ${row.geodesics.refined.within_pct}% within 0.5%, dual ${row.geodesics.dual.within_pct}%, ${row.geodesics.bytes_per_triangle.toFixed(1)} B/tri (${row.native_seconds.toFixed(1)} s)`);
    meshes.push(row);
  }
  meshes.sort((a, b) => a.faces - b.faces);
  const seconds = (performance.now() - t_start) / 1000;
  return { validity_curves: validityCurves, speed_curves: speedCurves, meshes, speed, drag, seconds, load_average: [load_before, os.loadavg()[0]] };
}

// ---- report -------------------------------------------------------------------------------------------

const f = (x, d = 2) => (x == null ? '–' : x.toFixed(d));
const pct = (x) => `${Number.isInteger(x) ? x : x.toFixed(1)}%`;
const name = (file) => file.replace(/\.(obj|ply)$/, '');

/** The "Surface (b/Surf)" section of BENCHMARKS.md. */
export function surfaceSection(s) {
  const allValid = s.meshes.every((m) => CONFIGS.every((c) => m.validity[c.key].valid === m.validity[c.key].curves));
  const allEnds = s.meshes.every((m) => CONFIGS.every((c) => m.validity[c.key].ends_interpolated === m.validity[c.key].terminated));
  const validity = [
    `| mesh | triangles | curves | ${CONFIGS.map((c) => c.label).join(' | ')} |`,
    `|---|---:|---:|${CONFIGS.map(() => '---:').join('|')}|`,
    ...s.meshes.map((m) => `| ${name(m.file)} | ${m.faces} | ${m.validity.olr.curves} | ${CONFIGS.map((c) => {
      const v = m.validity[c.key];
      return `${pct(v.valid_pct)} (${f(v.median_ms, 1)} ms)`;
    }).join(' | ')} |`),
  ];
  const speedRows = [];
  for (const [file, r] of Object.entries(s.speed)) {
    for (const kind of ['random', 'moderate']) {
      const x = r[kind];
      for (const [pass, y] of [['first', x], [`best of ${x.passes}`, x.best]])
        speedRows.push(`| ${name(file)} | ${r.faces} | ${kind === 'random' ? 'random over the surface' : 'moderate (5% disc)'} | ${pass} | ${x.curves} | ${f(y.median_ms)} | ${f(y.p90_ms)} | ${f(y.p99_ms)} | ${f(y.median_ms / 5)} | ${f(y.p99_ms / 50)} |`);
    }
  }
  const speed = [
    '| mesh | triangles | control polygons | pass | curves | median ms | p90 ms | p99 ms | median / 5 ms | p99 / 50 ms |',
    '|---|---:|---|---|---:|---:|---:|---:|---:|---:|',
    ...speedRows,
  ];
  const d = s.drag;
  const geo = [
    '| mesh | triangles | paths (sources × targets) | refined: within 0.5% | shorter than exact | worst ratio | mean ms | dual (paper): within 0.5% | worst ratio | mean ms | exact ms / source |',
    '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|',
    ...s.meshes.map((m) => {
      const g = m.geodesics, r = g.refined, u = g.dual;
      return `| ${name(m.file)} | ${g.triangles} | ${r.paths} (${g.sources} × ${g.targets_per_source}) | **${pct(r.within_pct)}** | ${r.shorter + u.shorter} | ${f(r.worst_ratio, 4)} | ${f(r.mean_ms)} | ${pct(u.within_pct)} | ${f(u.worst_ratio, 4)} | ${f(u.mean_ms, 3)} | ${f(g.exact_ms_per_source, 0)} |`;
    }),
  ];
  const mem = [
    '| mesh | triangles | search-graph nodes / triangle | mesh bytes | solver bytes | bytes / triangle | after the paths | build_mesh ms | GeodesicSolver ms | precompute ms | wasm: bytes / triangle | wasm: load ms (parse + build) |',
    '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|',
    ...s.meshes.map((m) => {
      const g = m.geodesics;
      return `| ${name(m.file)} | ${g.triangles} | ${f(g.graph_nodes / g.triangles, 1)} | ${g.mesh_bytes} | ${g.solver_bytes} | **${f(g.bytes_per_triangle, 1)}** | ${f(g.bytes_per_triangle_after_paths, 1)} | ${f(g.build_mesh_ms, 1)} | ${f(g.solver_ms, 1)} | ${f(g.precompute_ms, 1)} | ${f(m.wasm_bytes_per_triangle, 1)} | ${f(m.load_ms, 0)} |`;
    }),
  ];
  const worstValid = Math.min(...s.meshes.flatMap((m) => CONFIGS.map((c) => m.validity[c.key].valid_pct)));
  const big = s.meshes.filter((m) => m.faces > 200000).map((m) => name(m.file));
  const refinedMin = Math.min(...s.meshes.map((m) => m.geodesics.refined.within_pct));
  const refinedMax = Math.max(...s.meshes.map((m) => m.geodesics.refined.within_pct));
  const dualMin = Math.min(...s.meshes.map((m) => m.geodesics.dual.within_pct));
  const dualMax = Math.max(...s.meshes.map((m) => m.geodesics.dual.within_pct));
  const shorter = s.meshes.reduce((n, m) => n + m.geodesics.refined.shorter + m.geodesics.dual.shorter, 0);
  const worstBytes = Math.max(...s.meshes.map((m) => m.geodesics.bytes_per_triangle));
  const worstMesh = s.meshes.find((m) => m.geodesics.bytes_per_triangle === worstBytes);
  const over = s.meshes.filter((m) => m.geodesics.bytes_per_triangle > 120);
  const overNote = over.length
    ? `over 120: ${over.map((m) => {
        // Nodes beyond the face nodes and 2 per edge (ShortestPathOptions::steiner) sit on long edges.
        const extra = m.geodesics.graph_nodes - m.geodesics.triangles - 2 * m.geodesics.graph_edges;
        return extra > 0
          ? `${name(m.file)} (${extra} extra search-graph nodes, ${f(extra / m.geodesics.triangles, 2)} per triangle, on its edges longer than 2.25% of the diagonal, where long_edge_fraction, 0.75%, fits more than 3 times)`
          : name(m.file);
      }).join(', ')}`
    : 'every mesh is within it';
  return `## Surface (b/Surf)

Curves on the shared meshes (../shared/data/meshes, top level), in wasm through the TS API
(SurfaceMesh, traceBezier, SurfaceSpline) unless marked native. Random control points are uniform over
the surface's area (the same generator and seeds as \`splinekit trace --random\`). These measurements
took ${f(s.seconds, 0)} s; the 1-minute load average was ${f(s.load_average[0], 1)} at their start and
${f(s.load_average[1], 1)} at their end (other work shared the 2 cores), so times are noisy.

${summary(s)}

### Validity of traced curves (b/Surf §6.1)

${s.validity_curves} random control polygons per mesh (the same ones for every configuration), traced
with traceBezier. A curve is valid when tracing terminates without error and every two consecutive
points of its polyline share a face (checked in JS on the file-order output: the vertices with nonzero
barycentric weight of one point belong to the other's face, or both are on the same face). Cells: %
valid (median per-curve ms).

${validity.join('\n')}

Worst cell: **${pct(worstValid)}** valid. ${allEnds ? 'Every traced polyline starts at P0 and ends at P3 (within 1e-9 of the diagonal).' : 'Some polylines do not start at P0 or end at P3: see build/bench/results.json.'}${allValid ? '' : ' Failures are listed (first break, errors) in build/bench/results.json.'}
Not measured here: adaptive smoothness (turning ≤ 5° between consecutive geodesic segments), which
the native tests check (tests/native/surface/validity_test.cpp, 10 polygons per mesh).

### Per-curve trace time (OLR, uniform, 5 levels)

Per-curve ms as reported by traceBezier (the wasm work, timed inside the module), after 10 warm-up
curves. Random: 4 control points uniform over the surface's area, anywhere on it (the first 100 are
the polygons of the validity table; b/Surf §6.1 instead casts rays along the view direction, which
on spot_loop2_369k gave slower curves, 12.9 against 8.5 ms median, with the straightening of
2026-12-01 before chords). Moderate: 4
control points at the ends of straightest geodesics from a random centre, in random directions, of
random lengths up to 5% of the bounding-box diagonal. Every list is traced three times over: "first"
is the first pass as it came, "best of 3" takes per curve the fastest of the three (the work is
identical; the spread is other load on the machine). Between whole runs minutes apart, the same
code's medians on this 2-core virtual machine moved by up to 25% (2026-12-02, spot_loop2_369k random:
4.3 to 5.4 ms), which best of 3 does not take out. Budget: median ≤ 5 ms, p99 ≤ 50 ms (ratio > 1 =
over budget).

${speed.join('\n')}

### Dragging

On ${name(d.file)} (${d.faces} triangles), a 2-segment spline whose 3 anchors lie within a 5% disc
(straight handles, smooth middle anchor); the middle anchor moves ${d.moves} times by 0.2% of the
diagonal along a straightest geodesic. Per move: moveAnchor + trace() (OLR, 5 levels), wall clock in
Node including the wrapper, after 5 warm-up moves on a copy of the spline (the first of them, with
cold code, is shown apart); ${f(d.mean_points, 0)} polyline points on average. With ${d.moves} samples
the p99 is the slowest move. The same drag was replayed ${d.passes} times: the first row is the first
pass as measured; the second takes each move's best time over the passes (same work each time, so the
difference is other load on the machine; slowest move per pass: ${d.per_pass_max_ms.map((x) => f(x, 1)).join(', ')} ms).
Budget 16 ms (one frame at 60 Hz).

| moves | median ms | p99 ms | median / 16 ms | p99 / 16 ms |
|---|---:|---:|---:|---:|
| first pass | ${f(d.median_ms)} | ${f(d.p99_ms)} | ${f(d.median_ms / 16)} | ${f(d.p99_ms / 16)} |
| best of ${d.passes} passes | ${f(d.best_of_passes_median_ms)} | ${f(d.best_of_passes_p99_ms)} | ${f(d.best_of_passes_median_ms / 16)} | ${f(d.best_of_passes_p99_ms / 16)} |

First pass, parts: moveAnchor ${f(d.move_anchor_median_ms)} ms median; trace (wasm) ${f(d.trace_wasm_median_ms)} ms median,
${f(d.trace_wasm_max_ms)} ms max. The first warm-up move (cold code): ${f(d.first_cold_move_ms, 1)} ms.

### Shortest paths vs the exact geodesic distance (native)

bench/native/surface_bench.cpp (g++ -O3, one thread): random source vertices, each with ${s.meshes[0].geodesics.targets_per_source} random
target vertices; ${s.meshes[0].geodesics.sources} sources per mesh, ${bigSourceCount(s)} on ${big.join(', ') || 'none'} (one exact solve there: ${bigExact(s)}). Exact distances
from tests/native/reference/exact_geodesic.h (MMP windows with saddle pseudo-sources) on the same
repaired mesh. Ratio = path length / exact distance. "Refined" is GeodesicSolver::shortest_path with
its default search graph (2 Steiner nodes per edge, distances along straight runs through windows,
A* bound drained); "dual" is SearchGraph::kDual,
the paper's dual graph (face nodes, first arrival), which curve tracing uses. Both are then
straightened (funnel + flips). "Shorter than exact" counts paths of both graphs shorter than the exact
distance by more than 1e-9 relative (must be 0).

${geo.join('\n')}

Refined: ${pct(refinedMin)}–${pct(refinedMax)} of paths within 0.5% of the exact distance; dual graph: ${pct(dualMin)}–${pct(dualMax)}.
Paths shorter than exact: **${shorter}**.

### Why these defaults (ShortestPathOptions)

The defaults of wasm/core/surface/geodesic_options.h, and what they were chosen on (measured when each
was set; the header says what each option does).

- **steiner = 2, long_edge_fraction = 0.0075** (phase (i), the search graph). The paper puts one node
  per face and extra nodes only on edges longer than 5% of the bounding-box diagonal. On the shared
  meshes, 4 nodes per edge and 1% took the share of paths within 0.5% of the exact geodesic distance
  from 15-96% to 99-100% when the search measured its paths link by link (3 nodes gave 94% on mountain
  and stanford_bunny). Since 2026-12-03 it measures them along straight runs through windows
  (dual_search.cpp), and 2 nodes find the right strip at least as often as 4 did (\`surface_scale_bench
  steiner <mesh> 10 50 7\`, 10 sources × 50 targets against exact, native: spot_control_tri 99.6% with
  any count, hand_lowres, torus, fertility, spot, mountain and stanford_bunny 100%; torus was 99.0% with 4
  nodes on the links), at 0.5-0.6 of the time of 3 and 0.4 of 4 on the larger meshes. On shapes not
  tuned on (\`surface_scale_bench shape noisy-cube|small-noisy-coil|small-noisy-folded\`), 2 nodes give
  a noisy cube (±0.4 edge lengths) 99.2% (3 nodes 99.4%, 4 nodes 100%), a noisy coil 99.8%, and a
  coarse noisy folded body (28k triangles, 24 around) 98.2% (3 nodes 99.8%, 4 nodes 100%; the links
  with 4 nodes gave 55%); 1 node gives 99.0% on mountain and 80.6% on that folded body. On the folded
  body of "Surface at scale", whose long thin faces made the link-by-link search pick the strip of a
  neighbouring geodesic (14 of 20 pairs within 0.5%, worst 1.056; 8 nodes per edge were needed), the
  windows find all 20. long_edge_fraction went from 0.01 to 0.0075 on 2026-12-03 for that coarse noisy
  folded body (its edges reach 3.1% of the diagonal): edges beyond 2.25% get 3 nodes or more (at 0.01
  only those beyond 3%; at 0.005 those beyond 1.5%), which took it from 98.2% to 99.4% within 0.5% (0.005: 99.6%) and the noisy
  cube from 99.2% to 99.6% (0.005: 100%), for 23% more time on the folded body's paths and 80% on the
  cube's (0.005: 40% and 150%, and 170% on the noisy coil, whose 1.5-2.2% edges it also splits). The
  meshes of "Surface at scale" have at most a few edges beyond 2.25% of their diagonal (nodes within 0.01%, the same
  path lengths on 10 pairs each; the folded body's 10 paths 859 -> 898 ms natively). On the shared meshes it keeps 100% (spot_control_tri, hand_lowres, torus, mountain: 10 x 50 at
  2 nodes; spot_control_tri was 99.6%), the noisy coil 99.8%. (The long edges' nodes are numbered after all the others, and a bit per edge says which are long,
  so that the other edges' nodes are still found by a multiplication: looking up the long edges before
  each edge had cost the refined search 8-25% on the folded body once a few hundred edges were long.)
- **dual_heuristic_weight = 3** (the kDual search that curve tracing uses; weighted A*). On random
  whole-surface curves of nefertiti and spot_loop2_369k, a weight of 2 visits 7-20 times fewer nodes
  than 1 (the search drops from most of the trace time to a tenth of it); the paths are locally
  shortest either way and a little more often not globally (the dual column above), which curve
  tracing accepts: after the first level its paths join nearby points. 3 cuts the long tail of
  searches that must go round a concave region (spot_loop2_369k, random face pairs: p90 23k nodes
  visited at 2, 2.7k at 3, 1.2k at 4); phase (iii)'s chords make up for the rougher strips (curves on
  average 0.3% longer on nefertiti, 0.2% shorter on spot_loop2_369k; 4 makes nefertiti's 1% longer).
  (Measured with the label-correcting SLF/LLL search of before 2026-12-02; the search is now a heap
  A*, see "Surface at scale".)
- **dual_stretch_weight = 1.25** (2026-12-05): the kDual weight is at least 1.25 times the dual graph's
  stretch, measured when the graph is built (32 short Dijkstra runs over the centroids, the 90th
  percentile of graph over straight distance; a few ms). Across long thin faces the centroid path
  zigzags (a 7:1 quad split in two: 4.5 times the straight way along its short side), and where that
  passes the weight the greedy search expands everything within reach. Measured: nefertiti 1.52,
  spot_loop2_369k 1.35, coil 1.74, Stanford dragon 1.41 (weight 3 kept); knotted tube 5.2 (weight 6.5,
  0.965x the time), folded body 6.8 (8.5, 0.996x); a UV sphere of 2000 x 150 quads (7:1 at the equator,
  not tuned on) 20.1: native, 40 random curves, 0.64x the time and 0.09x the nodes, the same curves
  (wasm, 100 curves: median 20.1 -> 13.1 ms). A cylinder of 32:1 faces measures 21.5 against the
  zigzag's closed form 21.25 (tests/native/surface/geodesic_test.cpp). Tried first: distances along
  straight runs in the kDual search (the refined search's windows on face nodes): the sphere 0.92x
  but the near-regular meshes 1.13-1.14x, and the dragon's curves 1.4% longer.
- **dual_reverse_search_faces = 512** (2026-12-03): a kDual strip of 512 faces or more is searched again
  from the far end, and the one whose funnel path is shorter is straightened. The greedy search's A*
  term leads it down the landmarks' distance fields, so its strip depends on the end it starts from,
  and the straightening's work grows with the region between strip and geodesic. Of the long sides of
  300 random pairs (native), the one chosen straightens in 0.81-0.86 of the forward one's time (an
  oracle picking the faster: 0.75-0.81) and comes out 0.4-1.9% shorter; choosing by the two searches'
  lengths (free) did nearly as well, by the funnel paths' apex counts worse than the forward strip
  alone. Random whole-surface curves in one wasm module against the tree before (bench:ab, 100
  curves): 0.89x the time in total on the coil, 0.86x on the folded body, 0.94x on spot_loop2_369k,
  1.00x on nefertiti (no side that long) and 1.07x on the noisy spot, whose sides straighten cheaply
  enough that the second search and layouts cost more than they save. 128, 256 and 1024 faces did
  about as well.
- **landmark_descent = true, landmark_descent_gap = 0.05** (2026-12-04): such a strip also gets a
  candidate down the distance field of the landmark that bounds the ends' distance best, from the far
  end to the near end's level and the greedy search on, unless the descent ends farther from the near
  end than 5% of the best candidate's funnel length. On the coil the geodesic runs along the tube's
  inner side, which the greedy strip misses: random curves 0.66x the time in total (wasm, bench:ab),
  0.92x on the knotted tube, others within 2% (section "Surface at scale", Landmark descent). When
  its strip beats the forward one, the search from the far end is left out (a further 0.87x on the
  coil, 0.96x on the knotted tube, 0.95x on the folded body).
- **landmarks = 8, landmark_weight = 2, refined_landmark_share = 0.75, landmark_min_faces = 16384**
  (phase (i)'s landmark term, 2026-12-02, section "Surface at scale"). 8 landmarks take 16 bytes per
  triangle, what giving search records per edge rather than per node saved (18). Random whole-surface
  curves on the 384k-triangle coil (native, 10, loaded machine) took 356 ms at landmark_weight 1, 142
  at 2, 97 at 3 and 340 at 5. Counted in instructions instead (valgrind, native, random whole-surface
  curves, mesh loading subtracted; 2026-12-02 after the straightening fix), 2 against 3: noisy
  spot_loop2_369k 0.82x (40 curves), spot_loop2_369k 0.93x (40), nefertiti 0.92x (40), the coil
  0.995x (15), the folded body 1.00x (8); the curves came out shorter in total by 0.5% (noisy spot),
  2.3% (spot_loop2_369k) and 0.8% (nefertiti): a greedier search hands the straightening strips
  that settle more often on a longer local geodesic. 1 and 1.5 cost more (the search grows). The refined search
  (shortest paths) weighs them by 0.75 / the dual graph's stretch (2026-12-07): a landmark bounds the
  dual graph's distance, which runs longer than the surface's by about that stretch, so the bound over
  the stretch is one on the surface's distance; the share keeps a margin, as the stretch is a 90th
  percentile over short distances. The term is used only in a search whose ends it bounds farther
  apart than space does. Native, 40 random vertex pairs a mesh, against the Euclidean term alone,
  interleaved: knotted tube 0.84x the time, coil 0.84x, folded body 0.98x, the Stanford dragon
  (unseen) 0.97x, none more than 0.5% longer (a few shorter: other strips straighten further);
  nefertiti, the spots and the UV sphere within 1% (their searches leave the term out). A share of 1:
  the knotted tube 0.71x but 4 of 40 paths more than 0.5% longer. Before: a fixed scale that
  makes the search cheap on the coil is not admissible elsewhere (0.85: the coil's refined searches expand
  23k nodes instead of 1.2M, but 90% of nefertiti's paths within 0.5% of exact instead of 100%; 0.5
  to 0.7 keep nefertiti's lengths but expand 0.8-1.2M nodes on the coil again). Even landmark distances
  that are exact (MMP from the same 8 landmark faces, an oracle, 2026-12-03) cut the coil's refined
  searches only from 7.1M to 2.2M nodes (20 pairs, 2348 -> 871 ms natively): from far along a thin tube
  every landmark sees how far a node is along the tube, not where it lies around it, so the search
  still takes in the tube's whole girth between the ends. landmark_min_faces counts a component's
  faces, not the mesh's (2026-12-03): landmarks go to the largest components of at least that many
  faces, so that a scan's specks of debris (the Stanford dragon's 150) do not take them all (section
  "Surface at scale", "Scans with debris").
- **chord_min_turn = 0.03 rad** (phase (iii); 0.01 until 2026-12-04). Late in the straightening the
  path bends a little at apices far apart, and a chord there walks all the way between the
  neighbouring apices for a small gain; smaller bends get the semi-star (and zipper) flip. On random
  whole-surface curves (OLR, 5 levels, wasm, each curve traced by both builds in turn), 0.01 took 4-7%
  off the trace time on spot_loop2_369k and 1% on nefertiti against no bound; 0.03 then settled more
  first-level sides on other (longer) local geodesics. After the slides, windows, landmark descent
  and the layout fix of 2026-12-04 (lay_across no longer scales faces laid on from a drifted edge,
  which 0.03 had exposed: a coil path's layout 5e-7 longer than in space), 0.03 against 0.01 in one
  wasm module (bench:ab, 100 curves, best of 2, with the layout fix): per-curve median / total 0.875x
  / 0.872x on the knotted tube, 0.952x / 0.937x on the folded body, 0.957x / 0.960x on spot_loop2_369k,
  0.964x / 0.956x on nefertiti, 0.982x / 0.984x on the coil, 0.987x / 0.986x on the noisy spot; mean
  curve lengths -0.05%, 0.00%, 0.00%, -0.16%, 0.00%, +0.03%.
- **slides = true, slide_min = 4, slide_gap = 2** (phase (iii), 2026-12-03; Straightener::slide). A path
  pressed against a row of saddle vertices bends at each by up to its angle excess and stays locally
  shortest; it leaves the row with a larger bend, and flipping that bend makes the vertex before it the
  bend, a little smaller, one vertex per pass (the coil's inner side: excess 0.0016, bends of 0.026 that
  shrank 1% a pass, ~90 passes for each). The slide works out where the bend stops and flips every vertex
  on the way at once. In one wasm module against the tree before (bench:ab, 100 random curves, best of 2):
  per-curve median 0.74x on the coil (43.6 -> 28.3 ms), 1.01x nefertiti (no curve changed), 1.02x
  spot_loop2_369k, 1.01x the folded body, 1.02x the noisy spot, curves as long within 0.02% in total.
  slide_min = 4: with slides of any length, short ones on nefertiti and the noisy spot moved 98 of 100
  curves onto other local geodesics (each within 2%) and cost 4-6%; at 4 nefertiti's curves are the same.
  slide_gap = 2: passing any number of untouched boundary vertices between bends, slides ran along the
  folded body's long strips (210 vertices each) and cost it 19%; on the coil's rows the bends are one or
  two vertices apart.
- **window_min_faces = 1024, window_margin = 64** (phase (iii), 2026-12-04; Straightener::windowed_pass).
  A pass costs its whole strip (the layout moved past every change, the funnel path copied), while the
  coil's long paths end with bends sliding along the saddle vertices of the tube's inner side in three
  or four places, a vertex or two per pass, for some 70 of their 80 passes. A pass whose reflex vertices'
  windows (from a bend window_margin faces before each to one as far after, none of them reflex) cover at
  most half of a strip of window_min_faces or more straightens each window on its own, to the end, and
  puts them in at once. Native instructions of 20 random long paths: 0.63x on the coil, 0.96x on the
  knotted tube, 1.00x on the folded body and spot_loop2_369k, the same lengths to 1e-13 (128 and 2048:
  0.65x; 32: 0.65x; windows over up to a quarter of the strip: 0.63x). In one wasm module against the
  tree before (bench:ab, 100 random curves, best of 2): per-curve median 0.835x and total 0.785x on the
  coil, 0.962x / 0.944x on the knotted tube, 0.998x / 0.988x on the folded body, nefertiti, spot_loop2_369k
  and the noisy spot within 0.2% (no curve changed). Curves that changed came out on other local
  geodesics: mean length +0.0014% on the coil, +0.09% on the knotted tube (-0.03% over 60 other curves,
  native), +0.003% on the folded body; windows from 256 faces on a small noisy folded body took 32 of 300
  paths longer and 19 shorter (+0.05% in total), hence the long strips only. The knotted tube's paths bend at a few vertices, nearly
  all of them moving at once, so its windows would cover the strip and its passes stay whole.
- **max_passes = 100000** (phase (iii)): a safety bound on the passes (each flips every reflex vertex
  whose faces do not touch another's), not a tuning knob.

### Memory and precompute

Bytes held by the mesh structures (positions, faces, adjacency, vertex maps, file<->mesh face maps (8 bytes per triangle, since 2026-12-02: 5% faster curves on spot_loop2_369k, 9.5% on nefertiti, by the locality of the mesh order): mesh_bytes) and by the
solver (search graph, single-precision face centroids (12 bytes per triangle, since 2026-12-01: 3-5%
faster curves in wasm), vertex angle sums and search scratch: GeodesicSolver::bytes), per triangle, right after building
and again after the shortest paths above (the scratch list of touched nodes grows with the searches); precompute = build_mesh
(welding, orientation, adjacency, locality order) + GeodesicSolver construction, native, median of 3. The wasm columns
are SurfaceMesh.info.bytes per triangle and SurfaceMesh.load (file parse included) in Node.
Budget ≤ ~120 bytes per triangle: worst **${f(worstBytes, 1)}** (${name(worstMesh.file)}); ${overNote}.

${mem.join('\n')}
`;
}

function summary(s) {
  const cells = s.meshes.flatMap((m) => CONFIGS.map((c) => m.validity[c.key]));
  const valid = cells.reduce((n, v) => n + v.valid, 0), total = cells.reduce((n, v) => n + v.curves, 0);
  const speed = Object.entries(s.speed);
  const over = (x, budget) => `${f(x, x < 10 ? 2 : 1)} ms (${f(x / budget, x < budget ? 2 : 1)}× the budget)`;
  const g = s.meshes.map((m) => m.geodesics);
  const range = (xs, d = 0) => `${f(Math.min(...xs), d)}–${f(Math.max(...xs), d)}`;
  const d = s.drag;
  return [
    `- Validity: **${valid} of ${total}** traced curves valid (${s.meshes.length} meshes × ${CONFIGS.length} configurations × ${s.validity_curves} random polygons).`,
    ...speed.map(([file, r]) => `- Trace time on ${name(file)} (OLR, 5 levels), per curve the best of ${r.random.passes} passes: random polygons median ${over(r.random.best.median_ms, 5)}, p99 ${over(r.random.best.p99_ms, 50)} (first pass: median ${f(r.random.median_ms)}, p99 ${f(r.random.p99_ms, 1)} ms); moderate ones median ${over(r.moderate.best.median_ms, 5)}, p99 ${over(r.moderate.best.p99_ms, 50)}.`),
    `- Dragging an anchor on ${name(d.file)}: median ${over(d.median_ms, 16)}, p99 ${over(d.p99_ms, 16)} per move (first pass).`,
    `- Shortest paths (native): ${range(g.map((x) => x.refined.within_pct))}% within 0.5% of the exact distance with the refined graph, ${range(g.map((x) => x.dual.within_pct))}% with the paper's dual graph; ${g.reduce((n, x) => n + x.refined.shorter + x.dual.shorter, 0)} shorter than exact.`,
    `- Memory: ${range(g.filter((x) => x.triangles >= 10000).map((x) => x.bytes_per_triangle), 1)} bytes per triangle on the meshes of ≥ 10k triangles, ${range(g.map((x) => x.bytes_per_triangle), 1)} on all (budget ~120); precompute ${f(Math.max(...g.map((x) => x.precompute_ms)), 0)} ms on the largest mesh.`,
  ].join('\n');
}

function bigExact(s) {
  const g = s.meshes.find((m) => m.faces > 200000)?.geodesics;
  return g ? `${f(g.exact_ms_per_source / 1000, 0)} s, ${f(g.peak_rss_mb / 1024, 1)} GB peak` : '';
}

function bigSourceCount(s) {
  const big = s.meshes.filter((m) => m.faces > 200000);
  return big.length ? big[0].geodesics.sources : 0;
}
