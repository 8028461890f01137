import { writeFileSync } from 'node:fs';
import { basename } from 'node:path';
import { SplinekitError } from '../core/errors.js';
import { cageToOBJ, parseCage } from '../skin3d/cage.js';
import { SubdivisionRig, type Skin3dMethod } from '../skin3d/rig.js';
import { UsageError, medianMs, parse, readInput, readJSON, writeJSON, type Command } from './common.js';

const usage = `usage: splinekit skin3d <cage.obj> --handles <handles.json> --pose <pose.json>
       [--levels K] [--weights shepard|bbw] [--method fit|naive] [--json out.json] [-o out.obj]

Deforms a Catmull-Clark cage by linear blend skinning of its subdivision surface and fits the cage
so that its level-K surface follows the skinned one (Liu, Jacobson & Gingold 2014). cage.obj: an OBJ
with polygon faces and OpenSubdiv crease and corner tags ("t crease 2/1/0 v0 v1 sharpness",
"t corner 1/1/0 v sharpness"). handles.json:
{"handles":[{"x":..,"y":..,"z":..},...]}; pose.json: {"transforms":[[a11,a12,a13,t1, a21,a22,a23,t2,
a31,a32,a33,t3],...]}, one row-major 3×4 matrix per handle (x' = A x + t). --levels: 1..4 (default
3). --method naive skins the cage vertices themselves instead of fitting. Prints (or writes to
--json) {"cage":[[x,y,z],...],"stats":{...}} with the posed cage's vertices in file order; -o
writes the posed cage as OBJ with its crease and corner tags.`;

/** Cage files beyond this size are refused before reading. */
const MAX_CAGE_BYTES = 256 * 2 ** 20;

function readHandles(path: string): number[] {
  const json = readJSON(path, 'handles') as { handles?: unknown };
  if (!json || !Array.isArray(json.handles)) throw new SplinekitError('invalid-input', `${basename(path)}: expected {"handles":[{"x":..,"y":..,"z":..},...]}`);
  if (json.handles.length === 0) throw new SplinekitError('invalid-input', `${basename(path)}: no handles`);
  return json.handles.flatMap((h: unknown, i: number) => {
    const p = h as { x?: unknown; y?: unknown; z?: unknown };
    const xyz = [p?.x, p?.y, p?.z];
    if (!xyz.every((v) => typeof v === 'number' && Number.isFinite(v))) {
      throw new SplinekitError('invalid-input', `${basename(path)}: handle ${i} needs finite numbers x, y and z`);
    }
    return xyz as number[];
  });
}

function readTransforms(path: string, count: number): number[] {
  const json = readJSON(path, 'pose') as { transforms?: unknown };
  if (!json || !Array.isArray(json.transforms)) throw new SplinekitError('invalid-input', `${basename(path)}: expected {"transforms":[[a11,a12,a13,t1, a21,a22,a23,t2, a31,a32,a33,t3],...]}`);
  if (json.transforms.length !== count) {
    throw new SplinekitError('invalid-input', `${basename(path)}: ${json.transforms.length} transforms for ${count} handles`);
  }
  return json.transforms.flatMap((t: unknown, i: number) => {
    if (!Array.isArray(t) || t.length !== 12 || !t.every((v) => typeof v === 'number' && Number.isFinite(v))) {
      throw new SplinekitError('invalid-input', `${basename(path)}: transform ${i} must be 12 finite numbers (a row-major 3×4 matrix)`);
    }
    return t as number[];
  });
}

export const skin3d: Command = {
  summary: 'skin a Catmull-Clark cage with handles: the output stays a cage',
  usage,
  async run(args) {
    const { values, positionals } = parse({
      args,
      options: {
        handles: { type: 'string' },
        pose: { type: 'string' },
        levels: { type: 'string', default: '3' },
        weights: { type: 'string', default: 'shepard' },
        method: { type: 'string', default: 'fit' },
        o: { type: 'string', short: 'o' },
        json: { type: 'string' },
      },
      allowPositionals: true,
    });
    if (positionals.length !== 1) throw new UsageError('skin3d takes one cage OBJ file (see splinekit skin3d --help)');
    if (!values.handles || !values.pose) throw new UsageError('skin3d needs --handles and --pose (see splinekit skin3d --help)');
    if (!['shepard', 'bbw'].includes(values.weights!)) throw new UsageError(`--weights must be shepard or bbw, got "${values.weights}"`);
    if (!['fit', 'naive'].includes(values.method!)) throw new UsageError(`--method must be fit or naive, got "${values.method}"`);
    const levels = Number(values.levels);
    if (!Number.isInteger(levels) || levels < 1 || levels > 4) throw new UsageError(`--levels must be an integer in 1..4, got "${values.levels}"`);

    const file = positionals[0];
    const cage = parseCage(new TextDecoder().decode(readInput(file, MAX_CAGE_BYTES)), basename(file));
    const handles = readHandles(values.handles);
    const transforms = readTransforms(values.pose, handles.length / 3);
    const method = values.method as Skin3dMethod;
    const t0 = performance.now();
    const rig = SubdivisionRig.create(cage, { handles, levels, weights: values.weights as 'shepard' | 'bbw' });
    const precomputeMs = performance.now() - t0;
    try {
      const updateMs = medianMs(() => rig.pose(transforms, method));
      const posed = rig.pose(transforms, method).slice();
      const err = rig.error(method);
      if (values.o) writeFileSync(values.o, cageToOBJ(cage, posed));
      const result = {
        cage: Array.from({ length: posed.length / 3 }, (_, v) => [posed[3 * v], posed[3 * v + 1], posed[3 * v + 2]]),
        stats: {
          cage_vertices: rig.cageVertexCount,
          refined_vertices: rig.refinedVertexCount,
          levels,
          handles: rig.handleCount,
          weights: values.weights,
          method,
          precompute_ms: precomputeMs,
          update_ms: updateMs,
          error_rms: err.rms,
          memory_bytes: { M: rig.stats.memoryBytes.M, O: rig.stats.memoryBytes.O },
        },
      };
      writeJSON(values.json ?? '-', result);
      if (values.json && values.json !== '-') {
        console.log(
          `${basename(file)}: ${rig.cageVertexCount} cage vertices, level ${levels} (${rig.refinedVertexCount} vertices), ` +
            `${rig.handleCount} handles (${values.weights}), ${method}: precompute ${precomputeMs.toFixed(1)} ms, ` +
            `update ${result.stats.update_ms.toFixed(3)} ms, RMS distance to the target ${err.rms.toPrecision(3)} of the diagonal`,
        );
      }
    } finally {
      rig.dispose();
    }
  },
};
