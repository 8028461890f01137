// The shortest-path search's landmarks (SurfaceMeshOptions.landmarks; wasm/core/surface/landmarks.h)
// through the package: the option, what the mesh reports, the memory they take, and paths on a flat
// U (points close in space, far apart on the surface) that keep their closed-form lengths.
import { beforeAll, describe, expect, test } from 'vitest';
import { uShape } from './helpers.js';
import { DEFAULT_LANDMARKS, SplinekitError, SurfaceMesh, init, traceBezier } from '../../src/index.js';

beforeAll(async () => {
  await init();
});

// The flat U (helpers.ts): 160 × 64 unit cells, the slot at x in [S, S + 2), y >= B.
const W = 160, H = 64, S = 79, B = 8;

describe('landmarks', () => {
  const u = uShape(W, H, S, B);
  const { positions, triangles } = u;

  test('are on by default on large meshes, take 2 bytes per face each, and can be turned off', () => {
    const withLandmarks = SurfaceMesh.fromArrays(positions, triangles);
    const without = SurfaceMesh.fromArrays(positions, triangles, { landmarks: 0 });
    try {
      expect(DEFAULT_LANDMARKS).toBe(8);
      expect(withLandmarks.info.landmarks).toBe(8);
      expect(without.info.landmarks).toBe(0);
      const faces = triangles.length / 3;
      // 16-bit values per face and landmark, plus the landmark list and the target intervals.
      const extra = withLandmarks.info.bytes - without.info.bytes;
      expect(extra).toBeGreaterThanOrEqual(2 * 8 * faces);
      expect(extra).toBeLessThan(2 * 8 * faces + 1024);
      expect(withLandmarks.info.buildMs.search).toBeGreaterThan(0);
      expect(withLandmarks.info.buildMs.mesh).toBeGreaterThan(0);
    } finally {
      withLandmarks.dispose();
      without.dispose();
    }
  });

  test('paths across the slot go round its end: the closed-form length, with and without landmarks', () => {
    for (const landmarks of [DEFAULT_LANDMARKS, 0]) {
      const mesh = SurfaceMesh.fromArrays(positions, triangles, { landmarks });
      try {
        const corner1 = [S, B], corner2 = [S + 2, B];
        for (const [ax, ay, bx, by] of [[70.3, 60.2, 90.6, 55.1], [78.9, 63.5, 81.2, 63.5], [10.25, 40.5, 150.5, 12.75], [5.5, 9.5, 158.5, 62.5]]) {
          const path = mesh.shortestPath(u.pointAt(ax, ay), u.pointAt(bx, by));
          // Round the two reflex corners of the slot's end (both points lie above it, in their arms).
          const expected = Math.hypot(ax - corner1[0], ay - corner1[1]) + 2 + Math.hypot(bx - corner2[0], by - corner2[1]);
          expect(Math.abs(path.length - expected), `landmarks ${landmarks}: (${ax}, ${ay}) -> (${bx}, ${by})`).toBeLessThan(1e-9);
        }
        // Points below the slot see each other: the straight segment.
        const path = mesh.shortestPath(u.pointAt(3.5, 1.5), u.pointAt(155.25, 6.5));
        expect(Math.abs(path.length - Math.hypot(155.25 - 3.5, 5))).toBeLessThan(1e-9);
      } finally {
        mesh.dispose();
      }
    }
  });

  test('deferSearch: the mesh first, its search structures on buildSearch() or the first path, the same paths', () => {
    const eager = SurfaceMesh.fromArrays(positions, triangles);
    const lazy = SurfaceMesh.fromArrays(positions, triangles, { deferSearch: true });
    const called = SurfaceMesh.fromArrays(positions, triangles, { deferSearch: true });
    try {
      expect(eager.searchBuilt).toBe(true);
      expect(lazy.searchBuilt).toBe(false);
      // Before: the mesh alone (no landmarks, no search graph, no search time).
      expect(lazy.info.landmarks).toBe(0);
      expect(lazy.info.buildMs.search).toBe(0);
      const faces = triangles.length / 3;
      // (the search graph, centroids and landmarks take over 40 bytes per triangle)
      expect(eager.info.bytes - lazy.info.bytes).toBeGreaterThan(40 * faces);
      // The first path builds them; info then counts them as the eager mesh does.
      const a = u.pointAt(70.3, 60.2), b = u.pointAt(90.6, 55.1);
      const lazyPath = lazy.shortestPath(a, b);
      expect(lazy.searchBuilt).toBe(true);
      expect(lazy.info.landmarks).toBe(8);
      expect(lazy.info.bytes).toBe(eager.info.bytes);
      expect(lazy.info.buildMs.search).toBeGreaterThan(0);
      expect(lazyPath.length).toBe(eager.shortestPath(a, b).length);
      // buildSearch() does it at once and returns the info; a second call changes nothing.
      const info = called.buildSearch();
      expect(called.searchBuilt).toBe(true);
      expect(info.landmarks).toBe(8);
      expect(info.bytes).toBe(eager.info.bytes);
      const ms = info.buildMs.search;
      expect(called.buildSearch().buildMs.search).toBe(ms);
      expect(called.shortestPath(a, b).length).toBe(lazyPath.length);
    } finally {
      eager.dispose();
      lazy.dispose();
      called.dispose();
    }
  });

  test("a curve's work counters add up: chords among the kept flips, their walks' faces, the passes' faces", () => {
    const mesh = SurfaceMesh.fromArrays(positions, triangles);
    try {
      // A control polygon that crosses the slot twice: its sides go round the slot's end.
      const traced = traceBezier(mesh, [u.pointAt(20.5, 60.5), u.pointAt(120.5, 50.5), u.pointAt(30.5, 20.5), u.pointAt(140.5, 40.5)]);
      const c = traced.counters;
      expect(c.searchedPaths + c.seededPaths).toBeGreaterThan(20);
      expect(c.flips).toBeGreaterThan(0);
      expect(c.chordsTried).toBeGreaterThan(0);
      expect(c.chords).toBeGreaterThan(0);
      expect(c.chords).toBeLessThanOrEqual(c.flips);
      expect(c.chords).toBeLessThanOrEqual(c.chordsTried);
      // A kept chord walked at least the faces it put into the strip.
      expect(c.walkedFaces).toBeGreaterThanOrEqual(c.chords);
      // A pass works on a strip of two faces or more; this slot's strips are too short for windows.
      expect(c.passes).toBeGreaterThan(0);
      expect(c.passFaces).toBeGreaterThanOrEqual(2 * c.passes);
      expect(c.windows).toBe(0);
      for (const v of Object.values(c)) expect(Number.isInteger(v)).toBe(true);
    } finally {
      mesh.dispose();
    }
  });

  test('a bad landmark count is one clear error', () => {
    for (const landmarks of [-1, 2.5, 65, Number.NaN]) {
      let error: unknown;
      try {
        SurfaceMesh.fromArrays(positions, triangles, { landmarks }).dispose();
      } catch (err) {
        error = err;
      }
      expect(error).toBeInstanceOf(SplinekitError);
      expect((error as SplinekitError).code).toBe('invalid-input');
      expect((error as SplinekitError).message).toMatch(/landmarks must be an integer from 0 to 64/);
    }
  });
});
