/**
 * A coarse stand-in for a large mesh, for the frames where drawing every triangle would take too
 * long (a software rasteriser spends ~0.2 µs a triangle: a 2M-triangle mesh is ~0.4 s a frame).
 * Made by meshoptimizer's sloppy simplifier (`simplifySloppy`: vertex clustering on a grid it
 * sizes to reach the triangle count asked for, each cell kept as the one of its vertices that
 * least changes the surface), which takes about as long as one pass over the mesh and needs no
 * topology; its topology-preserving `simplify` looks better but takes seconds at 2M triangles.
 * The proxy looks like the mesh from a distance, which is all it is for (picking, tracing and the
 * still picture use the mesh).
 */
import { MeshoptSimplifier } from 'meshoptimizer/simplifier';

export interface MeshProxy {
  positions: Float32Array;
  triangles: Uint32Array;
  /** The mesh vertex each vertex of the proxy is (for its attributes, as its smooth normal). */
  vertices: Uint32Array;
}

/**
 * A proxy of about `target` triangles (fewer on a mesh the grid cannot bring to that count; the
 * mesh itself, compacted, if it has no more than `target`) of the mesh `positions` (x y z) /
 * `triangles` (a b c): its vertices are vertices of the mesh (only those its triangles use).
 * With the mesh's smooth vertex `normals`, a triangle of the proxy that faces against them at its
 * corners is left out: the clustering turned it over on a fold (where others cover the surface),
 * and it would be drawn as a back face, dark.
 */
export async function meshProxy(positions: Float32Array, triangles: Uint32Array, target: number, normals?: ArrayLike<number>): Promise<MeshProxy> {
  await MeshoptSimplifier.ready;
  if (positions.length === 0 || triangles.length === 0) return { positions: new Float32Array(0), triangles: new Uint32Array(0), vertices: new Uint32Array(0) };
  // The error bound is relative to the mesh's extent: 1 leaves the count alone to decide.
  let [kept] = triangles.length / 3 <= target ? [triangles.slice()] : MeshoptSimplifier.simplifySloppy(triangles, positions, 3, null, 3 * Math.max(1, Math.floor(target)), 1);
  if (normals) kept = facingAlong(positions, kept, normals);
  // Only the vertices the proxy uses: a few percent of a large mesh's, so that the proxy's
  // normals, its transfer to the page and its upload cost next to nothing.
  const [remap, used] = MeshoptSimplifier.compactMesh(kept);
  const out = new Float32Array(3 * used), vertices = new Uint32Array(used);
  for (let v = 0; v < remap.length; v++) {
    const w = remap[v];
    if (w === 0xffffffff) continue;
    vertices[w] = v;
    out[3 * w] = positions[3 * v];
    out[3 * w + 1] = positions[3 * v + 1];
    out[3 * w + 2] = positions[3 * v + 2];
  }
  return { positions: out, triangles: kept, vertices };
}

/** The triangles of `T` (on `P`) whose normal is on the side of the sum of `N` at their corners. */
function facingAlong(P: ArrayLike<number>, T: Uint32Array, N: ArrayLike<number>): Uint32Array {
  const out = new Uint32Array(T.length);
  let k = 0;
  for (let f = 0; f < T.length; f += 3) {
    const a = 3 * T[f], b = 3 * T[f + 1], c = 3 * T[f + 2];
    const ux = P[b] - P[a], uy = P[b + 1] - P[a + 1], uz = P[b + 2] - P[a + 2];
    const vx = P[c] - P[a], vy = P[c + 1] - P[a + 1], vz = P[c + 2] - P[a + 2];
    const sx = N[a] + N[b] + N[c], sy = N[a + 1] + N[b + 1] + N[c + 1], sz = N[a + 2] + N[b + 2] + N[c + 2];
    if ((uy * vz - uz * vy) * sx + (uz * vx - ux * vz) * sy + (ux * vy - uy * vx) * sz <= 0) continue;
    out[k++] = T[f];
    out[k++] = T[f + 1];
    out[k++] = T[f + 2];
  }
  return k === T.length ? T : out.slice(0, k);
}
