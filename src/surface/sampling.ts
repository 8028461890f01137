/** Random points on a mesh, reproducible from a seed (benchmarks, `splinekit trace --random`). */
import { mulberry32 } from '../core/random.js';
import type { MeshPoint, SurfaceMesh } from './mesh.js';

/** `count` points uniform over the mesh's area. */
export function randomMeshPoints(mesh: SurfaceMesh, count: number, seed: number): MeshPoint[] {
  const random = mulberry32(seed);
  const t = mesh.triangles, x = mesh.positions, faces = t.length / 3;
  const cumulative = new Float64Array(faces);
  let total = 0;
  for (let f = 0; f < faces; f++) {
    const a = 3 * t[3 * f], b = 3 * t[3 * f + 1], c = 3 * t[3 * f + 2];
    const e1 = [x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]];
    const e2 = [x[c] - x[a], x[c + 1] - x[a + 1], x[c + 2] - x[a + 2]];
    total += Math.hypot(e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]) / 2;
    cumulative[f] = total;
  }
  const out: MeshPoint[] = [];
  for (let i = 0; i < count; i++) {
    const r = random() * total;
    let lo = 0, hi = faces - 1;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (cumulative[mid] < r) lo = mid + 1;
      else hi = mid;
    }
    let u = random(), v = random();
    if (u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    out.push({ face: lo, uv: [u, v] });
  }
  return out;
}
