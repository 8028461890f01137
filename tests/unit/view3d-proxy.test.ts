// The stand-in the 3D view draws for a large mesh while it moves (web/view3d/proxy.ts): about the
// triangles asked for, on the surface, covering all of it.
import { expect, test } from 'vitest';
import { meshProxy } from '../../web/view3d/proxy.js';

/** A torus (radii 1 and r) of 2·n·m triangles. */
function torus(n: number, m: number, r: number): { positions: Float32Array; triangles: Uint32Array } {
  const positions = new Float32Array(3 * n * m), triangles = new Uint32Array(6 * n * m);
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < m; j++) {
      const u = (2 * Math.PI * i) / n, v = (2 * Math.PI * j) / m, o = 3 * (i * m + j);
      positions[o] = (1 + r * Math.cos(v)) * Math.cos(u);
      positions[o + 1] = (1 + r * Math.cos(v)) * Math.sin(u);
      positions[o + 2] = r * Math.sin(v);
    }
  }
  const id = (i: number, j: number) => (i % n) * m + (j % m);
  let k = 0;
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < m; j++) {
      triangles.set([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1)], k);
      k += 6;
    }
  }
  return { positions, triangles };
}

function area(P: Float32Array, T: Uint32Array): number {
  let a = 0;
  for (let f = 0; f < T.length; f += 3) {
    const [p, q, s] = [3 * T[f], 3 * T[f + 1], 3 * T[f + 2]];
    const u = [P[q] - P[p], P[q + 1] - P[p + 1], P[q + 2] - P[p + 2]], v = [P[s] - P[p], P[s + 1] - P[p + 1], P[s + 2] - P[p + 2]];
    a += 0.5 * Math.hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
  }
  return a;
}

test('a 2·400·250-triangle torus comes down to about the triangles asked for, on the surface and all of it', () => {
  const r = 0.35, mesh = torus(400, 250, r);
  const proxy = meshProxy(mesh.positions, mesh.triangles, 20_000);
  const faces = proxy.triangles.length / 3;
  expect(faces).toBeGreaterThan(20_000 / 3);
  expect(faces).toBeLessThan(20_000 * 2);
  let worst = 0;
  for (let i = 0; i < proxy.positions.length; i += 3) {
    const [x, y, z] = [proxy.positions[i], proxy.positions[i + 1], proxy.positions[i + 2]];
    worst = Math.max(worst, Math.abs(Math.hypot(Math.hypot(x, y) - 1, z) - r));
  }
  // Cells are ~0.02 wide here: a cluster's mean lies within about that of the surface (inside it, on the curved side).
  expect(worst).toBeLessThan(0.02);
  expect(Math.max(...proxy.triangles)).toBeLessThan(proxy.positions.length / 3);
  // No holes worth the name: the proxy's area is the mesh's within a few percent.
  expect(area(proxy.positions, proxy.triangles) / area(mesh.positions, mesh.triangles)).toBeGreaterThan(0.95);
  expect(area(proxy.positions, proxy.triangles) / area(mesh.positions, mesh.triangles)).toBeLessThan(1.05);
});

test('a small mesh asked for more triangles than it has keeps its shape', () => {
  const mesh = torus(20, 10, 0.3);
  const proxy = meshProxy(mesh.positions, mesh.triangles, 10_000);
  expect(proxy.triangles.length).toBeGreaterThan(0.9 * mesh.triangles.length);
  expect(proxy.triangles.length).toBeLessThanOrEqual(mesh.triangles.length);
});
