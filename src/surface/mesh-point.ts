/** A point on a face: (1−u−v)·p0 + u·p1 + v·p2 of the face's vertices, in file order. */
export interface MeshPoint {
  /** The face (file order). */
  face: number;
  /** Barycentric coordinates (u, v) with respect to the face's 2nd and 3rd vertex. */
  uv: [number, number];
}

/** A mesh point, or a vertex index (file order). */
export type MeshPointLike = MeshPoint | number;

/**
 * Kernels on mesh points over flat arrays, for code that holds a mesh's arrays rather than a
 * SurfaceMesh (a worker's copy, a three.js geometry): the point's position, its smooth normal, and
 * the smooth vertex normals themselves. A mesh point `{ face, uv: [u, v] }` is
 * (1−u−v)·v0 + u·v1 + v·v2 of its face's corners, as everywhere in the package.
 *
 * Shapes: `positions` and `normals` are #V×3 (x y z per vertex), `triangles` #F×3 (vertex indices
 * per face, in the file's order); Float32Array, Float64Array or plain arrays alike. Nothing is
 * allocated when a `target` is given.
 */

/** Barycentric interpolation of a per-vertex 3-vector (#V×3) at `p`, into `target`. */
function interpolate(values: ArrayLike<number>, triangles: ArrayLike<number>, p: MeshPoint, target: [number, number, number]): [number, number, number] {
  const f = 3 * p.face;
  const a = 3 * triangles[f], b = 3 * triangles[f + 1], c = 3 * triangles[f + 2];
  const u = p.uv[0], v = p.uv[1], w = 1 - u - v;
  target[0] = w * values[a] + u * values[b] + v * values[c];
  target[1] = w * values[a + 1] + u * values[b + 1] + v * values[c + 1];
  target[2] = w * values[a + 2] + u * values[b + 2] + v * values[c + 2];
  return target;
}

/**
 * Where mesh point `p` is: x y z. The face must exist (`0 ≤ p.face < #F`); SurfaceMesh.xyz is the
 * checked form of the same for a SurfaceMesh.
 */
export function meshPointPosition(
  positions: ArrayLike<number>,
  triangles: ArrayLike<number>,
  p: MeshPoint,
  target: [number, number, number] = [0, 0, 0],
): [number, number, number] {
  return interpolate(positions, triangles, p, target);
}

/**
 * The smooth normal at mesh point `p`: the vertex normals (#V×3, e.g. from vertexNormals)
 * interpolated and made unit length (left as it is where they cancel out).
 */
export function meshPointNormal(
  normals: ArrayLike<number>,
  triangles: ArrayLike<number>,
  p: MeshPoint,
  target: [number, number, number] = [0, 0, 0],
): [number, number, number] {
  interpolate(normals, triangles, p, target);
  const l = Math.hypot(target[0], target[1], target[2]) || 1;
  target[0] /= l;
  target[1] /= l;
  target[2] /= l;
  return target;
}

/**
 * Area-weighted vertex normals (#V×3): each vertex gets the sum of its faces' cross products
 * (v1−v0)×(v2−v0), made unit length; a vertex no face uses gets (0, 0, 0).
 */
export function vertexNormals(positions: ArrayLike<number>, triangles: ArrayLike<number>): Float32Array {
  const P = positions, T = triangles;
  const N = new Float32Array(P.length);
  for (let f = 0; f < T.length; f += 3) {
    const a = 3 * T[f], b = 3 * T[f + 1], c = 3 * T[f + 2];
    const ux = P[b] - P[a], uy = P[b + 1] - P[a + 1], uz = P[b + 2] - P[a + 2];
    const vx = P[c] - P[a], vy = P[c + 1] - P[a + 1], vz = P[c + 2] - P[a + 2];
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    for (const k of [a, b, c]) {
      N[k] += nx;
      N[k + 1] += ny;
      N[k + 2] += nz;
    }
  }
  for (let i = 0; i < N.length; i += 3) {
    const l = Math.hypot(N[i], N[i + 1], N[i + 2]);
    if (l > 0) {
      N[i] /= l;
      N[i + 1] /= l;
      N[i + 2] /= l;
    }
  }
  return N;
}
