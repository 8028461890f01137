// The coarse guide of long paths (SurfaceMeshOptions.guide; src/surface/coarse-guide.ts,
// wasm/core/surface/coarse_guide.h) through the package: built by default on large meshes, what the
// mesh reports, the memory it takes, deferred with the search, and curves on a flat U (points close in
// space, far apart on the surface) whose long sides follow it and keep their closed-form lengths; and
// that the guide of a mesh of long thin faces has near-regular triangles.
import { beforeAll, describe, expect, test } from 'vitest';
import { uShape } from './helpers.js';
import { MeshoptSimplifier } from 'meshoptimizer/simplifier';
import { DEFAULT_LANDMARKS, GUIDED_LANDMARKS, GUIDE_MIN_FACES, GUIDE_RATIO, SurfaceMesh, init, traceBezier } from '../../src/index.js';
import { guideTriangles } from '../../src/surface/coarse-guide.js';

beforeAll(async () => {
  await init();
});

// The flat U (helpers.ts): 260 × 128 unit cells, the slot at x in [S, S + 2), y >= B.
const W = 260, H = 128, S = 129, B = 8;

/** The length of the polyline x y z … */
function polylineLength(xyz: Float64Array): number {
  let length = 0;
  for (let i = 3; i < xyz.length; i += 3) length += Math.hypot(xyz[i] - xyz[i - 3], xyz[i + 1] - xyz[i - 2], xyz[i + 2] - xyz[i - 1]);
  return length;
}

/** Whether two file faces share a vertex (consecutive points of a traced curve must share a face). */
function shareAVertex(triangles: Int32Array, f: number, g: number): boolean {
  for (let a = 0; a < 3; a++) for (let b = 0; b < 3; b++) if (triangles[3 * f + a] === triangles[3 * g + b]) return true;
  return false;
}

describe('coarse guide', () => {
  const u = uShape(W, H, S, B);
  const { positions, triangles } = u;
  const faces = triangles.length / 3;

  test('is built by default on large meshes, a sixteenth of the faces, with 4 landmarks; guide: false leaves it out', () => {
    expect(faces).toBeGreaterThanOrEqual(GUIDE_MIN_FACES);
    const guided = SurfaceMesh.fromArrays(positions, triangles);
    const plain = SurfaceMesh.fromArrays(positions, triangles, { guide: false, landmarks: GUIDED_LANDMARKS });
    try {
      expect(guided.info.guideFaces).toBeGreaterThan(0.5 * GUIDE_RATIO * faces);
      expect(guided.info.guideFaces).toBeLessThanOrEqual(GUIDE_RATIO * faces);
      expect(guided.info.landmarks).toBe(GUIDED_LANDMARKS);
      expect(guided.info.buildMs.guide).toBeGreaterThan(0);
      expect(plain.info.guideFaces).toBe(0);
      expect(plain.info.buildMs.guide).toBe(0);
      // The guide's mesh and solver at a sixteenth of the size, and a vertex table: 2-20 bytes per face.
      const extra = guided.info.bytes - plain.info.bytes;
      expect(extra).toBeGreaterThan(2 * faces);
      expect(extra).toBeLessThan(20 * faces);
    } finally {
      guided.dispose();
      plain.dispose();
    }
  });

  test('long sides follow it, every traced curve stays on the surface, and a straight curve keeps the closed-form length', () => {
    const guided = SurfaceMesh.fromArrays(positions, triangles);
    const plain = SurfaceMesh.fromArrays(positions, triangles, { guide: false });
    try {
      // Control points P0 = P1 in one arm and P2 = P3 in the other: the curve is the geodesic between
      // them, round the slot's end (two corners), of the closed-form length.
      const ends: [number, number, number, number][] = [[60.3, 120.2, 200.6, 115.1], [128.5, 100.25, 131.5, 126.75], [3.5, 9.5, 257.5, 127.5]];
      let guidedSides = 0;
      for (const [ax, ay, bx, by] of ends) {
        const a = u.pointAt(ax, ay), b = u.pointAt(bx, by);
        const expected = Math.hypot(ax - S, ay - B) + 2 + Math.hypot(bx - (S + 2), by - B);
        for (const mesh of [guided, plain]) {
          const traced = traceBezier(mesh, [a, a, b, b]);
          if (mesh === guided) guidedSides += traced.counters.guided;
          else expect(traced.counters.guided).toBe(0);
          expect(Math.abs(polylineLength(traced.xyz) - expected), `(${ax}, ${ay}) -> (${bx}, ${by})`).toBeLessThan(1e-9 * expected);
        }
      }
      expect(guidedSides).toBeGreaterThanOrEqual(ends.length);
      // Random polygons over the whole U: consecutive points share a face, as without the guide.
      let rng = 7;
      const random = () => ((rng = (rng * 1103515245 + 12345) % 2 ** 31) / 2 ** 31);
      const points = Array.from({ length: 24 }, () => {
        for (;;) {
          const x = random() * W, y = random() * H;
          if (u.on(x, y)) return u.pointAt(x, y);
        }
      });
      for (let i = 0; i < points.length; i += 4) {
        const traced = traceBezier(guided, points.slice(i, i + 4));
        guidedSides += traced.counters.guided;
        for (let k = 1; k < traced.points.length; k++) {
          const f = traced.points[k - 1].face, g = traced.points[k].face;
          expect(f === g || shareAVertex(guided.triangles, f, g), `curve ${i / 4}, points ${k - 1} and ${k}`).toBe(true);
        }
      }
      expect(guidedSides).toBeGreaterThan(ends.length);
    } finally {
      guided.dispose();
      plain.dispose();
    }
  });

  test('waits with a deferred search: built by buildSearch() or the first curve, as the eager one', () => {
    const eager = SurfaceMesh.fromArrays(positions, triangles);
    const lazy = SurfaceMesh.fromArrays(positions, triangles, { deferSearch: true });
    const called = SurfaceMesh.fromArrays(positions, triangles, { deferSearch: true });
    try {
      expect(lazy.info.guideFaces).toBe(0);
      const a = u.pointAt(60.3, 120.2), b = u.pointAt(200.6, 115.1);
      const first = traceBezier(lazy, [a, a, b, b]);
      expect(first.counters.guided).toBeGreaterThan(0);
      expect(lazy.info.guideFaces).toBe(eager.info.guideFaces);
      expect(lazy.info.bytes).toBe(eager.info.bytes);
      const info = called.buildSearch();
      expect(info.guideFaces).toBe(eager.info.guideFaces);
      expect(info.buildMs.guide).toBeGreaterThan(0);
      expect(polylineLength(first.xyz)).toBe(polylineLength(traceBezier(eager, [a, a, b, b]).xyz));
    } finally {
      eager.dispose();
      lazy.dispose();
      called.dispose();
    }
  });

  test('a mesh the simplifier cannot bring to a quarter within its error bound gets no guide and the default landmarks', () => {
    // A 185 × 185 grid crumpled: every vertex moved by up to 15 cells each way in x, y and z, so that
    // hardly a collapse keeps the surface within 1% of its extent (68,450 triangles).
    const n = 185, pos: number[] = [], tri: number[] = [];
    let rng = 11;
    const jitter = () => ((rng = (rng * 1103515245 + 12345) % 2 ** 31) / 2 ** 31 - 0.5) * 30;
    for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) pos.push(i + jitter(), j + jitter(), jitter());
    for (let j = 0; j < n; j++)
      for (let i = 0; i < n; i++) {
        const a = j * (n + 1) + i;
        tri.push(a, a + 1, a + n + 2, a, a + n + 2, a + n + 1);
      }
    expect(tri.length / 3).toBeGreaterThanOrEqual(GUIDE_MIN_FACES);
    for (const deferSearch of [false, true]) {
      const spiky = SurfaceMesh.fromArrays(pos, tri, { deferSearch });
      const asked = SurfaceMesh.fromArrays(pos, tri, { deferSearch, landmarks: 2 });
      try {
        const info = spiky.buildSearch();
        expect(info.guideFaces).toBe(0);
        expect(info.landmarks).toBe(DEFAULT_LANDMARKS);
        expect(info.buildMs.guide).toBeGreaterThan(0); // (the simplification was tried)
        expect(asked.buildSearch().landmarks).toBe(2);
      } finally {
        spiky.dispose();
        asked.dispose();
      }
    }
  });
});

/** A closed tube of `around` × `along` quads split in two, its faces `stretch` times longer around than along. */
function thinFacedTube(around: number, along: number, stretch: number): { positions: Float64Array; triangles: Uint32Array } {
  const r = 1, step = (2 * Math.PI * r) / around / stretch;
  const positions = new Float64Array(3 * around * (along + 1));
  for (let j = 0; j <= along; j++)
    for (let i = 0; i < around; i++) {
      const a = (2 * Math.PI * i) / around, v = j * around + i;
      positions.set([r * Math.cos(a), r * Math.sin(a), j * step], 3 * v);
    }
  const triangles = new Uint32Array(6 * around * along);
  for (let j = 0, t = 0; j < along; j++)
    for (let i = 0; i < around; i++) {
      const a = j * around + i, b = j * around + ((i + 1) % around), c = a + around, d = b + around;
      triangles.set([a, b, d, a, d, c], t);
      t += 6;
    }
  return { positions, triangles };
}

/** The 99th percentile over faces of longest edge / shortest edge. */
function aspectP99(positions: ArrayLike<number>, triangles: ArrayLike<number>): number {
  const ratios: number[] = [];
  const edge = (u: number, v: number) => Math.hypot(positions[3 * u] - positions[3 * v], positions[3 * u + 1] - positions[3 * v + 1], positions[3 * u + 2] - positions[3 * v + 2]);
  for (let t = 0; t < triangles.length; t += 3) {
    const e = [edge(triangles[t], triangles[t + 1]), edge(triangles[t + 1], triangles[t + 2]), edge(triangles[t + 2], triangles[t])];
    ratios.push(Math.max(...e) / Math.min(...e));
  }
  ratios.sort((x, y) => x - y);
  return ratios[Math.floor(0.99 * (ratios.length - 1))];
}

test('the guide of a mesh of long thin faces has near-regular triangles, where plain simplification leaves slivers', () => {
  // (the guide's path is a search over its faces' centroids, which zigzags across slivers)
  const { positions, triangles } = thinFacedTube(64, 1200, 14);
  expect(aspectP99(positions, triangles)).toBeGreaterThan(13);
  const guide = guideTriangles(positions, triangles);
  expect(guide).not.toBeNull();
  const faces = triangles.length / 3;
  expect(guide!.length / 3).toBeLessThanOrEqual(GUIDE_RATIO * faces);
  expect(guide!.length / 3).toBeGreaterThan(0.5 * GUIDE_RATIO * faces);
  for (const v of guide!) expect(v).toBeLessThan(positions.length / 3);
  const [plain] = MeshoptSimplifier.simplify(triangles, Float32Array.from(positions), 3, 3 * Math.floor(faces * GUIDE_RATIO), 0.01);
  const regular = aspectP99(positions, guide!), sliver = aspectP99(positions, plain);
  expect(regular).toBeLessThan(5);
  expect(sliver).toBeGreaterThan(2 * regular);
});
