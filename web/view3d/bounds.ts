/**
 * A mesh's bounding box and sphere as three.js computes them (the sphere about the box's center,
 * through the farthest vertex), for a worker to compute instead of the page: two passes over the
 * positions are ~50 ms on the main thread at 1M vertices.
 */
export interface MeshBounds {
  /** min x y z, max x y z */
  box: [number, number, number, number, number, number];
  radius: number;
}

export function meshBounds(positions: ArrayLike<number>): MeshBounds {
  const P = positions;
  let x0 = Infinity, y0 = Infinity, z0 = Infinity, x1 = -Infinity, y1 = -Infinity, z1 = -Infinity;
  for (let i = 0; i + 2 < P.length; i += 3) {
    const x = P[i], y = P[i + 1], z = P[i + 2];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
    if (z < z0) z0 = z;
    if (z > z1) z1 = z;
  }
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, cz = (z0 + z1) / 2;
  let r2 = 0;
  for (let i = 0; i + 2 < P.length; i += 3) {
    const dx = P[i] - cx, dy = P[i + 1] - cy, dz = P[i + 2] - cz;
    r2 = Math.max(r2, dx * dx + dy * dy + dz * dz);
  }
  return { box: [x0, y0, z0, x1, y1, z1], radius: Math.sqrt(r2) };
}
