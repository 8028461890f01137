// The mesh report crosses from the core (wasm/core/surface/mesh.h report_fields) to SurfaceMesh.info
// by name. A mesh built here has a different known count in every field, each worked out below from
// how it is made, so a field read under another's name (or a renumbering on one side) fails.
import { beforeAll, expect, test } from 'vitest';
import { init, SurfaceMesh } from '../../src/index.js';
import { MESH_REPORT_FIELDS } from '../../src/surface/mesh.js';
import { meshHandles } from '../../src/surface/mesh-handle.js';

beforeAll(async () => {
  await init();
});

/** A mesh of known oddities; returns its arrays and the counts it must report. */
function oddMesh() {
  const positions: number[] = [];
  const triangles: number[] = [];
  const vertex = (x: number, y: number, z = 0) => positions.push(x, y, z) / 3 - 1;
  const face = (a: number, b: number, c: number) => triangles.push(a, b, c);

  // P1: a 3×1 strip of unit quads, bottom a0..a3, top a4..a7, two triangles per quad. The second
  // triangle of each quad is wound against the first: 3 flipped faces. Five later faces use copies
  // of a1, a5, a2, a7, a6 written after the originals: 5 welded vertices.
  const a = [0, 1, 2, 3].map((i) => vertex(i, 0)).concat([0, 1, 2, 3].map((i) => vertex(i, 1)));
  const d1 = vertex(1, 0), d5 = vertex(1, 1), d2 = vertex(2, 0), d7 = vertex(3, 1), d6 = vertex(2, 1);
  face(a[0], a[1], a[5]); face(a[0], a[4], a[5]); // quad 0: ccw (bl, br, tr), cw (bl, tl, tr)
  face(d1, a[2], a[6]); face(a[1], d5, a[6]); // quad 1: ccw, cw
  face(d2, a[3], d7); face(a[2], d6, a[7]); // quad 2: ccw, cw
  // Six vertices no face uses.
  for (let i = 0; i < 6; i++) vertex(20 + i, 20);
  // Two faces that repeat a vertex: each is kept on its own (a component of one face).
  face(a[0], a[0], a[4]);
  face(a[3], a[7], a[7]);
  // P2: a fin of four triangles on one edge b0–b1: 1 non-manifold edge; no two of the four are
  // adjacent, so each is a component and a boundary loop, and b0 and b1 each lie on 4 fans:
  // 2 non-manifold vertices with 3 extra copies each.
  const b0 = vertex(5, 0), b1 = vertex(6, 0);
  const wings = [vertex(5.5, 1), vertex(5.5, -1), vertex(5.5, 0, 1), vertex(5.5, 0, -1)];
  face(b0, b1, wings[0]); face(b1, b0, wings[1]); face(b0, b1, wings[2]); face(b1, b0, wings[3]);
  // P3: two bowties, two triangles touching at one vertex: 2 non-manifold vertices with one extra
  // copy each, 4 components, 4 boundary loops.
  for (const y of [5, 8]) {
    const c = vertex(0, y);
    face(c, vertex(1, y - 0.5), vertex(1, y + 0.5));
    face(c, vertex(-1, y + 0.5), vertex(-1, y - 0.5));
  }
  // P4: seven faces that repeat a face of P1 after welding, in another order or winding (as a
  // double-sided mesh has them): left out of the adjacency and the fans, no part or boundary of
  // their own; the face they repeat stands for them.
  face(a[5], a[1], a[0]); face(a[1], a[5], a[0]); face(a[0], a[1], a[5]); // P1's face 0 (a0 a1 a5)
  face(a[6], a[2], a[1]); face(a[1], a[2], a[6]); // its face 2 (d1 = a1, a2, a6)
  face(a[5], a[6], a[1]); // its face 3 (a1, d5 = a5, a6)
  face(a[4], a[0], a[5]); // its face 1 (a0 a4 a5)
  const expected = {
    vertices: 8 + 5 + 6 + 6 + 2 * 5,
    faces: 6 + 2 + 4 + 4 + 7,
    usedVertices: 8 + (6 + 2 * 3) + 2 * (5 + 1),
    weldedVertices: 5,
    unreferencedVertices: 6,
    degenerateFaces: 2,
    duplicateFaces: 7,
    nonManifoldEdges: 1,
    nonManifoldVertices: 4,
    flippedFaces: 3,
    boundaryLoops: 1 + 4 + 4,
    components: 1 + 2 + 4 + 4,
  };
  return { positions, triangles, expected };
}

test('every count of the mesh report lands in its own MeshInfo field', () => {
  const { positions, triangles, expected } = oddMesh();
  expect(new Set(Object.values(expected)).size).toBe(Object.keys(expected).length); // all different
  const mesh = SurfaceMesh.fromArrays(positions, triangles);
  try {
    const { bytes, warnings, landmarks, guideFaces, buildMs, ...counts } = mesh.info;
    expect(counts).toEqual(expected);
    expect(bytes).toBeGreaterThan(0);
    expect(landmarks).toBe(0); // (16 faces: below the landmarks' minimum)
    expect(guideFaces).toBe(0); // (and the coarse guide's)
    expect(buildMs.mesh).toBeGreaterThanOrEqual(0);
    expect(buildMs.search).toBeGreaterThanOrEqual(0);
    expect(warnings).toEqual([
      'welded 5 vertices that share a position with an earlier one',
      'ignored 6 vertices that no face uses',
      '2 faces repeat a vertex: curves do not cross them',
      '7 faces repeat an earlier face (a double-sided mesh?): taken as that face',
      '1 edges have more than two faces: treated as boundaries',
      '4 vertices join separate fans of faces: split',
      '3 faces were wound against their neighbours: re-oriented',
      'the mesh has 11 separate parts: curves cannot cross between them',
    ]);
    // The core names its counts in one order; the package reads exactly those names.
    const fields = meshHandles.get(mesh).reportFields();
    expect(Object.keys(fields)).toEqual([...MESH_REPORT_FIELDS]);
    // The two counts MeshInfo does not carry: no cut for orientability; boundary edges: the strip's
    // perimeter (8), and every fin and bowtie triangle's three edges (8 × 3).
    expect(fields.non_orientable_cuts).toBe(0);
    expect(fields.boundary_edges).toBe(8 + 8 * 3);
  } finally {
    mesh.dispose();
  }
});

test('a disposed mesh has no handle left to reach', () => {
  const { positions, triangles } = oddMesh();
  const mesh = SurfaceMesh.fromArrays(positions, triangles);
  expect(mesh.isDisposed).toBe(false);
  mesh.dispose();
  expect(mesh.isDisposed).toBe(true);
  expect(() => meshHandles.get(mesh)).toThrow('the mesh has been disposed');
  expect(() => mesh.shortestPath(0, 1)).toThrow('the mesh has been disposed');
  expect('handle' in mesh).toBe(false);
});
