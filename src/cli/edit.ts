import { writeFileSync } from 'node:fs';
import { basename } from 'node:path';
import { CatmullRom, FALLOFFS, LocalEdit, PARAMETERIZATIONS, type Falloff, type Parameterization } from '../index.js';
import { UsageError, parse, readJSON, writeJSON, type Command } from './common.js';

const usage = `usage: splinekit edit <curve.json> --drag I DX DY [--window L R]
       [--falloff linear|gaussian|cosine] [--alpha A] [--normals]
       [--param uniform|centripetal|chordal] [--json out.json] [-o out.svg]

Localized editing of a Catmull-Rom curve (Eyiyurekli & Breen): drags control point I by (DX, DY)
and spreads the move over an active window of L control points to its left and R to its right
(default 5 5; clamped at an open curve's ends, wrapping on a closed one), with the drop-off
--falloff (default cosine, --alpha A its exponent, default 1). --normals turns the direction
towards the curve normals at the window's ends (§3.4). --param sets the knot spacing (default
centripetal). curve.json: {"closed":bool,"points":[[x,y],...]}, the control points. --json writes
{"points":[[x,y],...],"bezier":{"closed","points","continuity"},"stats":{...}}: the moved control
points and the exact cubic Bézier form in the schema of \`splinekit info\`; -o writes it as SVG.`;

/** Takes `--name v1 .. vk` out of args (values may be negative numbers, which parseArgs would read as flags). */
function takeValues(args: string[], name: string, k: number): string[] | undefined {
  const at = args.indexOf(name);
  if (at < 0) return undefined;
  const values = args.slice(at + 1, at + 1 + k);
  if (values.length < k || values.some((v) => /^--?[a-z]/i.test(v))) {
    throw new UsageError(`${name} takes ${k} values (see splinekit edit --help)`);
  }
  args.splice(at, 1 + k);
  if (args.includes(name)) throw new UsageError(`${name} is given twice`);
  return values;
}

function integer(text: string, what: string, min = 0): number {
  const v = Number(text);
  if (text.trim() === '' || !Number.isInteger(v) || v < min) throw new UsageError(`${what} must be an integer >= ${min}, got "${text}"`);
  return v;
}

function finite(text: string, what: string): number {
  const v = Number(text);
  if (text.trim() === '' || !Number.isFinite(v)) throw new UsageError(`${what} must be a finite number, got "${text}"`);
  return v;
}

function pairs(p: Float64Array): [number, number][] {
  const out: [number, number][] = [];
  for (let i = 0; i < p.length; i += 2) out.push([p[i], p[i + 1]]);
  return out;
}

export const edit: Command = {
  summary: 'drag one control point of a Catmull-Rom curve, the move spread over a window',
  usage,
  async run(argv) {
    const args = [...argv];
    const drag = takeValues(args, '--drag', 3);
    const window = takeValues(args, '--window', 2);
    const { values, positionals } = parse({
      args,
      options: {
        falloff: { type: 'string', default: 'cosine' },
        alpha: { type: 'string', default: '1' },
        normals: { type: 'boolean', default: false },
        param: { type: 'string', default: 'centripetal' },
        json: { type: 'string' },
        o: { type: 'string', short: 'o' },
      },
      allowPositionals: true,
    });
    if (positionals.length !== 1) throw new UsageError('edit takes one curve.json file (see splinekit edit --help)');
    if (!drag) throw new UsageError('edit needs --drag I DX DY (see splinekit edit --help)');
    const index = integer(drag[0], '--drag I');
    const dx = finite(drag[1], '--drag DX'), dy = finite(drag[2], '--drag DY');
    const left = window ? integer(window[0], '--window L') : 5;
    const right = window ? integer(window[1], '--window R') : 5;
    if (!FALLOFFS.includes(values.falloff as Falloff)) throw new UsageError(`--falloff must be linear, gaussian or cosine, got "${values.falloff}"`);
    if (!PARAMETERIZATIONS.includes(values.param as Parameterization)) {
      throw new UsageError(`--param must be uniform, centripetal or chordal, got "${values.param}"`);
    }
    const alpha = finite(values.alpha!, '--alpha');
    if (alpha <= 0) throw new UsageError(`--alpha must be positive, got "${values.alpha}"`);

    const file = positionals[0];
    const json = readJSON(file, 'curve') as Record<string, unknown> | null;
    const curve = CatmullRom.fromJSON(json && typeof json === 'object' ? { ...json, parameterization: values.param } : json, basename(file));
    try {
      const before = curve.points();
      const lengthBefore = curve.length();
      const e = LocalEdit.begin(curve, index, { left, right, falloff: values.falloff as Falloff, alpha, normals: values.normals });
      const { window: w } = e;
      e.move(dx, dy);
      e.end();
      const after = curve.points();
      let moved = 0, largest = 0;
      for (let i = 0; i < after.length; i += 2) {
        const d = Math.hypot(after[i] - before[i], after[i + 1] - before[i + 1]);
        if (d > 0) moved++;
        largest = Math.max(largest, d);
      }
      const spline = curve.toBezier();
      const stats = {
        count: curve.count,
        closed: curve.closed,
        parameterization: curve.parameterization,
        dragged: index,
        displacement: [dx, dy],
        window: { left: w.left, right: w.right, first: w.first, last: w.last },
        falloff: values.falloff,
        alpha,
        normals: values.normals,
        moved,
        max_displacement: largest,
        length_before: lengthBefore,
        length_after: curve.length(),
        segments: curve.segmentCount,
      };
      const out = {
        points: pairs(after),
        bezier: { closed: spline.closed, points: pairs(spline.points), continuity: spline.continuity.map((t) => t.kind) },
        stats,
      };
      if (values.json) writeJSON(values.json, out);
      if (values.o) writeFileSync(values.o, curve.toSVG());
      if (values.json !== '-') {
        console.log(
          `${basename(file)}: ${stats.count} control points (${stats.closed ? 'closed' : 'open'}, ${stats.parameterization}); ` +
            `dragged ${index} by (${dx}, ${dy}) over the window ${w.first}..${w.last} (${w.left} left, ${w.right} right), ` +
            `${stats.falloff}${values.normals ? ' with normals' : ''}: ${moved} points moved`,
        );
      }
    } finally {
      curve.dispose();
    }
  },
};
