/**
 * The coarse guide of long shortest paths (wasm/core/surface/coarse_guide.h): a decimation of the
 * mesh on which a long path is found first, its strip on the mesh then following that path (on
 * coiled, folded and limbed shapes the greedy search's strip keeps to the wrong side of a turn and
 * the straightening sweeps the band between). Made by meshoptimizer's `simplify` (edge collapses
 * under a quadric error bound: the guide's vertices are mesh vertices, and its surface keeps the
 * mesh's topology), which the core needs: it walks from a point to the nearest kept vertex.
 */
import { MeshoptSimplifier, type SimplifierFlags } from 'meshoptimizer/simplifier';

/** Meshes of at least this many faces get a guide unless SurfaceMeshOptions.guide says otherwise. */
export const GUIDE_MIN_FACES = 65536;

/**
 * The guide's share of the mesh's faces: a sixteenth (2026-12-05, native, 30 random curves on the
 * benchmark's coil, knotted tube and folded body: a thirty-second and an eighth took 1.0-1.3 times
 * as long; the guide holds ~11 bytes per mesh face, BENCHMARKS.md "Surface at scale", Coarse guide).
 */
export const GUIDE_RATIO = 1 / 16;

/**
 * The simplifier's error bound, relative to the mesh's extent: it stops short of the face count
 * rather than move the surface farther (a guide a quarter of the mesh or larger is not built).
 */
const GUIDE_ERROR = 0.01;

/**
 * The simplifier's flags: 'RegularizeLight' keeps the guide's triangles near regular. The guide's
 * paths come from a search over its faces' centroids, which on slivers zigzags and takes the long
 * way: the plain simplification of the benchmark's folded body (its faces 14:1) made slivers up to
 * 55:1 (p99), and guided paths there often followed another limb before the straightening found the
 * short way (2026-12-05, native, 40 random curves: the three sides' straightening 713 → 274 ms,
 * the curves 950 → 455 ms; the coil and the knotted tube within their run-to-run noise, ±10%).
 */
const GUIDE_FLAGS: SimplifierFlags[] = ['RegularizeLight'];

/** Loads the simplifier's WebAssembly (init() awaits it with the core's). */
export function loadSimplifier(): Promise<void> {
  return MeshoptSimplifier.ready;
}

/**
 * The guide's triangles (three vertex indices of the mesh each) for the mesh `positions` (x y z) /
 * `triangles` (a b c), or null when the simplifier could not bring it below a quarter of the faces
 * within its error bound. The simplifier must be loaded (loadSimplifier).
 */
export function guideTriangles(positions: ArrayLike<number>, triangles: ArrayLike<number>): Uint32Array | null {
  const faces = triangles.length / 3;
  // Single precision relative to the box's centre (a scan in georeferenced coordinates keeps its
  // shape's digits).
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) {
    const k = i % 3;
    if (positions[i] < lo[k]) lo[k] = positions[i];
    if (positions[i] > hi[k]) hi[k] = positions[i];
  }
  const local = new Float32Array(positions.length);
  for (let i = 0; i < positions.length; i++) local[i] = positions[i] - (lo[i % 3] + hi[i % 3]) / 2;
  const [kept] = MeshoptSimplifier.simplify(Uint32Array.from(triangles), local, 3, 3 * Math.floor(faces * GUIDE_RATIO), GUIDE_ERROR, GUIDE_FLAGS);
  return kept.length > 0 && kept.length / 3 <= faces / 4 ? kept : null;
}
