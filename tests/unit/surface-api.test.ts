// The surface API (src/surface): SurfaceMesh's repairs report and file-order points, geodesics,
// SurfaceSpline editing and mapSplines. Most checks run on a plane, where geodesics are segments,
// parallel transport is translation and normal coordinates are Euclidean, so every expected value
// is computed here with plain vector arithmetic; the shared meshes check info against the data
// manifest and points against an independent OBJ reader.
import { beforeAll, describe, expect, test } from 'vitest';
import {
  SplinekitError,
  SurfaceMesh,
  SurfaceSpline,
  evalBezier,
  init,
  mapSplines,
  memory,
  parseSVG,
  traceBezier,
  type MeshPoint,
  type MeshPointLike,
} from '../../src/index.js';
import { readShared } from './helpers.js';
import { mulberry32 as random } from '../../src/core/random.js';

beforeAll(async () => {
  await init();
});

type Vec3 = [number, number, number];
const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const add = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
const mul = (a: Vec3, s: number): Vec3 => [a[0] * s, a[1] * s, a[2] * s];
const norm = (a: Vec3) => Math.hypot(a[0], a[1], a[2]);
const dist = (a: Vec3, b: Vec3) => norm(sub(a, b));
const unit = (a: Vec3): Vec3 => mul(a, 1 / norm(a));
const lerp = (a: Vec3, b: Vec3, t: number): Vec3 => add(mul(a, 1 - t), mul(b, t));

/** Naive OBJ reader: positions and fan triangles (v index of v/vt/vn only). */
function readObj(text: string): { positions: Vec3[]; faces: number[][] } {
  const positions: Vec3[] = [], faces: number[][] = [];
  for (const line of text.split('\n')) {
    const w = line.trim().split(/\s+/);
    if (w[0] === 'v') positions.push([Number(w[1]), Number(w[2]), Number(w[3])]);
    if (w[0] === 'f') {
      const f = w.slice(1).map((t) => parseInt(t.split('/')[0], 10) - 1);
      for (let i = 1; i + 1 < f.length; i++) faces.push([f[0], f[i], f[i + 1]]);
    }
  }
  return { positions, faces };
}


/**
 * A jittered 8×8 grid over [0, 4]² in the plane z = 0, faces wound counter-clockwise seen from +z,
 * diagonals alternating; boundary vertices stay on the square (convex domain).
 */
function planeArrays(n = 8, size = 4, seed = 2): { positions: number[]; triangles: number[] } {
  const rnd = random(seed);
  const positions: number[] = [];
  for (let j = 0; j <= n; j++)
    for (let i = 0; i <= n; i++) {
      const inner = i > 0 && j > 0 && i < n && j < n;
      positions.push(((i + (inner ? 0.6 * (rnd() - 0.5) : 0)) * size) / n, ((j + (inner ? 0.6 * (rnd() - 0.5) : 0)) * size) / n, 0);
    }
  const triangles: number[] = [];
  const at = (i: number, j: number) => j * (n + 1) + i;
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) {
      const a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if ((i + j) % 2) triangles.push(a, b, c, a, c, d);
      else triangles.push(a, b, d, b, c, d);
    }
  return { positions, triangles };
}

/** x, y, z of a mesh point from the arrays, by (1−u−v)p0 + u p1 + v p2 of the face in file order. */
function evalPoint(positions: ArrayLike<number>, triangles: ArrayLike<number>, p: MeshPointLike): Vec3 {
  if (typeof p === 'number') return [positions[3 * p], positions[3 * p + 1], positions[3 * p + 2]];
  const w = [1 - p.uv[0] - p.uv[1], p.uv[0], p.uv[1]];
  const out: Vec3 = [0, 0, 0];
  for (let k = 0; k < 3; k++) {
    const v = triangles[3 * p.face + k];
    for (let a = 0; a < 3; a++) out[a] += w[k] * positions[3 * v + a];
  }
  return out;
}

/** Locates a point of the plane z = 0 on the mesh (the face containing it, barycentrics in file order). */
function locate(positions: ArrayLike<number>, triangles: ArrayLike<number>, x: number, y: number): MeshPoint {
  for (let f = 0; f < triangles.length / 3; f++) {
    const [a, b, c] = [0, 1, 2].map((k) => triangles[3 * f + k]);
    const ax = positions[3 * a], ay = positions[3 * a + 1];
    const e1 = [positions[3 * b] - ax, positions[3 * b + 1] - ay], e2 = [positions[3 * c] - ax, positions[3 * c + 1] - ay];
    const det = e1[0] * e2[1] - e1[1] * e2[0];
    const u = ((x - ax) * e2[1] - (y - ay) * e2[0]) / det, v = (e1[0] * (y - ay) - e1[1] * (x - ax)) / det;
    if (u >= -1e-12 && v >= -1e-12 && u + v <= 1 + 1e-12) return { face: f, uv: [u, v] };
  }
  throw new Error(`(${x}, ${y}) is off the plane mesh`);
}

/** Euclidean cubic Bézier (power basis) and its de Casteljau split. */
function bezier(c: Vec3[], t: number): Vec3 {
  const out: Vec3 = [0, 0, 0];
  for (let k = 0; k < 3; k++) {
    const [p0, p1, p2, p3] = c.map((p) => p[k]);
    out[k] = p0 + t * (3 * (p1 - p0) + t * (3 * (p0 - 2 * p1 + p2) + t * (p3 - 3 * p2 + 3 * p1 - p0)));
  }
  return out;
}
function split(c: Vec3[], t: number): Vec3[] {
  const a = lerp(c[0], c[1], t), b = lerp(c[1], c[2], t), d = lerp(c[2], c[3], t);
  const ab = lerp(a, b, t), bd = lerp(b, d, t), m = lerp(ab, bd, t);
  return [c[0], a, ab, m, bd, d, c[3]];
}

function expectNear(actual: Vec3, expected: Vec3, tol: number, what = ''): void {
  expect(dist(actual, expected), `${what}: ${actual} vs ${expected}`).toBeLessThan(tol);
}

function failure(fn: () => unknown): SplinekitError {
  let error: unknown;
  try {
    fn();
  } catch (e) {
    error = e;
  }
  expect(error, 'expected a SplinekitError').toBeInstanceOf(SplinekitError);
  return error as SplinekitError;
}

// ---------------------------------------------------------------------------------------------
// SurfaceMesh on the shared meshes
// ---------------------------------------------------------------------------------------------

interface ManifestMesh {
  raw_vertices: number;
  vertices: number;
  unreferenced_vertices: number;
  duplicate_positions: number;
  triangles: number;
  boundary_loops: number;
  components: number;
  nonmanifold_edges: number;
}
const manifest = JSON.parse(readShared('manifest.json')).meshes as Record<string, ManifestMesh>;

describe('SurfaceMesh.load on the shared meshes', () => {
  const meshes = new Map<string, SurfaceMesh>();
  const load = async (rel: string) => {
    if (!meshes.has(rel)) meshes.set(rel, await SurfaceMesh.load(readShared(rel), rel.split('/').pop()!));
    return meshes.get(rel)!;
  };

  test.each(['meshes/spot.obj', 'meshes/stanford_bunny.obj', 'meshes/hand_lowres.obj', 'meshes/torus.obj'])('%s: info agrees with the manifest', async (rel) => {
    const m = manifest[rel];
    const mesh = await load(rel);
    const info = mesh.info;
    expect(info.vertices).toBe(m.raw_vertices);
    expect(info.faces).toBe(m.triangles);
    expect(info.weldedVertices).toBe(m.duplicate_positions);
    expect(info.unreferencedVertices).toBe(m.unreferenced_vertices);
    expect(info.usedVertices).toBe(m.vertices);
    expect(info.boundaryLoops).toBe(m.boundary_loops);
    expect(info.components).toBe(m.components);
    expect(info.nonManifoldEdges).toBe(m.nonmanifold_edges);
    expect(info.flippedFaces).toBe(0);
    expect(info.degenerateFaces).toBe(0);
    // The structures: at least each face's corners, neighbours and file<->mesh numbering (8 int32),
    // at most the ~120 bytes per triangle of the budget plus the search-graph nodes that long
    // edges add (BENCHMARKS.md, "Memory and precompute": 114-129 for these meshes).
    expect(info.bytes, 'bytes of the mesh structures').toBeGreaterThanOrEqual(32 * m.triangles);
    expect(info.bytes, 'bytes of the mesh structures').toBeLessThanOrEqual(160 * m.triangles);
    expect(mesh.faceCount).toBe(m.triangles);
    expect(mesh.positions.length).toBe(3 * m.raw_vertices);
  });

  test('the numbers the issue names', async () => {
    expect((await load('meshes/spot.obj')).info.weldedVertices).toBe(0); // OBJ v lines are unique; v//vn seams are not welds
    const bunny = (await load('meshes/stanford_bunny.obj')).info;
    expect(bunny.unreferencedVertices).toBe(1113);
    expect(bunny.warnings.join('\n')).toMatch(/1,113 vertices that no face uses/);
    expect((await load('meshes/hand_lowres.obj')).info.boundaryLoops).toBe(1);
    expect((await load('meshes/torus.obj')).info.components).toBe(1);
    expect((await load('meshes/spot.obj')).info.warnings).toEqual([]);
  });

  test('vertexPoint and xyz round-trip file vertices; vertexPoint picks the first face using the vertex', async () => {
    for (const rel of ['meshes/spot.obj', 'meshes/stanford_bunny.obj']) {
      const mesh = await load(rel);
      const obj = readObj(readShared(rel));
      const firstFace = new Map<number, number>();
      obj.faces.forEach((f, i) => f.forEach((v) => firstFace.has(v) || firstFace.set(v, i)));
      const rnd = random(9);
      for (let k = 0; k < 200; k++) {
        const v = Math.floor(rnd() * obj.positions.length);
        if (!firstFace.has(v)) {
          expect(failure(() => mesh.vertexPoint(v)).code).toBe('invalid-input');
          continue;
        }
        const p = mesh.vertexPoint(v);
        expect(p.face).toBe(firstFace.get(v));
        expect(obj.faces[p.face][p.uv[0] === 1 ? 1 : p.uv[1] === 1 ? 2 : 0]).toBe(v);
        expect(mesh.xyz(p)).toEqual(obj.positions[v]);
        expect(mesh.xyz(v)).toEqual(obj.positions[v]);
        // A face point: barycentrics of the file's face.
        const f = Math.floor(rnd() * obj.faces.length);
        const [a, b, c] = obj.faces[f].map((i) => obj.positions[i]);
        expectNear(mesh.xyz({ face: f, uv: [0.2, 0.5] }), add(add(mul(a, 0.3), mul(b, 0.2)), mul(c, 0.5)), 1e-12, `face ${f}`);
      }
      // The bunny's unreferenced vertices are refused by name.
      if (rel.includes('bunny')) {
        const unused = obj.positions.findIndex((_, i) => !firstFace.has(i));
        expect(failure(() => mesh.vertexPoint(unused)).message).toMatch(new RegExp(`vertex ${unused} is not used`));
      }
    }
  });

  test('shortestPath on spot: the same length both ways, points in file order, never below the straight distance', async () => {
    const mesh = await load('meshes/spot.obj');
    const rnd = random(4);
    for (let k = 0; k < 10; k++) {
      const a: MeshPoint = { face: Math.floor(rnd() * mesh.faceCount), uv: [0.3, 0.3] };
      const b: MeshPointLike = Math.floor(rnd() * mesh.info.vertices);
      const ab = mesh.shortestPath(a, b), ba = mesh.shortestPath(b, a);
      expect(Math.abs(ab.length - ba.length), `pair ${k}: ${ab.length} vs ${ba.length}`).toBeLessThan(1e-9 * ab.length);
      expect(ab.length).toBeGreaterThanOrEqual(dist(mesh.xyz(a), mesh.xyz(b)) * (1 - 1e-12));
      expectNear(ab.xyz.slice(0, 3) as unknown as Vec3, mesh.xyz(a), 1e-12, 'start');
      expectNear(ab.xyz.slice(-3) as unknown as Vec3, mesh.xyz(b), 1e-12, 'end');
      let length = 0;
      ab.points.forEach((p, i) => {
        const xyz = Array.from(ab.xyz.slice(3 * i, 3 * i + 3)) as Vec3;
        expectNear(mesh.xyz(p), xyz, 1e-9, `point ${i}`);
        if (i > 0) length += dist(xyz, Array.from(ab.xyz.slice(3 * i - 3, 3 * i)) as Vec3);
      });
      expect(Math.abs(length - ab.length)).toBeLessThan(1e-9 * ab.length);
    }
  });
});

// ---------------------------------------------------------------------------------------------
// Geodesics and spline editing on a plane
// ---------------------------------------------------------------------------------------------

describe('on a plane', () => {
  const { positions, triangles } = planeArrays();
  let mesh: SurfaceMesh;
  beforeAll(() => {
    mesh = SurfaceMesh.fromArrays(positions, triangles);
  });
  const at = (x: number, y: number) => locate(positions, triangles, x, y);
  const xyz = (p: MeshPointLike) => evalPoint(positions, triangles, p);
  const pointsXYZ = (s: SurfaceSpline) => s.points.map(xyz);

  test('the mesh is what the test built', () => {
    expect(mesh.info.components).toBe(1);
    expect(mesh.info.boundaryLoops).toBe(1);
    expect(mesh.info.warnings).toEqual([]);
    expect(Array.from(mesh.positions)).toEqual(positions);
  });

  test('shortestPath is the segment; straightest ends at start + length·direction', () => {
    const a = at(0.3, 0.4), b = at(3.7, 2.9);
    const path = mesh.shortestPath(a, b);
    expect(Math.abs(path.length - Math.hypot(3.4, 2.5))).toBeLessThan(1e-9);
    const rnd = random(6);
    for (let k = 0; k < 20; k++) {
      const start = at(1.5 + rnd(), 1.5 + rnd());
      const angle = 2 * Math.PI * rnd(), len = 0.2 + 1.2 * rnd();
      const dir: Vec3 = [Math.cos(angle), Math.sin(angle), 0];
      const s = mesh.straightest(start, dir, len);
      const end = Array.from(s.xyz.slice(-3)) as Vec3;
      expectNear(end, add(xyz(start), mul(dir, len)), 1e-9, `ray ${k}`);
      expectNear(mesh.xyz(s.points.at(-1)!), end, 1e-9, `ray ${k} point`);
      expect(Math.abs(s.length - len)).toBeLessThan(1e-9);
      // A direction off the surface is projected onto it (and its length does not matter).
      const tilted = mesh.straightest(start, [3 * dir[0], 3 * dir[1], 2], len);
      expectNear(Array.from(tilted.xyz.slice(-3)) as Vec3, end, 1e-9, `tilted ray ${k}`);
    }
  });

  test('fromPolygon: 3n+1 points, handles at 1/3 and 2/3 of each side', () => {
    const anchors = [at(0.5, 0.5), at(3.2, 1.0), at(2.5, 3.5), 40];
    const s = SurfaceSpline.fromPolygon(mesh, anchors);
    expect(s.points).toHaveLength(10);
    expect(s.segmentCount).toBe(3);
    expect(s.closed).toBe(false);
    const p = pointsXYZ(s), a = anchors.map(xyz);
    for (let k = 0; k < 3; k++) {
      expectNear(p[3 * k], a[k], 1e-12, `anchor ${k}`);
      expectNear(p[3 * k + 1], lerp(a[k], a[k + 1], 1 / 3), 1e-9, `handle ${3 * k + 1}`);
      expectNear(p[3 * k + 2], lerp(a[k], a[k + 1], 2 / 3), 1e-9, `handle ${3 * k + 2}`);
    }
    expectNear(p[9], a[3], 1e-12, 'last anchor');
    const closed = SurfaceSpline.fromPolygon(mesh, anchors.slice(0, 3), true);
    expect(closed.points).toHaveLength(9);
    expectNear(xyz(closed.points[8]), lerp(a[2], a[0], 2 / 3), 1e-9, 'closing handle');
  });

  test('moveAnchor translates the anchor and its handles by the same vector, nothing else', () => {
    const s = SurfaceSpline.fromPolygon(mesh, [at(0.5, 0.5), at(2.0, 1.5), at(3.5, 0.8)]);
    const before = pointsXYZ(s);
    const target = at(2.3, 2.1);
    s.moveAnchor(3, target);
    const after = pointsXYZ(s);
    const d = sub(xyz(target), before[3]);
    for (const i of [2, 3, 4]) expectNear(after[i], add(before[i], d), 1e-9, `point ${i}`);
    for (const i of [0, 1, 5, 6]) expectNear(after[i], before[i], 1e-12, `point ${i}`);
    // An end anchor carries its one handle.
    s.moveAnchor(0, at(0.2, 0.9));
    const end = pointsXYZ(s);
    expectNear(end[1], add(after[1], sub(end[0], after[0])), 1e-9, 'end handle');
  });

  test('setSmooth turns both handles to the bisector, keeping their lengths: collinear through the anchor', () => {
    const s = SurfaceSpline.fromPolygon(mesh, [at(0.5, 0.5), at(2.0, 2.2), at(3.5, 0.8)]);
    s.moveHandle(4, at(2.9, 2.5));
    const [hin, anchor, hout] = pointsXYZ(s).slice(2, 5);
    expect(s.isSmooth(3)).toBe(false);
    s.setSmooth(3, true);
    expect(s.isSmooth(3)).toBe(true);
    const p = pointsXYZ(s);
    // Independent: the common direction bisects the outgoing handle and the reversed incoming one.
    const axis = unit(sub(unit(sub(hout, anchor)), unit(sub(hin, anchor))));
    expectNear(p[4], add(anchor, mul(axis, dist(hout, anchor))), 1e-9, 'out handle');
    expectNear(p[2], sub(anchor, mul(axis, dist(hin, anchor))), 1e-9, 'in handle');
    expectNear(p[3], anchor, 1e-12, 'anchor');
    // Smooth: moving one handle turns the other opposite, keeping its length.
    const keep = dist(p[2], p[3]);
    s.moveHandle(4, at(3.0, 3.0));
    const q = pointsXYZ(s);
    expectNear(q[2], sub(q[3], mul(unit(sub(q[4], q[3])), keep)), 1e-9, 'opposite handle');
  });

  test('insert splits the segment at the curve point, keeping the ends (RDC and OLR)', () => {
    for (const scheme of ['rdc', 'olr'] as const) {
      const s = SurfaceSpline.fromPolygon(mesh, [at(0.5, 0.5), at(2.0, 3.0), at(3.5, 0.8)]);
      s.moveHandle(1, at(0.6, 3.2));
      s.moveHandle(2, at(3.3, 3.6));
      const old = pointsXYZ(s), oldSegment = s.segment(0);
      const t = 0.37;
      const onCurve = evalBezier(mesh, oldSegment, t, { scheme });
      const index = s.insert(0, t, { scheme });
      expect(index).toBe(3);
      expect(s.points).toHaveLength(10);
      expect(s.segmentCount).toBe(3);
      const p = pointsXYZ(s);
      expectNear(p[0], old[0], 1e-12, 'first anchor');
      expectNear(p[9], old[6], 1e-12, 'last anchor');
      for (const i of [4, 5]) expectNear(p[i + 3], old[i], 1e-12, `second segment point ${i}`);
      expectNear(p[3], xyz(onCurve), 1e-9, `${scheme}: new anchor = evalBezier at t`);
      // On a plane the curve is the Euclidean Bézier and the split is de Casteljau's.
      const c = old.slice(0, 4);
      expectNear(xyz(onCurve), bezier(c, t), 1e-9, `${scheme}: evalBezier`);
      split(c, t).forEach((q, i) => expectNear(p[i], q, 1e-9, `${scheme}: split point ${i}`));
      expect(s.isSmooth(3)).toBe(true);
    }
  });

  test('remove merges the segments on both sides of an anchor', () => {
    const s = SurfaceSpline.fromPolygon(mesh, [at(0.5, 0.5), at(2.0, 3.0), at(3.5, 0.8), at(3.5, 3.5)]);
    s.setSmooth(6, true);
    const old = s.toJSON();
    s.remove(3);
    expect(s.segmentCount).toBe(2);
    expect(s.points).toEqual([0, 1, 5, 6, 7, 8, 9].map((i) => old.points[i]));
    expect(s.isSmooth(3)).toBe(true); // the smooth anchor moved from 6 to 3
    s.remove(6);
    expect(s.points).toEqual([0, 1, 5, 6].map((i) => old.points[i]));
    expect(failure(() => s.remove(0)).code).toBe('invalid-input'); // one segment stays
  });

  test('rotate, scale and translate equal the Euclidean transforms', () => {
    const make = () => SurfaceSpline.fromPolygon(mesh, [at(1.5, 1.5), at(2.5, 1.8), at(2.2, 2.6)], true);
    const centre = at(2.0, 2.0), c = xyz(centre);
    const base = pointsXYZ(make());
    const rot = (p: Vec3, a: number): Vec3 => {
      const d = sub(p, c);
      return add(c, [Math.cos(a) * d[0] - Math.sin(a) * d[1], Math.sin(a) * d[0] + Math.cos(a) * d[1], 0]);
    };
    for (const angle of [0.6, -2.1, Math.PI]) {
      const s = make();
      s.rotate(centre, angle); // counter-clockwise seen from +z, the side the faces face
      pointsXYZ(s).forEach((p, i) => expectNear(p, rot(base[i], angle), 1e-6, `rotate ${angle}, point ${i}`));
    }
    for (const factor of [0.5, 1.7]) {
      const s = make();
      s.scale(centre, factor);
      pointsXYZ(s).forEach((p, i) => expectNear(p, add(c, mul(sub(base[i], c), factor)), 1e-6, `scale ${factor}, point ${i}`));
    }
    const s = make();
    const from = at(1.9, 2.1), to = at(2.4, 1.6);
    s.translate(from, to);
    const d = sub(xyz(to), xyz(from));
    pointsXYZ(s).forEach((p, i) => expectNear(p, add(base[i], d), 1e-6, `translate, point ${i}`));
  });

  test('toJSON / fromJSON round trip', () => {
    const s = SurfaceSpline.fromPolygon(mesh, [at(0.5, 0.5), at(2.0, 3.0), at(3.5, 0.8)]);
    s.setSmooth(3, true);
    const json = JSON.parse(JSON.stringify(s.toJSON()));
    const back = SurfaceSpline.fromJSON(mesh, json);
    expect(back.toJSON()).toEqual(s.toJSON());
    expect(back.isSmooth(3)).toBe(true);
    expect(back.isSmooth(0)).toBe(false);
    const a = s.trace(), b = back.trace();
    expect(Array.from(b.xyz)).toEqual(Array.from(a.xyz));
    expect(Array.from(b.segmentStarts)).toEqual(Array.from(a.segmentStarts));
    // The JSON is a copy: editing the spline does not change it.
    const frozen = s.toJSON();
    s.moveAnchor(3, at(2.2, 2.2));
    expect(frozen).toEqual(json);
  });

  test('mapSplines puts control point (x, y) at centre + scale·(x − cx, −(y − cy))', () => {
    const svg = `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
      <path d="M 10 50 C 20 30 30 30 40 50 S 60 70 70 50"/>
      <path d="M 30 80 C 40 90 60 90 70 80 C 60 60 40 60 30 80 Z"/>
    </svg>`;
    const doc = parseSVG(svg);
    expect(Array.from(doc.splines[0].points.slice(0, 2))).toEqual([10, 50]);
    const all = doc.splines.flatMap((sp) => Array.from(sp.points));
    const xs = all.filter((_, i) => i % 2 === 0), ys = all.filter((_, i) => i % 2 === 1);
    const cx = (Math.min(...xs) + Math.max(...xs)) / 2, cy = (Math.min(...ys) + Math.max(...ys)) / 2;
    const width = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys));
    const centre = at(2.0, 2.1), c = xyz(centre), size = 2.5, k = size / width;
    for (const rotation of [0, 0.5]) {
      const mapped = mapSplines(mesh, doc, { center: centre, size, up: [0, 1, 0], rotation });
      expect(mapped).toHaveLength(doc.splines.length);
      mapped.forEach((sp, s) => {
        expect(sp.closed).toBe(doc.splines[s].closed);
        const src = doc.splines[s].points;
        sp.points.forEach((p, i) => {
          const dx = k * (src[2 * i] - cx), dy = -k * (src[2 * i + 1] - cy);
          const r = rotation;
          const expected = add(c, [Math.cos(r) * dx - Math.sin(r) * dy, Math.sin(r) * dx + Math.cos(r) * dy, 0]);
          expectNear(xyz(p), expected, 1e-6, `rotation ${rotation}, spline ${s}, point ${i}`);
        });
      });
      // The S command joins the first spline smoothly at anchor 3.
      expect([0, 3, 6].map((a) => mapped[0].isSmooth(a))).toEqual([false, true, false]);
    }
    // Without `up`, the face's own frame: distances from the centre are still scaled exactly.
    const free = mapSplines(mesh, doc, { center: centre, size });
    free[0].points.forEach((p, i) => {
      const src = doc.splines[0].points;
      expect(Math.abs(dist(xyz(p), c) - k * Math.hypot(src[2 * i] - cx, src[2 * i + 1] - cy))).toBeLessThan(1e-6);
    });
  });

  test('bad points and edits throw invalid-input and leave the spline as it was', () => {
    expect(failure(() => mesh.resolve({ face: -1, uv: [0.1, 0.1] })).code).toBe('invalid-input');
    expect(failure(() => mesh.resolve({ face: mesh.faceCount, uv: [0.1, 0.1] })).code).toBe('invalid-input');
    expect(failure(() => mesh.resolve({ face: 0, uv: [0.7, 0.6] })).code).toBe('invalid-input');
    expect(failure(() => mesh.resolve({ face: 0, uv: [Number.NaN, 0] })).code).toBe('invalid-input');
    expect(failure(() => mesh.point(1.5, 0.1, 0.1)).code).toBe('invalid-input');
    expect(failure(() => mesh.vertexPoint(81)).code).toBe('invalid-input');
    expect(failure(() => mesh.xyz(-1)).code).toBe('invalid-input');
    expect(failure(() => mesh.shortestPath(0, { face: 0, uv: [2, 0] })).code).toBe('invalid-input');
    expect(failure(() => traceBezier(mesh, [0, 1, 2])).code).toBe('invalid-input');
    expect(failure(() => traceBezier(mesh, [0, 1, 2, 3], { scheme: 'xyz' as never })).code).toBe('invalid-input');
    expect(failure(() => traceBezier(mesh, [0, 1, 2, 3], { levels: 13 })).code).toBe('invalid-input');
    expect(failure(() => traceBezier(mesh, [0, 1, 2, 3], { adaptive: 0 })).code).toBe('invalid-input');
    expect(failure(() => SurfaceSpline.fromPolygon(mesh, [0])).code).toBe('invalid-input');
    expect(failure(() => SurfaceSpline.fromJSON(mesh, { closed: false, points: [at(1, 1), at(1, 2), at(2, 2)], smooth: [] })).code).toBe('invalid-input');
    expect(failure(() => SurfaceMesh.fromArrays([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 7])).code).toBe('invalid-input');
    expect(failure(() => SurfaceMesh.fromArrays([0, 0, 0, 1, Number.NaN, 0, 0, 1, 0], [0, 1, 2])).code).toBe('invalid-input');

    const s = SurfaceSpline.fromPolygon(mesh, [at(0.5, 0.5), at(2.0, 3.0), at(3.5, 0.8)]);
    const twin = SurfaceSpline.fromJSON(mesh, s.toJSON());
    const before = s.toJSON();
    const edits: [string, () => void][] = [
      ['moveAnchor to a bad point', () => s.moveAnchor(3, { face: 0, uv: [0.9, 0.9] })],
      ['moveAnchor of a handle', () => s.moveAnchor(1, at(1, 1))],
      ['moveHandle of an anchor', () => s.moveHandle(3, at(1, 1))],
      ['moveHandle to a missing face', () => s.moveHandle(2, { face: 999, uv: [0, 0] })],
      ['insert in a missing segment', () => s.insert(2, 0.5)],
      ['insert with a bad scheme', () => s.insert(0, 0.5, { scheme: 'nope' as never })],
      ['setSmooth of a handle', () => s.setSmooth(2, true)],
      ['rotate about a bad centre', () => s.rotate({ face: 0, uv: [-1, 0] }, 1)],
      ['translate to a missing vertex', () => s.translate(0, 1000)],
      ['append a bad anchor', () => s.appendAnchor(-3)],
    ];
    for (const [what, edit] of edits) {
      expect(failure(edit).code, what).toBe('invalid-input');
      expect(s.toJSON(), what).toEqual(before);
    }
    // And it still edits exactly like an untouched copy.
    s.moveAnchor(3, at(2.2, 2.4));
    twin.moveAnchor(3, at(2.2, 2.4));
    expect(s.toJSON()).toEqual(twin.toJSON());
  });
});

test('repairs are reported, and points still mean the file: duplicated seam, flipped face, unused vertex', () => {
  // A 3×2 patch: vertex 0 unused, the middle row written twice (row below / row above), face 3 flipped.
  const positions: number[] = [7, 7, 7];
  const id = new Map<string, number>();
  const v = (i: number, j: number, copy: number) => {
    const k = `${i},${j},${copy}`;
    if (!id.has(k)) id.set(k, positions.push(i, j, 0.2 * Math.sin(i + 2 * j)) / 3 - 1);
    return id.get(k)!;
  };
  const triangles: number[] = [];
  for (let j = 0; j < 2; j++)
    for (let i = 0; i < 3; i++) {
      const w = (a: number, b: number) => v(a, b, b === 1 && j === 1 ? 1 : 0);
      triangles.push(w(i, j), w(i + 1, j), w(i + 1, j + 1), w(i, j), w(i + 1, j + 1), w(i, j + 1));
    }
  [triangles[10], triangles[11]] = [triangles[11], triangles[10]]; // face 3
  const mesh = SurfaceMesh.fromArrays(positions, triangles);
  try {
    expect(mesh.info.vertices).toBe(positions.length / 3);
    expect(mesh.info.weldedVertices).toBe(4);
    expect(mesh.info.unreferencedVertices).toBe(1);
    expect(mesh.info.flippedFaces).toBe(1);
    expect(mesh.info.usedVertices).toBe(12);
    expect(mesh.info.components).toBe(1);
    expect(mesh.info.boundaryLoops).toBe(1);
    expect(mesh.info.warnings).toHaveLength(3);
    const on: MeshPoint = { face: 3, uv: [0.7, 0.2] };
    const above: MeshPoint = { face: 10, uv: [0.2, 0.2] }; // across the seam from face 3
    for (const path of [mesh.shortestPath(on, above), mesh.shortestPath(above, on)]) {
      const ends = [Array.from(path.xyz.slice(0, 3)), Array.from(path.xyz.slice(-3))] as Vec3[];
      const want = [evalPoint(positions, triangles, on), evalPoint(positions, triangles, above)];
      const flip = dist(ends[0], want[0]) < 1e-12 ? 0 : 1;
      expectNear(ends[0], want[flip], 1e-12, 'start');
      expectNear(ends[1], want[1 - flip], 1e-12, 'end');
      path.points.forEach((p, i) => expectNear(evalPoint(positions, triangles, p), Array.from(path.xyz.slice(3 * i, 3 * i + 3)) as Vec3, 1e-9, `point ${i}`));
    }
    const traced = traceBezier(mesh, [on, 4, { face: 8, uv: [0.1, 0.1] }, above]);
    traced.points.forEach((p, i) => expectNear(evalPoint(positions, triangles, p), Array.from(traced.xyz.slice(3 * i, 3 * i + 3)) as Vec3, 1e-9, `traced ${i}`));
    expectNear(Array.from(traced.xyz.slice(0, 3)) as Vec3, evalPoint(positions, triangles, on), 1e-12, 'P0');
    expectNear(Array.from(traced.xyz.slice(-3)) as Vec3, evalPoint(positions, triangles, above), 1e-12, 'P3');
    expect(mesh.normal(on)[2]).toBeLessThan(0); // the file's winding, not the repaired one
  } finally {
    mesh.dispose();
  }
});

test('a double-sided mesh is one surface: the faces of its second side are listed, and points on them are points on the first', () => {
  // The bumpy patch of the test above, every face written again with the other winding.
  const positions: number[] = [];
  const v = (i: number, j: number) => positions.push(i, j, 0.2 * Math.sin(i + 2 * j)) / 3 - 1;
  const grid = [0, 1, 2, 3].map((i) => [0, 1, 2].map((j) => v(i, j)));
  const once: number[] = [];
  for (let j = 0; j < 2; j++)
    for (let i = 0; i < 3; i++) once.push(grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j], grid[i + 1][j + 1], grid[i][j + 1]);
  const faces = once.length / 3;
  const twice = once.concat(Array.from({ length: faces }, (_, f) => [once[3 * f], once[3 * f + 2], once[3 * f + 1]]).flat());
  const single = SurfaceMesh.fromArrays(positions, once);
  const mesh = SurfaceMesh.fromArrays(positions, twice);
  try {
    expect(single.duplicateFaces).toHaveLength(0);
    expect(Array.from(mesh.duplicateFaces)).toEqual(Array.from({ length: faces }, (_, f) => faces + f));
    expect(mesh.info.duplicateFaces).toBe(faces);
    expect(mesh.info.components).toBe(1);
    expect(mesh.info.boundaryLoops).toBe(1);
    expect(mesh.info.nonManifoldEdges).toBe(0);
    expect(mesh.info.warnings).toEqual([`${faces} faces repeat an earlier face (a double-sided mesh?): taken as that face`]);
    // A path between points given on the second side: the same as between those points on the
    // first, and its points lie on the first side's faces.
    const a: MeshPoint = { face: faces + 1, uv: [0.2, 0.5] }, b: MeshPoint = { face: faces + 10, uv: [0.3, 0.1] };
    const a1: MeshPoint = { face: 1, uv: [0.5, 0.2] }, b1: MeshPoint = { face: 10, uv: [0.1, 0.3] };
    expectNear(evalPoint(positions, twice, a), evalPoint(positions, once, a1), 1e-15, 'a');
    const path = mesh.shortestPath(a, b), reference = single.shortestPath(a1, b1);
    expect(path.length).toBeCloseTo(reference.length, 12);
    expectNear(Array.from(path.xyz.slice(0, 3)) as Vec3, evalPoint(positions, once, a1), 1e-12, 'start');
    for (const p of path.points) expect(p.face).toBeLessThan(faces);
  } finally {
    mesh.dispose();
    single.dispose();
  }
});

// ---------------------------------------------------------------------------------------------
// Memory
// ---------------------------------------------------------------------------------------------

test('1,000 create/use/dispose cycles of a small SurfaceMesh leave memory().used where it was', () => {
  const { positions, triangles } = planeArrays(3, 1, 5);
  const cycle = () => {
    const mesh = SurfaceMesh.fromArrays(positions, triangles);
    mesh.shortestPath(0, 15);
    traceBezier(mesh, [0, 3, 12, 15]);
    const s = SurfaceSpline.fromPolygon(mesh, [0, 5, 15]);
    s.moveAnchor(3, 10);
    mesh.dispose();
    expect(mesh.isDisposed).toBe(true);
  };
  for (let i = 0; i < 5; i++) cycle(); // warm-up
  const before = memory().used;
  for (let i = 0; i < 1000; i++) cycle();
  expect(memory().used).toBe(before);
  // A disposed mesh refuses work instead of touching freed memory.
  const mesh = SurfaceMesh.fromArrays(positions, triangles);
  mesh.dispose();
  mesh.dispose(); // twice is harmless
  expect(failure(() => mesh.shortestPath(0, 15)).code).toBe('invalid-input');
}, 120_000);
