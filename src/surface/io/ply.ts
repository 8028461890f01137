/** PLY reader, ASCII and binary (see src/surface/mesh-io.ts for the conventions every reader keeps). */
import { SplinekitError } from '../../core/errors.js';
import { firstNonFinite, I32List, invalid, type ParsedMesh } from './common.js';
import { CR, latin1, LF, NON_FINITE, Scanner, SP, TAB } from './text.js';

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
export function parsePly(b: Uint8Array, file: string, fromText: boolean): ParsedMesh {
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
