import { mkdirSync, writeFileSync } from 'node:fs';
import { basename, join } from 'node:path';
import { DEFAULT_MAX_BYTES, MORPH_INTERPOLATIONS, Morph, SplinekitError, parseSVG, type MorphInterpolation, type MorphPin } from '../index.js';
import { UsageError, median, parse, readInput, readJSON, writeJSON, type Command } from './common.js';

const usage = `usage: splinekit morph <a.svg> <b.svg> [--frames N] [--pins pins.json]
       [--interpolation linear|intrinsic] [--out-dir D] [--json out.json]

Blends the first drawing into the second with the least work of bending and stretching
(Sederberg & Greenwood); every in-between is cubic Bézier splines. Frames are taken at
t = i/(N-1), N = 11 by default. pins.json: {"pins":[{"a":[x,y],"b":[x,y]},...]} holds the point
of the first drawing nearest a to the point of the second nearest b (document space).
--out-dir writes one SVG per frame (frame-000.svg, ...). --json writes
{"frames":[{"t":..,"splines":[...]}],"work":W,"stats":{"correspondence_ms":..,"frame_ms":..}}
with splines in the schema of \`splinekit info\`; "-" writes to stdout.`;

function readPins(path: string): MorphPin[] {
  const json = readJSON(path, 'pins') as { pins?: unknown };
  if (!json || !Array.isArray(json.pins)) throw new SplinekitError('invalid-input', `${basename(path)}: expected {"pins":[{"a":[x,y],"b":[x,y]},...]}`);
  return json.pins.map((p: unknown, i: number) => {
    const q = p as { a?: unknown; b?: unknown };
    const point = (v: unknown) => Array.isArray(v) && v.length === 2 && v.every((c) => typeof c === 'number' && Number.isFinite(c));
    if (!point(q?.a) || !point(q?.b)) throw new SplinekitError('invalid-input', `${basename(path)}: pin ${i} needs "a" and "b" as [x, y] with finite numbers`);
    return { a: q.a as [number, number], b: q.b as [number, number] };
  });
}

export const morph: Command = {
  summary: 'least-work blend of two SVGs: the in-betweens stay Bézier splines',
  usage,
  async run(args) {
    const { values, positionals } = parse({
      args,
      options: {
        frames: { type: 'string', default: '11' },
        pins: { type: 'string' },
        interpolation: { type: 'string', default: 'linear' },
        'out-dir': { type: 'string' },
        json: { type: 'string' },
      },
      allowPositionals: true,
    });
    if (positionals.length !== 2) throw new UsageError('morph takes two SVG files (see splinekit morph --help)');
    const frames = Number(values.frames);
    if (!/^\d+$/.test(values.frames!) || frames < 2 || frames > 10000) throw new UsageError(`--frames must be an integer in [2, 10000], got "${values.frames}"`);
    if (!MORPH_INTERPOLATIONS.includes(values.interpolation as MorphInterpolation)) {
      throw new UsageError(`--interpolation must be linear or intrinsic, got "${values.interpolation}"`);
    }
    const [fileA, fileB] = positionals;
    const docA = parseSVG(readInput(fileA, DEFAULT_MAX_BYTES), { name: basename(fileA) });
    const docB = parseSVG(readInput(fileB, DEFAULT_MAX_BYTES), { name: basename(fileB) });
    if (docA.splines.length === 0) throw new SplinekitError('invalid-input', `${basename(fileA)}: no path or shape to morph`);
    if (docB.splines.length === 0) throw new SplinekitError('invalid-input', `${basename(fileB)}: no path or shape to morph`);
    const pins = values.pins ? readPins(values.pins) : [];
    const t0 = performance.now();
    const m = Morph.create(docA, docB, { pins, interpolation: values.interpolation as MorphInterpolation });
    const correspondenceMs = performance.now() - t0;
    try {
      const times: number[] = [];
      for (let i = 0; i < 110; i++) {
        const a = performance.now();
        m.at(i / 109);
        if (i >= 10) times.push(performance.now() - a);
      }
      const ts = Array.from({ length: frames }, (_, i) => i / (frames - 1));
      if (values['out-dir']) {
        mkdirSync(values['out-dir'], { recursive: true });
        const digits = Math.max(3, String(frames - 1).length);
        ts.forEach((t, i) => writeFileSync(join(values['out-dir']!, `frame-${String(i).padStart(digits, '0')}.svg`), m.toSVG(t)));
      }
      const stats = { correspondence_ms: correspondenceMs, frame_ms: median(times), contours: m.contourCount, control_points: m.pointCount };
      if (values.json) {
        writeJSON(values.json, { frames: ts.map((t) => ({ t, splines: m.toJSON(t).splines })), work: m.work, stats });
      }
      if (values.json !== '-') {
        console.log(
          `${basename(fileA)} → ${basename(fileB)}: ${m.contourCount} contours, work ${m.work.toPrecision(4)}` +
            `, correspondence ${correspondenceMs.toFixed(1)} ms, frame ${stats.frame_ms.toFixed(4)} ms` +
            (values['out-dir'] ? `, ${frames} frames in ${values['out-dir']}` : ''),
        );
      }
    } finally {
      m.dispose();
    }
  },
};
