/**
 * What the mesh readers in this folder share: the format list, the arrays they return, the error
 * they throw for malformed content, and growable typed arrays to read into.
 */
import { SplinekitError } from '../../core/errors.js';

/**
 * The mesh file formats the package reads, by file extension: the one list that the format type,
 * the error for an unknown extension and the editor's file picker derive from.
 */
export const MESH_FORMATS = ['obj', 'off', 'ply', 'stl', 'gltf', 'glb'] as const;

/** A mesh file format (a file extension, lower case). */
export type MeshFormat = (typeof MESH_FORMATS)[number];

/** The result of `parseMesh`: flat arrays in the file's vertex and face order. */
export interface MeshArrays {
  /** x, y, z of every vertex, in file order (#V by 3, row-major). */
  positions: Float64Array;
  /** Three vertex indices per triangle, in file order (#T by 3, row-major). */
  triangles: Int32Array;
  /** The format the file was read as. */
  format: MeshFormat;
  /** Faces in the file before fan triangulation (STL: facets; glTF: triangles). */
  polygons: number;
}

/** What one format's reader returns (parseMesh adds the format). */
export type ParsedMesh = Omit<MeshArrays, 'format'>;

/** Throws SplinekitError('invalid-input') with the message prefixed by the file's name. */
export function invalid(file: string, message: string): never {
  throw new SplinekitError('invalid-input', `${file}: ${message}`);
}

/** A Float64Array that grows by doubling (no arrays of arrays on the hot paths). */
export class F64List {
  data: Float64Array;
  length = 0;
  constructor(capacity: number) {
    this.data = new Float64Array(Math.max(48, capacity));
  }
  push3(x: number, y: number, z: number): void {
    if (this.length + 3 > this.data.length) this.grow(this.length + 3);
    const d = this.data;
    d[this.length] = x;
    d[this.length + 1] = y;
    d[this.length + 2] = z;
    this.length += 3;
  }
  grow(min: number): void {
    const d = new Float64Array(Math.max(min, this.data.length * 2));
    d.set(this.data.subarray(0, this.length));
    this.data = d;
  }
  toArray(): Float64Array {
    return this.data.slice(0, this.length);
  }
}

/** An Int32Array that grows by doubling, with fan triangulation of a polygon held in another. */
export class I32List {
  data: Int32Array;
  length = 0;
  constructor(capacity: number) {
    this.data = new Int32Array(Math.max(48, capacity));
  }
  push(v: number): void {
    if (this.length === this.data.length) this.grow(this.length + 1);
    this.data[this.length++] = v;
  }
  push3(a: number, b: number, c: number): void {
    if (this.length + 3 > this.data.length) this.grow(this.length + 3);
    const d = this.data;
    d[this.length] = a;
    d[this.length + 1] = b;
    d[this.length + 2] = c;
    this.length += 3;
  }
  /** Fan-triangulates the polygon held in `poly` (v0, vi, vi+1) onto the end of this list. */
  pushFan(poly: I32List): void {
    const p = poly.data, k = poly.length;
    for (let i = 1; i + 1 < k; i++) this.push3(p[0], p[i], p[i + 1]);
  }
  grow(min: number): void {
    const d = new Int32Array(Math.max(min, this.data.length * 2));
    d.set(this.data.subarray(0, this.length));
    this.data = d;
  }
  toArray(): Int32Array {
    return this.data.slice(0, this.length);
  }
}

/** First vertex with a NaN or infinite coordinate, or -1. */
export function firstNonFinite(positions: ArrayLike<number>): number {
  for (let i = 0; i < positions.length; i++) if (!Number.isFinite(positions[i])) return Math.floor(i / 3);
  return -1;
}
