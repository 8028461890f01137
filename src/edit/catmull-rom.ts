/**
 * Catmull-Rom curves for sketching and localized editing (Eyiyurekli & Breen, "Localized editing
 * of Catmull-Rom splines"): a curve through every control point, built from points or from a
 * pointer stroke, resampled by arc length, evaluated, and written out as the exact cubic Bézier
 * spline of the shared model (see wasm/core/edit/catmull_rom.h for the formulas).
 *
 *   const curve = CatmullRom.fromStroke(samples, { resample: true });
 *   const edit = LocalEdit.begin(curve, 12, { left: 6, right: 9 });
 *   edit.move(10, -4); edit.end();
 *   const spline = curve.toBezier();
 *   curve.dispose();
 */
import { SplinekitError, checkStatus } from '../core/errors.js';
import { core } from '../core/module.js';
import type { CatmullRomHandle } from '../core/splinekit-core.mjs';
import { curveHandles } from './curve-handle.js';
import { splinesToPathData, formatNumber } from '../svg/path-data.js';
import { CONTINUITY_KINDS, type Spline } from '../spline/spline.js';

/** Knot spacing: dt = |ΔP|^a with a = 0 (uniform), ½ (centripetal: no cusps within a segment) or 1 (chordal). */
export type Parameterization = 'uniform' | 'centripetal' | 'chordal';

/** Every {@link Parameterization}, in the order of the core's enum. */
export const PARAMETERIZATIONS: readonly Parameterization[] = ['uniform', 'centripetal', 'chordal'];

/** The parameterization curves get when none is given: centripetal. */
export const DEFAULT_PARAMETERIZATION: Parameterization = 'centripetal';

/** Options of {@link CatmullRom.create}. */
export interface CatmullRomOptions {
  /** The last segment joins the last control point back to the first. Default false. */
  closed?: boolean;
  /** Knot spacing. Default 'centripetal'. */
  parameterization?: Parameterization;
}

/** One sample of a pointer stroke. */
export interface StrokeSample {
  /** Position, drawing units. */
  x: number;
  /** Position, drawing units. */
  y: number;
  /** Pen pressure in [0, 1] where the device gives it (1 when absent). */
  pressure?: number;
  /** Time stamp (ms) where the device gives it (the sample's index when absent). */
  time?: number;
}

/** Options of {@link CatmullRom.fromStroke}. */
export interface StrokeOptions {
  /** Samples closer than this to the last kept one are dropped (drawing units). Default 0: exact repeats only. */
  minSpacing?: number;
  /** Replace the kept samples by as many control points evenly spaced by arc length (§3.2). Default false. */
  resample?: boolean;
  /** Knot spacing. Default 'centripetal'. */
  parameterization?: Parameterization;
}

/** A Catmull-Rom curve as plain data (what `toJSON` writes and `fromJSON` reads; the CLI's curve.json). */
export interface CatmullRomJSON {
  /** Whether the curve is closed. */
  closed: boolean;
  /** Control points as [x, y] pairs. */
  points: [number, number][];
  /** Knot spacing (optional when reading: centripetal). */
  parameterization?: Parameterization;
}


function parameterizationIndex(p: Parameterization | undefined): number {
  const i = PARAMETERIZATIONS.indexOf(p ?? DEFAULT_PARAMETERIZATION);
  if (i < 0) throw new SplinekitError('invalid-input', `parameterization must be uniform, centripetal or chordal, got "${String(p)}"`);
  return i;
}

function flatten(points: ArrayLike<number> | readonly (readonly [number, number])[], what: string): Float64Array {
  if (points.length > 0 && Array.isArray(points[0])) {
    const pairs = points as readonly (readonly [number, number])[];
    const out = new Float64Array(2 * pairs.length);
    pairs.forEach((p, i) => {
      if (!Array.isArray(p) || p.length !== 2) throw new SplinekitError('invalid-input', `${what} ${i} must be [x, y]`);
      out[2 * i] = p[0];
      out[2 * i + 1] = p[1];
    });
    return out;
  }
  const flat = points as ArrayLike<number>;
  if (flat.length % 2 !== 0) throw new SplinekitError('invalid-input', `${what}s: a flat array needs x,y pairs (got ${flat.length} numbers)`);
  return Float64Array.from(flat);
}

/**
 * A Catmull-Rom curve through its control points: open (the end points repeated, so the curve
 * starts and ends at them) or closed. Holds wasm memory: call `dispose()` when done.
 */
export class CatmullRom {
  private pressureValues: Float64Array | undefined;
  private timeValues: Float64Array | undefined;

  private constructor(handle: CatmullRomHandle) {
    curveHandles.attach(this, handle);
  }

  private static make(fill: (h: CatmullRomHandle) => void): CatmullRom {
    const h = new (core().CatmullRomHandle)();
    try {
      fill(h);
    } catch (err) {
      h.delete();
      throw err;
    }
    return new CatmullRom(h);
  }

  /**
   * A curve through `points` (flat x,y numbers or [x, y] pairs). Throws a SplinekitError naming
   * the problem for fewer than 2 points (3 closed) or a non-finite coordinate.
   */
  static create(points: ArrayLike<number> | readonly (readonly [number, number])[], options: CatmullRomOptions = {}): CatmullRom {
    const xy = flatten(points, 'control point');
    const param = parameterizationIndex(options.parameterization);
    return CatmullRom.make((h) => {
      h.resizeInput(xy.length);
      h.input().set(xy);
      checkStatus(h.set(xy.length / 2, options.closed ?? false, param), 'Catmull-Rom curve', () => h.error());
    });
  }

  /**
   * An open curve from a pointer stroke (§3): the samples become control points (dropping
   * repeats closer than `minSpacing`), optionally resampled evenly by arc length keeping the
   * count. Pressure and time are kept per control point (`pressure`, `time`).
   */
  static fromStroke(samples: readonly StrokeSample[], options: StrokeOptions = {}): CatmullRom {
    const stride = 4;
    const param = parameterizationIndex(options.parameterization);
    const minSpacing = options.minSpacing ?? 0;
    const curve = CatmullRom.make((h) => {
      h.resizeInput(stride * samples.length);
      const input = h.input();
      samples.forEach((s, i) => {
        input[stride * i] = s.x;
        input[stride * i + 1] = s.y;
        input[stride * i + 2] = s.pressure ?? 1;
        input[stride * i + 3] = s.time ?? i;
      });
      checkStatus(h.capture(samples.length, stride, minSpacing, options.resample ?? false, param), 'stroke', () => h.error());
    });
    const h = curveHandles.get(curve);
    curve.pressureValues = h.pressure().slice();
    curve.timeValues = h.time().slice();
    return curve;
  }

  /** A curve from its JSON form ({@link CatmullRomJSON}); bad data throws a SplinekitError naming it. */
  static fromJSON(json: unknown, what = 'curve'): CatmullRom {
    const j = json as Partial<CatmullRomJSON> | null;
    if (!j || typeof j !== 'object' || !Array.isArray(j.points)) {
      throw new SplinekitError('invalid-input', `${what}: expected {"closed":bool,"points":[[x,y],...]}`);
    }
    if (j.closed !== undefined && typeof j.closed !== 'boolean') throw new SplinekitError('invalid-input', `${what}: "closed" must be true or false`);
    j.points.forEach((p: unknown, i: number) => {
      if (!Array.isArray(p) || p.length !== 2 || !p.every((v) => typeof v === 'number' && Number.isFinite(v))) {
        throw new SplinekitError('invalid-input', `${what}: point ${i} must be [x, y] with finite numbers`);
      }
    });
    return CatmullRom.create(j.points as [number, number][], { closed: j.closed ?? false, parameterization: j.parameterization });
  }

  /** Number of control points. */
  get count(): number {
    return curveHandles.get(this).count();
  }

  /** Whether the curve is closed. */
  get closed(): boolean {
    return curveHandles.get(this).closed();
  }

  /** The knot spacing. */
  get parameterization(): Parameterization {
    return PARAMETERIZATIONS[curveHandles.get(this).parameterization()];
  }

  /** Number of segments: count − 1 open, count closed. */
  get segmentCount(): number {
    return curveHandles.get(this).segmentCount();
  }

  /** Pen pressure per control point of a curve made by `fromStroke` (undefined otherwise, or after the points changed count). */
  get pressure(): Float64Array | undefined {
    return this.pressureValues?.length === this.count ? this.pressureValues : undefined;
  }

  /** Time stamp per control point of a curve made by `fromStroke` (undefined otherwise, or after the points changed count). */
  get time(): Float64Array | undefined {
    return this.timeValues?.length === this.count ? this.timeValues : undefined;
  }

  /** A copy of the control points, x,y pairs. */
  points(): Float64Array {
    return curveHandles.get(this).points().slice();
  }

  /** Replaces the control points (flat x,y or [x, y] pairs, any count ≥ 2, 3 closed); tangent overrides are cleared. */
  setPoints(points: ArrayLike<number> | readonly (readonly [number, number])[]): void {
    const xy = flatten(points, 'control point');
    const h = curveHandles.get(this);
    const closed = h.closed(), param = h.parameterization();
    const keep = h.points().slice();
    h.resizeInput(xy.length);
    h.input().set(xy);
    if (h.set(xy.length / 2, closed, param) !== 0) {
      const message = h.error();
      h.resizeInput(keep.length);
      h.input().set(keep);
      h.set(keep.length / 2, closed, param);
      throw new SplinekitError('invalid-input', `Catmull-Rom curve: ${message}`);
    }
  }

  /**
   * §3.2: `count` control points (default: as many as now) evenly spaced by arc length along the
   * curve; open curves keep their ends, closed ones start at point 0. Tangent overrides are cleared.
   */
  resample(count = this.count): void {
    const h = curveHandles.get(this);
    checkStatus(h.resample(count), 'resample', () => h.error());
  }

  /**
   * §3.2, variable resolution: replaces the control points strictly between `first` and `last`
   * (the window's ends, which stay) by `inner` points evenly spaced by arc length. On a closed
   * curve the range may wrap across the seam (then the points are rotated to start at `last`).
   * Returns the ends' new indices.
   */
  resampleRange(
    first: number,
    last: number,
    inner: number,
  ): {
    /** The new index of the window's first end. */
    first: number;
    /** The new index of the window's last end. */
    last: number;
  } {
    const h = curveHandles.get(this);
    checkStatus(h.resampleRange(first, last, inner), 'resample the window', () => h.error());
    return { first: h.newFirst(), last: h.newLast() };
  }

  /** Point of segment `segment` at local parameter u ∈ [0, 1] (Barry–Goldman pyramid). */
  point(segment: number, u: number, target: [number, number] = [0, 0]): [number, number] {
    return this.read(curveHandles.get(this).point(segment, u), 'point', target);
  }

  /** Unit left normal (the tangent turned +90°) of segment `segment` at u. */
  normal(segment: number, u: number, target: [number, number] = [0, 0]): [number, number] {
    return this.read(curveHandles.get(this).normal(segment, u), 'normal', target);
  }

  /** Tangent at control point i in position units ((P[i+1] − P[i−1]) / 2 on a uniform curve), or its override. */
  tangent(i: number, target: [number, number] = [0, 0]): [number, number] {
    return this.read(curveHandles.get(this).tangent(i), 'tangent', target);
  }

  /** The second §3.4: sets the tangent (direction and length) at control point i. */
  setTangent(i: number, tangent: readonly [number, number]): void {
    const h = curveHandles.get(this);
    checkStatus(h.setTangent(i, tangent[0], tangent[1]), 'tangent', () => h.error());
  }

  /** Back to the Catmull-Rom tangent at control point i. */
  clearTangent(i: number): void {
    const h = curveHandles.get(this);
    checkStatus(h.clearTangent(i), 'tangent', () => h.error());
  }

  /** Whether the tangent at control point i was set by `setTangent`. */
  tangentOverridden(i: number): boolean {
    return curveHandles.get(this).tangentOverridden(i);
  }

  /** Arc length of one segment. */
  segmentLength(segment: number): number {
    const h = curveHandles.get(this);
    const length = h.segmentLength(segment);
    if (length < 0) throw new SplinekitError('invalid-input', `segment length: ${h.error()}`);
    return length;
  }

  /** Arc length of the whole curve. */
  length(): number {
    let total = 0;
    for (let s = 0; s < this.segmentCount; s++) total += this.segmentLength(s);
    return total;
  }

  /**
   * The exact cubic Bézier form in the shared spline model: anchors at the control points, tags
   * C1 where both knot intervals are equal (always on a uniform curve), G1 with their ratio
   * otherwise, C0 where the tangent vanishes.
   */
  toBezier(): Spline {
    const h = curveHandles.get(this);
    checkStatus(h.bezier(), 'Bézier form', () => h.error());
    const kinds = h.bezierKinds(), ratios = h.bezierRatios();
    return {
      closed: h.closed(),
      points: h.bezierPoints().slice(),
      continuity: Array.from(kinds, (k, j) => ({ kind: CONTINUITY_KINDS[k], ratio: ratios[j], angle: 0 })),
    };
  }

  /** SVG path data of the Bézier form ("M … C … [Z]"). */
  toPathData(): string {
    return splinesToPathData([this.toBezier()]);
  }

  /** A standalone SVG document drawing the curve (stroked, no fill), its viewBox around the curve with a margin. */
  toSVG(options: {
    /** Stroke colour. Default 'black'. */
    stroke?: string;
    /** Stroke width. Default 1% of the larger side, at least 1e-6. */
    strokeWidth?: number;
  } = {}): string {
    const b = this.toBezier().points;
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (let i = 0; i < b.length; i += 2) {
      x0 = Math.min(x0, b[i]);
      x1 = Math.max(x1, b[i]);
      y0 = Math.min(y0, b[i + 1]);
      y1 = Math.max(y1, b[i + 1]);
    }
    const side = Math.max(x1 - x0, y1 - y0, 1e-6), m = 0.05 * side;
    const width = options.strokeWidth ?? Math.max(0.01 * side, 1e-6);
    const vb = [x0 - m, y0 - m, x1 - x0 + 2 * m, y1 - y0 + 2 * m].map(formatNumber).join(' ');
    return (
      `<svg xmlns="http://www.w3.org/2000/svg" viewBox="${vb}">\n` +
      `  <path d="${this.toPathData()}" fill="none" stroke="${options.stroke ?? 'black'}" stroke-width="${formatNumber(width)}"/>\n` +
      `</svg>\n`
    );
  }

  /** The curve as plain data ({@link CatmullRomJSON}). */
  toJSON(): CatmullRomJSON {
    const p = this.points();
    const points: [number, number][] = [];
    for (let i = 0; i < p.length; i += 2) points.push([p[i], p[i + 1]]);
    return { closed: this.closed, points, parameterization: this.parameterization };
  }

  /** A copy with its own wasm memory (tangent overrides are not copied). */
  clone(): CatmullRom {
    return CatmullRom.create(this.points(), { closed: this.closed, parameterization: this.parameterization });
  }

  /** Frees the wasm memory; the curve cannot be used afterwards. Safe to call twice. */
  dispose(): void {
    curveHandles.release(this);
  }

  /** Whether `dispose()` was called. */
  get disposed(): boolean {
    return !curveHandles.has(this);
  }

  private read(status: number, what: string, target: [number, number]): [number, number] {
    const h = curveHandles.get(this);
    checkStatus(status, what, () => h.error());
    const out = h.out();
    target[0] = out[0];
    target[1] = out[1];
    return target;
  }
}
