/** Object File Format (OFF) reader (see src/surface/mesh-io.ts for the conventions every reader keeps). */
import { SplinekitError } from '../../core/errors.js';
import { I32List, invalid, type ParsedMesh } from './common.js';
import { Scanner } from './text.js';

/**
 * Object File Format: `[ST][C][N][4][n]OFF` header, `#` comments, `nv nf ne` counts, one vertex per
 * line (extra values such as normals, colours or w are skipped), one face per line as
 * `n i0 … i(n-1)` (0-based) optionally followed by a colour.
 */
export function parseOff(b: Uint8Array, file: string): ParsedMesh {
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
