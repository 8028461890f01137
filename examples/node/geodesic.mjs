// A shortest path and a Bézier curve on a mesh generated here: a flat 1 × 1 square of 20 × 20
// cells, each split into two triangles, written as OBJ text. On a plane the geodesic is the
// straight segment, so the length printed can be checked by hand.
//   node geodesic.mjs
import { SurfaceMesh, init, traceBezier } from 'splinekit';

await init();
const n = 20;
const lines = [];
for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) lines.push(`v ${i / n} ${j / n} 0`);
const vertex = (i, j) => j * (n + 1) + i; // 0-based
for (let j = 0; j < n; j++) {
  for (let i = 0; i < n; i++) {
    const a = vertex(i, j) + 1, b = vertex(i + 1, j) + 1, c = vertex(i + 1, j + 1) + 1, d = vertex(i, j + 1) + 1;
    lines.push(`f ${a} ${b} ${c}`, `f ${a} ${c} ${d}`);
  }
}
const mesh = await SurfaceMesh.load(lines.join('\n'), 'grid.obj');
console.log(`grid.obj: ${mesh.info.vertices} vertices, ${mesh.info.faces} faces`);

const from = vertex(0, 0), to = vertex(n, 7); // (0, 0, 0) → (1, 0.35, 0)
const path = mesh.shortestPath(from, to);
const p = path.xyz, last = p.length - 3;
console.log(`geodesic (${p[0]}, ${p[1]}, ${p[2]}) → (${p[last]}, ${p[last + 1]}, ${p[last + 2]}): length ${path.length.toFixed(12)}, ${path.points.length} points`);

// A cubic Bézier curve with control points at vertices, traced by OLR subdivision.
const curve = traceBezier(mesh, [vertex(2, 2), vertex(2, 18), vertex(18, 18), vertex(18, 2)]);
console.log(`bezier: ${curve.points.length} points on the surface`);
mesh.dispose();
