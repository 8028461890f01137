import { SVGPathData, SVGPathDataTransformer, type SVGCommand } from 'svg-pathdata';
import { SplinekitError } from '../core/errors.js';
import { arcToCubics } from './arc.js';
import type { Matrix } from './matrix.js';

/** A spline before continuity is detected: flat points, 3n+1 (open) or 3n (closed). */
export interface RawSpline {
  closed: boolean;
  points: Float64Array;
}

function checkFinite(commands: SVGCommand[], where: string): void {
  for (const c of commands) {
    for (const [k, v] of Object.entries(c)) {
      if (typeof v === 'number' && !Number.isFinite(v)) {
        throw new SplinekitError('invalid-path-data', `${where}: path data has a number that is not finite (${k} = ${v})`);
      }
    }
  }
}

/**
 * Converts SVG path data to cubic splines, one per subpath, in the path's own coordinates.
 * Every command is supported: lines become cubics with handles at 1/3 and 2/3 (exact), quadratics
 * are degree-elevated (exact), S/T reflect the previous control point, and elliptical arcs become
 * cubics of at most 90° each, within 1e-4 of the arc's size (svg/arc.ts). A subpath closed by Z whose last point is not its start gets a
 * closing line; a subpath that is only a moveto becomes a one-point spline.
 */
export function pathDataToSplines(d: string, where: string): RawSpline[] {
  let commands: SVGCommand[];
  const word = /(?:^|[^a-z])(nan|[+-]?infinity)(?:$|[^a-z])/i.exec(d);
  if (word) throw new SplinekitError('invalid-path-data', `${where}: bad path data: "${word[1]}" is not a number`);
  try {
    const parsed = new SVGPathData(d);
    checkFinite(parsed.commands, where);
    // Straight C curves stay curves (normalizeC = false): their handles are part of the drawing.
    commands = parsed
      .toAbs()
      .normalizeST()
      .qtToC()
      .transform(SVGPathDataTransformer.NORMALIZE_HVZ(false, true, true, false)).commands;
  } catch (err) {
    if (err instanceof SplinekitError) throw err;
    const reason = err instanceof Error ? err.message : String(err);
    throw new SplinekitError('invalid-path-data', `${where}: bad path data: ${reason}`, { cause: err });
  }
  checkFinite(commands, where);

  // On-curve points bound the path's size from below: arcs are made accurate relative to it.
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (const c of commands) {
    if (!('x' in c) || !('y' in c)) continue; // Z (H and V are lines by now)
    minX = Math.min(minX, c.x); maxX = Math.max(maxX, c.x);
    minY = Math.min(minY, c.y); maxY = Math.max(maxY, c.y);
  }
  const pathSize = Number.isFinite(minX) ? Math.hypot(maxX - minX, maxY - minY) : 0;

  const out: RawSpline[] = [];
  let pts: number[] | null = null;
  let sx = 0, sy = 0; // subpath start
  let cx = 0, cy = 0; // current point
  const flush = (closed: boolean) => {
    if (pts) out.push({ closed, points: Float64Array.from(pts) });
    pts = null;
  };
  const begin = () => (pts ??= [cx, cy]);
  const line = (x: number, y: number) => {
    const p = begin();
    p.push(cx + (x - cx) / 3, cy + (y - cy) / 3, cx + (2 * (x - cx)) / 3, cy + (2 * (y - cy)) / 3, x, y);
  };
  for (const c of commands) {
    switch (c.type) {
      case SVGPathData.MOVE_TO:
        flush(false);
        pts = [c.x, c.y];
        sx = cx = c.x;
        sy = cy = c.y;
        break;
      case SVGPathData.LINE_TO:
        line(c.x, c.y);
        cx = c.x;
        cy = c.y;
        break;
      case SVGPathData.CURVE_TO:
        begin().push(c.x1, c.y1, c.x2, c.y2, c.x, c.y);
        cx = c.x;
        cy = c.y;
        break;
      case SVGPathData.ARC:
        begin().push(...arcToCubics(cx, cy, c, pathSize));
        cx = c.x;
        cy = c.y;
        break;
      case SVGPathData.CLOSE_PATH: {
        const p = begin();
        if (p.length > 2) {
          const tol = 1e-9 * Math.max(1, Math.abs(sx), Math.abs(sy));
          if (Math.abs(cx - sx) > tol || Math.abs(cy - sy) > tol) line(sx, sy);
          p.length -= 2; // the last anchor is the first one
          flush(true);
        } else {
          flush(false);
        }
        cx = sx;
        cy = sy;
        break;
      }
      default:
        throw new SplinekitError('internal', `${where}: unexpected path command after normalization (${c.type})`);
    }
  }
  flush(false);
  return out;
}

/** Shortest decimal that keeps 12 significant digits (relative error ≤ 5e-13). */
export function formatNumber(v: number): string {
  const s = String(Number(v.toPrecision(12)));
  return s === '-0' ? '0' : s;
}

/**
 * A formatter writing numbers rounded to `decimals` places (0–9), shortest form ("12.5", not
 * "12.50000"), as `String(Math.round(v * 10^decimals) / 10^decimals)` would — but from integers,
 * which the engine writes several times faster than fractions (a live view writes tens of thousands
 * of numbers per frame). Numbers too large for exact integer rounding are written as they are.
 */
export function fixedFormatter(decimals: number): (v: number) => string {
  if (!Number.isInteger(decimals) || decimals < 0 || decimals > 9) throw new RangeError(`fixedFormatter: decimals must be an integer from 0 to 9, got ${decimals}`);
  const q = 10 ** decimals;
  const zeros = '0'.repeat(decimals);
  return (v) => {
    let n = Math.round(v * q);
    if (!(Math.abs(n) < Number.MAX_SAFE_INTEGER)) return String(v);
    if (n === 0) return '0';
    let sign = '';
    if (n < 0) {
      sign = '-';
      n = -n;
    }
    const whole = Math.floor(n / q), frac = n - whole * q;
    if (frac === 0) return sign + whole;
    let f = String(frac);
    f = zeros.slice(f.length) + f;
    let end = f.length;
    while (f.charCodeAt(end - 1) === 48) end--;
    return `${sign}${whole}.${f.slice(0, end)}`;
  };
}

/**
 * Path data for splines, optionally mapped by `m` (e.g. document → element space), numbers
 * written by `format` (12 significant digits by default):
 * "M p0 C p1 p2 p3 …", closed splines end with "Z".
 */
export function splinesToPathData(splines: readonly RawSpline[], m?: Matrix, format: (v: number) => string = formatNumber): string {
  const parts: string[] = [];
  const pt = (pts: Float64Array, i: number) => {
    const x = pts[2 * i], y = pts[2 * i + 1];
    return m ? `${format(m.a * x + m.c * y + m.e)} ${format(m.b * x + m.d * y + m.f)}` : `${format(x)} ${format(y)}`;
  };
  for (const s of splines) {
    const n = s.points.length / 2;
    if (n === 0) continue;
    const segs = n <= 1 ? 0 : s.closed ? n / 3 : (n - 1) / 3;
    let d = `M${pt(s.points, 0)}`;
    for (let k = 0; k < segs; k++) {
      const end = 3 * k + 3 >= n ? 0 : 3 * k + 3;
      d += `C${pt(s.points, 3 * k + 1)} ${pt(s.points, 3 * k + 2)} ${pt(s.points, end)}`;
    }
    if (s.closed) d += 'Z';
    parts.push(d);
  }
  return parts.join('');
}
