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

/**
 * Where the view's single-precision coordinates start: the centre of the positions' bounding box
 * when the mesh lies farther from the origin than 16 times its size (a scan in georeferenced
 * coordinates, millions of units away and a few units across, which a float's 24 bits would round
 * to a blocky shape and a picking hierarchy to the wrong faces); else the origin itself, so that
 * the coordinates shown are the file's.
 */
export function displayOrigin(positions: ArrayLike<number>): [number, number, number] {
  const P = positions;
  if (P.length < 3) return [0, 0, 0];
  const lo = [P[0], P[1], P[2]], hi = [P[0], P[1], P[2]];
  for (let i = 3; i + 2 < P.length; i += 3)
    for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], P[i + k]);
      hi[k] = Math.max(hi[k], P[i + k]);
    }
  const centre: [number, number, number] = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2];
  const size = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  return Math.max(...centre.map(Math.abs)) > 16 * size ? centre : [0, 0, 0];
}

/** xyz − origin in single precision (the view's coordinates; see displayOrigin). */
export function toDisplay(xyz: ArrayLike<number>, origin: readonly [number, number, number]): Float32Array {
  const out = new Float32Array(xyz.length);
  for (let i = 0; i + 2 < xyz.length; i += 3) {
    out[i] = xyz[i] - origin[0];
    out[i + 1] = xyz[i + 1] - origin[1];
    out[i + 2] = xyz[i + 2] - origin[2];
  }
  return out;
}
