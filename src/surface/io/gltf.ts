/** glTF 2.0 / GLB reader through three.js's GLTFLoader (see src/surface/mesh-io.ts for the conventions every reader keeps). */
import type { BufferAttribute, InterleavedBufferAttribute, Mesh, Object3D } from 'three';
import { SplinekitError } from '../../core/errors.js';
import { firstNonFinite, invalid, type ParsedMesh } from './common.js';
import { SP } from './text.js';

const GLB_MAGIC = 0x46546c67; // 'glTF'
const CHUNK_JSON = 0x4e4f534a;
const CHUNK_BIN = 0x004e4942;

/** glTF JSON: untyped input, checked where it is used. */
// eslint-disable-next-line @typescript-eslint/no-explicit-any -- the file's JSON, any shape until checked
type Json = any;

function decodeDataUri(uri: string, file: string, what: string): Uint8Array {
  const comma = uri.indexOf(',');
  if (comma < 0 || !uri.slice(0, comma).endsWith(';base64')) {
    throw new SplinekitError('unsupported', `${file}: ${what} is a data: URI that is not base64`);
  }
  let text: string;
  try {
    text = atob(uri.slice(comma + 1));
  } catch {
    return invalid(file, `${what} is a data: URI with invalid base64`);
  }
  const out = new Uint8Array(text.length);
  for (let i = 0; i < text.length; i++) out[i] = text.charCodeAt(i);
  return out;
}

/**
 * glTF 2.0 (.gltf with embedded data: buffers, or .glb): every triangle primitive (TRIANGLES, and
 * strips and fans as GLTFLoader unrolls them) of the default scene, in document order, with the
 * world transform of its node applied (winding flipped under a mirroring transform). Points and
 * lines are skipped. Materials, textures and animations are dropped before loading: only geometry
 * is read, so no image decoding is needed (none is available in Node).
 */
export async function parseGltf(b: Uint8Array, file: string, format: 'gltf' | 'glb', fromText: boolean): Promise<ParsedMesh> {
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  const isGlb = b.length >= 4 && dv.getUint32(0, true) === GLB_MAGIC;
  let json: Json;
  let glbBin: Uint8Array | undefined;
  if (isGlb) {
    if (fromText) invalid(file, 'GLB given as a string: pass the file\'s bytes (ArrayBuffer or Uint8Array)');
    if (b.length < 20) invalid(file, `${b.length} bytes is too short for a GLB (truncated?)`);
    const version = dv.getUint32(4, true);
    if (version !== 2) throw new SplinekitError('unsupported', `${file}: GLB version ${version} is not supported (only glTF 2.0)`);
    const total = dv.getUint32(8, true);
    if (total > b.length) invalid(file, `the GLB header says ${total} bytes but the file has ${b.length} (truncated?)`);
    let off = 12;
    while (off + 8 <= total) {
      const length = dv.getUint32(off, true), type = dv.getUint32(off + 4, true);
      if (off + 8 + length > total) invalid(file, `GLB chunk at byte ${off} runs past the end of the file (truncated?)`);
      const chunk = b.subarray(off + 8, off + 8 + length);
      if (type === CHUNK_JSON && json === undefined) {
        try {
          json = JSON.parse(new TextDecoder().decode(chunk));
        } catch (e) {
          invalid(file, `the GLB JSON chunk is not valid JSON (${(e as Error).message})`);
        }
      } else if (type === CHUNK_BIN && glbBin === undefined) {
        glbBin = chunk;
      }
      off += 8 + ((length + 3) & ~3);
    }
    if (json === undefined) invalid(file, 'the GLB has no JSON chunk');
  } else {
    if (format === 'glb') invalid(file, 'not a GLB file (it does not start with \'glTF\')');
    try {
      json = JSON.parse(new TextDecoder().decode(b));
    } catch (e) {
      invalid(file, `not valid glTF JSON (${(e as Error).message})`);
    }
  }
  if (typeof json !== 'object' || json === null || Array.isArray(json)) invalid(file, 'the glTF JSON is not an object');
  const version = String(json.asset?.version ?? '');
  if (!version.startsWith('2')) throw new SplinekitError('unsupported', `${file}: glTF version '${version}' is not supported (only glTF 2.0)`);
  for (const ext of ['KHR_draco_mesh_compression', 'EXT_meshopt_compression', 'KHR_meshopt_compression']) {
    if (Array.isArray(json.extensionsRequired) && json.extensionsRequired.includes(ext)) {
      throw new SplinekitError('unsupported', `${file}: compressed geometry (${ext}) is not supported; export without mesh compression`);
    }
  }

  // One buffer for everything: the GLB BIN chunk and the data: URIs, 16-byte aligned.
  const buffers: Json[] = Array.isArray(json.buffers) ? json.buffers : [];
  const parts: Uint8Array[] = [];
  const bases: number[] = [];
  let size = 0;
  buffers.forEach((buffer, i) => {
    const what = `buffer ${i}${buffer?.name ? ` ('${buffer.name}')` : ''}`;
    let bytes: Uint8Array;
    if (buffer?.uri === undefined) {
      if (!isGlb || i !== 0 || !glbBin) invalid(file, `${what} has no uri and there is no GLB binary chunk`);
      bytes = glbBin;
    } else if (typeof buffer.uri === 'string' && buffer.uri.startsWith('data:')) {
      bytes = decodeDataUri(buffer.uri, file, what);
    } else {
      throw new SplinekitError(
        'unsupported',
        `${file}: ${what} refers to the external file '${String(buffer.uri)}'; external buffers are not supported (export as .glb, or embed the buffers)`,
      );
    }
    const byteLength = Number(buffer.byteLength);
    if (!(bytes.length >= byteLength)) invalid(file, `${what} has ${bytes.length} bytes, less than its byteLength ${buffer.byteLength} (truncated?)`);
    bases.push(size);
    parts.push(bytes.subarray(0, byteLength));
    size += (byteLength + 15) & ~15;
  });
  for (const view of Array.isArray(json.bufferViews) ? json.bufferViews : []) {
    const i = view?.buffer;
    if (!Number.isInteger(i) || i < 0 || i >= buffers.length) invalid(file, `a bufferView refers to buffer ${i}, which does not exist`);
    view.byteOffset = (view.byteOffset ?? 0) + bases[i];
    view.buffer = 0;
  }
  if (size > 0) json.buffers = [{ byteLength: size }];
  else delete json.buffers;
  // Geometry only: no materials, images or animations to load.
  for (const key of ['materials', 'textures', 'images', 'samplers', 'animations']) delete json[key];
  if (Array.isArray(json.extensionsUsed)) json.extensionsUsed = json.extensionsUsed.filter((e: unknown) => e !== 'KHR_draco_mesh_compression');
  for (const mesh of Array.isArray(json.meshes) ? json.meshes : []) {
    for (const primitive of Array.isArray(mesh?.primitives) ? mesh.primitives : []) {
      delete primitive.material;
      if (primitive?.extensions) delete primitive.extensions.KHR_draco_mesh_compression; // optional: fall back to plain data
    }
  }

  // Repack as one GLB for GLTFLoader (one copy of the binary data).
  const jsonBytes = new TextEncoder().encode(JSON.stringify(json));
  const jsonLength = (jsonBytes.length + 3) & ~3;
  const glb = new Uint8Array(12 + 8 + jsonLength + (size > 0 ? 8 + size : 0));
  const out = new DataView(glb.buffer);
  out.setUint32(0, GLB_MAGIC, true);
  out.setUint32(4, 2, true);
  out.setUint32(8, glb.length, true);
  out.setUint32(12, jsonLength, true);
  out.setUint32(16, CHUNK_JSON, true);
  glb.set(jsonBytes, 20);
  glb.fill(SP, 20 + jsonBytes.length, 20 + jsonLength);
  if (size > 0) {
    out.setUint32(20 + jsonLength, size, true);
    out.setUint32(24 + jsonLength, CHUNK_BIN, true);
    parts.forEach((part, i) => glb.set(part, 28 + jsonLength + bases[i]));
  }

  const { GLTFLoader } = await import('three/examples/jsm/loaders/GLTFLoader.js');
  let scene: Object3D | undefined;
  try {
    scene = (await new GLTFLoader().parseAsync(glb.buffer, '')).scene;
  } catch (e) {
    const message = e instanceof Error ? e.message : String(e);
    invalid(file, `glTF could not be read: ${message.replace(/^THREE\.GLTFLoader: /, '')}`);
  }
  if (!scene) invalid(file, 'the glTF has no scene');
  scene.updateMatrixWorld(true);

  // Every triangle mesh in document order, once per instance (EXT_mesh_gpu_instancing), with its world matrix.
  const instances: { mesh: Mesh; matrix: ArrayLike<number> }[] = [];
  let skipped = 0;
  scene.traverse((object) => {
    const o = object as Object3D & { isMesh?: boolean; isPoints?: boolean; isLine?: boolean };
    if (o.isPoints || o.isLine) skipped++;
    if (!o.isMesh) return;
    const mesh = object as Mesh;
    const instanced = mesh as Mesh & { isInstancedMesh?: boolean; count?: number; instanceMatrix?: { array: ArrayLike<number> } };
    if (instanced.isInstancedMesh && instanced.instanceMatrix) {
      for (let k = 0; k < (instanced.count ?? 0); k++) {
        const local = Array.from({ length: 16 }, (_, j) => instanced.instanceMatrix!.array[16 * k + j]);
        instances.push({ mesh, matrix: multiply4(mesh.matrixWorld.elements, local) });
      }
    } else {
      instances.push({ mesh, matrix: mesh.matrixWorld.elements });
    }
  });

  let nv = 0, nt = 0;
  for (const { mesh } of instances) {
    const count = mesh.geometry.getAttribute('position')?.count ?? 0;
    const index = mesh.geometry.getIndex();
    nv += count;
    nt += Math.floor((index ? index.count : count) / 3);
  }
  if (nt === 0) {
    invalid(file, `no triangle primitives in the default scene${skipped ? ` (skipped ${skipped} point or line primitive${skipped === 1 ? '' : 's'})` : ''}`);
  }
  const positions = new Float64Array(3 * nv);
  const triangles = new Int32Array(3 * nt);
  let v0 = 0, t = 0;
  for (const { mesh, matrix: e } of instances) {
    const name = `mesh '${mesh.name || mesh.uuid}'`;
    const attribute = mesh.geometry.getAttribute('position') as BufferAttribute | InterleavedBufferAttribute | undefined;
    if (!attribute) continue;
    for (let i = 0; i < attribute.count; i++) {
      const x = attribute.getX(i), y = attribute.getY(i), z = attribute.getZ(i);
      positions[3 * (v0 + i)] = e[0] * x + e[4] * y + e[8] * z + e[12];
      positions[3 * (v0 + i) + 1] = e[1] * x + e[5] * y + e[9] * z + e[13];
      positions[3 * (v0 + i) + 2] = e[2] * x + e[6] * y + e[10] * z + e[14];
    }
    const index = mesh.geometry.getIndex();
    const count = index ? index.count : attribute.count;
    if (count % 3 !== 0) invalid(file, `${name}: ${count} ${index ? 'indices' : 'vertices'} is not a multiple of 3`);
    // glTF: a transform with a negative determinant makes the winding clockwise; flip it back.
    const det = e[0] * (e[5] * e[10] - e[6] * e[9]) - e[4] * (e[1] * e[10] - e[2] * e[9]) + e[8] * (e[1] * e[6] - e[2] * e[5]);
    const second = det < 0 ? 2 : 1;
    for (let i = 0; i < count; i++) {
      const corner = i % 3 === 0 ? i : i % 3 === 1 ? i - 1 + second : i + 1 - second; // 0, 1, 2 or 0, 2, 1
      const local = index ? index.getX(corner) : corner;
      if (!(local >= 0 && local < attribute.count)) invalid(file, `${name}: index ${local} out of range (the primitive has ${attribute.count} vertices)`);
      triangles[t++] = v0 + local;
    }
    v0 += attribute.count;
  }
  const bad = firstNonFinite(positions);
  if (bad >= 0) invalid(file, `vertex ${bad + 1} has a non-finite coordinate`);
  return { positions, triangles, polygons: nt };
}

/** a·b for column-major 4×4 matrices. */
function multiply4(a: ArrayLike<number>, b: ArrayLike<number>): number[] {
  const out = new Array<number>(16);
  for (let col = 0; col < 4; col++) {
    for (let row = 0; row < 4; row++) {
      out[4 * col + row] = a[row] * b[4 * col] + a[4 + row] * b[4 * col + 1] + a[8 + row] * b[4 * col + 2] + a[12 + row] * b[4 * col + 3];
    }
  }
  return out;
}
