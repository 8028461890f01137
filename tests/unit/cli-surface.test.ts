// `splinekit geodesic` and `splinekit trace`: the command-line contract (acceptance checks use it
// exactly). Meshes are written here as OBJ/OFF/PLY text so every expected value is computed in
// this file from the file's own positions and the face/uv convention (1−u−v)·p0 + u·p1 + v·p2;
// shared meshes (spot with its v//vn seams, the bunny with unreferenced vertices, the hand with a
// boundary) check the same invariants on real data.
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, test } from 'vitest';
import { cli, readShared, sharedData, uShape } from './helpers.js';
import { mulberry32 as random } from '../../src/core/random.js';

const dir = mkdtempSync(join(tmpdir(), 'splinekit-surface-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

type Vec3 = [number, number, number];
type Point = number | { face: number; uv: [number, number] };

function write(name: string, value: unknown): string {
  const path = join(dir, name);
  writeFileSync(path, typeof value === 'string' ? value : JSON.stringify(value));
  return path;
}

// ---------------------------------------------------------------------------------------------
// Independent geometry
// ---------------------------------------------------------------------------------------------

const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const mul = (a: Vec3, s: number): Vec3 => [a[0] * s, a[1] * s, a[2] * s];
const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a: Vec3) => Math.hypot(a[0], a[1], a[2]);
const dist = (a: Vec3, b: Vec3) => norm(sub(a, b));

function polylineLength(points: Vec3[]): number {
  let s = 0;
  for (let i = 1; i < points.length; i++) s += dist(points[i - 1], points[i]);
  return s;
}

/** Distance of p from the segment ab. */
function segmentDistance(p: Vec3, a: Vec3, b: Vec3): number {
  const ab = sub(b, a);
  const t = Math.max(0, Math.min(1, dot(sub(p, a), ab) / dot(ab, ab)));
  return dist(p, add(a, mul(ab, t)));
}

/** Euclidean cubic Bézier by the power basis. */
function bezier(c: Vec3[], t: number): Vec3 {
  const out: Vec3 = [0, 0, 0];
  for (let k = 0; k < 3; k++) {
    const [p0, p1, p2, p3] = c.map((p) => p[k]);
    out[k] = p0 + t * (3 * (p1 - p0) + t * (3 * (p0 - 2 * p1 + p2) + t * (p3 - 3 * p2 + 3 * p1 - p0)));
  }
  return out;
}

/** Blossom f(a, b, c) of a cubic Bézier (de Casteljau with three parameters). */
function blossom(c: Vec3[], a: number, b: number, t: number): Vec3 {
  const lerp = (p: Vec3, q: Vec3, s: number) => add(mul(p, 1 - s), mul(q, s));
  const l1 = [lerp(c[0], c[1], a), lerp(c[1], c[2], a), lerp(c[2], c[3], a)];
  const l2 = [lerp(l1[0], l1[1], b), lerp(l1[1], l1[2], b)];
  return lerp(l2[0], l2[1], t);
}

/** Control points of the curve as a clamped cubic B-spline with 2^levels uniform intervals. */
function olrPolygon(c: Vec3[], levels: number): Vec3[] {
  const n = 2 ** levels;
  const knots = [0, 0, 0, ...Array.from({ length: n + 1 }, (_, k) => k / n), 1, 1, 1];
  return Array.from({ length: n + 3 }, (_, i) => blossom(c, knots[i + 1], knots[i + 2], knots[i + 3]));
}

/** The Bézier polygons of the 2^levels equal pieces, joined (RDC's polygon). */
function rdcPolygon(c: Vec3[], levels: number): Vec3[] {
  const n = 2 ** levels, out: Vec3[] = [c[0]];
  for (let k = 0; k < n; k++) {
    const a = k / n, b = (k + 1) / n;
    out.push(blossom(c, a, a, b), blossom(c, a, b, b), blossom(c, b, b, b));
  }
  return out;
}

/** Every vertex of `polygon` appears in `points` in order, and every point in between lies on its side. */
function expectOnPolygon(points: Vec3[], polygon: Vec3[], what: string): void {
  let at = 0, worst = 0;
  for (let k = 0; k < polygon.length; k++) {
    let found = -1;
    for (let i = at; i < points.length; i++) {
      if (k > 0) worst = Math.max(worst, segmentDistance(points[i], polygon[k - 1], polygon[k]));
      if (dist(points[i], polygon[k]) < 1e-9) {
        found = i;
        break;
      }
    }
    expect(found, `${what}: polygon vertex ${k} of ${polygon.length} not among the points (in order)`).toBeGreaterThanOrEqual(0);
    at = found;
  }
  expect(at, what).toBe(points.length - 1);
  expect(worst, what).toBeLessThan(1e-9);
}

/** Largest distance from the points to the Euclidean Bézier (densely sampled). */
function bezierDistance(points: Vec3[], c: Vec3[]): number {
  const samples = Array.from({ length: 20001 }, (_, k) => bezier(c, k / 20000));
  let worst = 0;
  for (const p of points) {
    let d = Infinity;
    for (let k = 1; k < samples.length; k++) d = Math.min(d, segmentDistance(p, samples[k - 1], samples[k]));
    worst = Math.max(worst, d);
  }
  return worst;
}

/** A mesh as the test knows it: positions and triangles in file order. */
interface Mesh {
  positions: Vec3[];
  faces: [number, number, number][];
}

function pointXYZ(mesh: Mesh, p: Point): Vec3 {
  if (typeof p === 'number') return mesh.positions[p];
  const [a, b, c] = mesh.faces[p.face].map((v) => mesh.positions[v]);
  const [u, v] = p.uv;
  return add(add(mul(a, 1 - u - v), mul(b, u)), mul(c, v));
}

/** Naive OBJ reader (positions and fan-triangulated faces, only the v index of v/vt/vn). */
function readObj(text: string): Mesh {
  const positions: Vec3[] = [], faces: [number, number, number][] = [];
  for (const line of text.split('\n')) {
    const w = line.trim().split(/\s+/);
    if (w[0] === 'v') positions.push([Number(w[1]), Number(w[2]), Number(w[3])]);
    if (w[0] === 'f') {
      const f = w.slice(1).map((t) => {
        const i = parseInt(t.split('/')[0], 10);
        return i < 0 ? positions.length + i : i - 1;
      });
      for (let i = 1; i + 1 < f.length; i++) faces.push([f[0], f[i], f[i + 1]]);
    }
  }
  return { positions, faces };
}

/** Position key: welded duplicates share it. */
const key = (p: Vec3) => p.join(',');

/** Positions of the vertices a mesh point actually depends on (weights above 1e-9). */
function support(mesh: Mesh, p: { face: number; uv: [number, number] }): string[] {
  const w = [1 - p.uv[0] - p.uv[1], p.uv[0], p.uv[1]];
  return mesh.faces[p.face].filter((_, k) => w[k] > 1e-9).map((v) => key(mesh.positions[v]));
}

function faceKeys(mesh: Mesh, f: number): string[] {
  return mesh.faces[f].map((v) => key(mesh.positions[v]));
}


// ---------------------------------------------------------------------------------------------
// Meshes written by the test
// ---------------------------------------------------------------------------------------------

/**
 * A jittered n×n grid over the unit square, on a tilted plane in 3D (origin o, orthonormal axes
 * e1, e2), diagonals alternating; boundary vertices stay on the square so the domain is convex.
 * Written as OFF.
 */
const plane = (() => {
  const n = 8;
  const e1: Vec3 = [2 / 3, 2 / 3, 1 / 3];
  const e2: Vec3 = [-2 / 3, 1 / 3, 2 / 3];
  const o: Vec3 = [0.25, -0.5, 1];
  const rnd = random(11);
  const positions: Vec3[] = [];
  const uv: [number, number][] = [];
  for (let j = 0; j <= n; j++)
    for (let i = 0; i <= n; i++) {
      const inner = i > 0 && j > 0 && i < n && j < n;
      const x = (i + (inner ? 0.6 * (rnd() - 0.5) : 0)) / n, y = (j + (inner ? 0.6 * (rnd() - 0.5) : 0)) / n;
      uv.push([x, y]);
      positions.push(add(o, add(mul(e1, x), mul(e2, y))));
    }
  const faces: [number, number, number][] = [];
  const at = (i: number, j: number) => j * (n + 1) + i;
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) {
      const a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if ((i + j) % 2) faces.push([a, b, c], [a, c, d]);
      else faces.push([a, b, d], [b, c, d]);
    }
  const text = ['OFF', `${positions.length} ${faces.length} 0`, ...positions.map((p) => p.join(' ')), ...faces.map((f) => `3 ${f.join(' ')}`)].join('\n') + '\n';
  return { mesh: { positions, faces } as Mesh, file: write('plane.off', text), e1, e2, o, n, cell: (i: number, j: number) => 2 * (j * n + i) };
})();

/** The surface of the unit cube, two triangles per side, outward winding. Written as ASCII PLY. */
const cube = (() => {
  const positions: Vec3[] = [];
  for (let i = 0; i < 8; i++) positions.push([i & 1, (i >> 1) & 1, (i >> 2) & 1]);
  const quads = [
    [0, 2, 3, 1], // z = 0
    [4, 5, 7, 6], // z = 1
    [0, 1, 5, 4], // y = 0
    [2, 6, 7, 3], // y = 1
    [0, 4, 6, 2], // x = 0
    [1, 3, 7, 5], // x = 1
  ];
  const faces: [number, number, number][] = [];
  for (const [a, b, c, d] of quads) faces.push([a, b, c], [a, c, d]);
  const text = [
    'ply',
    'format ascii 1.0',
    `element vertex ${positions.length}`,
    'property float x',
    'property float y',
    'property float z',
    `element face ${faces.length}`,
    'property list uchar int vertex_indices',
    'end_header',
    ...positions.map((p) => p.join(' ')),
    ...faces.map((f) => `3 ${f.join(' ')}`),
  ].join('\n') + '\n';
  return { mesh: { positions, faces } as Mesh, file: write('cube.ply', text) };
})();

/**
 * A bumpy 3×3 patch with repairs for the core to make: an unused vertex first, the middle row's
 * vertices written twice (the lower cells use one copy, the upper cells the other), and one face
 * wound against its neighbours. Written as OBJ.
 */
const messy = (() => {
  const positions: Vec3[] = [[9, 9, 9]]; // unused
  const index = new Map<string, number>();
  const vertex = (i: number, j: number, copy: number) => {
    const k = `${i},${j},${copy}`;
    if (!index.has(k)) {
      index.set(k, positions.length);
      positions.push([i / 3, j / 3, 0.15 * Math.sin(1.7 * i + 2.3 * j)]);
    }
    return index.get(k)!;
  };
  const faces: [number, number, number][] = [];
  for (let j = 0; j < 3; j++)
    for (let i = 0; i < 3; i++) {
      // Row j = 1 is the seam: cells below use copy 0, cells above copy 1.
      const v = (a: number, b: number) => vertex(a, b, b === 1 && j === 1 ? 1 : 0);
      faces.push([v(i, j), v(i + 1, j), v(i + 1, j + 1)], [v(i, j), v(i + 1, j + 1), v(i, j + 1)]);
    }
  const flipped = 9; // the second face of the middle cell (i = 1, j = 1)
  const f = faces[flipped];
  faces[flipped] = [f[0], f[2], f[1]];
  const text = ['# unused vertex, duplicated seam, one flipped face', ...positions.map((p) => `v ${p.join(' ')}`), ...faces.map((t) => `f ${t.map((v) => v + 1).join(' ')}`)].join('\n') + '\n';
  return { mesh: { positions, faces } as Mesh, file: write('messy.obj', text), flipped, far: index.get('3,3,0')! };
})();

const spotFile = join(sharedData, 'meshes/spot.obj');
const bunnyFile = join(sharedData, 'meshes/stanford_bunny.obj');
const handFile = join(sharedData, 'meshes/hand_lowres.obj');

const shared = new Map<string, Mesh>();
function sharedMesh(file: string): Mesh {
  if (!shared.has(file)) shared.set(file, readObj(readFileSync(file, 'utf8')));
  return shared.get(file)!;
}

// ---------------------------------------------------------------------------------------------
// Running the commands
// ---------------------------------------------------------------------------------------------

interface GeodesicJSON {
  paths: { length: number; points: Vec3[] }[];
  stats: { total_ms: number; per_path: { ms: number; visitedNodes: number; stripFaces: number; passes: number; flips: number }[] };
}
interface TraceJSON {
  curves: { points: { face: number; uv: [number, number]; xyz: Vec3 }[] }[];
  stats: { total_ms: number; per_curve_ms: number[]; per_curve: { searchedPaths: number; guided: number; seededPaths: number; visitedNodes: number; stripFaces: number; passes: number; flips: number }[]; redrawn: number };
}

let runs = 0;
/** Wall-clock ms of the last run of the CLI, start of Node to exit: a bound on any time it reports. */
let lastRunMs = 0;
function run<T>(args: string[]): T {
  const out = join(dir, `out-${runs++}.json`);
  const t0 = performance.now();
  const r = cli([...args, '--json', out]);
  lastRunMs = performance.now() - t0;
  expect(r.stderr, args.join(' ')).toBe('');
  expect(r.code).toBe(0);
  return JSON.parse(readFileSync(out, 'utf8')) as T;
}

function geodesic(mesh: string, pairs: [Point, Point][]): GeodesicJSON {
  return run<GeodesicJSON>(['geodesic', mesh, '--pairs', write(`pairs-${runs}.json`, { pairs })]);
}

function trace(mesh: string, curves: Point[][], extra: string[] = []): TraceJSON {
  return run<TraceJSON>(['trace', mesh, '--curves', write(`curves-${runs}.json`, { curves }), ...extra]);
}

/**
 * A time the CLI reports: the core's measurement of work it did (so more than 0 ms), rounded to
 * the microsecond as the CLI writes it, and within the wall-clock time of the whole command.
 */
function expectReportedMs(ms: number, what: string): void {
  expect(Number.isFinite(ms), what).toBe(true);
  expect(ms, what).toBeGreaterThan(0);
  expect(Math.abs(ms * 1e3 - Math.round(ms * 1e3)), `${what} is rounded to the microsecond`).toBeLessThan(1e-6);
  expect(ms, `${what} is within the command's wall-clock time`).toBeLessThan(lastRunMs);
}

/** Every invariant of a traced curve that holds on any mesh. */
function checkTraced(mesh: Mesh, controls: Point[], curve: TraceJSON['curves'][number], tol: number): void {
  const pts = curve.points;
  expect(pts.length).toBeGreaterThanOrEqual(2);
  expect(dist(pts[0].xyz, pointXYZ(mesh, controls[0]))).toBeLessThan(tol);
  expect(dist(pts[pts.length - 1].xyz, pointXYZ(mesh, controls[3]))).toBeLessThan(tol);
  let worstXYZ = 0;
  for (const p of pts) {
    expect(Number.isInteger(p.face) && p.face >= 0 && p.face < mesh.faces.length).toBe(true);
    const [u, v] = p.uv;
    expect(u).toBeGreaterThanOrEqual(-1e-9);
    expect(v).toBeGreaterThanOrEqual(-1e-9);
    expect(u + v).toBeLessThanOrEqual(1 + 1e-9);
    worstXYZ = Math.max(worstXYZ, dist(p.xyz, pointXYZ(mesh, p)));
  }
  expect(worstXYZ).toBeLessThan(tol);
  // Consecutive points lie on a common face: one's support is inside the other's face.
  for (let i = 1; i < pts.length; i++) {
    const a = pts[i - 1], b = pts[i];
    const inB = support(mesh, a).every((k) => faceKeys(mesh, b.face).includes(k));
    const inA = support(mesh, b).every((k) => faceKeys(mesh, a.face).includes(k));
    expect(inA || inB, `points ${i - 1} (face ${a.face}) and ${i} (face ${b.face}) share no face`).toBe(true);
  }
}

// ---------------------------------------------------------------------------------------------
// geodesic
// ---------------------------------------------------------------------------------------------

describe('splinekit geodesic', () => {
  test('on a plane the path is the straight segment, from vertex indices and face/uv points alike', () => {
    const { mesh, cell } = plane;
    const pairs: [Point, Point][] = [
      [{ face: cell(0, 0), uv: [0.2, 0.3] }, { face: cell(7, 7) + 1, uv: [0.5, 0.1] }],
      [10, 70], // interior vertices
      [0, 80], // corner to corner: along the boundary-free diagonal
      [{ face: cell(6, 1), uv: [0.25, 0.25] }, 60],
      [{ face: cell(2, 5) + 1, uv: [0, 0.5] }, { face: cell(5, 2), uv: [1, 0] }], // on an edge; at a vertex
      [{ face: cell(3, 3), uv: [0.1, 0.1] }, { face: cell(3, 3), uv: [0.6, 0.3] }], // same face
    ];
    const json = geodesic(plane.file, pairs);
    expect(json.paths).toHaveLength(pairs.length);
    expectReportedMs(json.stats.total_ms, 'total_ms of six paths');
    // Work per path: within one face nothing is searched or straightened; across the plane the search
    // expands nodes and the strip holds every face the straight segment crosses (at least those its
    // edge crossings name), in one pass that finds nothing to flip.
    expect(json.stats.per_path).toHaveLength(pairs.length);
    expect(json.stats.per_path[5]).toMatchObject({ visitedNodes: 0, stripFaces: 1, passes: 0, flips: 0 });
    for (const i of [0, 1, 2, 3]) {
      const w = json.stats.per_path[i];
      expect(w.visitedNodes, `pair ${i}`).toBeGreaterThan(0);
      expect(w.stripFaces, `pair ${i}`).toBeGreaterThanOrEqual(json.paths[i].points.length - 1);
      expect(w.passes, `pair ${i}`).toBeGreaterThanOrEqual(1);
    }
    json.paths.forEach((path, i) => {
      const a = pointXYZ(mesh, pairs[i][0]), b = pointXYZ(mesh, pairs[i][1]);
      expect(Math.abs(path.length - dist(a, b)), `pair ${i}`).toBeLessThan(1e-9);
      expect(dist(path.points[0], a)).toBeLessThan(1e-12);
      expect(dist(path.points[path.points.length - 1], b)).toBeLessThan(1e-12);
      for (const p of path.points) expect(segmentDistance(p, a, b)).toBeLessThan(1e-9);
      expect(Math.abs(polylineLength(path.points) - path.length)).toBeLessThan(1e-9);
    });
    // A long path crosses edges: its points are the crossings, in order along the segment.
    const long = json.paths[0].points;
    expect(long.length).toBeGreaterThan(8);
    const a = long[0], ab = sub(long[long.length - 1], a);
    for (let i = 1; i < long.length; i++) expect(dot(sub(long[i], a), ab)).toBeGreaterThanOrEqual(dot(sub(long[i - 1], a), ab) - 1e-12);
  });

  test('on the cube: corner to opposite corner is √5, opposite side centres are 2', () => {
    const { mesh } = cube;
    // Side z = 0 is faces 0-1 with diagonal 0-3 (face 0 = [0, 2, 3]): its centre is uv (0, 0.5) of face 0.
    const bottom: Point = { face: 0, uv: [0, 0.5] };
    const top: Point = { face: 2, uv: [0, 0.5] }; // face 2 = [4, 5, 7]: midpoint of 4-7
    expect(pointXYZ(mesh, bottom)).toEqual([0.5, 0.5, 0]);
    expect(pointXYZ(mesh, top)).toEqual([0.5, 0.5, 1]);
    // Inside side x = 0 (face 8 = [0, 4, 6]) and side x = 1 (face 10 = [1, 3, 7]).
    const left: Point = { face: 8, uv: [0.2, 0.3] }, right: Point = { face: 10, uv: [0.25, 0.3] };
    const json = geodesic(cube.file, [[0, 7], [bottom, top], [7, 0], [left, right]]);
    expect(Math.abs(json.paths[0].length - Math.sqrt(5))).toBeLessThan(1e-9);
    expect(Math.abs(json.paths[2].length - Math.sqrt(5))).toBeLessThan(1e-9);
    expect(Math.abs(json.paths[1].length - 2)).toBeLessThan(1e-9);
    const l = pointXYZ(mesh, left), r = pointXYZ(mesh, right);
    expect(l[0]).toBe(0);
    expect(r[0]).toBe(1);
    expect(Math.abs(json.paths[3].length - expectedCubeDistance(l, r))).toBeLessThan(1e-9);
    for (const [i, path] of json.paths.entries()) {
      expect(Math.abs(polylineLength(path.points) - path.length), `path ${i}`).toBeLessThan(1e-9);
      // Every point is on the cube's surface.
      for (const p of path.points) expect(Math.min(...p.map((x) => Math.min(Math.abs(x), Math.abs(x - 1))))).toBeLessThan(1e-9);
    }
    expect(json.paths[0].points[0]).toEqual([0, 0, 0]);
    expect(json.paths[0].points.at(-1)).toEqual([1, 1, 1]);
  });

  test('on spot.obj (v//vn seams) no path is shorter than the straight distance, and length is the polyline length', () => {
    const mesh = sharedMesh(spotFile);
    const rnd = random(3);
    const pairs: [Point, Point][] = [];
    for (let i = 0; i < 12; i++) {
      const a = Math.floor(rnd() * mesh.positions.length);
      let u = rnd(), v = rnd();
      if (u + v > 1) {
        u = 1 - u;
        v = 1 - v;
      }
      pairs.push([a, { face: Math.floor(rnd() * mesh.faces.length), uv: [u, v] }]);
    }
    const json = geodesic(spotFile, pairs);
    json.paths.forEach((path, i) => {
      const a = pointXYZ(mesh, pairs[i][0]), b = pointXYZ(mesh, pairs[i][1]);
      expect(path.length).toBeGreaterThanOrEqual(dist(a, b) * (1 - 1e-12));
      expect(Math.abs(polylineLength(path.points) - path.length)).toBeLessThan(1e-9 * Math.max(1, path.length));
      expect(dist(path.points[0], a)).toBeLessThan(1e-9);
      expect(dist(path.points.at(-1)!, b)).toBeLessThan(1e-9);
    });
  });

  test('vertex indices are file indices on the bunny (1,113 unreferenced vertices) and the hand (a boundary)', () => {
    for (const file of [bunnyFile, handFile]) {
      const mesh = sharedMesh(file);
      const used = new Set(mesh.faces.flat());
      const last = Math.max(...used);
      const first = Math.min(...used);
      const json = geodesic(file, [[first, last], [last, first]]);
      expect(json.paths[0].points[0]).toEqual(mesh.positions[first]);
      expect(json.paths[0].points.at(-1)).toEqual(mesh.positions[last]);
      expect(json.paths[0].length).toBeGreaterThanOrEqual(dist(mesh.positions[first], mesh.positions[last]) * (1 - 1e-12));
      expect(Math.abs(json.paths[0].length - json.paths[1].length)).toBeLessThan(1e-6 * json.paths[0].length);
    }
  });
});

// ---------------------------------------------------------------------------------------------
// File order on a mesh the core repairs
// ---------------------------------------------------------------------------------------------

describe('file-order semantics', () => {
  test('a face/uv point on the flipped face means (1−u−v)p0 + u p1 + v p2 of the file', () => {
    const { mesh, flipped, file, far } = messy;
    const on: Point = { face: flipped, uv: [0.7, 0.1] };
    const expected = pointXYZ(mesh, on);
    // p1 weighs 0.7: far from the mirrored reading (p2 weighing 0.7).
    const [, p1, p2] = mesh.faces[flipped].map((v) => mesh.positions[v]);
    expect(dist(p1, p2)).toBeGreaterThan(0.1);
    const elsewhere: Point = { face: 0, uv: [0.2, 0.2] };
    const json = geodesic(file, [[on, elsewhere], [elsewhere, on], [on, far]]);
    expect(dist(json.paths[0].points[0], expected)).toBeLessThan(1e-12);
    // Across the welded seam (face 0 is below it, the flipped face above).
    expect(dist(json.paths[0].points.at(-1)!, pointXYZ(mesh, elsewhere))).toBeLessThan(1e-12);
    expect(Math.abs(json.paths[0].length - json.paths[1].length)).toBeLessThan(1e-9);
    expect(dist(json.paths[1].points.at(-1)!, expected)).toBeLessThan(1e-12);
    expect(dist(json.paths[2].points[0], expected)).toBeLessThan(1e-12);
    expect(json.paths[2].points.at(-1)).toEqual(mesh.positions[far]);
    // The paths cross the welded seam: on a connected surface, never shorter than the straight distance.
    for (const p of json.paths) expect(p.length).toBeGreaterThanOrEqual(dist(p.points[0], p.points.at(-1)!) * (1 - 1e-12));
    const traced = trace(file, [[on, { face: 2, uv: [0.3, 0.3] }, { face: 14, uv: [0.1, 0.6] }, { face: flipped, uv: [0.05, 0.85] }]]);
    checkTraced(mesh, [on, { face: 2, uv: [0.3, 0.3] }, { face: 14, uv: [0.1, 0.6] }, { face: flipped, uv: [0.05, 0.85] }], traced.curves[0], 1e-12);
  });
});

function expectedCubeDistance(a: Vec3, b: Vec3): number {
  // Only used for points on opposite sides x = 0 and x = 1: the shortest of the unfoldings over
  // the four sides between them (each: 1 across plus the walk along the side).
  let best = Infinity;
  // Over side y = 0: unfold to length a.y + 1 + b.y along, |a.z − b.z| across.
  best = Math.min(best, Math.hypot(a[1] + 1 + b[1], a[2] - b[2]));
  best = Math.min(best, Math.hypot(1 - a[1] + 1 + 1 - b[1], a[2] - b[2]));
  best = Math.min(best, Math.hypot(a[2] + 1 + b[2], a[1] - b[1]));
  best = Math.min(best, Math.hypot(1 - a[2] + 1 + 1 - b[2], a[1] - b[1]));
  return best;
}

// ---------------------------------------------------------------------------------------------
// trace
// ---------------------------------------------------------------------------------------------

describe('splinekit trace', () => {
  const { mesh, cell } = plane;
  const controls: Point[][] = [
    [{ face: cell(0, 1), uv: [0.2, 0.3] }, 40, { face: cell(7, 0) + 1, uv: [0.3, 0.3] }, { face: cell(6, 7), uv: [0.1, 0.5] }],
    [10, 16, 64, 70],
    [{ face: cell(1, 6), uv: [0.3, 0.3] }, { face: cell(7, 7), uv: [0.3, 0.3] }, { face: cell(0, 0), uv: [0.3, 0.3] }, { face: cell(6, 1), uv: [0.3, 0.3] }],
  ];

  test('on a plane the polyline is the subdivided control polygon, from P0 to P3, with every point on a shared face', () => {
    const json = trace(plane.file, controls);
    expect(json.curves).toHaveLength(controls.length);
    json.curves.forEach((curve, i) => {
      checkTraced(mesh, controls[i], curve, 1e-9);
      const c = controls[i].map((p) => pointXYZ(mesh, p));
      // Geodesics on a plane are segments: OLR with 5 levels gives the 35 B-spline control points
      // of the curve over 32 uniform intervals, joined by segments through every edge crossing.
      const polygon = olrPolygon(c, 5);
      expect(polygon).toHaveLength(35);
      expectOnPolygon(curve.points.map((p) => p.xyz), polygon, `curve ${i}`);
      // It crosses the grid: many more points than the 35 of the subdivision alone.
      expect(curve.points.length).toBeGreaterThan(35);
    });
    // Within 1e-3 of the Euclidean Bézier for curves of moderate curvature (the third curve's
    // control polygon is a loop spanning the square: its 5-level polygon itself strays ~1e-3).
    for (const i of [0, 1]) {
      const c = controls[i].map((p) => pointXYZ(mesh, p));
      expect(bezierDistance(json.curves[i].points.map((p) => p.xyz), c), `curve ${i}`).toBeLessThan(1e-3);
    }
    expect(json.stats.per_curve_ms).toHaveLength(controls.length);
    json.stats.per_curve_ms.forEach((ms, i) => expectReportedMs(ms, `per_curve_ms of curve ${i}`));
    // total_ms is the sum of the per-curve times (each rounded on its own, the sum once more).
    const sum = json.stats.per_curve_ms.reduce((a, b) => a + b, 0);
    expect(Math.abs(json.stats.total_ms - sum)).toBeLessThanOrEqual(1e-3 * (controls.length + 1));
    expectReportedMs(json.stats.total_ms, 'total_ms');
    // Work per curve: the control polygon's 3 sides are searched; 5 OLR levels join the 34 sides of
    // the final polygon and those of every level before it, searched or straightened through known paths.
    expect(json.stats.per_curve).toHaveLength(controls.length);
    json.stats.per_curve.forEach((w, i) => {
      expect(w.searchedPaths, `curve ${i}`).toBeGreaterThanOrEqual(3);
      expect(w.searchedPaths + w.seededPaths, `curve ${i}`).toBeGreaterThanOrEqual(34);
      expect(w.visitedNodes, `curve ${i}`).toBeGreaterThan(0);
      expect(w.stripFaces, `curve ${i}`).toBeGreaterThanOrEqual(json.curves[i].points.length - 1);
    });
  });

  test('--scheme rdc, --levels and --adaptive are accepted and change the curve', () => {
    const base = trace(plane.file, controls);
    const key = (j: TraceJSON) => JSON.stringify(j.curves);
    for (const extra of [['--scheme', 'rdc'], ['--levels', '3'], ['--adaptive', '5'], ['--scheme', 'rdc', '--adaptive', '5']]) {
      const json = trace(plane.file, controls, extra);
      expect(key(json), extra.join(' ')).not.toBe(key(base));
      json.curves.forEach((curve, i) => checkTraced(mesh, controls[i], curve, 1e-9));
    }
    // On a plane: --levels 3 is the 11-point B-spline polygon, RDC is the Bézier polygons of its
    // 2^levels leaves (de Casteljau), 4 levels by default.
    const olr3 = trace(plane.file, controls, ['--levels', '3']);
    const rdc = trace(plane.file, controls, ['--scheme', 'rdc']);
    const rdc2 = trace(plane.file, controls, ['--scheme', 'rdc', '--levels', '2']);
    controls.forEach((control, i) => {
      const c = control.map((p) => pointXYZ(mesh, p));
      expectOnPolygon(olr3.curves[i].points.map((p) => p.xyz), olrPolygon(c, 3), `olr 3 levels, curve ${i}`);
      expectOnPolygon(rdc.curves[i].points.map((p) => p.xyz), rdcPolygon(c, 4), `rdc, curve ${i}`);
      expectOnPolygon(rdc2.curves[i].points.map((p) => p.xyz), rdcPolygon(c, 2), `rdc 2 levels, curve ${i}`);
    });
    // Fewer levels give fewer points (between the same ends).
    const coarse = trace(plane.file, controls, ['--levels', '1']);
    coarse.curves.forEach((c, i) => expect(c.points.length).toBeLessThan(base.curves[i].points.length));
    // Adaptive subdivision refines where the curve turns: it stays on the curve's hull and ends.
    const adaptive = trace(plane.file, controls, ['--adaptive', '5']);
    adaptive.curves.forEach((curve, i) => checkTraced(mesh, controls[i], curve, 1e-9));
  });

  test('on spot, the bunny and the hand: ends, barycentrics in file order, shared faces', () => {
    for (const file of [spotFile, bunnyFile, handFile]) {
      const mesh = sharedMesh(file);
      const size = boxSize(mesh);
      const rnd = random(5);
      const curves: Point[][] = [];
      for (let c = 0; c < 4; c++) {
        const f = Math.floor(rnd() * mesh.faces.length);
        // Control points near each other (a few faces apart), on faces around face f.
        const near = 0.05 * size, centre = pointXYZ(mesh, { face: f, uv: [1 / 3, 1 / 3] });
        const ring = mesh.faces.map((_, k) => k).filter((k) => dist(pointXYZ(mesh, { face: k, uv: [1 / 3, 1 / 3] }), centre) < near);
        curves.push([0, 1, 2, 3].map((k) => (k === 1 ? mesh.faces[ring[Math.floor(rnd() * ring.length)]][0] : { face: ring[Math.floor(rnd() * ring.length)], uv: [0.25, 0.5] as [number, number] })));
      }
      const json = trace(file, curves);
      json.curves.forEach((curve, i) => checkTraced(mesh, curves[i], curve, 1e-9 * size));
    }
  });

  test('--random 5 --seed 7 gives 5 curves, the same every time; another seed gives others', () => {
    const mesh = sharedMesh(spotFile);
    const a = run<TraceJSON>(['trace', spotFile, '--random', '5', '--seed', '7']);
    const b = run<TraceJSON>(['trace', spotFile, '--random', '5', '--seed', '7']);
    const c = run<TraceJSON>(['trace', spotFile, '--random', '5', '--seed', '8']);
    expect(a.curves).toHaveLength(5);
    expect(a.stats.per_curve_ms).toHaveLength(5);
    expect(b.curves).toEqual(a.curves);
    expect(c.curves).toHaveLength(5);
    expect(c.curves).not.toEqual(a.curves);
    expect(a.stats.redrawn).toBe(0); // (one part: the stream's first 20 points)
    for (const curve of a.curves) {
      const first = curve.points[0], last = curve.points.at(-1)!;
      checkTraced(mesh, [first, first, first, last], curve, 1e-9);
    }
  });

  test('a mesh of 65,536 triangles or more: long sides follow the coarse guide (--no-guide leaves it out), info names it', () => {
    // The flat U of helpers.ts, 260 × 128 cells (66,080 triangles), as OBJ; a curve with P0 = P1 in one
    // arm and P2 = P3 in the other is the geodesic round the slot's end, of a closed-form length.
    const u = uShape(260, 128, 129, 8);
    const lines: string[] = [];
    for (let i = 0; i < u.positions.length; i += 3) lines.push(`v ${u.positions[i]} ${u.positions[i + 1]} ${u.positions[i + 2]}`);
    for (let i = 0; i < u.triangles.length; i += 3) lines.push(`f ${u.triangles[i] + 1} ${u.triangles[i + 1] + 1} ${u.triangles[i + 2] + 1}`);
    const file = write('u.obj', `${lines.join('\n')}\n`);
    const a = u.pointAt(60.3, 120.2), b = u.pointAt(200.6, 115.1);
    const curves = write('u-curves.json', { curves: [[a, a, b, b]] });
    const expected = Math.hypot(60.3 - 129, 120.2 - 8) + 2 + Math.hypot(200.6 - 131, 115.1 - 8);
    for (const [flags, guided] of [[[], true], [['--no-guide'], false]] as const) {
      const out = run<TraceJSON>(['trace', file, '--curves', curves, ...flags]);
      expect(out.stats.per_curve[0].guided > 0, flags.join(' ')).toBe(guided);
      expect(Math.abs(polylineLength(out.curves[0].points.map((p) => p.xyz)) - expected)).toBeLessThan(1e-9 * expected);
    }
    const info = cli(['info', file]);
    expect(info.code).toBe(0);
    expect(info.stdout).toMatch(/search: 4 landmarks, a coarse guide of \d+ triangles, \d+\.\d MB/);
  });

  test('on a mesh of two parts, --random draws each polygon on one part, and a given curve across them is refused', () => {
    // The plane and a copy of it 5 units away: faces [0, F) and [F, 2F), vertices likewise.
    const { positions, faces } = plane.mesh;
    const V = positions.length, F = faces.length;
    const two: Mesh = {
      positions: [...positions, ...positions.map(([x, y, z]) => [x + 5, y, z] as Vec3)],
      faces: [...faces, ...faces.map((f) => f.map((v) => v + V) as [number, number, number])],
    };
    const text = ['OFF', `${2 * V} ${2 * F} 0`, ...two.positions.map((p) => p.join(' ')), ...two.faces.map((f) => `3 ${f.join(' ')}`)].join('\n') + '\n';
    const file = write('two-parts.off', text);
    const json = run<TraceJSON>(['trace', file, '--random', '6', '--seed', '3']);
    expect(json.curves).toHaveLength(6);
    // Two parts of equal area: a polygon lands on one part with probability 1/8.
    expect(json.stats.redrawn).toBeGreaterThan(0);
    for (const curve of json.curves) {
      const onFirst = curve.points[0].face < F;
      expect(curve.points.every((p) => p.face < F === onFirst), 'every point of a curve on one part').toBe(true);
      const first = curve.points[0], last = curve.points.at(-1)!;
      checkTraced(two, [first, first, first, last], curve, 1e-9);
    }
    const across = write('across.json', { curves: [[0, 1, 2, 3], [0, 1, V + 2, V + 3]] });
    const r = cli(['trace', file, '--curves', across]);
    expect(r.code).toBe(1);
    expect(r.stderr.trimEnd().split('\n')).toHaveLength(1);
    expect(r.stderr).toMatch(/across\.json: curve 1: .*not connected/);
  });
});

function boxSize(mesh: Mesh): number {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const p of mesh.positions)
    for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], p[k]);
      hi[k] = Math.max(hi[k], p[k]);
    }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

// ---------------------------------------------------------------------------------------------
// errors
// ---------------------------------------------------------------------------------------------

describe('errors: one line on stderr, exit 1 for bad input, 2 for bad usage', () => {
  test('bad points, files and meshes', () => {
    const pairs = (p: unknown) => write(`bad-${runs++}.json`, { pairs: p });
    const curves = (c: unknown) => write(`bad-${runs++}.json`, { curves: c });
    const nanMesh = write('nan.obj', 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n');
    const nanOff = write('nan.off', 'OFF\n3 1 0\n0 0 0\n1 NaN 0\n0 1 0\n3 0 1 2\n');
    const farMesh = write('far.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 7\n');
    const cases: [string[], number, RegExp][] = [
      [['geodesic', plane.file, '--pairs', pairs([[{ face: 9999, uv: [0.1, 0.1] }, 0]])], 1, /face 9999/],
      [['geodesic', plane.file, '--pairs', pairs([[0, { face: -1, uv: [0.1, 0.1] }]])], 1, /face -1/],
      [['geodesic', plane.file, '--pairs', pairs([[{ face: 3, uv: [0.8, 0.5] }, 0]])], 1, /outside face 3/],
      [['geodesic', plane.file, '--pairs', pairs([[{ face: 3, uv: [-0.2, 0.5] }, 0]])], 1, /outside face 3/],
      [['geodesic', plane.file, '--pairs', pairs([[0, 81]])], 1, /vertex 81/],
      [['geodesic', plane.file, '--pairs', pairs([[0, -1]])], 1, /vertex -1/],
      [['geodesic', plane.file, '--pairs', pairs([[0]])], 1, /pair 0/],
      [['geodesic', plane.file, '--pairs', write('junk.json', 'not json{')], 1, /not valid JSON/],
      [['geodesic', plane.file, '--pairs', write('nopairs.json', { curves: [] })], 1, /pairs/],
      [['trace', plane.file, '--curves', write('junk2.json', '{"curves": [[0, 1, 2, 3]')], 1, /not valid JSON/],
      [['trace', plane.file, '--curves', curves([[0, 1, 2]])], 1, /curve 0 .*4 control points/],
      [['trace', plane.file, '--curves', curves([[0, 1, 2, 3], [0, 1, { face: 0, uv: [2, 2] }, 3]])], 1, /curve 1 point 2/],
      [['trace', plane.file, '--curves', curves([[0, 1, 2, 3000]])], 1, /vertex 3000/],
      [['geodesic', join(dir, 'missing.obj'), '--pairs', pairs([[0, 1]])], 1, /cannot read .*missing\.obj/],
      [['trace', join(dir, 'missing.off'), '--curves', curves([[0, 1, 2, 3]])], 1, /cannot read .*missing\.off/],
      [['geodesic', plane.file, '--pairs', join(dir, 'missing.json')], 1, /cannot read pairs/],
      [['geodesic', nanMesh, '--pairs', pairs([[0, 1]])], 1, /nan\.obj line 3: non-finite coordinate/],
      [['trace', nanOff, '--curves', curves([[0, 1, 2, 2]])], 1, /nan\.off line 4: non-finite coordinate/],
      [['geodesic', farMesh, '--pairs', pairs([[0, 1]])], 1, /far\.obj line 5: face index 7 out of range/],
    ];
    for (const [args, code, message] of cases) {
      const r = cli(args);
      expect(r.code, args.join(' ')).toBe(code);
      expect(r.stderr.trimEnd().split('\n'), args.join(' ')).toHaveLength(1);
      expect(r.stderr, args.join(' ')).toMatch(message);
    }
  });

  test('usage errors exit with 2', () => {
    const curves = write('usage-curves.json', { curves: [[0, 1, 2, 3]] });
    const cases: [string[], RegExp][] = [
      [['geodesic', plane.file], /--pairs/],
      [['geodesic', '--pairs', write('usage-pairs.json', { pairs: [[0, 1]] })], /mesh/],
      [['trace', plane.file, '--curves', curves, '--levels', '3', '--adaptive', '5'], /--levels and --adaptive/],
      [['trace', plane.file, '--curves', curves, '--scheme', 'xyz'], /--scheme/],
      [['trace', plane.file], /--curves or --random/],
      [['trace', plane.file, '--curves', curves, '--random', '3'], /--curves or --random/],
      [['trace', plane.file, '--curves', curves, '--levels', 'two'], /--levels/],
      [['trace', plane.file, '--curves', curves, '--adaptive', '0'], /--adaptive/],
      [['trace', plane.file, '--random', '0'], /--random/],
      [['geodesic', plane.file, '--pairs', curves, '--bogus'], /bogus/],
    ];
    for (const [args, message] of cases) {
      const r = cli(args);
      expect(r.code, args.join(' ')).toBe(2);
      expect(r.stderr.trimEnd().split('\n').length, args.join(' ')).toBeGreaterThanOrEqual(1);
      expect(r.stderr.split('\n')[0], args.join(' ')).toMatch(message);
    }
  });
});

// Shared data sanity (the file-order checks above rely on it).
test('the shared meshes are what the tests assume', () => {
  expect(readShared('meshes/spot.obj')).toMatch(/^f \d+\/\/\d+ /m);
  const bunny = sharedMesh(bunnyFile);
  expect(bunny.positions.length - new Set(bunny.faces.flat()).size).toBe(1113);
});
