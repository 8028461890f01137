// The stand-in the 3D view draws for a large mesh while it moves (web/view3d/proxy.ts, made by
// meshoptimizer): about the triangles asked for, a valid index buffer over only the vertices it
// uses, on the surface, covering all of it, facing out.
import { expect, test } from 'vitest';
import { vertexNormals } from '../../src/surface/mesh-point.js';
import { meshProxy, type MeshProxy } from '../../web/view3d/proxy.js';

interface Mesh {
  positions: Float32Array;
  triangles: Uint32Array;
}

/** A closed n × m grid mesh of 2·n·m triangles (wrapping both ways) over point(i / n, j / m). */
function wrapped(n: number, m: number, point: (s: number, t: number) => [number, number, number]): Mesh {
  const positions = new Float32Array(3 * n * m), triangles = new Uint32Array(6 * n * m);
  for (let i = 0; i < n; i++) for (let j = 0; j < m; j++) positions.set(point(i / n, j / m), 3 * (i * m + j));
  const id = (i: number, j: number) => (i % n) * m + (j % m);
  let k = 0;
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < m; j++) {
      triangles.set([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1)], k);
      k += 6;
    }
  }
  return { positions, triangles };
}

/** A torus (radii 1 and r) of 2·n·m triangles, facing out. */
function torus(n: number, m: number, r: number): Mesh {
  return wrapped(n, m, (s, t) => {
    const u = 2 * Math.PI * s, v = 2 * Math.PI * t;
    return [(1 + r * Math.cos(v)) * Math.cos(u), (1 + r * Math.cos(v)) * Math.sin(u), r * Math.sin(v)];
  });
}

/** The unit sphere as a latitude-longitude mesh (n rings, m meridians, closed at the poles), facing out. */
function sphere(n: number, m: number): Mesh {
  const positions: number[] = [0, 0, -1];
  for (let i = 1; i < n; i++) {
    const lat = Math.PI * (i / n - 0.5);
    for (let j = 0; j < m; j++) positions.push(Math.cos(lat) * Math.cos((2 * Math.PI * j) / m), Math.cos(lat) * Math.sin((2 * Math.PI * j) / m), Math.sin(lat));
  }
  positions.push(0, 0, 1);
  const ring = (i: number, j: number) => 1 + (i - 1) * m + (j % m), top = positions.length / 3 - 1;
  const triangles: number[] = [];
  for (let j = 0; j < m; j++) triangles.push(0, ring(1, j + 1), ring(1, j), top, ring(n - 1, j), ring(n - 1, j + 1));
  for (let i = 1; i < n - 1; i++) for (let j = 0; j < m; j++) triangles.push(ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i, j), ring(i + 1, j + 1), ring(i + 1, j));
  return { positions: Float32Array.from(positions), triangles: Uint32Array.from(triangles) };
}

type Vec = [number, number, number];
const corner = (P: Float32Array, v: number): Vec => [P[3 * v], P[3 * v + 1], P[3 * v + 2]];
const sub = (a: Vec, b: Vec): Vec => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a: Vec, b: Vec): Vec => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a: Vec, b: Vec) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** Each triangle's corners, centroid, normal (twice the area, as long). */
function* faces({ positions: P, triangles: T }: Mesh): Generator<{ a: number; b: number; c: number; centroid: Vec; normal: Vec }> {
  for (let f = 0; f < T.length; f += 3) {
    const [a, b, c] = [T[f], T[f + 1], T[f + 2]], [p, q, s] = [corner(P, a), corner(P, b), corner(P, c)];
    yield { a, b, c, centroid: [(p[0] + q[0] + s[0]) / 3, (p[1] + q[1] + s[1]) / 3, (p[2] + q[2] + s[2]) / 3], normal: cross(sub(q, p), sub(s, p)) };
  }
}

function area(mesh: Mesh): number {
  let a = 0;
  for (const f of faces(mesh)) a += 0.5 * Math.hypot(...f.normal);
  return a;
}

function bounds(P: Float32Array): { lo: Vec; hi: Vec } {
  const lo: Vec = [Infinity, Infinity, Infinity], hi: Vec = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < P.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], P[i]);
    hi[i % 3] = Math.max(hi[i % 3], P[i]);
  }
  return { lo, hi };
}

/**
 * What any proxy of `mesh` must be: every index in range, every vertex used and one of the mesh's
 * (the one `vertices` names), no triangle with a
 * repeated or coincident corner, the mesh's bounding box within `slack`, its area the mesh's
 * within 5%.
 */
function expectValid(proxy: MeshProxy, mesh: Mesh, slack: number): void {
  const nv = proxy.positions.length / 3, used = new Uint8Array(nv);
  expect(proxy.triangles.length % 3).toBe(0);
  for (const f of faces(proxy)) {
    for (const v of [f.a, f.b, f.c]) {
      expect(v).toBeLessThan(nv);
      used[v] = 1;
    }
    expect(f.a !== f.b && f.b !== f.c && f.a !== f.c, `triangle ${f.a} ${f.b} ${f.c}`).toBe(true);
    expect(Math.hypot(...f.normal)).toBeGreaterThan(0);
  }
  expect(used.every((u) => u === 1)).toBe(true);
  // Each vertex is the mesh vertex it names.
  expect(proxy.vertices.length).toBe(nv);
  for (let v = 0; v < nv; v++) {
    expect(proxy.vertices[v]).toBeLessThan(mesh.positions.length / 3);
    expect(corner(proxy.positions, v)).toEqual(corner(mesh.positions, proxy.vertices[v]));
  }
  const box = bounds(proxy.positions), meshBox = bounds(mesh.positions);
  for (let k = 0; k < 3; k++) {
    expect(Math.abs(box.lo[k] - meshBox.lo[k]), `low side ${k}`).toBeLessThan(slack);
    expect(Math.abs(box.hi[k] - meshBox.hi[k]), `high side ${k}`).toBeLessThan(slack);
  }
  // No holes worth the name (and no pile of overlapping folds).
  expect(area(proxy) / area(mesh)).toBeGreaterThan(0.95);
  expect(area(proxy) / area(mesh)).toBeLessThan(1.05);
}

test('a 2·400·250-triangle torus comes down to about the triangles asked for, on the surface, all of it, facing out', async () => {
  const r = 0.35, mesh = torus(400, 250, r);
  const proxy = await meshProxy(mesh.positions, mesh.triangles, 20_000, vertexNormals(mesh.positions, mesh.triangles));
  const n = proxy.triangles.length / 3;
  expect(n).toBeGreaterThan(0.85 * 20_000);
  expect(n).toBeLessThanOrEqual(20_000);
  expect(proxy.positions.length / 3).toBeLessThan(mesh.positions.length / 3 / 10);
  expectValid(proxy, mesh, 0.02);
  const offTorus = ([x, y, z]: Vec) => Math.abs(Math.hypot(Math.hypot(x, y) - 1, z) - r);
  // Its vertices are the mesh's (on the torus to float precision)…
  let worst = 0;
  for (let v = 0; v < proxy.positions.length / 3; v++) worst = Math.max(worst, offTorus(corner(proxy.positions, v)));
  expect(worst).toBeLessThan(1e-5);
  // …and its triangles stay near it: 20k triangles are ~0.03 across, a chord of the tube
  // (radius 0.35) that long sags ~0.0003 below it; cells of the clustering's grid are wider.
  let farthest = 0, inward = 0;
  for (const f of faces(proxy)) {
    farthest = Math.max(farthest, offTorus(f.centroid));
    const [x, y] = f.centroid, ring = Math.hypot(x, y);
    if (dot(f.normal, [x - x / ring, y - y / ring, f.centroid[2]]) <= 0) inward += 0.5 * Math.hypot(...f.normal);
  }
  expect(farthest).toBeLessThan(0.01);
  // Turned-over triangles (dark back faces on screen) are left out: what faces in is slivers.
  expect(inward / area(proxy)).toBeLessThan(1e-3);
});

test('a sphere of 2·200·300 triangles comes down to about the triangles asked for, near the sphere', async () => {
  const mesh = sphere(200, 300);
  const proxy = await meshProxy(mesh.positions, mesh.triangles, 5_000, vertexNormals(mesh.positions, mesh.triangles));
  const n = proxy.triangles.length / 3;
  expect(n).toBeGreaterThan(0.8 * 5_000);
  expect(n).toBeLessThanOrEqual(5_000);
  expectValid(proxy, mesh, 0.03);
  let farthest = 0, inward = 0;
  for (const f of faces(proxy)) {
    farthest = Math.max(farthest, Math.abs(Math.hypot(...f.centroid) - 1));
    if (dot(f.normal, f.centroid) <= 0) inward++;
  }
  // 5k triangles on a unit sphere are ~0.07 across: their chords sag ~0.001 inside it.
  expect(farthest).toBeLessThan(0.01);
  expect(inward).toBeLessThan(0.002 * n);
});

test('triangles facing against the normals given are left out', async () => {
  const mesh = torus(200, 100, 0.3), normals = vertexNormals(mesh.positions, mesh.triangles);
  const along = await meshProxy(mesh.positions, mesh.triangles, 4_000, normals);
  const against = await meshProxy(mesh.positions, mesh.triangles, 4_000, normals.map((x) => -x));
  expect(along.triangles.length / 3).toBeGreaterThan(3_000);
  expect(against.triangles.length).toBeLessThan(0.01 * along.triangles.length);
});

test('a small mesh asked for more triangles than it has is itself', async () => {
  const mesh = torus(20, 10, 0.3);
  const proxy = await meshProxy(mesh.positions, mesh.triangles, 10_000);
  expect(proxy.triangles.length).toBe(mesh.triangles.length);
  expect(proxy.positions.length).toBe(mesh.positions.length);
  expectValid(proxy, mesh, 1e-6);
});

test('an empty mesh has an empty proxy', async () => {
  const proxy = await meshProxy(new Float32Array(0), new Uint32Array(0), 1000);
  expect(proxy.positions.length).toBe(0);
  expect(proxy.triangles.length).toBe(0);
});
