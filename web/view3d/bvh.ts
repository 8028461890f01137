/**
 * A bounding volume hierarchy over a triangle mesh, for picking: the nearest triangle a ray hits,
 * with its barycentric coordinates in the triangle's own vertex order — exactly a mesh point
 * (face, u, v) where the hit is (1-u-v)·p0 + u·p1 + v·p2. Both sides of a triangle count.
 *
 * Flat arrays throughout (nodes as bounds + child/range indices); built once per mesh in
 * O(n log n) with median splits on the longest axis, queried in O(log n) for a typical ray.
 */

export interface RayHit {
  face: number;
  u: number;
  v: number;
  /** Distance along the ray (in units of the direction's length). */
  t: number;
}

const LEAF_SIZE = 8;

/** A built hierarchy as flat arrays (what a worker hands over). */
export interface BVHArrays {
  bounds: Float32Array;
  nodes: Int32Array;
  order: Uint32Array;
}

export class TriangleBVH {
  /** Per node: min xyz, max xyz. */
  private readonly bounds: Float32Array;
  /** Per node: [left child or -1 for a leaf, first, count] (first/count index `order`). */
  private readonly nodes: Int32Array;
  /** Triangle indices, grouped by leaf. */
  private readonly order: Uint32Array;
  private nodeCount = 0;

  /** Builds the hierarchy, or adopts one built elsewhere (`built`, for the same mesh). */
  constructor(
    private readonly positions: ArrayLike<number>,
    private readonly triangles: ArrayLike<number>,
    built?: BVHArrays,
  ) {
    if (built) {
      this.bounds = built.bounds;
      this.nodes = built.nodes;
      this.order = built.order;
      this.nodeCount = built.nodes.length / 3;
      return;
    }
    const n = triangles.length / 3;
    this.order = new Uint32Array(n);
    const centroids = new Float32Array(3 * n);
    const triMin = new Float32Array(3 * n), triMax = new Float32Array(3 * n);
    for (let f = 0; f < n; f++) {
      this.order[f] = f;
      for (let k = 0; k < 3; k++) {
        let lo = Infinity, hi = -Infinity;
        for (let c = 0; c < 3; c++) {
          const x = positions[3 * triangles[3 * f + c] + k];
          if (x < lo) lo = x;
          if (x > hi) hi = x;
        }
        triMin[3 * f + k] = lo;
        triMax[3 * f + k] = hi;
        centroids[3 * f + k] = (lo + hi) / 2;
      }
    }
    const maxNodes = Math.max(1, 2 * Math.ceil(n / (LEAF_SIZE / 2)) + 1);
    this.bounds = new Float32Array(6 * maxNodes);
    this.nodes = new Int32Array(3 * maxNodes);
    const stack: [number, number, number][] = [[this.alloc(), 0, n]];
    while (stack.length > 0) {
      const [node, first, count] = stack.pop()!;
      const b = 6 * node;
      let cmin0 = Infinity, cmin1 = Infinity, cmin2 = Infinity, cmax0 = -Infinity, cmax1 = -Infinity, cmax2 = -Infinity;
      let bmin0 = Infinity, bmin1 = Infinity, bmin2 = Infinity, bmax0 = -Infinity, bmax1 = -Infinity, bmax2 = -Infinity;
      for (let i = first; i < first + count; i++) {
        const f = 3 * this.order[i];
        bmin0 = Math.min(bmin0, triMin[f]);
        bmin1 = Math.min(bmin1, triMin[f + 1]);
        bmin2 = Math.min(bmin2, triMin[f + 2]);
        bmax0 = Math.max(bmax0, triMax[f]);
        bmax1 = Math.max(bmax1, triMax[f + 1]);
        bmax2 = Math.max(bmax2, triMax[f + 2]);
        cmin0 = Math.min(cmin0, centroids[f]);
        cmin1 = Math.min(cmin1, centroids[f + 1]);
        cmin2 = Math.min(cmin2, centroids[f + 2]);
        cmax0 = Math.max(cmax0, centroids[f]);
        cmax1 = Math.max(cmax1, centroids[f + 1]);
        cmax2 = Math.max(cmax2, centroids[f + 2]);
      }
      const B = this.bounds;
      B[b] = bmin0;
      B[b + 1] = bmin1;
      B[b + 2] = bmin2;
      B[b + 3] = bmax0;
      B[b + 4] = bmax1;
      B[b + 5] = bmax2;
      const ex = [cmax0 - cmin0, cmax1 - cmin1, cmax2 - cmin2];
      const axis = ex[0] >= ex[1] && ex[0] >= ex[2] ? 0 : ex[1] >= ex[2] ? 1 : 2;
      if (count <= LEAF_SIZE || ex[axis] <= 0) {
        this.nodes[3 * node] = -1;
        this.nodes[3 * node + 1] = first;
        this.nodes[3 * node + 2] = count;
        continue;
      }
      // Median split (nth element by centroid along the axis).
      const mid = first + (count >> 1);
      this.select(centroids, axis, first, first + count - 1, mid);
      const left = this.alloc(), right = this.alloc();
      this.nodes[3 * node] = left;
      this.nodes[3 * node + 1] = first;
      this.nodes[3 * node + 2] = count;
      if (right !== left + 1) throw new Error('bvh: node allocation out of order');
      stack.push([left, first, mid - first], [right, mid, first + count - mid]);
    }
  }

  /** The arrays of the hierarchy (trimmed to the nodes in use). */
  toArrays(): BVHArrays {
    return { bounds: this.bounds.slice(0, 6 * this.nodeCount), nodes: this.nodes.slice(0, 3 * this.nodeCount), order: this.order };
  }

  /** The nearest triangle hit by the ray origin + t·dir (t ≥ 0), or null. */
  raycast(ox: number, oy: number, oz: number, dx: number, dy: number, dz: number, maxT = Infinity): RayHit | null {
    const P = this.positions, T = this.triangles;
    const ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
    let best: RayHit | null = null, bestT = maxT;
    const stack = [0];
    while (stack.length > 0) {
      const node = stack.pop()!;
      const b = 6 * node;
      // Slab test.
      let t0 = 0, t1 = bestT;
      let a = (this.bounds[b] - ox) * ix, c = (this.bounds[b + 3] - ox) * ix;
      t0 = Math.max(t0, Math.min(a, c));
      t1 = Math.min(t1, Math.max(a, c));
      a = (this.bounds[b + 1] - oy) * iy;
      c = (this.bounds[b + 4] - oy) * iy;
      t0 = Math.max(t0, Math.min(a, c));
      t1 = Math.min(t1, Math.max(a, c));
      a = (this.bounds[b + 2] - oz) * iz;
      c = (this.bounds[b + 5] - oz) * iz;
      t0 = Math.max(t0, Math.min(a, c));
      t1 = Math.min(t1, Math.max(a, c));
      if (!(t0 <= t1)) continue; // also rejects NaN (a ray along a slab's face)
      const left = this.nodes[3 * node];
      if (left >= 0) {
        stack.push(left, left + 1);
        continue;
      }
      const first = this.nodes[3 * node + 1], count = this.nodes[3 * node + 2];
      for (let i = first; i < first + count; i++) {
        const f = this.order[i];
        const i0 = 3 * T[3 * f], i1 = 3 * T[3 * f + 1], i2 = 3 * T[3 * f + 2];
        // Möller–Trumbore: u, v are the weights of p1 and p2.
        const e1x = P[i1] - P[i0], e1y = P[i1 + 1] - P[i0 + 1], e1z = P[i1 + 2] - P[i0 + 2];
        const e2x = P[i2] - P[i0], e2y = P[i2 + 1] - P[i0 + 1], e2z = P[i2 + 2] - P[i0 + 2];
        const px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
        const det = e1x * px + e1y * py + e1z * pz;
        if (Math.abs(det) < 1e-30) continue;
        const inv = 1 / det;
        const sx = ox - P[i0], sy = oy - P[i0 + 1], sz = oz - P[i0 + 2];
        const u = (sx * px + sy * py + sz * pz) * inv;
        if (u < 0 || u > 1) continue;
        const qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
        const v = (dx * qx + dy * qy + dz * qz) * inv;
        if (v < 0 || u + v > 1) continue;
        const t = (e2x * qx + e2y * qy + e2z * qz) * inv;
        if (t < 0 || t >= bestT) continue;
        bestT = t;
        best = { face: f, u, v, t };
      }
    }
    return best;
  }

  private alloc(): number {
    return this.nodeCount++;
  }

  /** Quickselect: puts the k-th smallest (by centroid on `axis`) at k, smaller before, larger after. */
  private select(centroids: Float32Array, axis: number, lo: number, hi: number, k: number): void {
    const o = this.order;
    while (hi > lo) {
      const pivot = centroids[3 * o[(lo + hi) >> 1] + axis];
      let i = lo, j = hi;
      while (i <= j) {
        while (centroids[3 * o[i] + axis] < pivot) i++;
        while (centroids[3 * o[j] + axis] > pivot) j--;
        if (i <= j) {
          const t = o[i];
          o[i] = o[j];
          o[j] = t;
          i++;
          j--;
        }
      }
      if (k <= j) hi = j;
      else if (k >= i) lo = i;
      else return;
    }
  }
}
