/**
 * `splinekit geodesic` and `splinekit trace`: shortest paths and Bézier curves on a mesh (b/Surf).
 * Mesh points in the JSON inputs are vertex indices (integers) or {"face":f,"uv":[u,v]}, both in
 * the file's order; outputs use the same convention.
 */
import { basename } from 'node:path';
import { DEFAULT_MAX_MESH_BYTES, DEFAULT_TRACE_LEVELS, DEFAULT_TRACE_SCHEME, SplinekitError, SurfaceMesh, randomMeshPoints, traceBezier, type MeshPoint, type MeshPointLike, type SurfaceMeshOptions, type TraceOptions } from '../index.js';
import { meshHandles } from '../surface/mesh-handle.js';
import { UsageError, parse, readInput, readJSON, writeJSON, type Command } from './common.js';

export async function loadMesh(path: string, options: SurfaceMeshOptions = {}): Promise<SurfaceMesh> {
  return SurfaceMesh.load(readInput(path, DEFAULT_MAX_MESH_BYTES), basename(path), options);
}

/** A mesh point from JSON: a vertex index or {"face":f,"uv":[u,v]}; checked against the mesh. */
function meshPoint(mesh: SurfaceMesh, value: unknown, where: string): MeshPoint {
  try {
    if (typeof value === 'number') return mesh.resolve(value as MeshPointLike, where);
    const p = value as { face?: unknown; uv?: unknown };
    if (p && typeof p.face === 'number' && Array.isArray(p.uv) && p.uv.length === 2 && p.uv.every((x) => typeof x === 'number'))
      return mesh.resolve({ face: p.face, uv: [p.uv[0], p.uv[1]] }, where);
  } catch (err) {
    if (err instanceof SplinekitError) throw new SplinekitError('invalid-input', err.message.startsWith(where) ? err.message : `${where}: ${err.message}`);
    throw err;
  }
  throw new SplinekitError('invalid-input', `${where}: expected a vertex index or {"face":f,"uv":[u,v]}`);
}

function round(x: number): number {
  return Math.round(x * 1e3) / 1e3;
}

const geodesicUsage = `usage: splinekit geodesic <mesh> --pairs <pairs.json> [--json out.json]

Locally shortest geodesic paths between pairs of mesh points (b/Surf §5.1). pairs.json:
{"pairs":[[a,b],...]} where a point is a vertex index or {"face":f,"uv":[u,v]} (the point
(1-u-v)·p0 + u·p1 + v·p2 of the face's vertices), indices in the file's order. --json writes
{"paths":[{"length":L,"points":[[x,y,z],...]}],"stats":{"total_ms":..,"per_path":[{"ms":..,
"visitedNodes":..,"stripFaces":..,"passes":..,"flips":..},...]}}; total_ms covers the path
computations only; per_path gives each path's time and work (graph nodes the search expanded, faces
of the strip straightened, straightening passes, flips kept).`;

export const geodesic: Command = {
  summary: 'shortest paths between points on a mesh',
  usage: geodesicUsage,
  async run(args) {
    const { values, positionals } = parse({ args, allowPositionals: true, options: { pairs: { type: 'string' }, json: { type: 'string' } } });
    if (positionals.length !== 1) throw new UsageError(`expected one mesh file\n${geodesicUsage}`);
    if (!values.pairs) throw new UsageError(`--pairs is required\n${geodesicUsage}`);
    const json = readJSON(values.pairs, 'pairs') as { pairs?: unknown };
    if (!json || !Array.isArray(json.pairs)) throw new SplinekitError('invalid-input', `${basename(values.pairs)}: expected {"pairs":[[a,b],...]}`);
    const mesh = await loadMesh(positionals[0]);
    try {
      const pairs = json.pairs.map((pair: unknown, i: number) => {
        if (!Array.isArray(pair) || pair.length !== 2) throw new SplinekitError('invalid-input', `${basename(values.pairs!)}: pair ${i} must be [a, b]`);
        return [meshPoint(mesh, pair[0], `pair ${i} start`), meshPoint(mesh, pair[1], `pair ${i} end`)] as const;
      });
      let total = 0;
      const perPath: Record<string, number>[] = [];
      const paths = pairs.map(([a, b]) => {
        const path = mesh.shortestPath(a, b);
        const handle = meshHandles.get(mesh);
        total += handle.milliseconds();
        const { visitedNodes, stripFaces, passes, flips } = handle.pathCounters();
        perPath.push({ ms: round(handle.milliseconds()), visitedNodes, stripFaces, passes, flips });
        const points: number[][] = [];
        for (let i = 0; i < path.xyz.length; i += 3) points.push([path.xyz[i], path.xyz[i + 1], path.xyz[i + 2]]);
        return { length: path.length, points };
      });
      if (values.json) writeJSON(values.json, { paths, stats: { total_ms: round(total), per_path: perPath } });
      else {
        paths.forEach((p, i) => console.log(`pair ${i}: length ${p.length.toPrecision(8)}, ${p.points.length} points`));
        console.log(`${paths.length} paths in ${round(total)} ms`);
      }
    } finally {
      mesh.dispose();
    }
  },
};

const traceUsage = `usage: splinekit trace <mesh> (--curves <curves.json> | --random N [--seed S])
       [--scheme olr|rdc] [--levels K | --adaptive DEG] [--json out.json]

Traces cubic Bézier curves on the mesh by subdivision (b/Surf §3.5-§4): OLR (default, ${DEFAULT_TRACE_LEVELS.olr} levels)
or RDC (${DEFAULT_TRACE_LEVELS.rdc} levels), uniform or adaptive with an angle threshold in degrees. curves.json:
{"curves":[[p0,p1,p2,p3],...]} with points as in \`splinekit geodesic\`; --random N draws N
curves with control points uniform over the surface's area (seed S, default 1; on a mesh of
several parts, a polygon whose points fall on separate parts is drawn again). A curve cannot
cross between parts: given ones that would are refused. --json writes
{"curves":[{"points":[{"face":f,"uv":[u,v],"xyz":[x,y,z]},...]}],"stats":{"total_ms":..,
"per_curve_ms":[...],"per_curve":[{"searchedPaths":..,"guided":..,"seededPaths":..,"visitedNodes":..,
"stripFaces":..,"passes":..,"flips":..},...],"redrawn":n}}: the whole polyline on the surface, every
edge crossing included; per_curve is each curve's work (shortest paths searched, of those the ones
found along the coarse guide, and straightened through known ones, graph nodes expanded, strip faces
straightened, passes, flips); redrawn counts the random polygons drawn again. A mesh of 65,536
triangles or more gets a coarse guide (itself simplified to a sixteenth) that finds long paths' way
first; --no-guide leaves it out.`;

function integerOption(value: string | undefined, name: string, min: number, max: number): number | undefined {
  if (value === undefined) return undefined;
  const n = Number(value);
  if (!Number.isInteger(n) || n < min || n > max) throw new UsageError(`--${name} must be an integer from ${min} to ${max} (got "${value}")`);
  return n;
}

/**
 * Traces `count` random curves (control points uniform over the surface's area, seed `seed`) with
 * `add`. On a mesh of several parts (a scan's debris) a polygon whose points lie on separate parts
 * cannot be traced: it is drawn again from the same stream (on a mesh of one part the polygons are
 * the stream's first 4·count points). Returns how many were drawn again.
 */
function traceRandom(mesh: SurfaceMesh, count: number, seed: number, options: TraceOptions, add: (traced: ReturnType<typeof traceBezier>) => void): number {
  let pool = randomMeshPoints(mesh, 4 * count, seed);
  let next = 0, redrawn = 0;
  for (let traced = 0; traced < count; ) {
    if (next + 4 > pool.length) {
      if (redrawn > 100 * count) throw new SplinekitError('invalid-input', `could not draw ${count} random curves whose control points lie on one connected part of the mesh (${redrawn} tried)`);
      pool = randomMeshPoints(mesh, 2 * pool.length, seed); // (the same stream, longer)
    }
    const polygon = pool.slice(next, next + 4);
    next += 4;
    try {
      add(traceBezier(mesh, polygon, options));
      traced++;
    } catch (err) {
      if (!(err instanceof SplinekitError && err.message.includes('not connected'))) throw err;
      redrawn++;
    }
  }
  return redrawn;
}

export const trace: Command = {
  summary: 'Bézier curves on a mesh by geodesic subdivision',
  usage: traceUsage,
  async run(args) {
    const { values, positionals } = parse({
      args,
      allowPositionals: true,
      options: {
        curves: { type: 'string' },
        random: { type: 'string' },
        seed: { type: 'string' },
        scheme: { type: 'string' },
        levels: { type: 'string' },
        adaptive: { type: 'string' },
        json: { type: 'string' },
        'no-guide': { type: 'boolean' },
      },
    });
    if (positionals.length !== 1) throw new UsageError(`expected one mesh file\n${traceUsage}`);
    if (!values.curves === (values.random === undefined)) throw new UsageError(`give either --curves or --random\n${traceUsage}`);
    if (values.levels !== undefined && values.adaptive !== undefined) throw new UsageError('--levels and --adaptive exclude each other');
    const scheme = values.scheme ?? DEFAULT_TRACE_SCHEME;
    if (scheme !== 'olr' && scheme !== 'rdc') throw new UsageError(`--scheme must be olr or rdc (got "${scheme}")`);
    const options: TraceOptions = { scheme, levels: integerOption(values.levels, 'levels', 0, 12) };
    if (values.adaptive !== undefined) {
      const deg = Number(values.adaptive);
      if (!(deg > 0 && deg < 180)) throw new UsageError(`--adaptive must be an angle in degrees between 0 and 180 (got "${values.adaptive}")`);
      options.adaptive = deg;
    }
    const count = integerOption(values.random, 'random', 1, 1_000_000);
    const seed = integerOption(values.seed, 'seed', 0, 2 ** 32 - 1) ?? 1;
    let curvesJSON: unknown[] | undefined;
    if (values.curves) {
      const json = readJSON(values.curves, 'curves') as { curves?: unknown };
      if (!json || !Array.isArray(json.curves)) throw new SplinekitError('invalid-input', `${basename(values.curves)}: expected {"curves":[[p0,p1,p2,p3],...]}`);
      curvesJSON = json.curves;
    }
    const mesh = await loadMesh(positionals[0], values['no-guide'] ? { guide: false } : {});
    try {
      const perCurve: number[] = [];
      const work: Record<string, number>[] = [];
      const curves: { points: { face: number; uv: [number, number]; xyz: number[] }[] }[] = [];
      const add = (traced: ReturnType<typeof traceBezier>) => {
        perCurve.push(traced.ms);
        const { searchedPaths, guided, seededPaths, visitedNodes, stripFaces, passes, flips } = traced.counters;
        work.push({ searchedPaths, guided, seededPaths, visitedNodes, stripFaces, passes, flips });
        curves.push({ points: traced.points.map((p, i) => ({ face: p.face, uv: p.uv, xyz: [traced.xyz[3 * i], traced.xyz[3 * i + 1], traced.xyz[3 * i + 2]] })) });
      };
      let redrawn = 0;
      if (curvesJSON) {
        const polygons = curvesJSON.map((c: unknown, i: number) => {
          if (!Array.isArray(c) || c.length !== 4) throw new SplinekitError('invalid-input', `${basename(values.curves!)}: curve ${i} must have 4 control points`);
          return c.map((p, k) => meshPoint(mesh, p, `curve ${i} point ${k}`));
        });
        polygons.forEach((polygon, i) => {
          try {
            add(traceBezier(mesh, polygon, options));
          } catch (err) {
            if (err instanceof SplinekitError) throw new SplinekitError(err.code, `${basename(values.curves!)}: curve ${i}: ${err.message.replace(/^trace: curve 0: /, '')}`);
            throw err;
          }
        });
      } else {
        redrawn = traceRandom(mesh, count!, seed, options, add);
      }
      const total = perCurve.reduce((a, b) => a + b, 0);
      if (values.json) writeJSON(values.json, { curves, stats: { total_ms: round(total), per_curve_ms: perCurve.map(round), per_curve: work, redrawn } });
      else {
        const sorted = [...perCurve].sort((a, b) => a - b);
        console.log(
          `${basename(positionals[0])}: ${curves.length} curves (${scheme}, ${options.adaptive ? `adaptive ${options.adaptive}°` : `${options.levels ?? DEFAULT_TRACE_LEVELS[scheme]} levels`}), ` +
            `${curves.reduce((n, c) => n + c.points.length, 0)} points, ${round(total)} ms (median ${round(sorted[sorted.length >> 1])} ms per curve)` +
            (redrawn ? `; ${redrawn} random polygons drawn again: their points lay on separate parts of the mesh` : ''),
        );
      }
    } finally {
      mesh.dispose();
    }
  },
};
