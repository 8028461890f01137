/**
 * STL reader: ASCII by the scanner here, binary through three.js's STLLoader (see
 * src/surface/mesh-io.ts for the conventions every reader keeps).
 */
import { F64List, firstNonFinite, invalid, type ParsedMesh } from './common.js';
import { latin1, Scanner, SP } from './text.js';

/** STL, ASCII or binary: triangle soup, 3 vertices per facet in file order. */
export async function parseStl(b: Uint8Array, file: string, fromText: boolean): Promise<ParsedMesh> {
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
function parseStlAscii(b: Uint8Array, file: string): ParsedMesh {
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
