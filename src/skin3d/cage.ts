/**
 * Quad (or any polygon) cages for subdivision-surface skinning: read from and written to Wavefront
 * OBJ with OpenSubdiv's crease and corner tags (`t crease 2/1/0 v0 v1 sharpness`,
 * `t corner n/1/0 v1 … vn sharpness` or `n/n/0` with one sharpness per vertex; 0-based vertex indices,
 * as in OpenSubdiv's regression shapes).
 */
import { SplinekitError } from '../core/errors.js';

/** One crease tag: edge (a, b) (0-based vertex indices) and its sharpness (> 0; `Infinity` = infinitely sharp). */
export interface CageCrease {
  /** First vertex (0-based). */
  a: number;
  /** Second vertex (0-based). */
  b: number;
  /** Levels the crease stays sharp (decays by one per level); `Infinity` never decays. */
  sharpness: number;
}

/** One corner tag: vertex v (0-based) made a corner (OpenSubdiv's vertex sharpness). */
export interface CageCorner {
  /** The vertex (0-based). */
  v: number;
  /** Levels the vertex stays a corner (decays by one per level; a fraction blends); `Infinity` never decays. */
  sharpness: number;
}

/** A polygon cage: flat arrays, vertices in file order. */
export interface Cage {
  /** x,y,z per vertex (3 per vertex), in file order. */
  positions: Float64Array;
  /** Number of vertices of each face (≥ 3). */
  faceSizes: Uint32Array;
  /** The faces' 0-based vertex indices, concatenated. */
  faceIndices: Uint32Array;
  /** Crease tags (OpenSubdiv convention). */
  creases: CageCrease[];
  /** Corner tags (OpenSubdiv `t corner`), if any. */
  corners?: CageCorner[];
}

function fail(name: string, line: number, message: string): never {
  throw new SplinekitError('invalid-input', `${name}: line ${line}: ${message}`);
}

function parseSharpness(text: string | undefined): number {
  if (text === undefined) return NaN;
  return /^[+]?inf(inity)?$/i.test(text) ? Infinity : Number(text);
}

/**
 * Reads a cage from OBJ text: `v x y z`, `f` with `v`, `v/vt`, `v//vn`, `v/vt/vn` corners (1-based or
 * negative indices), `t crease 2/1/0 v0 v1 sharpness` and `t corner n/1/0 v1 … vn sharpness` (or
 * `n/n/0`) tags; other statements are skipped. Throws a SplinekitError naming the problem: a
 * non-finite coordinate, a face with fewer than 3 or a repeated vertex, an index out of range, a
 * non-manifold edge (shared by more than two faces), a bad crease or corner tag, or no faces.
 *
 * @param objText the OBJ file's text
 * @param name names the file in errors (default 'cage.obj')
 */
export function parseCage(objText: string, name = 'cage.obj'): Cage {
  const positions: number[] = [], sizes: number[] = [], indices: number[] = [];
  const creases: (CageCrease & { line: number })[] = [];
  const corners: (CageCorner & { line: number })[] = [];
  const lines = objText.split(/\r?\n/);
  for (let l = 0; l < lines.length; l++) {
    const tokens = lines[l].trim().split(/\s+/);
    const tag = tokens[0];
    if (tag === 'v') {
      const xyz = tokens.slice(1, 4).map(Number);
      if (xyz.length < 3 || !xyz.every(Number.isFinite)) fail(name, l + 1, `vertex ${positions.length / 3 + 1} needs 3 finite coordinates, got "${tokens.slice(1).join(' ')}"`);
      positions.push(...xyz);
    } else if (tag === 'f') {
      const nv = positions.length / 3, face: number[] = [];
      for (const corner of tokens.slice(1)) {
        const k = Number(corner.split('/')[0]);
        if (!Number.isInteger(k) || k === 0) fail(name, l + 1, `invalid face index "${corner}"`);
        const v = k > 0 ? k - 1 : nv + k;
        if (v < 0 || (k < 0 && v >= nv)) fail(name, l + 1, `face index ${k} is out of range`);
        if (face.includes(v)) fail(name, l + 1, `face ${sizes.length + 1} repeats vertex ${v + 1}`);
        face.push(v);
      }
      if (face.length < 3) fail(name, l + 1, `face ${sizes.length + 1} has ${face.length} vertices, expected at least 3`);
      sizes.push(face.length);
      indices.push(...face);
    } else if (tag === 't' && tokens[1] === 'crease') {
      const a = Number(tokens[3]), b = Number(tokens[4]), sharpness = parseSharpness(tokens[5]);
      if (tokens[2] !== '2/1/0' || !Number.isInteger(a) || !Number.isInteger(b) || !(sharpness > 0)) {
        fail(name, l + 1, `expected "t crease 2/1/0 v0 v1 sharpness" with 0-based vertices and a positive sharpness, got "${lines[l].trim()}"`);
      }
      creases.push({ a, b, sharpness, line: l + 1 });
    } else if (tag === 't' && tokens[1] === 'corner') {
      const counts = /^(\d+)\/(\d+)\/0$/.exec(tokens[2] ?? '');
      const n = counts ? Number(counts[1]) : 0, m = counts ? Number(counts[2]) : 0;
      const vertices = tokens.slice(3, 3 + n).map(Number), values = tokens.slice(3 + n).map(parseSharpness);
      if (!counts || n < 1 || (m !== 1 && m !== n) || tokens.length !== 3 + n + m || !vertices.every(Number.isInteger) || !values.every((s) => s > 0)) {
        fail(name, l + 1, `expected "t corner n/1/0 v1 … vn sharpness" (or n/n/0, one sharpness per vertex) with 0-based vertices and positive sharpness, got "${lines[l].trim()}"`);
      }
      vertices.forEach((v, k) => corners.push({ v, sharpness: values[m === 1 ? 0 : k], line: l + 1 }));
    }
  }
  const nv = positions.length / 3;
  if (sizes.length === 0) throw new SplinekitError('invalid-input', `${name}: no faces (${nv} vertices but no 'f' lines)`);
  const out = indices.find((v) => v >= nv);
  if (out !== undefined) throw new SplinekitError('invalid-input', `${name}: a face refers to vertex ${out + 1}, but the file has ${nv} vertices`);
  // Edges: at most two faces each.
  const edgeFaces = new Map<number, number>();
  for (let f = 0, at = 0; f < sizes.length; at += sizes[f], f++) {
    for (let k = 0; k < sizes[f]; k++) {
      const u = indices[at + k], w = indices[at + ((k + 1) % sizes[f])];
      const key = Math.min(u, w) * nv + Math.max(u, w);
      const count = (edgeFaces.get(key) ?? 0) + 1;
      if (count > 2) throw new SplinekitError('invalid-input', `${name}: non-manifold edge ${Math.min(u, w) + 1}-${Math.max(u, w) + 1} is shared by more than two faces (face ${f + 1} is the third)`);
      edgeFaces.set(key, count);
    }
  }
  for (const c of creases) {
    if (!edgeFaces.has(Math.min(c.a, c.b) * nv + Math.max(c.a, c.b)) || Math.max(c.a, c.b) >= nv || Math.min(c.a, c.b) < 0) {
      fail(name, c.line, `crease ${c.a} ${c.b} (0-based) is not an edge of the cage`);
    }
  }
  for (const c of corners) {
    if (c.v < 0 || c.v >= nv) fail(name, c.line, `corner vertex ${c.v} (0-based) is outside 0..${nv - 1}`);
  }
  const cage: Cage = {
    positions: Float64Array.from(positions),
    faceSizes: Uint32Array.from(sizes),
    faceIndices: Uint32Array.from(indices),
    creases: creases.map(({ a, b, sharpness }) => ({ a, b, sharpness })),
  };
  if (corners.length > 0) cage.corners = corners.map(({ v, sharpness }) => ({ v, sharpness }));
  return cage;
}

/**
 * Writes a cage as OBJ: its vertices (or `positions`, e.g. a posed cage, 3 per vertex), its faces and
 * its crease and corner tags (infinitely sharp as `inf`, which parseCage reads back).
 */
export function cageToOBJ(cage: Cage, positions: Float64Array = cage.positions): string {
  if (positions.length !== cage.positions.length) {
    throw new SplinekitError('invalid-input', `cageToOBJ: expected ${cage.positions.length} coordinates, got ${positions.length}`);
  }
  const out: string[] = [];
  for (let v = 0; v < positions.length; v += 3) out.push(`v ${positions[v]} ${positions[v + 1]} ${positions[v + 2]}`);
  for (let f = 0, at = 0; f < cage.faceSizes.length; at += cage.faceSizes[f], f++) {
    out.push(`f ${Array.from(cage.faceIndices.subarray(at, at + cage.faceSizes[f]), (v) => v + 1).join(' ')}`);
  }
  for (const c of cage.creases) out.push(`t crease 2/1/0 ${c.a} ${c.b} ${Number.isFinite(c.sharpness) ? c.sharpness : 'inf'}`);
  for (const c of cage.corners ?? []) out.push(`t corner 1/1/0 ${c.v} ${Number.isFinite(c.sharpness) ? c.sharpness : 'inf'}`);
  return `${out.join('\n')}\n`;
}
