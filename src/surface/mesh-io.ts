/**
 * Triangle-mesh import: OBJ, OFF, PLY, STL, glTF and GLB files to flat arrays.
 *
 *   const { positions, triangles } = await parseMesh(bytes, 'bunny.obj');
 *
 * Indices are in the FILE's order: vertex i of the output is the i-th vertex of the file, and faces
 * come in file order, polygons fan-triangulated in place as (v0, vi, vi+1). Nothing is welded and
 * unreferenced vertices are kept: the core does that later and maps its results back to these
 * indices. STL is triangle soup (3 vertices per facet); glTF/GLB merges its triangle primitives in
 * document order with their node transforms applied.
 *
 * OBJ, OFF, PLY and ASCII STL are read by the small parsers below. The three.js loaders cannot be
 * used for them: OBJLoader de-indexes, there is no OFF loader, PLYLoader silently drops faces with
 * fewer than 3 or more than 4 vertices, returns partial data for a truncated ASCII file and
 * de-indexes the mesh when faces carry colours or texture coordinates, and STLLoader keeps going
 * (with a console message) past a facet with a bad vertex line. Binary STL and glTF/GLB go through
 * three.js (`STLLoader`, `GLTFLoader`), loaded on first use.
 *
 * Errors are SplinekitError: 'unsupported' for a format or feature this module does not read,
 * 'file-too-large' beyond `maxBytes`, 'invalid-input' for malformed content, with a message naming
 * the file, the line (text formats) and the problem. No partial data is ever returned.
 */
import type { BufferAttribute, InterleavedBufferAttribute, Mesh, Object3D } from 'three';
import { SplinekitError } from '../core/errors.js';

export type MeshFormat = 'obj' | 'off' | 'ply' | 'stl' | 'gltf' | 'glb';

export interface MeshArrays {
  /** x, y, z of every vertex, in file order (#V by 3, row-major). */
  positions: Float64Array;
  /** Three vertex indices per triangle, in file order (#T by 3, row-major). */
  triangles: Int32Array;
  format: MeshFormat;
  /** Faces in the file before fan triangulation (STL: facets; glTF: triangles). */
  polygons: number;
}

export interface MeshParseOptions {
  /** Inputs larger than this many bytes are refused with SplinekitError('file-too-large'). Default 512 MiB. */
  maxBytes?: number;
}

export const DEFAULT_MAX_MESH_BYTES = 512 * 1024 * 1024;

const FORMATS: readonly MeshFormat[] = ['obj', 'off', 'ply', 'stl', 'gltf', 'glb'];

/** The mesh format of a file name, by its extension (case-insensitive). */
export function meshFormatOf(fileName: string): MeshFormat {
  const base = fileName.slice(Math.max(fileName.lastIndexOf('/'), fileName.lastIndexOf('\\')) + 1);
  const dot = base.lastIndexOf('.');
  const ext = dot >= 0 ? base.slice(dot + 1).toLowerCase() : '';
  if ((FORMATS as readonly string[]).includes(ext)) return ext as MeshFormat;
  throw new SplinekitError(
    'unsupported',
    `${fileName}: ${ext ? `unsupported mesh format '.${ext}'` : 'no file extension to tell the mesh format'} ` +
      '(expected .obj, .off, .ply, .stl, .gltf or .glb)',
  );
}

/**
 * Parses a mesh file into flat arrays in the file's vertex and face order.
 * @param data the file's bytes, or its text for the text formats
 * @param fileName names the format (by extension) and the file in error messages
 */
export async function parseMesh(
  data: ArrayBuffer | Uint8Array | string,
  fileName: string,
  options: MeshParseOptions = {},
): Promise<MeshArrays> {
  const format = meshFormatOf(fileName);
  const maxBytes = options.maxBytes ?? DEFAULT_MAX_MESH_BYTES;
  const isText = typeof data === 'string';
  let bytes: Uint8Array;
  if (isText) {
    checkSize(data.length, maxBytes, fileName); // a lower bound of the UTF-8 size: refuse before encoding
    bytes = new TextEncoder().encode(data);
  } else if (ArrayBuffer.isView(data)) {
    bytes = new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  } else if (data instanceof ArrayBuffer || /^\[object (Shared)?ArrayBuffer\]$/.test(Object.prototype.toString.call(data))) {
    bytes = new Uint8Array(data); // (also an ArrayBuffer from another realm: a worker, an iframe)
  } else {
    throw new SplinekitError('invalid-input', `${fileName}: expected an ArrayBuffer, a Uint8Array or a string`);
  }
  checkSize(bytes.length, maxBytes, fileName);
  if (bytes.length === 0) throw new SplinekitError('invalid-input', `${fileName}: the file is empty`);

  let out: Omit<MeshArrays, 'format'>;
  switch (format) {
    case 'obj': out = parseObj(bytes, fileName); break;
    case 'off': out = parseOff(bytes, fileName); break;
    case 'ply': out = parsePly(bytes, fileName, isText); break;
    case 'stl': out = await parseStl(bytes, fileName, isText); break;
    case 'gltf':
    case 'glb': out = await parseGltf(bytes, fileName, format, isText); break;
  }
  return { positions: out.positions, triangles: out.triangles, format, polygons: out.polygons };
}

// ---------------------------------------------------------------------------------------------
// Shared helpers
// ---------------------------------------------------------------------------------------------

function checkSize(size: number, maxBytes: number, file: string): void {
  if (size > maxBytes) {
    const mib = (n: number) => (n / 2 ** 20).toFixed(n < 2 ** 20 ? 3 : 1);
    throw new SplinekitError(
      'file-too-large',
      `${file}: ${mib(size)} MiB is larger than the ${mib(maxBytes)} MiB limit (options.maxBytes)`,
    );
  }
}

function invalid(file: string, message: string): never {
  throw new SplinekitError('invalid-input', `${file}: ${message}`);
}

/** A Float64Array / Int32Array that grows by doubling (no arrays of arrays on the hot paths). */
class F64List {
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

class I32List {
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
function firstNonFinite(positions: ArrayLike<number>): number {
  for (let i = 0; i < positions.length; i++) if (!Number.isFinite(positions[i])) return Math.floor(i / 3);
  return -1;
}

const LF = 10, CR = 13, SP = 32, TAB = 9, HASH = 35, BSL = 92, SLASH = 47, MINUS = 45, PLUS = 43, DOT = 46;
const POW10 = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
  1e17, 1e18, 1e19, 1e20, 1e21, 1e22];
const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
const NON_FINITE = /^[+-]?(nan|inf|infinity)$/i;

function latin1(b: Uint8Array, s: number, e: number): string {
  let out = '';
  for (let i = s; i < e; i++) out += String.fromCharCode(b[i]);
  return out;
}

/**
 * The decimal number in b[s, e), exactly as Number() would read it; NaN if it is not a plain decimal
 * (or ±Infinity / NaN when it spells one). Fast path (Clinger): at most 15 significant digits and a
 * decimal exponent within ±22, where one IEEE multiply or divide of exact values rounds correctly.
 */
function parseDecimal(b: Uint8Array, s: number, e: number): number {
  let i = s, neg = false, c = b[i];
  if (c === MINUS) { neg = true; i++; } else if (c === PLUS) i++;
  let mant = 0, sig = 0, exp = 0, nd = 0;
  while (i < e) {
    c = b[i] - 48;
    if (c >>> 0 > 9) break;
    if (mant !== 0 || c !== 0) { mant = mant * 10 + c; sig++; }
    nd++;
    i++;
  }
  if (i < e && b[i] === DOT) {
    i++;
    while (i < e) {
      c = b[i] - 48;
      if (c >>> 0 > 9) break;
      if (mant !== 0 || c !== 0) { mant = mant * 10 + c; sig++; }
      exp--;
      nd++;
      i++;
    }
  }
  if (nd > 0 && i < e && (b[i] | 32) === 101 /* e */) {
    i++;
    let eneg = false;
    c = b[i];
    if (c === MINUS) { eneg = true; i++; } else if (c === PLUS) i++;
    let ev = 0, ed = 0;
    while (i < e && ev < 100000) {
      c = b[i] - 48;
      if (c >>> 0 > 9) break;
      ev = ev * 10 + c;
      ed++;
      i++;
    }
    if (ed === 0) return NaN;
    exp += eneg ? -ev : ev;
  }
  if (nd === 0 || i !== e) return slowDecimal(b, s, e);
  if (sig > 15 || exp > 22 || exp < -22) return Number(latin1(b, s, e)); // a valid decimal, off the fast path
  const v = mant === 0 ? 0 : exp >= 0 ? mant * POW10[exp] : mant / POW10[-exp];
  return neg ? -v : v;
}

function slowDecimal(b: Uint8Array, s: number, e: number): number {
  const text = latin1(b, s, Math.min(e, s + 400));
  if (DECIMAL.test(text)) return Number(text);
  if (NON_FINITE.test(text)) return text.toLowerCase().includes('inf') ? (text[0] === '-' ? -Infinity : Infinity) : NaN;
  return NaN;
}

/**
 * A cursor over the bytes of a text file that keeps the line number. Tokens are runs of bytes
 * above space; '#' starts a comment to the end of the line; with `continuation` (OBJ) a backslash
 * at the end of a line joins it with the next.
 */
class Scanner {
  readonly b: Uint8Array;
  readonly n: number;
  pos: number;
  line: number;
  /** The last token read is b[ts, te). */
  ts = 0;
  te = 0;

  constructor(b: Uint8Array, readonly file: string, readonly continuation: boolean, pos = 0, line = 1) {
    this.b = b;
    this.n = b.length;
    if (pos === 0 && b.length >= 3 && b[0] === 0xef && b[1] === 0xbb && b[2] === 0xbf) pos = 3; // UTF-8 BOM
    this.pos = pos;
    this.line = line;
  }

  fail(message: string, line = this.line): never {
    throw new SplinekitError('invalid-input', `${this.file} line ${line}: ${message}`);
  }

  /** True when b[p] is a backslash that ends its line (only trailing CRs after it). */
  isContinuation(p: number): boolean {
    if (!this.continuation || this.b[p] !== BSL) return false;
    let q = p + 1;
    while (q < this.n && this.b[q] === CR) q++;
    return q >= this.n || this.b[q] === LF;
  }

  /** Skips spaces, tabs and CRs within the line (and line continuations). */
  skipBlanks(): void {
    const b = this.b, n = this.n;
    let p = this.pos;
    for (;;) {
      while (p < n) {
        const c = b[p];
        if (c === SP || c === TAB || c === CR || c === 11 || c === 12) p++;
        else break;
      }
      if (p < n && b[p] === BSL && this.isContinuation(p)) {
        p++;
        while (p < n && b[p] === CR) p++;
        if (p < n) { p++; this.line++; }
        continue;
      }
      break;
    }
    this.pos = p;
  }

  /** True at the end of the line, at a comment, or at the end of the input (after skipBlanks). */
  atLineEnd(): boolean {
    const p = this.pos;
    if (p >= this.n) return true;
    const c = this.b[p];
    return c === LF || c === HASH;
  }

  /** Moves past the end of the current line (and the lines it continues onto). */
  nextLine(): void {
    const b = this.b, n = this.n;
    let p = this.pos;
    for (;;) {
      const start = p;
      while (p < n && b[p] !== LF) p++;
      if (p >= n) break;
      let q = p - 1;
      while (q >= start && b[q] === CR) q--;
      p++;
      this.line++;
      if (!(this.continuation && q >= start && b[q] === BSL)) break;
    }
    this.pos = p;
  }

  /** Reads the next token of this line into [ts, te); false at the end of the line. */
  token(): boolean {
    this.skipBlanks();
    if (this.atLineEnd()) return false;
    const b = this.b, n = this.n;
    let p = this.pos;
    this.ts = p;
    while (p < n) {
      const c = b[p];
      if (c <= SP || c === HASH || (c === BSL && this.isContinuation(p))) break;
      p++;
    }
    this.te = p;
    this.pos = p;
    return true;
  }

  /** Reads the next token, crossing blank and comment lines; false at the end of the input. */
  anyToken(): boolean {
    while (!this.token()) {
      if (this.pos >= this.n) return false;
      this.nextLine();
    }
    return true;
  }

  /** The last token, shortened for messages. */
  text(): string {
    const t = latin1(this.b, this.ts, Math.min(this.te, this.ts + 40));
    return this.te - this.ts > 40 ? `${t}…` : t;
  }

  number(): number {
    return parseDecimal(this.b, this.ts, this.te);
  }

  /** The last token as a non-negative integer, or fails naming `what`. */
  count(what: string): number {
    const v = this.number();
    if (!Number.isInteger(v) || v < 0 || v > 2 ** 31 - 1) this.fail(`${what} '${this.text()}' is not a non-negative integer`);
    return v;
  }

  /** The last token as a finite coordinate of vertex `vertex` (0-based), or fails. */
  coordinate(vertex: number): number {
    const v = this.number();
    if (Number.isFinite(v)) return v;
    const t = this.text();
    if (Number.isNaN(v) && !NON_FINITE.test(t)) this.fail(`invalid coordinate '${t}' in vertex ${vertex + 1}`);
    return this.fail(`non-finite coordinate '${t}' in vertex ${vertex + 1}`);
  }
}

// ---------------------------------------------------------------------------------------------
// OBJ
// ---------------------------------------------------------------------------------------------

/**
 * Wavefront OBJ: `v x y z [w] [r g b]` and `f` with `v`, `v/vt`, `v//vn`, `v/vt/vn` corners,
 * 1-based or negative (relative) indices. Everything else (vt, vn, o, g, s, usemtl, mtllib, l, p,
 * curves) is skipped. Positive indices may point forward; they are checked once the file is read.
 */
function parseObj(b: Uint8Array, file: string): Omit<MeshArrays, 'format'> {
  const s: Scanner = new Scanner(b, file, true);
  const n = b.length;
  const positions = new F64List(Math.min(n / 8, 2 ** 26));
  const triangles = new I32List(Math.min(n / 8, 2 ** 26));
  const poly = new I32List(64);
  const forward = { index: -1, line: 0 }; // the largest index beyond the vertices read so far, and its line
  let polygons = 0;
  while (s.pos < n) {
    s.skipBlanks();
    if (s.pos >= n) break;
    const c = b[s.pos];
    if ((c === 118 /* v */ || c === 102 /* f */) && (s.pos + 1 >= n || b[s.pos + 1] <= SP || s.isContinuation(s.pos + 1))) {
      s.pos++;
      if (c === 118) {
        readObjVertex(s, positions);
      } else {
        readObjFace(s, poly, positions.length / 3, forward);
        triangles.pushFan(poly);
        polygons++;
      }
    }
    s.nextLine(); // the rest: w, colours, comments, or a statement that is skipped
  }
  const nv = positions.length / 3;
  if (forward.index >= nv) s.fail(`face index ${forward.index + 1} out of range (file has ${nv} vertices)`, forward.line);
  if (nv === 0) invalid(file, 'no vertices (no \'v\' lines)');
  if (polygons === 0) invalid(file, `no faces: ${nv} vertices but no 'f' lines`);
  return { positions: positions.toArray(), triangles: triangles.toArray(), polygons };
}

/** `v x y z`: the three coordinates (what follows is left for nextLine). */
function readObjVertex(s: Scanner, positions: F64List): void {
  const nv = positions.length / 3;
  if (!s.token()) s.fail(`vertex ${nv + 1} has 0 coordinates, expected 3`);
  const x = s.coordinate(nv);
  if (!s.token()) s.fail(`vertex ${nv + 1} has 1 coordinate, expected 3`);
  const y = s.coordinate(nv);
  if (!s.token()) s.fail(`vertex ${nv + 1} has 2 coordinates, expected 3`);
  positions.push3(x, y, s.coordinate(nv));
}

/** `f` corners (`v`, `v/vt`, `v//vn`, `v/vt/vn`) into `poly`, as 0-based vertex indices. */
function readObjFace(s: Scanner, poly: I32List, nv: number, forward: { index: number; line: number }): void {
  const b = s.b;
  poly.length = 0;
  while (s.token()) {
    const te = s.te;
    let p = s.ts, neg = false;
    if (b[p] === MINUS) { neg = true; p++; } else if (b[p] === PLUS) p++;
    const d0 = p;
    let v = 0;
    while (p < te) {
      const d = b[p] - 48;
      if (d >>> 0 > 9) break;
      v = v * 10 + d;
      p++;
    }
    if (p === d0 || (p < te && b[p] !== SLASH) || v > 2 ** 31 - 1) s.fail(`invalid face index '${s.text()}'`);
    if (v === 0) s.fail('face index 0 is invalid (OBJ indices start at 1)');
    let index: number;
    if (neg) {
      index = nv - v;
      if (index < 0) s.fail(`face index -${v} out of range (${nv} vertices before this line)`);
    } else {
      index = v - 1;
      if (index >= nv && index > forward.index) { forward.index = index; forward.line = s.line; }
    }
    poly.push(index);
  }
  if (poly.length < 3) s.fail(`face has ${poly.length} ${poly.length === 1 ? 'vertex' : 'vertices'}, expected at least 3`);
}

// ---------------------------------------------------------------------------------------------
// OFF
// ---------------------------------------------------------------------------------------------

/**
 * Object File Format: `[ST][C][N][4][n]OFF` header, `#` comments, `nv nf ne` counts, one vertex per
 * line (extra values such as normals, colours or w are skipped), one face per line as
 * `n i0 … i(n-1)` (0-based) optionally followed by a colour.
 */
function parseOff(b: Uint8Array, file: string): Omit<MeshArrays, 'format'> {
  const s: Scanner = new Scanner(b, file, false);
  if (!s.anyToken()) invalid(file, 'the file is empty (no OFF header)');
  const header = s.text();
  const m = /^(ST)?(C)?(N)?(4)?(n)?OFF$/.exec(header);
  if (!m) s.fail(`expected the 'OFF' header, found '${header}'`);
  const headerLine = s.line;
  const need = (what: string) => {
    if (!s.anyToken()) s.fail(`file ends before the ${what} (truncated?)`);
  };
  need(m[5] ? 'dimension' : 'vertex count');
  if (s.text() === 'BINARY') {
    throw new SplinekitError('unsupported', `${file} line ${headerLine}: binary OFF is not supported (save it as ASCII OFF)`);
  }
  let dim = 3;
  if (m[5]) {
    dim = s.count('dimension');
    need('vertex count');
  }
  const nv = s.count('vertex count');
  need('face count');
  const nf = s.count('face count');
  s.nextLine(); // the edge count, when present, is not used
  if (nv === 0) invalid(file, 'no vertices (the OFF header says 0)');
  if (nf === 0) invalid(file, 'no faces (the OFF header says 0)');
  // Every record takes at least 2 bytes: refuse impossible counts before allocating for them.
  if (nv + nf > b.length / 2) invalid(file, `the header announces ${nv} vertices and ${nf} faces, more than a file of ${b.length} bytes can hold (truncated?)`);

  const read = Math.min(dim, 3);
  const positions = new Float64Array(nv * 3);
  for (let i = 0; i < nv; i++) {
    if (!s.anyToken()) s.fail(`file ends after ${i} of ${nv} vertices (truncated?)`);
    for (let k = 0; k < read; k++) {
      if (k > 0 && !s.token()) s.fail(`vertex ${i + 1} has ${k} coordinate${k === 1 ? '' : 's'}, expected ${read}`);
      positions[3 * i + k] = s.coordinate(i);
    }
    s.nextLine();
  }

  const triangles = new I32List(nf * 3);
  const poly = new I32List(64);
  for (let f = 0; f < nf; f++) {
    if (!s.anyToken()) s.fail(`file ends after ${f} of ${nf} faces (truncated?)`);
    const k = s.count(`face ${f + 1} vertex count`);
    if (k < 3) s.fail(`face ${f + 1} has ${k} ${k === 1 ? 'vertex' : 'vertices'}, expected at least 3`);
    poly.length = 0;
    for (let j = 0; j < k; j++) {
      if (!s.token()) s.fail(`face ${f + 1} lists ${j} of its ${k} vertex indices`);
      const v = s.number();
      if (!Number.isInteger(v)) s.fail(`invalid face index '${s.text()}'`);
      if (v < 0 || v >= nv) s.fail(`face index ${v} out of range (file has ${nv} vertices)`);
      poly.push(v);
    }
    triangles.pushFan(poly);
    s.nextLine(); // colour, if any
  }
  return { positions, triangles: triangles.toArray(), polygons: nf };
}

// ---------------------------------------------------------------------------------------------
// PLY
// ---------------------------------------------------------------------------------------------

/** PLY scalar types: [type code, size in bytes]. Codes: 0 i8, 1 u8, 2 i16, 3 u16, 4 i32, 5 u32, 6 f32, 7 f64. */
const PLY_TYPES: Record<string, [number, number]> = {
  char: [0, 1], int8: [0, 1], uchar: [1, 1], uint8: [1, 1], short: [2, 2], int16: [2, 2], ushort: [3, 2],
  uint16: [3, 2], int: [4, 4], int32: [4, 4], uint: [5, 4], uint32: [5, 4], float: [6, 4], float32: [6, 4],
  double: [7, 8], float64: [7, 8],
};

interface PlyProperty {
  name: string;
  list: boolean;
  /** Value type code (item type for lists) and its size in bytes. */
  type: number;
  size: number;
  /** List count type code and size (lists only). */
  countType: number;
  countSize: number;
}

interface PlyElement {
  name: string;
  count: number;
  properties: PlyProperty[];
}

interface PlyHeader {
  format: 'ascii' | 'binary_little_endian' | 'binary_big_endian';
  elements: PlyElement[];
  /** Byte offset of the body and its line number. */
  body: number;
  bodyLine: number;
  vertex: PlyElement;
  /** Property indices of x, y, z in the vertex element. */
  xyz: [number, number, number];
  face: PlyElement;
  /** Property index of the vertex index list in the face element. */
  faceList: number;
}

const LITTLE_ENDIAN_HOST = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;

function readBinary(dv: DataView, off: number, type: number, le: boolean): number {
  switch (type) {
    case 0: return dv.getInt8(off);
    case 1: return dv.getUint8(off);
    case 2: return dv.getInt16(off, le);
    case 3: return dv.getUint16(off, le);
    case 4: return dv.getInt32(off, le);
    case 5: return dv.getUint32(off, le);
    case 6: return dv.getFloat32(off, le);
    default: return dv.getFloat64(off, le);
  }
}

/** Bytes of one element when it has no lists; with lists, the least it can take. */
function plyMinSize(el: PlyElement): number {
  let size = 0;
  for (const p of el.properties) size += p.list ? p.countSize : p.size;
  return size;
}

function parsePlyHeader(b: Uint8Array, file: string): PlyHeader {
  if (latin1(b, 0, 3) !== 'ply' || (b.length > 3 && b[3] !== LF && b[3] !== CR)) invalid(file, 'not a PLY file (it does not start with \'ply\')');
  const END = 'end_header';
  let end = -1;
  for (let i = 4; i + END.length <= b.length; i++) {
    if (b[i] === 101 && (b[i - 1] === LF || b[i - 1] === CR) && latin1(b, i, i + END.length) === END) { end = i; break; }
  }
  if (end < 0) invalid(file, 'the PLY header has no \'end_header\' (truncated?)');
  let body = end + END.length;
  while (body < b.length && (b[body] === SP || b[body] === TAB)) body++;
  if (body < b.length && b[body] === CR) body++;
  if (body < b.length && b[body] === LF) body++;

  const lines = latin1(b, 0, end).split(/\r\n|\r|\n/);
  let format = '';
  const elements: PlyElement[] = [];
  for (let li = 1; li < lines.length; li++) {
    const text = lines[li].trim();
    const words = text.split(/\s+/);
    const fail = (message: string): never => {
      throw new SplinekitError('invalid-input', `${file} line ${li + 1}: ${message}`);
    };
    const typeOf = (name: string | undefined) => PLY_TYPES[name ?? ''] ?? fail(`unknown PLY property type '${name}'`);
    switch (words[0]) {
      case '':
      case 'comment':
      case 'obj_info':
        break;
      case 'format':
        format = words[1] ?? '';
        if (!['ascii', 'binary_little_endian', 'binary_big_endian'].includes(format)) fail(`unknown PLY format '${format}'`);
        break;
      case 'element': {
        const count = Number(words[2]);
        if (words.length < 3 || !Number.isInteger(count) || count < 0) fail(`bad element line '${text}'`);
        elements.push({ name: words[1], count, properties: [] });
        break;
      }
      case 'property': {
        const el = elements[elements.length - 1] ?? fail('property before any element');
        if (words[1] === 'list') {
          if (words.length < 5) fail(`bad list property line '${text}'`);
          const [countType, countSize] = typeOf(words[2]);
          const [type, size] = typeOf(words[3]);
          if (countType >= 6) fail(`list count type '${words[2]}' is not an integer type`);
          el.properties.push({ name: words[4], list: true, type, size, countType, countSize });
        } else {
          if (words.length < 3) fail(`bad property line '${text}'`);
          const [type, size] = typeOf(words[1]);
          el.properties.push({ name: words[2], list: false, type, size, countType: 0, countSize: 0 });
        }
        break;
      }
      default:
        fail(`unknown PLY header keyword '${words[0]}'`);
    }
  }
  if (!format) invalid(file, 'the PLY header has no \'format\' line');

  const vertex = elements.find((e) => e.name === 'vertex');
  if (!vertex || vertex.count === 0) invalid(file, 'no vertices (no \'vertex\' element in the PLY header)');
  const xyz = ['x', 'y', 'z'].map((name) => vertex.properties.findIndex((p) => p.name === name && !p.list));
  if (xyz.some((i) => i < 0)) invalid(file, 'the PLY vertex element has no x, y and z properties');
  const face = elements.find((e) => e.name === 'face');
  if (!face || face.count === 0) invalid(file, 'no faces (no \'face\' element in the PLY header)');
  const lists = face.properties.filter((p) => p.list);
  const named = face.properties.findIndex((p) => p.list && (p.name === 'vertex_indices' || p.name === 'vertex_index'));
  const faceList = named >= 0 ? named : lists.length === 1 ? face.properties.indexOf(lists[0]) : -1;
  if (faceList < 0) invalid(file, 'the PLY face element has no vertex_indices list');

  // Every element takes at least a byte per property (binary) or two (ASCII): refuse impossible
  // counts before allocating for them.
  const remaining = b.length - body;
  for (const el of elements) {
    const per = format === 'ascii' ? 2 * Math.max(1, el.properties.length) : Math.max(1, plyMinSize(el));
    if (el.count * per > remaining) {
      invalid(file, `the header announces ${el.count} '${el.name}' elements, more than the ${remaining} bytes after the header can hold (truncated?)`);
    }
  }
  return {
    format: format as PlyHeader['format'], elements, body, bodyLine: lines.length + 1,
    vertex, xyz: xyz as [number, number, number], face, faceList,
  };
}

/**
 * Stanford PLY, ASCII or binary (either endianness): the `vertex` element's x, y, z and the `face`
 * element's `vertex_indices` (or `vertex_index`) list; every other element and property is skipped.
 */
function parsePly(b: Uint8Array, file: string, fromText: boolean): Omit<MeshArrays, 'format'> {
  const header = parsePlyHeader(b, file);
  const positions = new Float64Array(header.vertex.count * 3);
  const triangles = new I32List(header.face.count * 3);
  if (header.format === 'ascii') {
    readPlyAscii(b, file, header, positions, triangles);
  } else {
    if (fromText) {
      invalid(file, `${header.format} PLY given as a string: pass the file's bytes (ArrayBuffer or Uint8Array), text decoding corrupts binary data`);
    }
    readPlyBinary(b, file, header, positions, triangles);
    const bad = firstNonFinite(positions);
    if (bad >= 0) invalid(file, `vertex ${bad + 1} has a non-finite coordinate (${positions[3 * bad]}, ${positions[3 * bad + 1]}, ${positions[3 * bad + 2]})`);
  }
  return { positions, triangles: triangles.toArray(), polygons: header.face.count };
}

function readPlyAscii(b: Uint8Array, file: string, h: PlyHeader, positions: Float64Array, triangles: I32List): void {
  const s: Scanner = new Scanner(b, file, false, h.body, h.bodyLine);
  const nv = h.vertex.count;
  const poly = new I32List(64);
  for (const el of h.elements) {
    const isVertex = el === h.vertex, isFace = el === h.face;
    for (let i = 0; i < el.count; i++) {
      if (!s.anyToken()) s.fail(`file ends after ${i} of ${el.count} '${el.name}' elements (truncated?)`);
      poly.length = 0;
      for (let pi = 0; pi < el.properties.length; pi++) {
        const p = el.properties[pi];
        if (pi > 0 && !s.token()) s.fail(`'${el.name}' ${i + 1} ends before its property '${p.name}'`);
        if (p.list) {
          const k = s.count(`'${p.name}' list length`);
          for (let j = 0; j < k; j++) {
            if (!s.token()) s.fail(`'${el.name}' ${i + 1} lists ${j} of the ${k} values of '${p.name}'`);
            if (isFace && pi === h.faceList) {
              const v = s.number();
              if (!Number.isInteger(v)) s.fail(`invalid face index '${s.text()}'`);
              if (v < 0 || v >= nv) s.fail(`face ${i + 1}: vertex index ${v} out of range (file has ${nv} vertices)`);
              poly.push(v);
            }
          }
        } else if (isVertex && (pi === h.xyz[0] || pi === h.xyz[1] || pi === h.xyz[2])) {
          positions[3 * i + h.xyz.indexOf(pi)] = s.coordinate(i);
        } else if (Number.isNaN(s.number()) && !NON_FINITE.test(s.text())) {
          s.fail(`invalid value '${s.text()}' for '${el.name}' property '${p.name}'`);
        }
      }
      if (s.token()) s.fail(`extra value '${s.text()}' after '${el.name}' ${i + 1} (the header lists ${el.properties.length} properties)`);
      if (isFace) {
        if (poly.length < 3) s.fail(`face ${i + 1} has ${poly.length} ${poly.length === 1 ? 'vertex' : 'vertices'}, expected at least 3`);
        triangles.pushFan(poly);
      }
      s.nextLine();
    }
  }
}

function readPlyBinary(b: Uint8Array, file: string, h: PlyHeader, positions: Float64Array, triangles: I32List): void {
  const le = h.format === 'binary_little_endian';
  const dv = new DataView(b.buffer, b.byteOffset, b.byteLength);
  let off = h.body;
  for (const el of h.elements) {
    if (el.properties.some((p) => p.list)) {
      off = readPlyBinaryLists(dv, off, le, file, h, el, positions, triangles);
      continue;
    }
    const stride = plyMinSize(el);
    if (off + el.count * stride > b.length) {
      invalid(file, `the file ends inside '${el.name}' element ${Math.floor((b.length - off) / stride) + 1} of ${el.count} (truncated?)`);
    }
    if (el === h.vertex) {
      const offsets = h.xyz.map((pi) => el.properties.slice(0, pi).reduce((sum, p) => sum + p.size, 0));
      const types = h.xyz.map((pi) => el.properties[pi].type);
      if (types.every((t) => t === 6) && le === LITTLE_ENDIAN_HOST && (stride | offsets[0] | offsets[1] | offsets[2]) % 4 === 0) {
        // The common case, float x, y, z in host byte order: read through an aligned copy.
        const floats = new Float32Array(b.slice(off, off + el.count * stride).buffer);
        copyStrided(floats, stride / 4, offsets[0] / 4, offsets[1] / 4, offsets[2] / 4, positions, el.count);
      } else {
        for (let k = 0; k < 3; k++) {
          for (let i = 0, o = off + offsets[k]; i < el.count; i++, o += stride) positions[3 * i + k] = readBinary(dv, o, types[k], le);
        }
      }
    }
    off += el.count * stride;
  }
}

function copyStrided(src: Float32Array, step: number, f0: number, f1: number, f2: number, out: Float64Array, n: number): void {
  for (let i = 0, o = 0; i < n; i++, o += step) {
    out[3 * i] = src[o + f0];
    out[3 * i + 1] = src[o + f1];
    out[3 * i + 2] = src[o + f2];
  }
}

/** Reads an element with list properties (faces, usually); returns the offset after it. */
function readPlyBinaryLists(
  dv: DataView, off: number, le: boolean, file: string, h: PlyHeader, el: PlyElement, positions: Float64Array, triangles: I32List,
): number {
  const len = dv.byteLength, nv = h.vertex.count;
  const props = el.properties, isVertex = el === h.vertex, faceList = el === h.face ? h.faceList : -1;
  const truncated = (i: number): never => invalid(file, `the file ends inside '${el.name}' element ${i + 1} of ${el.count} (truncated?)`);
  for (let i = 0; i < el.count; i++) {
    for (let pi = 0; pi < props.length; pi++) {
      const p = props[pi];
      if (!p.list) {
        if (off + p.size > len) truncated(i);
        if (isVertex && (pi === h.xyz[0] || pi === h.xyz[1] || pi === h.xyz[2])) positions[3 * i + h.xyz.indexOf(pi)] = readBinary(dv, off, p.type, le);
        off += p.size;
        continue;
      }
      if (off + p.countSize > len) truncated(i);
      const k = readBinary(dv, off, p.countType, le);
      off += p.countSize;
      if (k < 0) invalid(file, `'${el.name}' ${i + 1} has a negative '${p.name}' list length ${k}`);
      if (off + k * p.size > len) truncated(i);
      if (pi === faceList) {
        if (k < 3) invalid(file, `face ${i + 1} has ${k} ${k === 1 ? 'vertex' : 'vertices'}, expected at least 3`);
        const bad = p.type === 4 ? fanInt32(dv, off, k, le, nv, triangles) : fanAny(dv, off, k, p.type, p.size, le, nv, triangles);
        if (bad !== undefined) invalid(file, `face ${i + 1}: vertex index ${bad} out of range (file has ${nv} vertices)`);
      }
      off += k * p.size;
    }
  }
  return off;
}

/** Fan-triangulates k int32 indices at `at` into `triangles`; returns the first out-of-range index, if any. */
function fanInt32(dv: DataView, at: number, k: number, le: boolean, nv: number, triangles: I32List): number | undefined {
  const first = dv.getInt32(at, le);
  let prev = dv.getInt32(at + 4, le);
  if (first < 0 || first >= nv) return first;
  if (prev < 0 || prev >= nv) return prev;
  for (let j = 2; j < k; j++) {
    const v = dv.getInt32(at + 4 * j, le);
    if (v < 0 || v >= nv) return v;
    triangles.push3(first, prev, v);
    prev = v;
  }
  return undefined;
}

function fanAny(dv: DataView, at: number, k: number, type: number, size: number, le: boolean, nv: number, triangles: I32List): number | undefined {
  let first = 0, prev = 0;
  for (let j = 0; j < k; j++, at += size) {
    const v = readBinary(dv, at, type, le);
    if (!(v >= 0 && v < nv && Number.isInteger(v))) return v;
    if (j === 0) first = v;
    else if (j >= 2) triangles.push3(first, prev, v);
    prev = v;
  }
  return undefined;
}

// ---------------------------------------------------------------------------------------------
// STL
// ---------------------------------------------------------------------------------------------

/** STL, ASCII or binary: triangle soup, 3 vertices per facet in file order. */
async function parseStl(b: Uint8Array, file: string, fromText: boolean): Promise<Omit<MeshArrays, 'format'>> {
  const exactBinary = b.length >= 84 && 84 + 50 * new DataView(b.buffer, b.byteOffset, 84).getUint32(80, true) === b.length;
  let p = 0;
  if (b.length >= 3 && b[0] === 0xef && b[1] === 0xbb && b[2] === 0xbf) p = 3;
  while (p < b.length && b[p] <= SP) p++;
  const startsSolid = latin1(b, p, p + 5).toLowerCase() === 'solid';
  // Binary STL headers often start with 'solid' too; text never holds a NUL byte.
  const hasNul = b.subarray(0, 1024).includes(0);
  if (fromText || (startsSolid && !exactBinary && !hasNul)) return parseStlAscii(b, file);

  if (b.length < 84) invalid(file, `${b.length} bytes is too short for a binary STL (84-byte header; truncated?)`);
  const facets = new DataView(b.buffer, b.byteOffset, 84).getUint32(80, true);
  if (facets === 0) invalid(file, 'no faces (the binary STL header says 0 triangles)');
  const size = 84 + 50 * facets;
  if (size > b.length) invalid(file, `binary STL of ${facets} triangles needs ${size} bytes but the file has ${b.length} (truncated?)`);
  const { STLLoader } = await import('three/examples/jsm/loaders/STLLoader.js');
  // Exactly the announced size, so that STLLoader also reads it as binary (it tests size, then 'solid').
  const geometry = new STLLoader().parse(b.slice(0, size).buffer);
  const source = geometry.getAttribute('position').array;
  if (source.length !== 9 * facets) invalid(file, `binary STL gave ${source.length / 9} triangles, expected ${facets}`);
  const positions = Float64Array.from(source);
  geometry.dispose();
  const bad = firstNonFinite(positions);
  if (bad >= 0) invalid(file, `triangle ${Math.floor(bad / 3) + 1} has a non-finite coordinate`);
  const triangles = new Int32Array(3 * facets);
  for (let i = 0; i < triangles.length; i++) triangles[i] = i;
  return { positions, triangles, polygons: facets };
}

/** ASCII STL: solid … facet normal … outer loop, vertex ×3, endloop, endfacet … endsolid. */
function parseStlAscii(b: Uint8Array, file: string): Omit<MeshArrays, 'format'> {
  const s: Scanner = new Scanner(b, file, false);
  const positions = new F64List(b.length / 20);
  let facets = 0, inSolid = false, facetLine = 0, corners = -1; // corners < 0: outside a facet
  const keyword = (word: string) => {
    if (s.te - s.ts !== word.length) return false;
    for (let i = 0; i < word.length; i++) if ((b[s.ts + i] | 32) !== word.charCodeAt(i)) return false;
    return true;
  };
  while (s.anyToken()) {
    if (keyword('vertex')) {
      if (corners < 0) s.fail('\'vertex\' outside a facet');
      if (corners === 3) s.fail(`facet ${facets + 1} (line ${facetLine}) has more than 3 vertices`);
      const nv = positions.length / 3;
      let x = 0, y = 0, z = 0;
      for (let k = 0; k < 3; k++) {
        if (!s.token()) s.fail(`vertex has ${k} coordinate${k === 1 ? '' : 's'}, expected 3`);
        const v = s.coordinate(nv);
        if (k === 0) x = v; else if (k === 1) y = v; else z = v;
      }
      positions.push3(x, y, z);
      corners++;
    } else if (keyword('facet')) {
      if (!inSolid) s.fail('\'facet\' before \'solid\'');
      if (corners >= 0) s.fail(`'facet' inside facet ${facets + 1} (line ${facetLine}), which has no 'endfacet'`);
      corners = 0;
      facetLine = s.line;
    } else if (keyword('endfacet')) {
      if (corners < 0) s.fail('\'endfacet\' without \'facet\'');
      if (corners !== 3) s.fail(`facet ${facets + 1} (line ${facetLine}) has ${corners} ${corners === 1 ? 'vertex' : 'vertices'}, expected 3`);
      corners = -1;
      facets++;
    } else if (keyword('solid')) {
      if (inSolid) s.fail('\'solid\' inside a solid (missing \'endsolid\')');
      inSolid = true;
    } else if (keyword('endsolid')) {
      if (corners >= 0) s.fail(`'endsolid' inside facet ${facets + 1} (line ${facetLine})`);
      inSolid = false;
    } else if (!keyword('outer') && !keyword('loop') && !keyword('endloop')) {
      s.fail(`unexpected '${s.text()}' in an ASCII STL`);
    }
    s.nextLine(); // the rest of the line: solid name, facet normal, "loop"
  }
  if (corners >= 0) s.fail(`the file ends inside facet ${facets + 1} (line ${facetLine}) (truncated?)`);
  if (inSolid) s.fail('the file ends without \'endsolid\' (truncated?)');
  if (facets === 0) invalid(file, 'no faces (no facets in the ASCII STL)');
  const triangles = new Int32Array(3 * facets);
  for (let i = 0; i < triangles.length; i++) triangles[i] = i;
  return { positions: positions.toArray(), triangles, polygons: facets };
}

// ---------------------------------------------------------------------------------------------
// glTF / GLB
// ---------------------------------------------------------------------------------------------

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
async function parseGltf(b: Uint8Array, file: string, format: 'gltf' | 'glb', fromText: boolean): Promise<Omit<MeshArrays, 'format'>> {
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
