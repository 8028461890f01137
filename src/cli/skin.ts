import { writeFileSync } from 'node:fs';
import { basename } from 'node:path';
import { DEFAULT_MAX_BYTES, SkinRig, SplinekitError, parseSVG, type AffineMatrix, type SkinHandle, type SkinRigOptions } from '../index.js';
import { domainWeights } from '../skin/auto-weights.js';
import { UsageError, medianMs, parse, readInput, readJSON, writeJSON, type Command } from './common.js';

const usage = `usage: splinekit skin <in.svg> --handles <handles.json> --pose <pose.json>
       [--weights shepard|harmonic|bbw] [--method fit|naive] [--flexible] [--samples N]
       [-o out.svg] [--json out.json]

Deforms the drawing by linear blend skinning and keeps it cubic Bézier splines with their
continuity (Liu, Jacobson & Gingold 2014). handles.json: {"handles":[{"x":..,"y":..},...]} in
document space; pose.json: {"transforms":[[a,b,c,d,e,f],...]}, one SVG matrix per handle (rest →
posed). --method naive moves every control point by the deformation instead of fitting;
--flexible relaxes G1 and angle junctions' tangent ratios after the fit. --json writes the
splines in the schema of \`splinekit info\` plus stats (update_ms: median of 100 updates).`;

function readHandles(path: string): SkinHandle[] {
  const json = readJSON(path, 'handles') as { handles?: unknown };
  if (!json || !Array.isArray(json.handles)) throw new SplinekitError('invalid-input', `${basename(path)}: expected {"handles":[{"x":..,"y":..},...]}`);
  return json.handles.map((h: unknown, i: number) => {
    const p = h as { x?: unknown; y?: unknown };
    if (typeof p?.x !== 'number' || typeof p?.y !== 'number' || !Number.isFinite(p.x) || !Number.isFinite(p.y)) {
      throw new SplinekitError('invalid-input', `${basename(path)}: handle ${i} needs finite numbers x and y`);
    }
    return { x: p.x, y: p.y };
  });
}

function readPose(path: string, count: number): AffineMatrix[] {
  const json = readJSON(path, 'pose') as { transforms?: unknown };
  if (!json || !Array.isArray(json.transforms)) throw new SplinekitError('invalid-input', `${basename(path)}: expected {"transforms":[[a,b,c,d,e,f],...]}`);
  if (json.transforms.length !== count) {
    throw new SplinekitError('invalid-input', `${basename(path)}: ${json.transforms.length} transforms for ${count} handles`);
  }
  return json.transforms.map((t: unknown, i: number) => {
    if (!Array.isArray(t) || t.length !== 6 || !t.every((v) => typeof v === 'number' && Number.isFinite(v))) {
      throw new SplinekitError('invalid-input', `${basename(path)}: transform ${i} must be 6 finite numbers [a,b,c,d,e,f]`);
    }
    return t as unknown as AffineMatrix;
  });
}

export const skin: Command = {
  summary: 'skin an SVG with handles: the output stays Bézier splines',
  usage,
  async run(args) {
    const { values, positionals } = parse({
      args,
      options: {
        handles: { type: 'string' },
        pose: { type: 'string' },
        weights: { type: 'string', default: 'shepard' },
        method: { type: 'string', default: 'fit' },
        flexible: { type: 'boolean', default: false },
        samples: { type: 'string', default: '100' },
        o: { type: 'string', short: 'o' },
        json: { type: 'string' },
      },
      allowPositionals: true,
    });
    if (positionals.length !== 1) throw new UsageError('skin takes one SVG file (see splinekit skin --help)');
    if (!values.handles || !values.pose) throw new UsageError('skin needs --handles and --pose (see splinekit skin --help)');
    if (!['shepard', 'harmonic', 'bbw'].includes(values.weights!)) throw new UsageError(`--weights must be shepard, harmonic or bbw, got "${values.weights}"`);
    if (!['fit', 'naive'].includes(values.method!)) throw new UsageError(`--method must be fit or naive, got "${values.method}"`);
    const samples = Number(values.samples);
    if (!Number.isInteger(samples)) throw new UsageError(`--samples must be an integer, got "${values.samples}"`);

    const file = positionals[0];
    const doc = parseSVG(readInput(file, DEFAULT_MAX_BYTES), { name: basename(file) });
    const handles = readHandles(values.handles);
    const pose = readPose(values.pose, handles.length);
    const t0 = performance.now();
    const options: SkinRigOptions = { handles, samples };
    if (values.weights !== 'shepard') options.weights = domainWeights(doc, handles, values.weights as 'harmonic' | 'bbw', { samples });
    const rig = SkinRig.create(doc, options);
    const precomputeMs = performance.now() - t0;
    try {
      const naive = values.method === 'naive';
      const updateMs = medianMs(() => rig.pose(pose));
      let relaxMs = 0;
      if (values.flexible && !naive) {
        const a = performance.now();
        rig.relax();
        relaxMs = performance.now() - a;
      }
      const points = naive ? rig.baseline('naive').slice() : rig.points().slice();
      const posed = rig.posedDocument(points);
      const err = rig.error(naive ? 'naive' : 'fit');
      if (values.o) writeFileSync(values.o, posed.toSVG());
      const stats = {
        curves: rig.curveCount,
        handles: handles.length,
        weights: values.weights,
        method: values.method,
        precompute_ms: precomputeMs,
        update_ms: updateMs,
        relax_ms: relaxMs,
        error_rms: err.rms,
      };
      if (values.json) writeJSON(values.json, { ...posed.toJSON(), stats });
      if (values.json !== '-') {
        console.log(
          `${basename(file)}: ${stats.curves} curves, ${handles.length} handles (${values.weights}), ${values.method}` +
            `: precompute ${precomputeMs.toFixed(1)} ms, update ${stats.update_ms.toFixed(3)} ms` +
            (values.flexible ? `, relax ${relaxMs.toFixed(1)} ms` : '') +
            `, RMS distance to the target ${err.rms.toPrecision(3)}`,
        );
      }
    } finally {
      rig.dispose();
    }
  },
};
