#!/usr/bin/env node
/**
 * Generates the sample meshes of Surface mode (public/samples/meshes): a smooth pebble, a torus
 * knot and a vase. Deterministic (seeded noise), no dependencies:
 *
 *   node public/samples/meshes/generate.mjs
 *
 * Our own work, dedicated to the public domain (CC0 1.0), like the files it writes.
 */
import { writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));

// ---- seeded gradient noise (Perlin 1985 style, on a 256 lattice) -------------------------------

function mulberry32(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function makeNoise(seed) {
  const random = mulberry32(seed);
  const perm = new Uint8Array(512);
  const p = Array.from({ length: 256 }, (_, i) => i);
  for (let i = 255; i > 0; i--) {
    const j = Math.floor(random() * (i + 1));
    [p[i], p[j]] = [p[j], p[i]];
  }
  for (let i = 0; i < 512; i++) perm[i] = p[i & 255];
  const grad = [
    [1, 1, 0], [-1, 1, 0], [1, -1, 0], [-1, -1, 0], [1, 0, 1], [-1, 0, 1],
    [1, 0, -1], [-1, 0, -1], [0, 1, 1], [0, -1, 1], [0, 1, -1], [0, -1, -1],
  ];
  const fade = (t) => t * t * t * (t * (t * 6 - 15) + 10);
  const dot = (h, x, y, z) => {
    const g = grad[h % 12];
    return g[0] * x + g[1] * y + g[2] * z;
  };
  return (x, y, z) => {
    const X = Math.floor(x), Y = Math.floor(y), Z = Math.floor(z);
    x -= X; y -= Y; z -= Z;
    const xi = X & 255, yi = Y & 255, zi = Z & 255;
    const u = fade(x), v = fade(y), w = fade(z);
    const a = perm[xi] + yi, aa = perm[a] + zi, ab = perm[a + 1] + zi;
    const b = perm[xi + 1] + yi, ba = perm[b] + zi, bb = perm[b + 1] + zi;
    const lerp = (t, p, q) => p + t * (q - p);
    return lerp(w,
      lerp(v, lerp(u, dot(perm[aa], x, y, z), dot(perm[ba], x - 1, y, z)), lerp(u, dot(perm[ab], x, y - 1, z), dot(perm[bb], x - 1, y - 1, z))),
      lerp(v, lerp(u, dot(perm[aa + 1], x, y, z - 1), dot(perm[ba + 1], x - 1, y, z - 1)), lerp(u, dot(perm[ab + 1], x, y - 1, z - 1), dot(perm[bb + 1], x - 1, y - 1, z - 1))));
  };
}

// ---- icosphere --------------------------------------------------------------------------------

function icosphere(subdivisions) {
  const t = (1 + Math.sqrt(5)) / 2;
  let positions = [
    [-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
    [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1],
  ].map(([x, y, z]) => {
    const l = Math.hypot(x, y, z);
    return [x / l, y / l, z / l];
  });
  let faces = [
    [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
    [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
  ];
  for (let s = 0; s < subdivisions; s++) {
    const mid = new Map();
    const middle = (a, b) => {
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      let m = mid.get(key);
      if (m === undefined) {
        const [pa, pb] = [positions[a], positions[b]];
        const p = [pa[0] + pb[0], pa[1] + pb[1], pa[2] + pb[2]];
        const l = Math.hypot(...p);
        m = positions.length;
        positions.push([p[0] / l, p[1] / l, p[2] / l]);
        mid.set(key, m);
      }
      return m;
    };
    const next = [];
    for (const [a, b, c] of faces) {
      const ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      next.push([a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]);
    }
    faces = next;
  }
  return { positions, faces };
}

// ---- the shapes -------------------------------------------------------------------------------

/** A river pebble: a flattened, noise-displaced icosphere (5 subdivisions: 20,480 triangles). */
function pebble() {
  const noise = makeNoise(7);
  const fbm = (x, y, z) => noise(x, y, z) + 0.45 * noise(2.1 * x + 5.2, 2.1 * y + 1.3, 2.1 * z + 7.7) + 0.18 * noise(4.3 * x + 9.1, 4.3 * y + 3.7, 4.3 * z + 2.9);
  const { positions, faces } = icosphere(5);
  const out = positions.map(([x, y, z]) => {
    const r = 1 + 0.16 * fbm(1.1 * x, 1.1 * y, 1.1 * z);
    // Flattened and stretched like a stone worn by a river; a little lopsided.
    const sx = 1.35 + 0.1 * x, sy = 0.72, sz = 1.0;
    return [x * r * sx, y * r * sy, z * r * sz];
  });
  return { positions: out, faces };
}

/** A (3, 5) torus knot tube with a slowly swelling radius: closed, genus 1 (25,600 triangles). */
function torusKnot() {
  const P = 3, Q = 5, tubular = 400, radial = 32, R = 1, tube = 0.2;
  const curve = (u) => {
    const qu = (Q / P) * u, cs = Math.cos(qu);
    return [R * (2 + cs) * 0.5 * Math.cos(u), R * (2 + cs) * 0.5 * Math.sin(u), R * Math.sin(qu) * 0.5];
  };
  const positions = [], faces = [];
  for (let i = 0; i < tubular; i++) {
    const u = (i / tubular) * P * Math.PI * 2;
    const p1 = curve(u), p2 = curve(u + 0.01);
    const T = [p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]];
    const N = [p2[0] + p1[0], p2[1] + p1[1], p2[2] + p1[2]];
    let B = [T[1] * N[2] - T[2] * N[1], T[2] * N[0] - T[0] * N[2], T[0] * N[1] - T[1] * N[0]];
    let Nn = [B[1] * T[2] - B[2] * T[1], B[2] * T[0] - B[0] * T[2], B[0] * T[1] - B[1] * T[0]];
    const lb = Math.hypot(...B), ln = Math.hypot(...Nn);
    B = B.map((v) => v / lb);
    Nn = Nn.map((v) => v / ln);
    const r = tube * (1 + 0.25 * Math.sin((i / tubular) * Math.PI * 2 * 2));
    for (let j = 0; j < radial; j++) {
      const v = (j / radial) * Math.PI * 2, cx = -r * Math.cos(v), cy = r * Math.sin(v);
      positions.push([p1[0] + cx * Nn[0] + cy * B[0], p1[1] + cx * Nn[1] + cy * B[1], p1[2] + cx * Nn[2] + cy * B[2]]);
    }
  }
  for (let i = 0; i < tubular; i++) {
    for (let j = 0; j < radial; j++) {
      const a = i * radial + j, b = ((i + 1) % tubular) * radial + j;
      const c = ((i + 1) % tubular) * radial + ((j + 1) % radial), d = i * radial + ((j + 1) % radial);
      faces.push([a, b, d], [b, c, d]);
    }
  }
  return { positions, faces };
}

/**
 * A vase: a surface of revolution with a foot, a belly, a neck and a flared lip, open at the top
 * (one boundary loop), closed at the bottom by a fan (64 around × 64 up: 8,256 triangles).
 */
function vase() {
  const around = 64, up = 64;
  const profile = (t) => {
    // radius along the height t ∈ [0, 1]
    const belly = 0.55 * Math.exp(-(((t - 0.33) / 0.24) ** 2));
    const lip = 0.2 * Math.exp(-(((t - 1) / 0.09) ** 2));
    return 0.3 + belly + lip - 0.12 * Math.exp(-(((t - 0.78) / 0.1) ** 2));
  };
  const height = 1.9;
  const positions = [[0, 0, 0]], faces = [];
  for (let i = 0; i <= up; i++) {
    const t = i / up, r = profile(t);
    for (let j = 0; j < around; j++) {
      const a = (j / around) * Math.PI * 2;
      positions.push([r * Math.cos(a), t * height, -r * Math.sin(a)]);
    }
  }
  const at = (i, j) => 1 + i * around + (j % around);
  for (let j = 0; j < around; j++) faces.push([0, at(0, j + 1), at(0, j)]);
  for (let i = 0; i < up; i++) {
    for (let j = 0; j < around; j++) faces.push([at(i, j), at(i, j + 1), at(i + 1, j + 1)], [at(i, j), at(i + 1, j + 1), at(i + 1, j)]);
  }
  return { positions, faces };
}

// ---- writers ----------------------------------------------------------------------------------

function binaryPLY({ positions, faces }, comment) {
  const header =
    `ply\nformat binary_little_endian 1.0\ncomment ${comment}\ncomment CC0 1.0 (public domain), splinekit sample\n` +
    `element vertex ${positions.length}\nproperty float x\nproperty float y\nproperty float z\n` +
    `element face ${faces.length}\nproperty list uchar int vertex_indices\nend_header\n`;
  const head = Buffer.from(header, 'ascii');
  const body = Buffer.alloc(positions.length * 12 + faces.length * 13);
  let o = 0;
  for (const p of positions) for (const c of p) o = body.writeFloatLE(c, o);
  for (const f of faces) {
    o = body.writeUInt8(3, o);
    for (const v of f) o = body.writeInt32LE(v, o);
  }
  return Buffer.concat([head, body]);
}

function obj({ positions, faces }, comment) {
  const lines = [`# ${comment}`, '# CC0 1.0 (public domain), splinekit sample'];
  for (const p of positions) lines.push(`v ${p.map((c) => +c.toFixed(5)).join(' ')}`);
  for (const f of faces) lines.push(`f ${f.map((v) => v + 1).join(' ')}`);
  return Buffer.from(`${lines.join('\n')}\n`, 'ascii');
}

const files = [
  ['pebble.ply', binaryPLY(pebble(), 'A river pebble: noise-displaced icosphere')],
  ['torus-knot.ply', binaryPLY(torusKnot(), 'A (3,5) torus knot tube')],
  ['vase.obj', obj(vase(), 'A vase: surface of revolution, open at the top')],
];
for (const [name, bytes] of files) {
  writeFileSync(join(here, name), bytes);
  console.log(`${name}: ${(bytes.length / 1024).toFixed(0)} kB`);
}
