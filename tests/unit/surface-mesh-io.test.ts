// Mesh import (src/surface/mesh-io.ts): every shared mesh parses with the counts of the data
// manifest and the indices of the file; small meshes written here in every format read back exactly;
// malformed files give a SplinekitError naming the file, the line and the problem.
import { readFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, test } from 'vitest';
import { PLYLoader } from 'three/examples/jsm/loaders/PLYLoader.js';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { SplinekitError } from '../../src/core/errors.js';
import { MESH_FILE_ACCEPT, MESH_FORMATS, meshFormatList, meshFormatOf, parseMesh, type MeshArrays, type MeshFormat } from '../../src/surface/mesh-io.js';
import { readShared, sharedData } from './helpers.js';

interface ManifestMesh {
  raw_vertices: number;
  vertices: number;
  unreferenced_vertices: number;
  faces: number;
  triangles: number;
  face_sizes: Record<string, number>;
  bbox_min: [number, number, number];
  bbox_max: [number, number, number];
}
const manifest = JSON.parse(readShared('manifest.json')).meshes as Record<string, ManifestMesh>;
const bytesOf = (rel: string) => new Uint8Array(readFileSync(join(sharedData, rel)));

async function failure(promise: Promise<unknown>): Promise<SplinekitError> {
  const error = await promise.then(() => undefined, (e: unknown) => e);
  expect(error, 'expected a SplinekitError').toBeInstanceOf(SplinekitError);
  return error as SplinekitError;
}

/** Asserts that parsing fails with `code` and a message containing every part. */
async function expectError(data: string | Uint8Array, file: string, code: string, ...parts: (string | RegExp)[]): Promise<void> {
  const e = await failure(parseMesh(data, file));
  expect(e.code, e.message).toBe(code);
  expect(e.message).toContain(file);
  for (const part of parts) {
    if (typeof part === 'string') expect(e.message).toContain(part);
    else expect(e.message).toMatch(part);
  }
}

// ---------------------------------------------------------------------------------------------
// An independent, naive OBJ reader (split and Number) to check the fast parser against
// ---------------------------------------------------------------------------------------------

function naiveObj(text: string): { positions: number[]; triangles: number[]; polygons: number } {
  const positions: number[] = [], triangles: number[] = [];
  let polygons = 0;
  for (const line of text.split('\n')) {
    const w = line.trim().split(/\s+/);
    if (w[0] === 'v') positions.push(Number(w[1]), Number(w[2]), Number(w[3]));
    if (w[0] === 'f') {
      const f = w.slice(1).map((t) => {
        const i = parseInt(t, 10);
        return i < 0 ? positions.length / 3 + i : i - 1;
      });
      for (let i = 1; i + 1 < f.length; i++) triangles.push(f[0], f[i], f[i + 1]);
      polygons++;
    }
  }
  return { positions, triangles, polygons };
}

/** Index of the first element that differs (Object.is), the shorter length if one is a prefix, or -1. */
function firstDifference(a: ArrayLike<number>, b: ArrayLike<number>): number {
  const n = Math.min(a.length, b.length);
  for (let i = 0; i < n; i++) if (!Object.is(a[i], b[i])) return i;
  return a.length === b.length ? -1 : n;
}

function referenced(m: MeshArrays): Set<number> {
  return new Set(m.triangles);
}

// ---------------------------------------------------------------------------------------------
// Shared data
// ---------------------------------------------------------------------------------------------

const topLevel = readdirSync(join(sharedData, 'meshes')).filter((f) => /\.(obj|off|ply|stl|glb|gltf)$/i.test(f)).sort();
const quads = readdirSync(join(sharedData, 'meshes/quad')).filter((f) => f.endsWith('.obj')).sort();

describe('shared meshes', () => {
  test('the data folder has the meshes the manifest lists', () => {
    expect(topLevel.length).toBeGreaterThanOrEqual(9);
    for (const f of topLevel) expect(manifest[`meshes/${f}`], f).toBeDefined();
  });

  test.each(topLevel)('%s parses with the manifest counts, in file order', async (f) => {
    const rel = `meshes/${f}`;
    const m = manifest[rel];
    const mesh = await parseMesh(bytesOf(rel), f);
    expect(mesh.format).toBe(meshFormatOf(f));
    // raw_vertices counts every vertex of the file; V (vertices) only those faces use.
    expect(mesh.positions.length / 3).toBe(m.raw_vertices);
    expect(m.raw_vertices).toBe(m.vertices + m.unreferenced_vertices);
    expect(referenced(mesh).size).toBe(m.vertices);
    expect(mesh.triangles.length / 3).toBe(m.triangles);
    expect(mesh.polygons).toBe(m.faces);
    let lo = Infinity, hi = -Infinity;
    for (const v of mesh.triangles) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    expect(lo).toBeGreaterThanOrEqual(0);
    expect(hi).toBeLessThan(mesh.positions.length / 3);
    // Bounding box of the used vertices (the manifest rounds to 4-6 digits).
    const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
    for (const v of referenced(mesh)) {
      for (let k = 0; k < 3; k++) {
        min[k] = Math.min(min[k], mesh.positions[3 * v + k]);
        max[k] = Math.max(max[k], mesh.positions[3 * v + k]);
      }
    }
    const diag = Math.hypot(...m.bbox_max.map((x, k) => x - m.bbox_min[k]));
    for (let k = 0; k < 3; k++) {
      expect(Math.abs(min[k] - m.bbox_min[k])).toBeLessThan(1e-3 * diag);
      expect(Math.abs(max[k] - m.bbox_max[k])).toBeLessThan(1e-3 * diag);
    }
  });

  test('stanford_bunny keeps its 1,113 unreferenced vertices (the core welds and drops later)', async () => {
    const mesh = await parseMesh(bytesOf('meshes/stanford_bunny.obj'), 'stanford_bunny.obj');
    expect(mesh.positions.length / 3).toBe(35947);
    expect(mesh.positions.length / 3 - referenced(mesh).size).toBe(1113);
  });

  test.each(topLevel.filter((f) => f.endsWith('.obj')))('%s equals a naive split-and-Number reading exactly', async (f) => {
    const text = readShared(`meshes/${f}`);
    const mesh = await parseMesh(text, f); // also the string input path
    const ref = naiveObj(text);
    expect(mesh.polygons).toBe(ref.polygons);
    expect(firstDifference(mesh.triangles, ref.triangles)).toBe(-1);
    expect(firstDifference(mesh.positions, ref.positions)).toBe(-1);
  });

  test('spot_loop2_369k.ply equals three.js PLYLoader (positions and index)', async () => {
    const bytes = bytesOf('meshes/spot_loop2_369k.ply');
    const mesh = await parseMesh(bytes, 'spot_loop2_369k.ply');
    const geometry = new PLYLoader().parse(bytes.slice().buffer);
    expect(firstDifference(mesh.positions, geometry.getAttribute('position').array)).toBe(-1);
    expect(firstDifference(mesh.triangles, geometry.getIndex()!.array)).toBe(-1);
  });

  // Quad cages: the manifest's counts where it lists the file (the OpenSubdiv shapes added later
  // are not in it), and always the counts and fan of a plain line-by-line read of the OBJ text.
  test.each(quads)('quad/%s: fan triangulation gives the manifest / plain-read triangle count', async (f) => {
    const rel = `meshes/quad/${f}`;
    const naive = naiveObj(readShared(rel));
    const mesh = await parseMesh(bytesOf(rel), f);
    expect(mesh.positions.length / 3).toBe(naive.positions.length / 3);
    expect(mesh.polygons).toBe(naive.polygons);
    expect(mesh.polygons).toBeGreaterThan(0);
    expect(firstDifference(mesh.triangles, naive.triangles)).toBe(-1);
    const m = manifest[rel];
    if (m) {
      expect(mesh.positions.length / 3).toBe(m.raw_vertices);
      expect(mesh.polygons).toBe(m.faces);
      expect(mesh.triangles.length / 3).toBe(m.triangles);
      const expected = Object.entries(m.face_sizes).reduce((sum, [size, count]) => sum + (Number(size) - 2) * count, 0);
      expect(mesh.triangles.length / 3).toBe(expected);
    }
  });
});

// ---------------------------------------------------------------------------------------------
// Round trips: a small mesh with an unreferenced vertex, a pentagon, quads and triangles
// ---------------------------------------------------------------------------------------------

// Coordinates are exact in float32, so binary formats read back exactly.
const V: number[][] = [
  [0, 0, 0], [1.5, 0, 0], [1.5, 1.25, 0], [0, 1.25, 0],
  [0, 0, 2], [1.5, 0, 2], [1.5, 1.25, 2], [0, 1.25, 2],
  [0.75, 0.625, 2.5], [-3.125, 100.5, -0.0078125] /* unreferenced */, [0.75, 0, 0],
];
const F: number[][] = [
  [0, 3, 2, 1, 10], // pentagon (bottom, with vertex 10 on the edge 1-0)
  [0, 10, 1, 5, 4], // pentagon (front)
  [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7],
  [4, 5, 8], [5, 6, 8], [6, 7, 8], [7, 4, 8],
];
const fan = (faces: number[][]) => faces.flatMap((f) => f.slice(1, -1).flatMap((_, i) => [f[0], f[i + 1], f[i + 2]]));
const TRIANGLES = fan(F);
const POSITIONS = V.flat();
const SOUP = TRIANGLES.flatMap((v) => V[v]);

function expectMesh(mesh: MeshArrays, positions = POSITIONS, triangles = TRIANGLES, polygons = F.length): void {
  expect(Array.from(mesh.positions)).toEqual(positions);
  expect(Array.from(mesh.triangles)).toEqual(triangles);
  expect(mesh.polygons).toBe(polygons);
}

function toOff(header = 'OFF'): string {
  return [
    `${header}`, '# a comment', `${V.length} ${F.length} 0`, '',
    ...V.map((v) => `${v.join(' ')}${header.startsWith('C') ? ' 0.5 0.5 0.5 1' : ''}`),
    ...F.map((f, i) => `${f.length} ${f.join(' ')}${i % 2 ? ' 255 0 0' : ''}  # face ${i}`),
  ].join('\n');
}

function toPlyAscii(indexName = 'vertex_indices'): string {
  return [
    'ply', 'format ascii 1.0', 'comment written by the test', `element vertex ${V.length}`,
    'property float x', 'property float y', 'property float z', 'property uchar red',
    `element face ${F.length}`, `property list uchar int ${indexName}`, 'property uchar flags',
    'element edge 1', 'property int vertex1', 'property int vertex2', 'end_header',
    ...V.map((v) => `${v.join(' ')} 200`), ...F.map((f) => `${f.length} ${f.join(' ')} 7`), '0 1',
  ].join('\r\n') + '\r\n';
}

/** Binary PLY: little endian with float xyz and extra properties, or big endian with doubles. */
function toPlyBinary(littleEndian: boolean): Uint8Array {
  const header = littleEndian
    ? ['ply', 'format binary_little_endian 1.0', `element vertex ${V.length}`, 'property uchar flag', 'property float x',
      'property float y', 'property float z', 'property float nx', `element face ${F.length}`,
      'property list uchar int vertex_indices', 'property list uchar float texcoord', 'end_header', '']
    : ['ply', 'format binary_big_endian 1.0', `element vertex ${V.length}`, 'property double x', 'property double y',
      'property double z', `element face ${F.length}`, 'property list ushort uint vertex_indices', 'end_header', ''];
  const head = new TextEncoder().encode(header.join('\n'));
  const out = new Uint8Array(head.length + 4096);
  out.set(head);
  const dv = new DataView(out.buffer);
  let o = head.length;
  for (const v of V) {
    if (littleEndian) {
      dv.setUint8(o++, 9);
      for (const x of [...v, 0.5]) { dv.setFloat32(o, x, true); o += 4; }
    } else {
      for (const x of v) { dv.setFloat64(o, x, false); o += 8; }
    }
  }
  for (const f of F) {
    if (littleEndian) {
      dv.setUint8(o++, f.length);
      for (const i of f) { dv.setInt32(o, i, true); o += 4; }
      dv.setUint8(o++, 2);
      dv.setFloat32(o, 0.25, true);
      dv.setFloat32(o + 4, 0.75, true);
      o += 8;
    } else {
      dv.setUint16(o, f.length, false);
      o += 2;
      for (const i of f) { dv.setUint32(o, i, false); o += 4; }
    }
  }
  return out.slice(0, o);
}

function toStlAscii(): string {
  const lines = ['solid test'];
  for (let t = 0; t < TRIANGLES.length; t += 3) {
    lines.push('  facet normal 0 0 1', '    outer loop');
    for (let k = 0; k < 3; k++) lines.push(`      vertex ${V[TRIANGLES[t + k]].map((x) => x.toExponential()).join(' ')}`);
    lines.push('    endloop', '  endfacet');
  }
  lines.push('endsolid test', '');
  return lines.join('\n');
}

function toStlBinary(header = 'binary STL from the test'): Uint8Array {
  const n = TRIANGLES.length / 3;
  const out = new Uint8Array(84 + 50 * n);
  out.set(new TextEncoder().encode(header).subarray(0, 80));
  const dv = new DataView(out.buffer);
  dv.setUint32(80, n, true);
  for (let t = 0; t < n; t++) {
    for (let k = 0; k < 3; k++) {
      const v = V[TRIANGLES[3 * t + k]];
      for (let c = 0; c < 3; c++) dv.setFloat32(84 + 50 * t + 12 + 12 * k + 4 * c, v[c], true);
    }
  }
  return out;
}

// ---- glTF built by hand: two nodes, a mesh of two triangle primitives and a points primitive ---

/** glTF JSON as the tests edit it. */
// eslint-disable-next-line @typescript-eslint/no-explicit-any -- the tests edit any field, valid or not
type Json = any;
interface GltfModel { json: Json; bin: Uint8Array }

/**
 * Mesh 0 has primitive A (indexed, uint16: the first 4 triangles of the fixture over vertices 0-7)
 * and primitive B (not indexed: the last two fixture triangles as soup); mesh 1 is a POINTS
 * primitive. Node 0 (translation) has child node 1 (scale, mesh 0); node 2 holds mesh 1.
 */
function gltfModel(options: { scale?: number[]; points?: boolean; trianglesToo?: boolean } = {}): GltfModel {
  const A = TRIANGLES.slice(0, 12).map((v) => v % 8); // 4 triangles on vertices 0..7
  const B = TRIANGLES.slice(-6);
  const posA = new Float32Array(V.slice(0, 8).flat());
  const idxA = new Uint16Array(A);
  const posB = new Float32Array(B.flatMap((v) => V[v]));
  const bytes = new Uint8Array(posA.byteLength + 24 + posB.byteLength);
  bytes.set(new Uint8Array(posA.buffer), 0);
  bytes.set(new Uint8Array(idxA.buffer), posA.byteLength);
  bytes.set(new Uint8Array(posB.buffer), posA.byteLength + 24);
  const trianglesToo = options.trianglesToo ?? true;
  const json = {
    asset: { version: '2.0', generator: 'splinekit test' },
    scene: 0,
    scenes: [{ nodes: [0, 2] }],
    nodes: [
      { translation: [10, 0, 0], children: [1] },
      { scale: options.scale ?? [2, 2, 2], ...(trianglesToo ? { mesh: 0 } : {}) },
      { mesh: 1 },
    ],
    meshes: [
      { primitives: [{ attributes: { POSITION: 0 }, indices: 1, material: 0 }, { attributes: { POSITION: 2 }, mode: 4 }] },
      { primitives: [{ attributes: { POSITION: 0 }, mode: 0 }] },
    ],
    materials: [{ pbrMetallicRoughness: { baseColorTexture: { index: 0 } } }],
    textures: [{ source: 0 }],
    images: [{ uri: 'texture-that-does-not-exist.png' }],
    buffers: [{ byteLength: bytes.length }],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: posA.byteLength },
      { buffer: 0, byteOffset: posA.byteLength, byteLength: idxA.byteLength },
      { buffer: 0, byteOffset: posA.byteLength + 24, byteLength: posB.byteLength },
    ],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 8, type: 'VEC3', min: [0, 0, 0], max: [1.5, 1.25, 2] },
      { bufferView: 1, componentType: 5123, count: A.length, type: 'SCALAR' },
      { bufferView: 2, componentType: 5126, count: B.length, type: 'VEC3', min: [0, 0, 2], max: [1.5, 1.25, 2.5] },
    ],
  };
  if (!options.points) json.scenes[0].nodes = [0];
  return { json, bin: bytes };
}

function glb({ json, bin }: GltfModel): Uint8Array {
  const text = new TextEncoder().encode(JSON.stringify(json));
  const jl = (text.length + 3) & ~3, bl = (bin.length + 3) & ~3;
  const out = new Uint8Array(12 + 8 + jl + 8 + bl);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, 0x46546c67, true);
  dv.setUint32(4, 2, true);
  dv.setUint32(8, out.length, true);
  dv.setUint32(12, jl, true);
  dv.setUint32(16, 0x4e4f534a, true);
  out.set(text, 20);
  out.fill(0x20, 20 + text.length, 20 + jl);
  dv.setUint32(20 + jl, bl, true);
  dv.setUint32(24 + jl, 0x004e4942, true);
  out.set(bin, 28 + jl);
  return out;
}

function gltfText({ json, bin }: GltfModel): string {
  const buffers = [{ byteLength: bin.length, uri: `data:application/octet-stream;base64,${Buffer.from(bin).toString('base64')}` }];
  return JSON.stringify({ ...json, buffers });
}

/** What gltfModel() should give: A's 8 vertices then B's 6, all under translate(10,0,0)·scale. */
function expectedGltf(scale = [2, 2, 2]): { positions: number[]; triangles: number[] } {
  const A = TRIANGLES.slice(0, 12).map((v) => v % 8);
  const B = TRIANGLES.slice(-6);
  const xf = (v: number[]) => [10 + scale[0] * v[0], scale[1] * v[1], scale[2] * v[2]];
  const positions = [...V.slice(0, 8).map(xf), ...B.map((v) => xf(V[v]))].flat();
  const triangles = [...A, ...B.map((_, i) => 8 + i)];
  return { positions, triangles };
}

describe('round trips', () => {
  test('OBJ with every face-corner form, negative indices, continuations and ignored statements', async () => {
    const corner = (i: number, k: number) => [`${i + 1}`, `${i + 1}/${k + 1}`, `${i + 1}//${k + 1}`, `${i + 1}/${k + 1}/${k + 1}`][k % 4];
    const lines = [
      '# test mesh', 'mtllib test.mtl', 'o thing', 'g group1',
      ...V.map((v, i) => `v ${v.join(' ')}${i === 2 ? ' 1.0' : i === 3 ? ' 0.1 0.2 0.3' : ''}`),
      'vt 0 0', 'vn 0 0 1', 'vp 0.5', 's 1', 'usemtl red', 'l 1 2 3', 'p 4',
    ];
    F.forEach((f, fi) => {
      if (fi === 2) lines.push(`f ${f.map((i) => i - V.length).join(' ')}`); // negative: relative to the vertices so far
      else if (fi === 3) lines.push(`f ${f.slice(0, 2).map((i, k) => corner(i, k)).join(' ')} \\`, `  ${f.slice(2).map((i, k) => corner(i, k + 2)).join(' ')}`);
      else lines.push(`\tf  ${f.map((i, k) => corner(i, k + fi)).join('   ')}  # trailing comment`);
    });
    const text = lines.join('\r\n');
    expectMesh(await parseMesh(text, 'test.obj'));
    expectMesh(await parseMesh(new TextEncoder().encode(text), 'TEST.OBJ'));
    expectMesh(await parseMesh(new TextEncoder().encode(text).buffer, 'dir/test.Obj'));
  });

  test('OBJ faces may point forward to vertices defined later', async () => {
    const mesh = await parseMesh('f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n', 'forward.obj');
    expectMesh(mesh, [0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2], 1);
  });

  test('OBJ numbers: exponents, signs, leading dots, many digits', async () => {
    const text = 'v 1e3 -2.5E-2 +.5\nv 0.1234567890123456789 -0 3.\nv 1e-30 123456789012345678 7\nf 1 2 3\n';
    const mesh = await parseMesh(text, 'numbers.obj');
    expect(Array.from(mesh.positions)).toEqual([1000, -0.025, 0.5, Number('0.1234567890123456789'), -0, 3, 1e-30, Number('123456789012345678'), 7]);
  });

  test.each(['OFF', 'COFF', 'NOFF'])('%s', async (header) => {
    expectMesh(await parseMesh(toOff(header), `test-${header}.off`));
  });

  test('OFF with the counts on the header line', async () => {
    const mesh = await parseMesh('OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n', 'one.off');
    expectMesh(mesh, [0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2], 1);
  });

  test('ASCII PLY (CRLF, extra properties and elements, vertex_indices or vertex_index)', async () => {
    expectMesh(await parseMesh(toPlyAscii(), 'test.ply'));
    expectMesh(await parseMesh(new TextEncoder().encode(toPlyAscii('vertex_index')), 'test.ply'));
  });

  test.each([true, false])('binary PLY, little endian = %s', async (le) => {
    const bytes = toPlyBinary(le);
    expectMesh(await parseMesh(bytes, 'test.ply'));
    expectMesh(await parseMesh(bytes.slice().buffer, 'test.ply'));
  });

  test('ASCII STL: triangle soup in file order (doubles kept)', async () => {
    const mesh = await parseMesh(toStlAscii(), 'test.stl');
    expectMesh(mesh, SOUP, SOUP.map((_, i) => i).slice(0, SOUP.length / 3), TRIANGLES.length / 3);
  });

  test('binary STL (also one whose header starts with "solid"), equal to three.js STLLoader', async () => {
    for (const header of ['binary STL from the test', 'solid but actually binary']) {
      const bytes = toStlBinary(header);
      const mesh = await parseMesh(bytes, 'test.stl');
      expectMesh(mesh, SOUP, SOUP.map((_, i) => i).slice(0, SOUP.length / 3), TRIANGLES.length / 3);
      expect(mesh.positions).toEqual(Float64Array.from(new STLLoader().parse(bytes.slice().buffer).getAttribute('position').array));
    }
  });

  test('GLB: triangle primitives merged in document order with node transforms; points skipped', async () => {
    const { positions, triangles } = expectedGltf();
    const mesh = await parseMesh(glb(gltfModel({ points: true })), 'test.glb');
    expectMesh(mesh, positions, triangles, triangles.length / 3);
    expect(mesh.format).toBe('glb');
  });

  test('glTF with data: URI buffers reads the same as the GLB', async () => {
    const { positions, triangles } = expectedGltf();
    const mesh = await parseMesh(gltfText(gltfModel({ points: true })), 'test.gltf');
    expectMesh(mesh, positions, triangles, triangles.length / 3);
    expect(mesh.format).toBe('gltf');
  });

  test('GLB with EXT_mesh_gpu_instancing: every instance, in order, under its node', async () => {
    const model = gltfModel();
    const json = model.json as Json;
    const offset = (model.bin.length + 3) & ~3;
    const bin = new Uint8Array(offset + 24);
    bin.set(model.bin);
    new Float32Array(bin.buffer, offset, 6).set([0, 0, 0, 100, 0, 0]);
    json.buffers = [{ byteLength: bin.length }];
    json.bufferViews.push({ buffer: 0, byteOffset: offset, byteLength: 24 });
    json.accessors.push({ bufferView: 3, componentType: 5126, count: 2, type: 'VEC3' });
    json.extensionsUsed = ['EXT_mesh_gpu_instancing'];
    json.nodes[1].extensions = { EXT_mesh_gpu_instancing: { attributes: { TRANSLATION: 3 } } };
    const mesh = await parseMesh(glb({ json, bin }), 'instanced.glb');
    const A = TRIANGLES.slice(0, 12).map((v) => v % 8);
    const B = TRIANGLES.slice(-6);
    const xf = (dx: number) => (v: number[]) => [10 + 2 * (v[0] + dx), 2 * v[1], 2 * v[2]];
    const positions = [
      ...V.slice(0, 8).map(xf(0)), ...V.slice(0, 8).map(xf(100)),
      ...B.map((v) => xf(0)(V[v])), ...B.map((v) => xf(100)(V[v])),
    ].flat();
    const triangles = [...A, ...A.map((v) => v + 8), ...B.map((_, i) => 16 + i), ...B.map((_, i) => 22 + i)];
    expectMesh(mesh, positions, triangles, triangles.length / 3);
  });

  test('glTF triangle strips are unrolled into triangles over the same vertices', async () => {
    const model = gltfModel();
    const json = model.json as Json;
    json.meshes[0].primitives = [{ attributes: { POSITION: 0 }, mode: 5 }]; // 8 vertices: 6 triangles
    const mesh = await parseMesh(glb(model), 'strip.glb');
    expect(mesh.positions.length / 3).toBe(8);
    expect(mesh.triangles.length / 3).toBe(6);
    for (let t = 0; t < 6; t++) expect([...mesh.triangles.slice(3 * t, 3 * t + 3)].sort()).toEqual([t, t + 1, t + 2]);
  });

  test('glTF under a mirroring transform flips the winding (the glTF rule), keeping vertex order', async () => {
    const scale = [-1, 1, 1];
    const { positions, triangles } = expectedGltf(scale);
    const flipped = triangles.flatMap((_, t) => (t % 3 === 0 ? [triangles[t], triangles[t + 2], triangles[t + 1]] : []));
    expectMesh(await parseMesh(glb(gltfModel({ scale })), 'mirror.glb'), positions, flipped, triangles.length / 3);
  });
});

// ---------------------------------------------------------------------------------------------
// Errors
// ---------------------------------------------------------------------------------------------

const tri = 'v 0 0 0\nv 1 0 0\nv 0 1 0\n';

describe('format and size', () => {
  test('meshFormatOf by extension, case-insensitive', () => {
    expect(meshFormatOf('a/b/Bunny.OBJ')).toBe('obj');
    expect(meshFormatOf('x.tar.ply')).toBe('ply');
    expect(meshFormatOf('C:\\models\\m.GlB')).toBe('glb');
    for (const name of ['model.3ds', 'model', 'obj', 'model.obj.bak']) {
      expect(() => meshFormatOf(name)).toThrowError(SplinekitError);
      try {
        meshFormatOf(name);
      } catch (e) {
        expect((e as SplinekitError).code).toBe('unsupported');
        expect((e as SplinekitError).message).toContain(name);
      }
    }
  });

  test('one format list: every listed extension is read, the error and the accept list name them all', async () => {
    expect([...MESH_FORMATS]).toEqual(['obj', 'off', 'ply', 'stl', 'gltf', 'glb']);
    expect(MESH_FILE_ACCEPT).toBe('.obj,.off,.ply,.stl,.gltf,.glb');
    expect(meshFormatList()).toBe('.obj, .off, .ply, .stl, .gltf or .glb');
    for (const f of MESH_FORMATS) expect(meshFormatOf(`m.${f.toUpperCase()}`)).toBe(f);
    const e = await failure(Promise.resolve().then(() => meshFormatOf('model.3ds')));
    expect(e.message).toBe(`model.3ds: unsupported mesh format '.3ds' (expected ${meshFormatList()})`);
    // Each listed format has a reader: the same triangle in every text format parses to the same arrays.
    const texts: Partial<Record<MeshFormat, string>> = {
      obj: 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n',
      off: 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n',
      ply: 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n',
      stl: 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n',
    };
    for (const [format, text] of Object.entries(texts)) {
      const mesh = await parseMesh(text, `t.${format}`);
      expect(mesh.format).toBe(format);
      expect(Array.from(mesh.positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
      expect(Array.from(mesh.triangles)).toEqual([0, 1, 2]);
    }
  });

  test('parseMesh refuses an unknown format, an empty file and one beyond maxBytes', async () => {
    await expectError(tri, 'model.fbx', 'unsupported', "'.fbx'");
    await expectError('', 'empty.obj', 'invalid-input', 'empty');
    await expectError(new Uint8Array(0), 'empty.stl', 'invalid-input', 'empty');
    const big = await failure(parseMesh(`${tri}f 1 2 3\n`, 'big.obj', { maxBytes: 10 }));
    expect(big.code).toBe('file-too-large');
    expect(big.message).toContain('big.obj');
    const bigBytes = await failure(parseMesh(toStlBinary(), 'big.stl', { maxBytes: 100 }));
    expect(bigBytes.code).toBe('file-too-large');
  });
});

describe('OBJ errors', () => {
  test.each([
    ['out of range', `${tri}f 1 2 900\n`, ['line 4', 'face index 900 out of range (file has 3 vertices)']],
    ['out of range, reported on its line', `${tri}f 1 2 3\n\nf 1 2 4\n`, ['line 6', 'face index 4 out of range']],
    ['negative beyond the start', `${tri}f -1 -2 -4\n`, ['line 4', 'face index -4 out of range']],
    ['index 0', `${tri}f 0 1 2\n`, ['line 4', 'index 0']],
    ['bad index', `${tri}f 1 2 x3\n`, ['line 4', "invalid face index 'x3'"]],
    ['float index', `${tri}f 1 2 3.0\n`, ['line 4', "invalid face index '3.0'"]],
    ['two-vertex face', `${tri}f 1 2\n`, ['line 4', 'face has 2 vertices, expected at least 3']],
    ['empty face', `${tri}f\n`, ['line 4', 'face has 0 vertices']],
    ['NaN', 'v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n', ['line 2', "non-finite coordinate 'nan' in vertex 2"]],
    ['Infinity', 'v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n', ['line 3', "non-finite coordinate '-inf'"]],
    ['overflow', 'v 1e999 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n', ['line 1', "non-finite coordinate '1e999'"]],
    ['garbage coordinate', 'v 0 0 0\nv 1 0 0\nv 0 1,5 0\nf 1 2 3\n', ['line 3', "invalid coordinate '1,5'"]],
    ['two coordinates', 'v 0 0\n', ['line 1', 'vertex 1 has 2 coordinates, expected 3']],
    ['no vertices', '# nothing\n\n   \n', ['no vertices']],
    ['no faces', tri + 'l 1 2\n', ['no faces', '3 vertices']],
  ])('%s', async (_, text, parts) => {
    await expectError(text, 'spot.obj', 'invalid-input', ...parts);
  });

  test('a line number counts continued lines', async () => {
    await expectError(`${tri}f 1 \\\n 2 \\\n 3 0\n`, 'cont.obj', 'invalid-input', 'line 6', 'index 0');
  });
});

describe('OFF errors', () => {
  const head = 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n';
  test.each([
    ['missing header', '3 1 0\n0 0 0\n', 'invalid-input', ['line 1', "expected the 'OFF' header, found '3'"]],
    ['binary OFF', 'OFF BINARY\n', 'unsupported', ['binary OFF']],
    ['out of range', `${head}3 0 1 3\n`, 'invalid-input', ['line 6', 'face index 3 out of range (file has 3 vertices)']],
    ['negative index', `${head}3 0 1 -1\n`, 'invalid-input', ['line 6', 'face index -1 out of range']],
    ['two-vertex face', `${head}2 0 1\n`, 'invalid-input', ['line 6', 'face 1 has 2 vertices']],
    ['short face', `${head}4 0 1 2\n`, 'invalid-input', ['line 6', 'face 1 lists 3 of its 4 vertex indices']],
    ['truncated faces', 'OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n', 'invalid-input', ['file ends after 1 of 2 faces']],
    ['truncated vertices', 'OFF\n4 1 0\n0 0 0\n1 0 0\n', 'invalid-input', ['file ends after 2 of 4 vertices']],
    ['NaN', 'OFF\n3 1 0\n0 0 0\n1 NaN 0\n0 1 0\n3 0 1 2\n', 'invalid-input', ['line 4', "non-finite coordinate 'NaN' in vertex 2"]],
    ['short vertex', 'OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n', 'invalid-input', ['line 4', 'vertex 2 has 2 coordinates']],
    ['no faces', 'OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n', 'invalid-input', ['no faces']],
    ['no vertices', 'OFF\n0 0 0\n', 'invalid-input', ['no vertices']],
    ['bad count', 'OFF\n3 x 0\n', 'invalid-input', ['line 2', "face count 'x'"]],
    ['impossible counts', 'OFF\n300000000 1 0\n0 0 0\n', 'invalid-input', ['300000000 vertices', 'truncated']],
  ])('%s', async (_, text, code, parts) => {
    await expectError(text, 'm.off', code, ...parts);
  });
});

describe('PLY errors', () => {
  const ascii = (vertices: string, faces: string, nf = 1) =>
    `ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face ${nf}\nproperty list uchar int vertex_indices\nend_header\n${vertices}${faces}`;
  const verts = '0 0 0\n1 0 0\n0 1 0\n';
  test.each([
    ['not PLY', 'solid x\n', ['not a PLY file']],
    ['no end_header', 'ply\nformat ascii 1.0\nelement vertex 3\n', ["no 'end_header'"]],
    ['unknown type', 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n', ['line 4', "unknown PLY property type 'float128'"]],
    ['no face element', 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n', ['no faces']],
    ['no xyz', 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float a\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n1\n3 0 0 0\n', ['no x, y and z']],
    ['out of range', ascii(verts, '3 0 1 7\n'), ['line 13', 'face 1: vertex index 7 out of range (file has 3 vertices)']],
    ['two-vertex face', ascii(verts, '2 0 1\n'), ['line 13', 'face 1 has 2 vertices']],
    ['NaN', ascii('0 0 0\n1 nan 0\n0 1 0\n', '3 0 1 2\n'), ['line 11', "non-finite coordinate 'nan' in vertex 2"]],
    ['truncated ASCII', ascii(verts, '3 0 1 2\n', 2), ['file ends after 1 of 2 \'face\' elements', 'truncated']],
    ['extra value', ascii(verts, '3 0 1 2 5\n'), ['line 13', "extra value '5'"]],
  ])('%s', async (_, text, parts) => {
    await expectError(text, 'cow.ply', 'invalid-input', ...parts);
  });

  test('truncated binary PLY, at every cut', async () => {
    const bytes = toPlyBinary(true);
    const headerEnd = new TextDecoder().decode(bytes).indexOf('end_header') + 11;
    for (const cut of [headerEnd, headerEnd + 7, headerEnd + 100, bytes.length - 9, bytes.length - 1]) {
      await expectError(bytes.slice(0, cut), 'cut.ply', 'invalid-input', 'truncated');
    }
  });

  test('binary PLY: index out of range, NaN coordinate, given as a string', async () => {
    const bad = toPlyBinary(false);
    const dv = new DataView(bad.buffer);
    const faces = bad.length - F.reduce((s, f) => s + 2 + 4 * f.length, 0);
    dv.setUint32(faces + 2 + 4, 99, false); // face 1, its second index
    await expectError(bad, 'big.ply', 'invalid-input', 'face 1: vertex index 99 out of range (file has 11 vertices)');
    const nan = toPlyBinary(false);
    const headerEnd = new TextDecoder().decode(nan).indexOf('end_header') + 11;
    new DataView(nan.buffer).setFloat64(headerEnd + 24 * 4 + 8, NaN, false);
    await expectError(nan, 'nan.ply', 'invalid-input', 'vertex 5 has a non-finite coordinate');
    await expectError(new TextDecoder('latin1').decode(toPlyBinary(true)), 'str.ply', 'invalid-input', 'given as a string');
  });
});

describe('STL errors', () => {
  const facet = (vertices: string[]) => `facet normal 0 0 1\nouter loop\n${vertices.map((v) => `vertex ${v}\n`).join('')}endloop\nendfacet\n`;
  test.each([
    ['two-vertex facet', `solid a\n${facet(['0 0 0', '1 0 0'])}endsolid a\n`, ['line 7', 'facet 1 (line 2) has 2 vertices, expected 3']],
    ['four-vertex facet', `solid a\n${facet(['0 0 0', '1 0 0', '0 1 0', '1 1 0'])}endsolid a\n`, ['line 7', 'more than 3 vertices']],
    ['NaN', `solid a\n${facet(['0 0 0', '1 0 0', '0 1 0'])}${facet(['0 0 0', '1 nan 0', '0 1 0'])}endsolid a\n`, ['line 12', "non-finite coordinate 'nan'"]],
    ['garbage', `solid a\n${facet(['0 0 0', '1 0 0', '0 1 0'])}garbage\nendsolid a\n`, ['line 9', "unexpected 'garbage'"]],
    ['no endsolid', `solid a\n${facet(['0 0 0', '1 0 0', '0 1 0'])}`, ['without \'endsolid\'', 'truncated']],
    ['ends inside a facet', `solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n`, ['inside facet 1', 'truncated']],
    ['no facets', 'solid a\nendsolid a\n', ['no faces']],
  ])('%s', async (_, text, parts) => {
    await expectError(text, 'part.stl', 'invalid-input', ...parts);
  });

  test('binary STL whose header starts with "solid": truncated is reported, trailing bytes are ignored', async () => {
    const bytes = toStlBinary('solid exported by a CAD tool');
    await expectError(bytes.slice(0, bytes.length - 10), 'cad.stl', 'invalid-input', 'truncated');
    const padded = new Uint8Array(bytes.length + 7);
    padded.set(bytes);
    expectMesh(await parseMesh(padded, 'cad.stl'), SOUP, SOUP.map((_, i) => i).slice(0, SOUP.length / 3), TRIANGLES.length / 3);
  });

  test('binary STL: truncated, too short, no triangles, NaN', async () => {
    const bytes = toStlBinary();
    await expectError(bytes.slice(0, bytes.length - 10), 'part.stl', 'invalid-input', 'truncated', `has ${bytes.length - 10}`);
    await expectError(bytes.slice(0, 50), 'part.stl', 'invalid-input', 'too short');
    await expectError(bytes.slice(0, 84).fill(0, 80), 'part.stl', 'invalid-input', 'no faces');
    const nan = bytes.slice();
    new DataView(nan.buffer).setFloat32(84 + 50 * 2 + 12 + 4, NaN, true);
    await expectError(nan, 'part.stl', 'invalid-input', 'triangle 3 has a non-finite coordinate');
  });
});

describe('glTF errors', () => {
  test('external buffer: unsupported, naming the buffer', async () => {
    const model = gltfModel();
    const text = JSON.stringify({ ...model.json, buffers: [{ byteLength: model.bin.length, uri: 'scene.bin' }] });
    await expectError(text, 'scene.gltf', 'unsupported', "external file 'scene.bin'", 'buffer 0');
  });

  test('only points: no triangle primitives, with the skipped count', async () => {
    await expectError(glb(gltfModel({ points: true, trianglesToo: false })), 'points.glb', 'invalid-input', 'no triangle primitives', 'skipped 1 point or line primitive');
  });

  test('truncated, not a GLB, bad JSON, glTF 1, Draco', async () => {
    const bytes = glb(gltfModel());
    await expectError(bytes.slice(0, bytes.length - 40), 'cut.glb', 'invalid-input', 'truncated');
    await expectError(bytes.slice(0, 16), 'cut.glb', 'invalid-input', 'truncated');
    await expectError(tri, 'notglb.glb', 'invalid-input', "not a GLB file");
    await expectError('{"asset": ', 'bad.gltf', 'invalid-input', 'not valid glTF JSON');
    await expectError('{"asset": {"version": "1.0"}}', 'old.gltf', 'unsupported', "glTF version '1.0'");
    const draco = gltfModel();
    Object.assign(draco.json, { extensionsUsed: ['KHR_draco_mesh_compression'], extensionsRequired: ['KHR_draco_mesh_compression'] });
    await expectError(glb(draco), 'draco.glb', 'unsupported', 'KHR_draco_mesh_compression');
  });

  test('an accessor past the end of its buffer is invalid input, not a crash', async () => {
    const model = gltfModel();
    (model.json.accessors as { count: number }[])[0].count = 1000;
    await expectError(glb(model), 'overrun.glb', 'invalid-input', 'glTF could not be read');
  });

  test('a GLB given as a string is refused', async () => {
    await expectError(new TextDecoder('latin1').decode(glb(gltfModel())), 'str.glb', 'invalid-input', 'given as a string');
  });
});
