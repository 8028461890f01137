/**
 * Surface mode's worker: loads the mesh (parse, weld, precompute) and runs every spline edit and
 * trace off the main thread. It holds one SurfaceMesh; each request brings a spline's control
 * points, so the worker keeps no history and a stale request is harmless. Requests are answered
 * in order, one at a time.
 */
import { SurfaceMesh, SurfaceSpline, init, mapSplines, meshPointNormal, parseSVG, vertexNormals, type MeshPoint, type SurfaceSplineJSON } from '../../../src/index.js';
import { serveRequests } from '../../app/worker-host.js';
import { TriangleBVH, type BVHArrays } from '../../view3d/bvh.js';
import { displayOrigin, meshBounds, shiftBounds, toDisplay } from '../../view3d/bounds.js';
import { meshProxy } from '../../view3d/proxy.js';
import type { PolygonPaths, SplineOp, SurfaceReply, SurfaceRequest, TracedPolyline } from './protocol.js';

/**
 * Drawn polylines float this fraction of the mesh size above the surface (along its normal). Zero:
 * the view draws them toward the camera instead (web/view3d/lines.ts), which works on both sides
 * of the surface (the inside of the vase, seen through its mouth).
 */
const LIFT = 0;

let mesh: SurfaceMesh | null = null;
/** Smooth vertex normals of `mesh` (area weighted), for lifting polylines. */
let normals: Float32Array | null = null;
let lift = 0;
/** Where the view's coordinates start (displayOrigin): every position posted is relative to it. */
let origin: [number, number, number] = [0, 0, 0];
const ready = init();

const post = serveRequests<SurfaceRequest, SurfaceReply>(handle);

async function handle(req: SurfaceRequest): Promise<void> {
  await ready;
  switch (req.type) {
    case 'load':
      return await load(req.id, req.bytes, req.name);
    case 'run':
      return run(req);
    case 'path':
      return path(req.id, req.a, req.b);
    case 'map':
      return map(req);
  }
}

/** Meshes of more faces get their picking hierarchy after they are shown (it takes seconds at 2M). */
const PICKING_LATER_FACES = 250_000;

/**
 * Meshes of more faces come with a proxy of about PROXY_TRIANGLES (the view draws it while the mesh
 * moves on a renderer too slow to draw every triangle each frame; meshoptimizer's sloppy
 * simplifier: ~95 ms to make at 2M faces, ~230 ms the first time in a worker, while its
 * WebAssembly is still in baseline code and its memory grows).
 */
const PROXY_FACES = 250_000;
const PROXY_TRIANGLES = 60_000;

/**
 * Loads a mesh: the mesh itself first (posted as 'progress' for the view: the user can look and
 * orbit), then on large meshes its picking hierarchy (another 'progress'), then its search
 * structures (graph, landmarks: the larger part of the build on a large mesh), before the requests
 * that came after this one.
 */
async function load(id: number, bytes: ArrayBuffer, name: string): Promise<void> {
  const t0 = performance.now();
  const next = await SurfaceMesh.load(new Uint8Array(bytes), name, { deferSearch: true }); // throws: the previous mesh stays
  mesh?.dispose();
  mesh = next;
  const P = next.positions;
  // The faces shown and picked: a face that repeats an earlier one (a double-sided mesh's other
  // side) collapsed to a point, so that it neither fights the first for the pixels, turns the
  // normals round, nor takes a click (the face indices stay the file's).
  const T = next.duplicateFaces.length > 0 ? next.triangles.slice() : next.triangles;
  for (const f of next.duplicateFaces) T[3 * f + 1] = T[3 * f + 2] = T[3 * f];
  normals = vertexNormals(P, T);
  lift = LIFT * next.scale;
  const fileBounds = meshBounds(P); // (one pass over the positions for both)
  origin = displayOrigin(fileBounds.box);
  const positions = toDisplay(P, origin), triangles = new Uint32Array(T.length);
  triangles.set(T);
  const later = T.length / 3 > PICKING_LATER_FACES;
  const bvhArrays = (bvh: BVHArrays) => [bvh.bounds.buffer, bvh.nodes.buffer, bvh.order.buffer];
  // (later: the hierarchy is built on copies, the arrays shown are handed over at once)
  const kept = later ? { positions: positions.slice(), triangles: triangles.slice() } : null;
  const bvh = later ? null : new TriangleBVH(positions, triangles).toArrays();
  const shownNormals = normals.slice();
  const coarse = T.length / 3 > PROXY_FACES ? await meshProxy(positions, triangles, PROXY_TRIANGLES, normals) : null;
  // (the proxy's vertices are the mesh's: shaded with the mesh's own smooth normals, it looks
  // like the mesh, where its own would show every fold of the clustering)
  const proxy = coarse ? { positions: coarse.positions, triangles: coarse.triangles, normals: gather(normals, coarse.vertices) } : null;
  post({ type: 'progress', stage: 'shown', id, info: structuredClone(next.info), positions, triangles, normals: shownNormals, proxy, bounds: shiftBounds(fileBounds, origin), bvh, scale: next.scale, ms: performance.now() - t0 }, [
    positions.buffer,
    triangles.buffer,
    shownNormals.buffer,
    ...(proxy ? [proxy.positions.buffer, proxy.triangles.buffer, proxy.normals.buffer] : []),
    ...(bvh ? bvhArrays(bvh) : []),
  ]);
  if (kept) {
    const picking = new TriangleBVH(kept.positions, kept.triangles).toArrays();
    post({ type: 'progress', stage: 'picking', id, bvh: picking }, bvhArrays(picking));
  }
  const info = next.buildSearch();
  post({ type: 'loaded', id, info, ms: performance.now() - t0 });
}

/** The rows (x y z) of `rows` at `at`. */
function gather(rows: Float32Array, at: Uint32Array): Float32Array {
  const out = new Float32Array(3 * at.length);
  for (let i = 0; i < at.length; i++) {
    const r = 3 * at[i];
    out[3 * i] = rows[r];
    out[3 * i + 1] = rows[r + 1];
    out[3 * i + 2] = rows[r + 2];
  }
  return out;
}

function needMesh(): SurfaceMesh {
  if (!mesh) throw new Error('no mesh is loaded');
  return mesh;
}

function run(req: Extract<SurfaceRequest, { type: 'run' }>): void {
  const m = needMesh();
  const t0 = performance.now();
  let spline: SurfaceSpline | null = req.json ? new SurfaceSpline(m, req.json) : null;
  try {
    for (const op of req.ops) spline = apply(m, spline, op);
    if (!spline) throw new Error('no spline to edit');
    const json = spline.toJSON();
    let trace: TracedPolyline | null = null, traceMs = 0;
    const transfer: Transferable[] = [];
    if (req.trace) {
      const t1 = performance.now();
      const r = spline.trace(req.trace);
      // The core's own time for the curves (what the paper reports), else the call's.
      traceMs = typeof r.ms === 'number' && r.ms > 0 ? r.ms : performance.now() - t1;
      const where = flatPoints(r.points);
      const xyz = Float64Array.from(r.xyz, (x, i) => x - origin[i % 3]); // (the view's coordinates)
      trace = { xyz, lifted: liftPoints(m, r.points, r.xyz), where, segmentStarts: Int32Array.from(r.segmentStarts) };
      transfer.push(trace.xyz.buffer, trace.lifted.buffer, trace.where.buffer, trace.segmentStarts.buffer);
    }
    let polygon: PolygonPaths | null = null;
    if (req.polygon) {
      polygon = controlPolygon(m, json);
      transfer.push(polygon.lifted.buffer, polygon.starts.buffer);
    }
    post({ type: 'ran', id: req.id, json, trace, polygon, traceMs, ms: performance.now() - t0 }, transfer);
  } finally {
    spline?.dispose();
  }
}

/** Applies one edit; returns the spline (a new one for 'fromPolygon'). */
function apply(m: SurfaceMesh, spline: SurfaceSpline | null, op: SplineOp): SurfaceSpline {
  if (op.op === 'fromPolygon') {
    spline?.dispose();
    return SurfaceSpline.fromPolygon(m, op.anchors);
  }
  if (!spline) throw new Error(`no spline to ${op.op}`);
  switch (op.op) {
    case 'append':
      spline.appendAnchor(op.p);
      break;
    case 'moveAnchor':
      spline.moveAnchor(op.index, op.to);
      break;
    case 'moveHandle':
      spline.moveHandle(op.index, op.to);
      break;
    case 'setSmooth':
      spline.setSmooth(op.anchor, op.smooth);
      break;
    case 'insert':
      spline.insert(op.segment, op.t, op.options);
      break;
    case 'remove':
      spline.remove(op.anchor);
      break;
    case 'translate':
      spline.translate(op.from, op.to);
      break;
    case 'rotate':
      spline.rotate(op.center, op.radians);
      break;
    case 'scale':
      spline.scale(op.center, op.factor);
      break;
  }
  return spline;
}

/** The geodesics anchor → handle of every segment end. */
function controlPolygon(m: SurfaceMesh, json: SurfaceSplineJSON): PolygonPaths {
  const pts = json.points, n = pts.length;
  const parts: Float32Array[] = [];
  const pairs: [number, number][] = [];
  for (let a = 0; a < n; a += 3) {
    if (a + 1 < n) pairs.push([a, a + 1]);
    if (a - 1 >= 0) pairs.push([a, a - 1]);
  }
  if (json.closed && n > 0) pairs.push([0, n - 1]);
  for (const [a, b] of pairs) {
    const g = m.shortestPath(pts[a], pts[b]);
    parts.push(liftPoints(m, g.points, g.xyz));
  }
  const total = parts.reduce((s, p) => s + p.length, 0);
  const lifted = new Float32Array(total), starts = new Int32Array(parts.length);
  let o = 0;
  parts.forEach((p, i) => {
    starts[i] = o / 3;
    lifted.set(p, o);
    o += p.length;
  });
  return { lifted, starts };
}

function path(id: number, a: MeshPoint, b: MeshPoint): void {
  const m = needMesh();
  const g = m.shortestPath(a, b);
  const lifted = liftPoints(m, g.points, g.xyz);
  post({ type: 'path', id, lifted, length: g.length }, [lifted.buffer]);
}

function map(req: Extract<SurfaceRequest, { type: 'map' }>): void {
  const m = needMesh();
  const t0 = performance.now();
  const doc = parseSVG(req.svg, { name: req.name });
  if (doc.splines.length === 0) throw new Error(`${req.name}: no curves to place`);
  const splines = mapSplines(m, doc, { center: req.center, size: req.size, rotation: req.rotation, up: req.up });
  const json = splines.map((s) => s.toJSON());
  for (const s of splines) s.dispose();
  post({ type: 'mapped', id: req.id, splines: json, ms: performance.now() - t0 });
}

// ---- flat arrays -------------------------------------------------------------------------------

function flatPoints(points: readonly MeshPoint[]): Float64Array {
  const out = new Float64Array(3 * points.length);
  points.forEach((p, i) => {
    out[3 * i] = p.face;
    out[3 * i + 1] = p.uv[0];
    out[3 * i + 2] = p.uv[1];
  });
  return out;
}

/** xyz + lift × the interpolated smooth normal at each mesh point, in the view's coordinates. */
function liftPoints(m: SurfaceMesh, points: readonly MeshPoint[], xyz: ArrayLike<number>): Float32Array {
  if (lift === 0) return toDisplay(xyz, origin);
  const T = m.triangles, N = normals!;
  const out = new Float32Array(3 * points.length);
  const n: [number, number, number] = [0, 0, 0];
  for (let i = 0; i < points.length; i++) {
    meshPointNormal(N, T, points[i], n);
    out[3 * i] = xyz[3 * i] - origin[0] + lift * n[0];
    out[3 * i + 1] = xyz[3 * i + 1] - origin[1] + lift * n[1];
    out[3 * i + 2] = xyz[3 * i + 2] - origin[2] + lift * n[2];
  }
  return out;
}
