import { basename, extname } from 'node:path';
import { DEFAULT_MAX_BYTES, MESH_FORMATS, parseSVG, type MeshInfo } from '../index.js';
import { UsageError, parse, readInput, writeJSON, type Command } from './common.js';
import { loadMesh } from './surface.js';

const usage = `usage: splinekit info <file.svg | mesh> [--json out.json]

Reads an SVG and prints what the spline model makes of it: elements, splines, segments,
continuity tags and warnings. --json writes the counts and the geometry (control points in
document space, document order, one continuity tag per junction); "-" writes to stdout.
A mesh (${MESH_FORMATS.map((f) => '.' + f).join(', ')}) gets what building it found and
repaired: vertices, faces, parts, boundaries, welded, repeated, non-manifold and flipped
elements, with the warnings the editor shows; --json writes them (SurfaceMesh.info).`;

/** The mesh's report as the CLI prints it. */
function printMesh(file: string, m: MeshInfo): void {
  console.log(`${basename(file)}: ${m.vertices} vertices, ${m.faces} faces, ${m.components} parts, ${m.boundaryLoops} boundary loops`);
  console.log(
    `repairs: welded ${m.weldedVertices}, unused ${m.unreferencedVertices}, degenerate ${m.degenerateFaces}, repeated ${m.duplicateFaces}, ` +
      `non-manifold ${m.nonManifoldEdges} edges / ${m.nonManifoldVertices} vertices, flipped ${m.flippedFaces}`,
  );
  console.log(`search: ${m.landmarks} landmarks, ${m.guideFaces > 0 ? `a coarse guide of ${m.guideFaces} triangles` : 'no coarse guide'}, ${(m.bytes / 2 ** 20).toFixed(1)} MB`);
  console.log(`warnings: ${m.warnings.length}`);
  for (const w of m.warnings) console.log(`  - ${w}`);
}

export const info: Command = {
  summary: 'counts and geometry of an SVG as splines, or what a mesh is made of',
  usage,
  async run(args) {
    const { values, positionals } = parse({ args, options: { json: { type: 'string' } }, allowPositionals: true });
    if (positionals.length !== 1) throw new UsageError('info takes one SVG or mesh file (see splinekit info --help)');
    const file = positionals[0];
    if ((MESH_FORMATS as readonly string[]).includes(extname(file).slice(1).toLowerCase())) {
      const mesh = await loadMesh(file);
      try {
        if (values.json !== '-') printMesh(file, mesh.info);
        if (values.json) writeJSON(values.json, { file: basename(file), ...mesh.info });
      } finally {
        mesh.dispose();
      }
      return;
    }
    const doc = parseSVG(readInput(file, DEFAULT_MAX_BYTES), { name: basename(file) });
    const stats = doc.stats();
    if (values.json !== '-') {
      const c = stats.continuity;
      console.log(`${basename(file)}: ${stats.elements} elements, ${stats.splines} splines, ${stats.segments} segments`);
      console.log(`continuity: C0 ${c.C0}, C1 ${c.C1}, G1 ${c.G1}, angle ${c.angle}, none ${c.none}`);
      console.log(`warnings: ${stats.warnings}`);
      for (const w of doc.warnings) console.log(`  - ${w.message}`);
    }
    if (values.json) {
      writeJSON(values.json, {
        file: basename(file),
        counts: stats,
        warnings: doc.warnings,
        size: doc.size,
        bounds: doc.bounds,
        ...doc.toJSON(),
      });
    }
  },
};
