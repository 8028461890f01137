/** Wavefront OBJ reader (see src/surface/mesh-io.ts for the conventions every reader keeps). */
import { F64List, I32List, invalid, type ParsedMesh } from './common.js';
import { MINUS, PLUS, Scanner, SLASH, SP } from './text.js';

/**
 * Wavefront OBJ: `v x y z [w] [r g b]` and `f` with `v`, `v/vt`, `v//vn`, `v/vt/vn` corners,
 * 1-based or negative (relative) indices. Everything else (vt, vn, o, g, s, usemtl, mtllib, l, p,
 * curves) is skipped. Positive indices may point forward; they are checked once the file is read.
 */
export function parseObj(b: Uint8Array, file: string): ParsedMesh {
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
