import { basename } from 'node:path';
import { DEFAULT_MAX_BYTES, parseSVG } from '../index.js';
import { UsageError, parse, readInput, writeJSON, type Command } from './common.js';

const usage = `usage: splinekit info <file.svg> [--json out.json]

Reads an SVG and prints what the spline model makes of it: elements, splines, segments,
continuity tags and warnings. --json writes the counts and the geometry (control points in
document space, document order, one continuity tag per junction); "-" writes to stdout.`;

export const info: Command = {
  summary: 'counts and geometry of an SVG as splines',
  usage,
  async run(args) {
    const { values, positionals } = parse({ args, options: { json: { type: 'string' } }, allowPositionals: true });
    if (positionals.length !== 1) throw new UsageError('info takes one SVG file (see splinekit info --help)');
    const file = positionals[0];
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
