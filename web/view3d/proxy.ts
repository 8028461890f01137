/**
 * A coarse stand-in for a large mesh, for the frames where drawing every triangle would take too
 * long (a software rasteriser spends ~0.2 µs a triangle: a 2M-triangle mesh is ~0.4 s a frame).
 * Built by vertex clustering (Rossignac and Borrel): the vertices are binned in a grid, each bin
 * becomes one vertex (the mean of its vertices), and a triangle survives if its corners fall in
 * three different bins. One pass over the mesh, no topology needed; the proxy looks like the mesh
 * from a distance, which is all it is for (picking, tracing and the still picture use the mesh).
 */
/** The most grid cells the clustering uses (an Int32Array of them: 32 MiB). */
const MAX_CELLS = 1 << 23;

export interface MeshProxy {
  positions: Float32Array;
  triangles: Uint32Array;
}

/**
 * A proxy of about `target` triangles (within a factor of two or so: the grid is sized from the
 * surface area) of the mesh `positions` (x y z) / `triangles` (a b c).
 */
export function meshProxy(positions: ArrayLike<number>, triangles: ArrayLike<number>, target: number): MeshProxy {
  const P = positions, T = triangles, nv = P.length / 3;
  if (nv === 0 || T.length === 0) return { positions: new Float32Array(0), triangles: new Uint32Array(0) };
  let x0 = Infinity, y0 = Infinity, z0 = Infinity, x1 = -Infinity, y1 = -Infinity, z1 = -Infinity;
  for (let i = 0; i < P.length; i += 3) {
    const x = P[i], y = P[i + 1], z = P[i + 2];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
    if (z < z0) z0 = z;
    if (z > z1) z1 = z;
  }
  let area = 0;
  for (let f = 0; f < T.length; f += 3) {
    const a = 3 * T[f], b = 3 * T[f + 1], c = 3 * T[f + 2];
    const ux = P[b] - P[a], uy = P[b + 1] - P[a + 1], uz = P[b + 2] - P[a + 2];
    const vx = P[c] - P[a], vy = P[c + 1] - P[a + 1], vz = P[c + 2] - P[a + 2];
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    area += 0.5 * Math.sqrt(nx * nx + ny * ny + nz * nz);
  }
  // A surface crosses about 1.5 A / h² cells of side h, and a closed mesh has two triangles per
  // vertex: `target` / 2 cells. The grid is dense (one slot per cell, made coarser if that would
  // be more than MAX_CELLS).
  const diagonal = Math.hypot(x1 - x0, y1 - y0, z1 - z0);
  let h = Math.max(Math.sqrt((1.5 * area) / Math.max(target / 2, 1)), diagonal * 1e-6, 1e-30);
  const cells = (side: number) => (Math.floor((x1 - x0) / side) + 1) * (Math.floor((y1 - y0) / side) + 1) * (Math.floor((z1 - z0) / side) + 1);
  while (cells(h) > MAX_CELLS) h *= 1.25;
  const nx = Math.floor((x1 - x0) / h) + 1, ny = Math.floor((y1 - y0) / h) + 1, nz = Math.floor((z1 - z0) / h) + 1;
  const inv = 1 / h;
  const slot = new Int32Array(nx * ny * nz).fill(-1);
  const cluster = new Int32Array(nv);
  let clusters = 0;
  for (let v = 0; v < nv; v++) {
    const ix = Math.min(nx - 1, ((P[3 * v] - x0) * inv) | 0);
    const iy = Math.min(ny - 1, ((P[3 * v + 1] - y0) * inv) | 0);
    const iz = Math.min(nz - 1, ((P[3 * v + 2] - z0) * inv) | 0);
    const cell = ix + nx * (iy + ny * iz);
    let c = slot[cell];
    if (c < 0) c = slot[cell] = clusters++;
    cluster[v] = c;
  }
  const sums = new Float64Array(4 * clusters);
  for (let v = 0; v < nv; v++) {
    const c = 4 * cluster[v];
    sums[c] += P[3 * v];
    sums[c + 1] += P[3 * v + 1];
    sums[c + 2] += P[3 * v + 2];
    sums[c + 3] += 1;
  }
  const out = new Float32Array(3 * clusters);
  for (let c = 0; c < clusters; c++) {
    const n = sums[4 * c + 3];
    out[3 * c] = sums[4 * c] / n;
    out[3 * c + 1] = sums[4 * c + 1] / n;
    out[3 * c + 2] = sums[4 * c + 2] / n;
  }
  const kept = new Uint32Array(T.length);
  let k = 0;
  for (let f = 0; f < T.length; f += 3) {
    const a = cluster[T[f]], b = cluster[T[f + 1]], c = cluster[T[f + 2]];
    if (a === b || b === c || a === c) continue;
    // A triangle turned over by the clustering lies on a fold (where the surface is covered by
    // others): it would be drawn as a back face, dark. Left out.
    if (normalDot(P, 3 * T[f], 3 * T[f + 1], 3 * T[f + 2], out, 3 * a, 3 * b, 3 * c) <= 0) continue;
    kept[k++] = a;
    kept[k++] = b;
    kept[k++] = c;
  }
  return { positions: out, triangles: kept.slice(0, k) };
}

/** The dot product of the normals of triangles (a b c) of P and (p q r) of Q (offsets of x). */
function normalDot(P: ArrayLike<number>, a: number, b: number, c: number, Q: ArrayLike<number>, p: number, q: number, r: number): number {
  const ux = P[b] - P[a], uy = P[b + 1] - P[a + 1], uz = P[b + 2] - P[a + 2];
  const vx = P[c] - P[a], vy = P[c + 1] - P[a + 1], vz = P[c + 2] - P[a + 2];
  const sx = Q[q] - Q[p], sy = Q[q + 1] - Q[p + 1], sz = Q[q + 2] - Q[p + 2];
  const tx = Q[r] - Q[p], ty = Q[r + 1] - Q[p + 1], tz = Q[r + 2] - Q[p + 2];
  return (uy * vz - uz * vy) * (sy * tz - sz * ty) + (uz * vx - ux * vz) * (sz * tx - sx * tz) + (ux * vy - uy * vx) * (sx * ty - sy * tx);
}
