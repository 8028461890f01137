// Meshes generated for the editor's benchmark and the e2e tests that open large files
// (tests/e2e/surface.spec.ts), so that both measure the same surface.

/**
 * A bumpy torus of 2·n² triangles (n² vertices) as binary little-endian PLY: a closed, smooth
 * surface, so that nothing but its size matters.
 */
export function bumpyTorusPLY(n) {
  const nv = n * n, nf = 2 * nv;
  const header = Buffer.from(`ply\nformat binary_little_endian 1.0\nelement vertex ${nv}\nproperty float x\nproperty float y\nproperty float z\nelement face ${nf}\nproperty list uchar int vertex_indices\nend_header\n`);
  const body = Buffer.alloc(12 * nv + 13 * nf);
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) {
      const u = (2 * Math.PI * i) / n, v = (2 * Math.PI * j) / n, r = 0.35 * (1 + 0.05 * Math.sin(7 * u) * Math.sin(5 * v));
      const o = 12 * (i * n + j);
      body.writeFloatLE((1 + r * Math.cos(v)) * Math.cos(u), o);
      body.writeFloatLE((1 + r * Math.cos(v)) * Math.sin(u), o + 4);
      body.writeFloatLE(r * Math.sin(v), o + 8);
    }
  }
  const id = (i, j) => (i % n) * n + (j % n);
  let o = 12 * nv;
  const tri = (a, b, c) => {
    body[o] = 3;
    body.writeInt32LE(a, o + 1);
    body.writeInt32LE(b, o + 5);
    body.writeInt32LE(c, o + 9);
    o += 13;
  };
  for (let i = 0; i < n; i++) {
    for (let j = 0; j < n; j++) {
      tri(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      tri(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }
  return Buffer.concat([header, body]);
}
