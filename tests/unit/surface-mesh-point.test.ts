// The mesh-point kernels on flat arrays (src/surface/mesh-point.ts) that the editor's worker and
// picking use: positions against SurfaceMesh.xyz (the checked form), corners against the vertex
// positions, normals against closed forms (a flat sheet, the octahedron's symmetry), and the
// `target` form against the allocating one.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { beforeAll, describe, expect, test } from 'vitest';
import { SurfaceMesh, init, meshPointNormal, meshPointPosition, randomMeshPoints, vertexNormals, type MeshPoint } from '../../src/index.js';
import { repoRoot } from './helpers.js';

beforeAll(async () => {
  await init();
});

/** The regular octahedron: vertices ±e_i, 8 faces wound outward. */
const OCTA_POSITIONS = [1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1];
const OCTA_TRIANGLES = [0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5];

describe('meshPointPosition', () => {
  test('agrees with SurfaceMesh.xyz at random points of a sample mesh, Float32 and Float64 arrays alike', async () => {
    const bytes = readFileSync(join(repoRoot, 'public/samples/meshes/pebble.ply'));
    const mesh = await SurfaceMesh.load(new Uint8Array(bytes), 'pebble.ply');
    try {
      const points = randomMeshPoints(mesh, 500, 7);
      const P32 = Float32Array.from(mesh.positions), T = Uint32Array.from(mesh.triangles);
      for (const p of points) {
        const want = mesh.xyz(p);
        const got = meshPointPosition(mesh.positions, mesh.triangles, p);
        for (let k = 0; k < 3; k++) expect(got[k]).toBeCloseTo(want[k], 12);
        const got32 = meshPointPosition(P32, T, p);
        for (let k = 0; k < 3; k++) expect(Math.abs(got32[k] - want[k])).toBeLessThan(1e-5 * mesh.scale);
      }
    } finally {
      mesh.dispose();
    }
  });

  test('a face corner is its vertex, the barycentre the mean of the three', () => {
    const T = OCTA_TRIANGLES, P = OCTA_POSITIONS;
    for (let f = 0; f < T.length / 3; f++) {
      const corners: [number, number][] = [
        [0, 0],
        [1, 0],
        [0, 1],
      ];
      corners.forEach(([u, v], c) => {
        const got = meshPointPosition(P, T, { face: f, uv: [u, v] });
        expect(got).toEqual([P[3 * T[3 * f + c]], P[3 * T[3 * f + c] + 1], P[3 * T[3 * f + c] + 2]]);
      });
      const mid = meshPointPosition(P, T, { face: f, uv: [1 / 3, 1 / 3] });
      for (let k = 0; k < 3; k++) expect(mid[k]).toBeCloseTo((P[3 * T[3 * f] + k] + P[3 * T[3 * f + 1] + k] + P[3 * T[3 * f + 2] + k]) / 3, 14);
    }
  });

  test('writes into the target it is given and returns it', () => {
    const target: [number, number, number] = [9, 9, 9];
    const out = meshPointPosition(OCTA_POSITIONS, OCTA_TRIANGLES, { face: 0, uv: [0.25, 0.5] }, target);
    expect(out).toBe(target);
    // face 0 = (e_x, e_y, e_z): 0.25·e_y + 0.5·e_z + 0.25·e_x.
    expect(target).toEqual([0.25, 0.25, 0.5]);
  });
});

describe('vertexNormals and meshPointNormal', () => {
  test('the octahedron: by symmetry each vertex normal is its position, and a face centre has the face normal', () => {
    const N = vertexNormals(OCTA_POSITIONS, OCTA_TRIANGLES);
    for (let i = 0; i < OCTA_POSITIONS.length; i++) expect(N[i]).toBeCloseTo(OCTA_POSITIONS[i], 6);
    // Face 0's centre: the mean of e_x, e_y, e_z, made unit: (1,1,1)/√3.
    const n = meshPointNormal(N, OCTA_TRIANGLES, { face: 0, uv: [1 / 3, 1 / 3] });
    for (let k = 0; k < 3; k++) expect(n[k]).toBeCloseTo(1 / Math.sqrt(3), 6);
    // Along an edge the normal turns between the two vertex normals, staying unit.
    const e = meshPointNormal(N, OCTA_TRIANGLES, { face: 0, uv: [0.5, 0] });
    expect(Math.hypot(...e)).toBeCloseTo(1, 12);
    expect(e[0]).toBeCloseTo(Math.SQRT1_2, 6);
    expect(e[1]).toBeCloseTo(Math.SQRT1_2, 6);
    expect(e[2]).toBeCloseTo(0, 12);
  });

  test('a flat sheet: every normal is the sheet normal, area weights or not; a vertex no face uses gets zero', () => {
    // Two triangles of very different areas in the plane z = 2, wound counter-clockwise (normal +z), and an unused vertex 4.
    const P = [0, 0, 2, 10, 0, 2, 0, 1, 2, 10, 10, 2, 5, 5, 5];
    const T = [0, 1, 2, 1, 3, 2];
    const N = vertexNormals(P, T);
    for (let v = 0; v < 4; v++) expect([N[3 * v], N[3 * v + 1], N[3 * v + 2]]).toEqual([0, 0, 1]);
    expect([N[12], N[13], N[14]]).toEqual([0, 0, 0]);
    const p: MeshPoint = { face: 1, uv: [0.2, 0.3] };
    expect(meshPointNormal(N, T, p)).toEqual([0, 0, 1]);
  });

  test('area weighting: a vertex shared by a large and a small face leans toward the large one', () => {
    // Vertex 0 at the origin; a large face in the plane z = 0 (normal +z) and a small one in x = 0 (wound toward −x).
    const P = [0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 1, 0, -1, 0];
    const T = [0, 1, 2, 0, 4, 3];
    const N = vertexNormals(P, T);
    // The faces' cross products: large (4,0,0)×(0,4,0) = (0,0,16); small (0,-1,0)×(0,0,1) = (-1,0,0).
    const large = [0, 0, 16], small = [-1, 0, 0];
    const sum = [large[0] + small[0], large[1] + small[1], large[2] + small[2]];
    const l = Math.hypot(sum[0], sum[1], sum[2]);
    for (let k = 0; k < 3; k++) expect(N[k]).toBeCloseTo(sum[k] / l, 6);
  });
});
