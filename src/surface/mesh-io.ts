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
 * One reader per format in ./io/ (obj.ts, off.ts, ply.ts, stl.ts, gltf.ts); this module picks one by
 * the file's extension and holds the public types. OBJ, OFF, PLY and ASCII STL are read by small
 * parsers over the bytes (./io/text.ts). The three.js loaders cannot be
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
import { SplinekitError } from '../core/errors.js';
import { MESH_FORMATS, type MeshArrays, type MeshFormat, type ParsedMesh } from './io/common.js';
import { parseGltf } from './io/gltf.js';
import { parseObj } from './io/obj.js';
import { parseOff } from './io/off.js';
import { parsePly } from './io/ply.js';
import { parseStl } from './io/stl.js';

export { MESH_FORMATS, type MeshArrays, type MeshFormat } from './io/common.js';

/** Options of parseMesh. */
export interface MeshParseOptions {
  /** Inputs larger than this many bytes are refused with SplinekitError('file-too-large'). Default 512 MiB. */
  maxBytes?: number;
}

/** The default of `MeshParseOptions.maxBytes`: 512 MiB. */
export const DEFAULT_MAX_MESH_BYTES = 512 * 1024 * 1024;

/** The file-picker `accept` list of the mesh formats: ".obj,.off,.ply,.stl,.gltf,.glb". */
export const MESH_FILE_ACCEPT = MESH_FORMATS.map((f) => `.${f}`).join(',');

/** The mesh formats as a reader would list them: ".obj, .off, .ply, .stl, .gltf or .glb". */
export function meshFormatList(conjunction = 'or'): string {
  const dotted = MESH_FORMATS.map((f) => `.${f}`);
  return `${dotted.slice(0, -1).join(', ')} ${conjunction} ${dotted[dotted.length - 1]}`;
}

/** The mesh format of a file name, by its extension (case-insensitive). */
export function meshFormatOf(fileName: string): MeshFormat {
  const base = fileName.slice(Math.max(fileName.lastIndexOf('/'), fileName.lastIndexOf('\\')) + 1);
  const dot = base.lastIndexOf('.');
  const ext = dot >= 0 ? base.slice(dot + 1).toLowerCase() : '';
  if ((MESH_FORMATS as readonly string[]).includes(ext)) return ext as MeshFormat;
  throw new SplinekitError(
    'unsupported',
    `${fileName}: ${ext ? `unsupported mesh format '.${ext}'` : 'no file extension to tell the mesh format'} ` +
      `(expected ${meshFormatList()})`,
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

  let out: ParsedMesh;
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


function checkSize(size: number, maxBytes: number, file: string): void {
  if (size > maxBytes) {
    const mib = (n: number) => (n / 2 ** 20).toFixed(n < 2 ** 20 ? 3 : 1);
    throw new SplinekitError(
      'file-too-large',
      `${file}: ${mib(size)} MiB is larger than the ${mib(maxBytes)} MiB limit (options.maxBytes)`,
    );
  }
}
