// The skin3d TS API (src/skin3d): cage I/O, SubdivisionRig against hand values and invariants,
// weights given per refined or per cage vertex, refined cages, and wasm memory hygiene.
import { beforeAll, expect, test } from 'vitest';
import { SplinekitError, SubdivisionRig, cageToOBJ, init, memory, parseCage, refineCage, type Cage } from '../../src/index.js';
import { readShared } from './helpers.js';

beforeAll(async () => {
  await init();
});

const ID = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0];
const cube = () => parseCage(readShared('meshes/quad/cube_quad.obj'), 'cube_quad.obj');
const maxDiff = (a: ArrayLike<number>, b: ArrayLike<number>) => {
  expect(a.length).toBe(b.length);
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
};

test('parseCage reads faces and crease tags; cageToOBJ writes them back', () => {
  const c = parseCage(readShared('meshes/quad/catmark_car.obj'), 'car');
  expect(c.positions.length / 3).toBe(1642);
  expect(c.faceSizes.length).toBe(1575);
  expect(c.creases).toHaveLength(314);
  expect(c.creases[0]).toEqual({ a: 9, b: 27, sharpness: 6 });
  const back = parseCage(cageToOBJ(c));
  expect(back).toEqual(c);
  const sharp: Cage = { ...cube(), creases: [{ a: 0, b: 1, sharpness: Infinity }] };
  expect(parseCage(cageToOBJ(sharp)).creases).toEqual(sharp.creases);
});

test('parseCage names the problem', () => {
  const bad = (text: string) => {
    try {
      parseCage(text, 'x.obj');
    } catch (err) {
      expect(err).toBeInstanceOf(SplinekitError);
      return (err as Error).message;
    }
    throw new Error('no error');
  };
  expect(bad('v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n')).toMatch(/x\.obj: non-manifold edge 1-2/);
  expect(bad('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n')).toMatch(/line 4: face 1 repeats vertex 2/);
  expect(bad('v 0 0 0\nv 1 0 NaN\n')).toMatch(/line 2: vertex 2 needs 3 finite coordinates/);
  expect(bad('v 0 0 0\n')).toMatch(/no faces/);
  expect(bad('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n')).toMatch(/vertex 9, but the file has 3/);
  expect(bad('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 2/1/0 0 1 -2\n')).toMatch(/line 5: expected "t crease/);
});

test('the cube at level 1: refined() is the hand-computed Catmull-Clark refinement of the posed cage', () => {
  const c = cube();
  const rig = SubdivisionRig.create(c, { handles: [0, 0, 2, 0, 0, -2], levels: 1 });
  try {
    expect(rig.refinedVertexCount).toBe(26);
    expect(rig.refinedTriangles.length).toBe(6 * 4 * 2 * 3);
    // Vertex points are 5/9 of the (valence-3) cube corners and come first; face points are the
    // face centres (one coordinate ±1), last.
    const rest = rig.restRefined;
    for (let k = 0; k < 24; k++) expect(rest[k]).toBeCloseTo((5 / 9) * c.positions[k], 14);
    for (let f = 20; f < 26; f++) expect([0, 1, 2].map((a) => Math.abs(rest[3 * f + a])).sort()).toEqual([0, 0, 1]);
    // A shared scaling by 2 doubles the cage, and refined() of the pose doubles the refinement.
    const S = [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0];
    const posed = rig.pose([...S, ...S]).slice();
    expect(maxDiff(posed, c.positions.map((x) => 2 * x))).toBeLessThan(1e-9);
    expect(maxDiff(rig.refined(), rest.map((x) => 2 * x))).toBeLessThan(1e-9);
    expect(maxDiff(rig.refined(c.positions), rest)).toBeLessThan(1e-15);
    expect(rig.error('fit').rms).toBeLessThan(1e-10);
  } finally {
    rig.dispose();
  }
});

test('the fit beats naive; naive is the blend of the cage vertices; target is the blend of the refined rest surface', () => {
  const c = parseCage(readShared('meshes/quad/spot_control_mesh.obj'));
  const P = c.positions, handles = [0, 60, 120].flatMap((v) => [P[3 * v], P[3 * v + 1], P[3 * v + 2]]);
  const rig = SubdivisionRig.create(c, { handles, levels: 2 });
  try {
    const a = 0.8, cs = Math.cos(a), sn = Math.sin(a);
    const T = [...ID, ...ID, cs, -sn, 0, 0.1, sn, cs, 0, 0, 0, 0, 1, 0.2];
    const naive = rig.pose(T, 'naive').slice();
    const w = rig.weights, H = 3;
    const blend = (p: ArrayLike<number>, wi: (i: number) => number) =>
      [0, 1, 2].map((r) => [0, 1, 2].reduce((acc, i) => acc + wi(i) * (T[12 * i + 4 * r] * p[0] + T[12 * i + 4 * r + 1] * p[1] + T[12 * i + 4 * r + 2] * p[2] + T[12 * i + 4 * r + 3]), 0));
    // Refined vertex 0 is cage vertex 0's descendant; the target at it is the blend with its weights.
    const target = rig.target();
    expect(maxDiff(target.subarray(0, 3), blend(rig.restRefined.subarray(0, 3), (i) => w[i]))).toBeLessThan(1e-12);
    expect(naive.length).toBe(P.length);
    const fit = rig.error('fit'), base = rig.error('naive');
    expect(fit.perVertex.length).toBe(rig.refinedVertexCount);
    expect(fit.rms).toBeGreaterThan(0);
    expect(fit.rms).toBeLessThan(base.rms);
    expect(Math.max(...fit.perVertex)).toBeLessThan(Math.max(...base.perVertex));
    expect(w.length).toBe(rig.refinedVertexCount * H);
  } finally {
    rig.dispose();
  }
});

test('weights given per refined vertex or per cage vertex, and solveWeights, give the same rigs', () => {
  const c = parseCage(readShared('meshes/quad/torus_quad.obj'));
  const handles = [1.35, 0, 0, -1.35, 0, 0];
  const T = [...ID, 1, 0, 0, 0.3, 0, 1, 0, 0, 0, 0, 1, 0];
  const progress: number[] = [];
  const perRefined = SubdivisionRig.solveWeights(c, handles, 2, 'shepard', (f) => progress.push(f));
  expect(progress).toEqual([0, 1]);
  const a = SubdivisionRig.create(c, { handles, levels: 2 });
  const b = SubdivisionRig.create(c, { handles, levels: 2, weights: { perRefinedVertex: perRefined } });
  expect(maxDiff(a.weights, perRefined)).toBe(0);
  // Per cage vertex: half/half everywhere is one shared transform, the average of the two.
  const halves = new Float64Array((c.positions.length / 3) * 2).fill(0.5);
  const h = SubdivisionRig.create(c, { handles, levels: 2, weights: { perCageVertex: halves } });
  try {
    const posedA = a.pose(T).slice(), posedB = b.pose(T).slice();
    // Same refined weights; the naive baseline's cage weights differ (descendants vs the vertices), not the fit.
    expect(maxDiff(posedA, posedB)).toBeLessThan(1e-6);
    const moved = h.pose(T);
    for (let v = 0; v < c.positions.length / 3; v++) expect(moved[3 * v]).toBeCloseTo(c.positions[3 * v] + 0.15, 9);
    expect(() => SubdivisionRig.create(c, { handles, weights: { perCageVertex: new Float64Array(3) } })).toThrow(/weights must be a Float64Array of 144 values/);
  } finally {
    a.dispose();
    b.dispose();
    h.dispose();
  }
});

test('solveWeights with bbw reports progress after each handle and gives the rig\'s own bbw weights', () => {
  const c = parseCage(readShared('meshes/quad/torus_quad.obj'));
  const handles = [1.35, 0, 0, -1.35, 0, 0, 0, 0.65, 0];
  const progress: number[] = [];
  const solved = SubdivisionRig.solveWeights(c, handles, 2, 'bbw', (f) => progress.push(f));
  expect(progress).toEqual([0, ...[1, 2, 3].map((k) => (0.95 * k) / 3), 1]);
  const rig = SubdivisionRig.create(c, { handles, levels: 2, weights: 'bbw' });
  try {
    expect(maxDiff(rig.weights, solved)).toBe(0);
  } finally {
    rig.dispose();
  }
});

test('bbw weights: bounded, a partition of unity', () => {
  const c = parseCage(readShared('meshes/quad/torus_quad.obj'));
  const rig = SubdivisionRig.create(c, { handles: [1.35, 0, 0, -1.35, 0, 0, 0, 0.65, 0], levels: 2, weights: 'bbw' });
  try {
    const w = rig.weights;
    for (let v = 0; v < rig.refinedVertexCount; v++) {
      const row = [w[3 * v], w[3 * v + 1], w[3 * v + 2]];
      expect(Math.min(...row)).toBeGreaterThanOrEqual(-1e-12);
      expect(row[0] + row[1] + row[2]).toBeCloseTo(1, 12);
    }
  } finally {
    rig.dispose();
  }
});

test('limit(): the regular torus lands on its bicubic B-spline surface; posed limits follow the pose', () => {
  const c = parseCage(readShared('meshes/quad/torus_quad.obj'));
  const rig = SubdivisionRig.create(c, { handles: [1.35, 0, 0], levels: 1 });
  try {
    // Vertex point of cage vertex 6i + j at level 1 has the limit (1,4,1)⊗(1,4,1)/36 of the cage.
    const P = c.positions, lim = rig.limit(P).slice(); // a view: copied before the next call
    for (const [i, j] of [[0, 0], [5, 3], [11, 5]]) {
      const want = [0, 0, 0];
      for (let di = -1; di <= 1; di++)
        for (let dj = -1; dj <= 1; dj++) {
          const w = ((di === 0 ? 4 : 1) * (dj === 0 ? 4 : 1)) / 36, v = 6 * ((i + di + 12) % 12) + ((j + dj + 6) % 6);
          for (let a = 0; a < 3; a++) want[a] += w * P[3 * v + a];
        }
      expect(maxDiff(lim.subarray(3 * (6 * i + j), 3 * (6 * i + j) + 3), want)).toBeLessThan(1e-14);
    }
    const moved = rig.pose([1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3]).slice();
    const posedLimit = rig.limit();
    expect(posedLimit[0]).toBeCloseTo(lim[0] + 1, 9);
    expect(moved[2]).toBeCloseTo(P[2] + 3, 9);
  } finally {
    rig.dispose();
  }
});

test('refineCage: subdividing the refined cage once is subdividing the cage twice (creases decayed)', () => {
  const c = parseCage(readShared('meshes/quad/catmark_cube_creases1.obj'));
  const once = refineCage(c, 1);
  expect(once.faceSizes.every((n) => n === 4)).toBe(true);
  // Each crease's two halves carry its sharpness less one; the 0.1 crease is smooth after a level.
  expect(once.creases.length).toBe(2 * c.creases.filter((k) => k.sharpness > 1).length);
  expect(new Set(once.creases.map((k) => k.sharpness))).toEqual(new Set([4]));
  const a = SubdivisionRig.create(c, { handles: [0, 0, 0], levels: 2 });
  const b = SubdivisionRig.create(once, { handles: [0, 0, 0], levels: 1 });
  try {
    expect(maxDiff(a.restRefined, b.restRefined)).toBeLessThan(1e-14);
  } finally {
    a.dispose();
    b.dispose();
  }
});

test('corner tags: parsed (n/1/0 and n/n/0), written back, kept by the rig and decayed by refineCage', () => {
  const text = cageToOBJ(cube()) + 't corner 1/1/0 0 inf\nt corner 2/2/0 6 7 2 0.5\n';
  const c = parseCage(text);
  expect(c.corners).toEqual([{ v: 0, sharpness: Infinity }, { v: 6, sharpness: 2 }, { v: 7, sharpness: 0.5 }]);
  expect(parseCage(cageToOBJ(c))).toEqual(c);
  expect(parseCage(cageToOBJ(cube())).corners).toBeUndefined();
  // Vertex 0 (infinitely sharp) stays on the cage vertex at level 3; vertex 6 (sharpness 2) does
  // at level 2 but not at 3; untagged, both move.
  const at = (cage: Cage, levels: number, v: number) => {
    const rig = SubdivisionRig.create(cage, { handles: [0, 0, 0], levels });
    try {
      return Array.from(rig.restRefined.subarray(3 * v, 3 * v + 3));
    } finally {
      rig.dispose();
    }
  };
  const P = (v: number) => Array.from(c.positions.subarray(3 * v, 3 * v + 3));
  expect(at(c, 3, 0)).toEqual(P(0));
  expect(at(c, 2, 6)).toEqual(P(6));
  expect(maxDiff(at(c, 3, 6), P(6))).toBeGreaterThan(1e-3);
  expect(maxDiff(at(cube(), 3, 0), P(0))).toBeGreaterThan(1e-3);
  // refineCage: sharpness less one on the vertex points; 0.5 is gone after a level.
  const once = refineCage(c, 1);
  expect(once.corners).toEqual([{ v: 0, sharpness: Infinity }, { v: 6, sharpness: 1 }]);
  expect(maxDiff(at(once, 2, 6), at(c, 3, 6))).toBeLessThan(1e-14);
  const bad = (t: string) => () => parseCage(cageToOBJ(cube()) + t, 'x.obj');
  expect(bad('t corner 1/1/0 0 0\n')).toThrow(/line 15: expected "t corner/);
  expect(bad('t corner 2/1/0 0\n')).toThrow(/expected "t corner/);
  expect(bad('t corner 1/1/0 8 1\n')).toThrow(/corner vertex 8 \(0-based\) is outside 0\.\.7/);
});

test('bad arguments throw and leave nothing behind; create/dispose does not leak; pose allocates nothing', () => {
  const c = cube();
  expect(() => SubdivisionRig.create(c, { handles: [0, 0] })).toThrow(/3 numbers per handle/);
  expect(() => SubdivisionRig.create(c, { handles: [0, 0, NaN] })).toThrow(/non-finite/);
  expect(() => SubdivisionRig.create(c, { handles: [0, 0, 0], levels: 5 })).toThrow(/levels must be an integer in 1\.\.4/);
  const rig0 = SubdivisionRig.create(c, { handles: [0, 0, 1], levels: 1 });
  rig0.dispose();
  const before = memory().used;
  for (let k = 0; k < 50; k++) SubdivisionRig.create(c, { handles: [0, 0, 1], levels: 2 }).dispose();
  expect(memory().used).toBe(before);
  const rig = SubdivisionRig.create(c, { handles: [0, 0, 1, 0, 0, -1], levels: 2 });
  expect(() => rig.pose(ID)).toThrow(/expected 2 transforms \(12 numbers each\), got 12 values/);
  expect(() => rig.pose([...ID, ...ID.map(() => NaN)])).toThrow(/transform 1 has a non-finite entry/);
  rig.pose([...ID, ...ID]);
  const used = memory().used;
  for (let k = 0; k < 1000; k++) rig.pose([...ID, ...ID]);
  expect(memory().used).toBe(used);
  rig.dispose();
  expect(() => rig.pose([...ID, ...ID])).toThrow(/used after dispose/);
});
