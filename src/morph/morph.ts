import { checkStatus, SplinekitError } from '../core/errors.js';
import { HandleLinks } from '../core/handles.js';
import { core } from '../core/module.js';
import type { MorphHandle } from '../core/splinekit-core.mjs';
import { SplineSet } from '../spline/spline-set.js';
import { splineSetHandles } from '../spline/spline-set-handle.js';
import type { Spline } from '../spline/spline.js';
import type { SvgDocument, SplinesJSON } from '../svg/document.js';
import { parseSVG } from '../svg/import.js';
import { morphAnimatedSVG, morphFrameSVG, type MorphAnimationOptions, type MorphStyle } from './svg-out.js';
import { MORPH_INTERPOLATIONS, type MorphInterpolation, type MorphOptions } from './options.js';

const handles = new HandleLinks<MorphHandle>(() => new SplinekitError('invalid-input', 'Morph used after dispose()'));

/** What the search found for one contour of the blend. */
export interface MorphContour {
  /** Index of the first key's spline this contour starts as, or -1 when it grows from a point. */
  contourA: number;
  /** Index of the second key's spline it ends as, or -1 when it shrinks to a point. */
  contourB: number;
  /** The least work of this pair (eq. 3–5, lengths in units of the keys' mean total length). */
  work: number;
  /** The anchor of the second key's (prepared) chain matched to the first key's anchor 0. */
  start: number;
  /** Whether the second key's contour is traversed backwards. */
  reversed: boolean;
  /** How many pins hold this pair. */
  pins: number;
}

/** The correspondence of a morph: per contour what the search found, and the matched anchors. */
export interface MorphCorrespondence {
  /** One entry per output contour (the first key's order, then contours that grow). */
  contours: MorphContour[];
  /** Matched anchors as x,y pairs: `a[2k], a[2k+1]` on the first key meets `b[2k], b[2k+1]` on the second. */
  a: Float64Array;
  /** See `a`. */
  b: Float64Array;
}

/** A drawing to morph: a parsed SVG (all its splines, document space) or splines. */
export type MorphKey = SvgDocument | readonly Pick<Spline, 'closed' | 'points'>[];

function splinesOf(key: MorphKey): readonly Pick<Spline, 'closed' | 'points'>[] {
  return Array.isArray(key) ? key : (key as SvgDocument).splines;
}

function optional(v: number | undefined, name: string): number {
  if (v === undefined) return NaN;
  if (typeof v !== 'number' || !Number.isFinite(v)) throw new SplinekitError('invalid-input', `morph: ${name} must be a finite number, got ${String(v)}`);
  return v;
}

/**
 * A least-work blend of two drawings whose in-betweens stay cubic Bézier splines (Sederberg &
 * Greenwood, "Shape blending of 2-D piecewise curves", 1993). `create` pairs the contours and
 * finds each pair's correspondence once; `at(t)` is then an allocation-free evaluation.
 *
 *   const m = Morph.create(parseSVG(a), parseSVG(b));
 *   m.at(0.5);            // control points of every contour, x,y pairs
 *   m.toSVG(0.5);         // the in-between as an SVG document
 *   m.dispose();
 */
export class Morph {
  /** Total least work over all contours. */
  readonly work: number;
  /** Number of output contours. */
  readonly contourCount: number;
  /** Output contour c owns points [starts[c], starts[c] + counts[c]) of `at(t)`. */
  readonly starts: Int32Array;
  /** Control points per output contour (3n closed, 3n+1 open). */
  readonly counts: Int32Array;
  /** Whether each output contour is closed. */
  readonly closed: boolean[];
  /** Per output anchor (contour by contour): whether every in-between is C1 there. */
  readonly coupled: Uint8Array;
  /** What the search found per contour, and the matched anchors. */
  readonly correspondence: MorphCorrespondence;
  /** Grid cells the correspondence search relaxed (a measure of its work). */
  readonly searchCells: number;
  /** Paint of the in-betweens' SVG: the first key's first shape's fill and fill rule. */
  readonly style: MorphStyle;
  /** The region both keys are drawn in: [xmin, ymin, xmax, ymax]. */
  readonly frame: [number, number, number, number];
  private mode: number;

  private constructor(handle: MorphHandle, options: MorphOptions, style: MorphStyle, frame: [number, number, number, number]) {
    handles.attach(this, handle);
    this.mode = Morph.modeOf(options.interpolation ?? 'linear');
    this.work = handle.work();
    this.contourCount = handle.contourCount();
    this.starts = handle.starts().slice();
    this.counts = handle.counts().slice();
    this.closed = Array.from(handle.closed(), (c) => c !== 0);
    this.coupled = Uint8Array.from(handle.coupled());
    this.searchCells = handle.cells();
    const info = handle.contours();
    const contours: MorphContour[] = [];
    for (let c = 0; c < this.contourCount; c++) {
      contours.push({ contourA: info[6 * c], contourB: info[6 * c + 1], work: info[6 * c + 2], start: info[6 * c + 3], reversed: info[6 * c + 4] !== 0, pins: info[6 * c + 5] });
    }
    checkStatus(handle.evaluate(0, 0), 'morph', () => handle.error());
    const k0 = handle.points().slice();
    checkStatus(handle.evaluate(1, 0), 'morph', () => handle.error());
    const k1 = handle.points().slice();
    const a: number[] = [], b: number[] = [];
    for (let c = 0; c < this.contourCount; c++) {
      for (let p = this.starts[c]; p < this.starts[c] + this.counts[c]; p += 3) {
        a.push(k0[2 * p], k0[2 * p + 1]);
        b.push(k1[2 * p], k1[2 * p + 1]);
      }
    }
    this.correspondence = { contours, a: Float64Array.from(a), b: Float64Array.from(b) };
    this.style = style;
    this.frame = frame;
  }

  private static modeOf(m: MorphInterpolation): number {
    if (!MORPH_INTERPOLATIONS.includes(m)) throw new SplinekitError('invalid-input', `morph: interpolation must be linear or intrinsic, got "${String(m)}"`);
    return m === 'intrinsic' ? 1 : 0;
  }

  /**
   * Pairs the contours of `a` and `b` and finds each pair's least-work correspondence. Throws
   * SplinekitError('invalid-input') naming the problem for empty or malformed keys, bad options or
   * pins that cross. Requires `await init()`.
   */
  static create(a: MorphKey, b: MorphKey, options: MorphOptions = {}): Morph {
    const sa = splinesOf(a), sb = splinesOf(b);
    if (sa.length === 0) throw new SplinekitError('invalid-input', 'morph: the first shape has no contour');
    if (sb.length === 0) throw new SplinekitError('invalid-input', 'morph: the second shape has no contour');
    const args = [
      optional(options.stretching, 'stretching'),
      optional(options.bending, 'bending'),
      optional(options.kinking, 'kinking'),
      optional(options.kinkExponent, 'kinkExponent'),
      optional(options.segmentLimit, 'segmentLimit'),
      optional(options.continuityTolerance, 'continuityTolerance'),
      optional(options.lengthUnit, 'lengthUnit'),
      optional(options.travel, 'travel'),
    ] as const;
    Morph.modeOf(options.interpolation ?? 'linear');
    const pins = options.pins ?? [];
    pins.forEach((p, i) => {
      const ok = [p?.a?.[0], p?.a?.[1], p?.b?.[0], p?.b?.[1]].every((v) => typeof v === 'number' && Number.isFinite(v));
      if (!ok) throw new SplinekitError('invalid-input', `morph: pin ${i} needs finite points a: [x, y] and b: [x, y]`);
    });
    const setA = SplineSet.from(sa);
    let setB: SplineSet | undefined;
    const handle = new (core().MorphHandle)();
    try {
      setB = SplineSet.from(sb);
      handle.resizePins(pins.length);
      const view = handle.pins();
      pins.forEach((p, i) => view.set([p.a[0], p.a[1], p.b[0], p.b[1]], 4 * i));
      const status = handle.setup(splineSetHandles.get(setA), splineSetHandles.get(setB), ...args, directionOf(options.direction));
      checkStatus(status, 'morph', () => handle.error());
      const ba = setA.totalBounds()!, bb = setB.totalBounds()!;
      const frame: [number, number, number, number] = [Math.min(ba[0], bb[0]), Math.min(ba[1], bb[1]), Math.max(ba[2], bb[2]), Math.max(ba[3], bb[3])];
      return new Morph(handle, options, styleOf(a), frame);
    } catch (err) {
      handle.delete();
      throw err;
    } finally {
      setA.dispose();
      setB?.dispose();
    }
  }

  /** The interpolation `at` uses; set it to switch ('linear' or 'intrinsic'). */
  get interpolation(): MorphInterpolation {
    return this.mode === 1 ? 'intrinsic' : 'linear';
  }

  /** Switches the interpolation of later `at` calls; throws for anything but 'linear' or 'intrinsic'. */
  set interpolation(m: MorphInterpolation) {
    this.mode = Morph.modeOf(m);
  }

  /** Number of control points over all output contours. */
  get pointCount(): number {
    return handles.get(this).pointCount();
  }

  /**
   * The in-between at `t` (0: the first key, 1: the second; outside [0, 1] extrapolates): control
   * points of every contour as x,y pairs, laid out by `starts`/`counts`. A view into wasm memory,
   * valid until the next call; allocates nothing.
   */
  at(t: number): Float64Array {
    const h = handles.get(this);
    checkStatus(h.evaluate(t, this.mode), 'morph', () => h.error());
    return h.points();
  }

  /** The in-between at `t` as splines (copies), with continuity tags: C1 where coupled, C0 elsewhere. */
  splines(t: number): Spline[] {
    const points = this.at(t);
    const out: Spline[] = [];
    let anchor = 0;
    for (let c = 0; c < this.contourCount; c++) {
      const pts = points.slice(2 * this.starts[c], 2 * (this.starts[c] + this.counts[c]));
      const n = this.closed[c] ? this.counts[c] / 3 : (this.counts[c] - 1) / 3;
      const anchors = this.closed[c] ? n : n + 1;
      const continuity = [];
      for (let j = 0; j < (this.closed[c] ? n : n - 1); j++) {
        const a = this.closed[c] ? j : j + 1;
        continuity.push({ kind: this.coupled[anchor + a] ? ('C1' as const) : ('C0' as const), ratio: 1, angle: 0 });
      }
      anchor += anchors;
      out.push({ closed: this.closed[c], points: pts, continuity });
    }
    return out;
  }

  /** The in-between at `t` as an SVG document (one path, the first key's paint). */
  toSVG(t: number): string {
    return morphFrameSVG(this.splines(t), this.style, this.frame);
  }

  /** The in-between at `t` parsed back into an SvgDocument (continuity detected as on import). */
  document(t: number): SvgDocument {
    return parseSVG(this.toSVG(t), { name: `morph at t=${t}` });
  }

  /**
   * The in-between at `t` in the CLI's `info` schema: control points in document space, one
   * continuity tag per junction detected as on import (relative to the keys' size).
   */
  toJSON(t: number): SplinesJSON {
    const splines = this.splines(t);
    const set = SplineSet.from(splines);
    try {
      const size = Math.hypot(this.frame[2] - this.frame[0], this.frame[3] - this.frame[1]);
      const tags = set.classify(size);
      return {
        splines: splines.map((s, i) => {
          const points: [number, number][] = [];
          for (let k = 0; k < s.points.length; k += 2) points.push([s.points[k], s.points[k + 1]]);
          return { closed: s.closed, points, continuity: tags[i].map((tag) => tag.kind) };
        }),
      };
    } finally {
      set.dispose();
    }
  }

  /**
   * An SVG that plays the blend with no script: the path data of every frame has the same
   * commands, animated by SMIL `<animate attributeName="d">` ('smil', default) or CSS keyframes of
   * `d: path(...)` ('css').
   */
  animatedSVG(options: MorphAnimationOptions = {}): string {
    const frames = options.frames ?? 25;
    if (!Number.isInteger(frames) || frames < 2 || frames > 1000) throw new SplinekitError('invalid-input', `morph animation: frames must be an integer in [2, 1000], got ${frames}`);
    const list: Spline[][] = [];
    for (let i = 0; i < frames; i++) list.push(this.splines(i / (frames - 1)));
    return morphAnimatedSVG(list, this.style, this.frame, options);
  }

  /** Frees the wasm memory; the morph cannot be used afterwards (a second call does nothing). */
  dispose(): void {
    handles.release(this);
  }
}

function directionOf(d: MorphOptions['direction']): number {
  if (d === undefined) return -1;
  const i = ['winding', 'both', 'forward'].indexOf(d);
  if (i < 0) throw new SplinekitError('invalid-input', `morph: direction must be winding, both or forward, got "${String(d)}"`);
  return i;
}

function styleOf(key: MorphKey): MorphStyle {
  if (Array.isArray(key)) return { fill: 'black', fillRule: 'nonzero' };
  const doc = key as SvgDocument;
  const shape = doc.shapes[0];
  if (!shape) return { fill: 'black', fillRule: 'nonzero' };
  const fill = doc.paintColor(shape.style.fill);
  const stroke = doc.paintColor(shape.style.stroke);
  return {
    fill: fill ?? 'none',
    fillRule: shape.style.fillRule,
    ...(stroke ? { stroke, strokeWidth: shape.style.strokeWidth } : {}),
  };
}
