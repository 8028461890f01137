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
 * Where the view's single-precision coordinates start, from the positions' bounding box (meshBounds):
 * its centre when the mesh lies farther from the origin than 16 times its size (a scan in
 * georeferenced coordinates, millions of units away and a few units across, which a float's 24 bits
 * would round to a blocky shape and a picking hierarchy to the wrong faces); else the origin itself,
 * so that the coordinates shown are the file's.
 */
export function displayOrigin(box: MeshBounds['box']): [number, number, number] {
  const [x0, y0, z0, x1, y1, z1] = box;
  const centre: [number, number, number] = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2];
  const size = Math.hypot(x1 - x0, y1 - y0, z1 - z0);
  return Number.isFinite(size) && Math.max(...centre.map(Math.abs)) > 16 * size ? centre : [0, 0, 0];
}

/** The same bounds in the view's coordinates (less `origin`; the radius is the same). */
export function shiftBounds(bounds: MeshBounds, origin: readonly [number, number, number]): MeshBounds {
  const [x0, y0, z0, x1, y1, z1] = bounds.box, [ox, oy, oz] = origin;
  return { box: [x0 - ox, y0 - oy, z0 - oz, x1 - ox, y1 - oy, z1 - oz], radius: bounds.radius };
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
