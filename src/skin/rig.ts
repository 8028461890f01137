import type { AffineMatrix } from '../core/affine.js';
import { checkStatus, SplinekitError } from '../core/errors.js';
import { core } from '../core/module.js';
import type { SkinRigHandle } from '../core/splinekit-core.mjs';
import { SplineSet } from '../spline/spline-set.js';
import { splineSetHandles } from '../spline/spline-set-handle.js';
import { CONTINUITY_KINDS, type ContinuityKind } from '../spline/spline.js';
import type { SvgDocument } from '../svg/document.js';


/**
 * Linear blend skinning of a drawing whose output stays cubic Bézier splines with their
 * continuity — Liu, Jacobson & Gingold 2014 (wasm/core/skin/rig.h has the math).
 *
 *   const rig = SkinRig.create(doc, { handles: [{x: 10, y: 20}, …] });
 *   rig.pose(transforms);   // per frame: one matrix–vector product in wasm
 *   rig.relax();            // on release: flexible G1 / angle
 *   const svg = rig.toSVG();
 */

/** A point handle in document space. */
export interface SkinHandle {
  /** x in document space. */
  x: number;
  /** y in document space. */
  y: number;
}

/** 'fit' is this rig; the others are the paper's baselines (§5). */
export type SkinMethod = 'fit' | 'naive' | 'interpolated' | 'jacobian';
const METHOD_CODE: Record<SkinMethod, number> = { fit: 0, naive: 1, interpolated: 2, jacobian: 3 };

/**
 * Weights w_i at arbitrary rest positions: fills `out` (#points × #handles, row-major) and, when
 * given, `gradients` (#points × #handles × 2). Shepard weights are built in; harmonic and BBW
 * come from `SkinWeights` (skin/weights.ts).
 */
export interface WeightSource {
  /** Number of handles: columns of `out`. */
  readonly handleCount: number;
  /** Fills `out` (#points × #handles, row-major) with the weights at `points` (x,y pairs). */
  weightsAt(points: Float64Array, out: Float64Array): void;
  /** Fills `out` (#points × #handles × 2) with ∇w at `points`; only the Jacobian baseline calls it. */
  gradientsAt?(points: Float64Array, out: Float64Array): void;
}

/**
 * Weights already evaluated at the rig's query positions (see SkinRig.weightQueries): for a
 * worker that computes slow weights (harmonic, BBW) from plain arrays.
 */
export interface PrecomputedWeights {
  /** Number of handles: columns of every array. */
  readonly handleCount: number;
  /** At the curve samples: #samples × #handles, row-major. */
  readonly samples: Float64Array;
  /** At the control points: #points × #handles. */
  readonly points: Float64Array;
  /** ∇w at the control points: #points × #handles × 2 (only the Jacobian baseline needs them). */
  readonly gradients?: Float64Array;
}

/** Where a rig needs its weights: curve samples (midpoint rule) and control points, x,y pairs. */
export interface WeightQueries {
  /** The curve samples, x,y pairs: `samples` per curve, curves in spline order. */
  samples: Float64Array;
  /** The control points of every spline, x,y pairs, in spline order. */
  points: Float64Array;
}

/** What SkinRig.create needs: the handles, and optionally weights, quadrature and continuity. */
export interface SkinRigOptions {
  /** The handles, in the order of the transforms given to pose(). At least one. */
  handles: readonly SkinHandle[];
  /** 'shepard' (default), a weight source, or weights precomputed at weightQueries(). */
  weights?: 'shepard' | WeightSource | PrecomputedWeights;
  /** Exponent of Shepard weights |p − h|^−power. Default 2. */
  shepardPower?: number;
  /** Quadrature samples per curve, for Â and Ŵ alike (paper: 100). Default 100. */
  samples?: number;
  /** Ignore continuity: every junction is C0 (the paper's unconstrained formulation). */
  unconstrained?: boolean;
  /** Per-junction kinds overriding the document's tags: overrides[spline][junction]. */
  continuity?: (ContinuityKind | undefined)[][];
}

/** How far a deformation is from the target (each curve's rest shape under the blended transforms). */
export interface SkinError {
  /** Σ_j ℓ_j ∫|B_j − s|² dt: the integrated squared distance to the target, length-weighted. */
  total: number;
  /** sqrt(total / Σ ℓ_j): a root-mean-square distance, in document units. */
  rms: number;
  /** Per curve (in spline order), the mean squared distance over its samples (for heat maps). */
  perCurve: Float64Array;
}


/**
 * A skinning rig for an SVG document (Liu, Jacobson & Gingold 2014): create() precomputes
 * weights and one factorization; pose() fits every cubic curve to the blended handle transforms,
 * keeping the continuity tags, in one matrix–vector product. Holds wasm memory: dispose() it.
 */
export class SkinRig {
  /** Number of handles (transforms per pose). */
  readonly handleCount: number;
  /** Number of cubic curves (segments) over all splines. */
  readonly curveCount: number;
  /** Milliseconds spent in create() (weights and the precompute). */
  readonly precomputeMs: number;
  private handle: SkinRigHandle | undefined;
  private readonly doc: SvgDocument;
  private readonly pointCount: number;

  private constructor(doc: SvgDocument, handle: SkinRigHandle, handleCount: number, precomputeMs: number) {
    this.doc = doc;
    this.handle = handle;
    this.handleCount = handleCount;
    this.curveCount = handle.curveCount();
    this.pointCount = doc.splines.reduce((n, s) => n + s.points.length / 2, 0);
    this.precomputeMs = precomputeMs;
  }

  /** The positions where a rig for `doc` with `samples` per curve evaluates weights. */
  static weightQueries(doc: SvgDocument, samples = 100): WeightQueries {
    const set = SplineSet.from(doc.splines);
    const h = new (core().SkinRigHandle)();
    try {
      h.resizeKinds(doc.splines.reduce((n, s) => n + s.continuity.length, 0));
      checkStatus(h.setup(splineSetHandles.get(set), 1, samples), 'skin', () => h.errorMessage());
      return { samples: h.samplePoints().slice(), points: h.controlPoints().slice() };
    } finally {
      h.delete();
      set.dispose();
    }
  }

  /** Builds the rig: weights at the curve samples and control points, then one factorization. */
  static create(doc: SvgDocument, options: SkinRigOptions): SkinRig {
    const t0 = performance.now();
    const handles = options.handles;
    if (handles.length === 0) throw new SplinekitError('invalid-input', 'skin: at least one handle is needed');
    handles.forEach((h, i) => {
      if (!Number.isFinite(h.x) || !Number.isFinite(h.y)) throw new SplinekitError('invalid-input', `skin: handle ${i} has a non-finite position`);
    });
    const samples = options.samples ?? 100;
    if (!Number.isInteger(samples) || samples < 4 || samples > 10000) {
      throw new SplinekitError('invalid-input', `skin: samples must be an integer in [4, 10000], got ${samples}`);
    }
    const source = options.weights ?? 'shepard';
    if (source !== 'shepard' && source.handleCount !== handles.length) {
      throw new SplinekitError('invalid-input', `skin: the weights are for ${source.handleCount} handles, the rig has ${handles.length}`);
    }
    const set = SplineSet.from(doc.splines);
    const h = new (core().SkinRigHandle)();
    try {
      const kinds: number[] = [];
      doc.splines.forEach((s, i) => {
        s.continuity.forEach((tag, j) => {
          const kind = options.unconstrained ? 'C0' : options.continuity?.[i]?.[j] ?? tag.kind;
          kinds.push(CONTINUITY_KINDS.indexOf(kind));
        });
      });
      h.resizeKinds(kinds.length);
      h.kinds().set(kinds);
      checkStatus(h.setup(splineSetHandles.get(set), handles.length, samples), 'skin', () => h.errorMessage());
      if (source === 'shepard') {
        const power = options.shepardPower ?? 2;
        if (!(power > 0)) throw new SplinekitError('invalid-input', `skin: shepardPower must be positive, got ${power}`);
        const hv = h.handles();
        handles.forEach((p, i) => ((hv[2 * i] = p.x), (hv[2 * i + 1] = p.y)));
        h.useShepard(power);
      } else if ('weightsAt' in source) {
        // Copy the positions out first: the source may allocate in wasm memory (views go stale).
        const samplesXY = h.samplePoints().slice(), controls = h.controlPoints().slice();
        const sw = new Float64Array(h.sampleWeights().length), pw = new Float64Array(h.pointWeights().length);
        source.weightsAt(samplesXY, sw);
        source.weightsAt(controls, pw);
        const pg = new Float64Array(h.pointGradients().length);
        source.gradientsAt?.(controls, pg);
        h.sampleWeights().set(sw);
        h.pointWeights().set(pw);
        h.pointGradients().set(pg);
      } else {
        const expect = (what: string, got: Float64Array | undefined, want: number) => {
          if (got && got.length !== want) throw new SplinekitError('invalid-input', `skin: precomputed ${what} weights have ${got.length} values, the rig needs ${want}`);
        };
        expect('sample', source.samples, h.sampleWeights().length);
        expect('point', source.points, h.pointWeights().length);
        expect('gradient', source.gradients, h.pointGradients().length);
        h.sampleWeights().set(source.samples);
        h.pointWeights().set(source.points);
        if (source.gradients) h.pointGradients().set(source.gradients);
      }
      checkStatus(h.precompute(), 'skin', () => h.errorMessage());
    } catch (err) {
      h.delete();
      throw err;
    } finally {
      set.dispose();
    }
    return new SkinRig(doc, h, handles.length, performance.now() - t0);
  }

  private live(): SkinRigHandle {
    if (!this.handle) throw new Error('SkinRig used after dispose()');
    return this.handle;
  }

  /**
   * Poses the handles: `transforms` holds one affine matrix per handle (rest → posed), either
   * flat (6 numbers each, a b c d e f) or as arrays. Returns the fitted control points of all
   * splines, in document order (a view into wasm memory, valid until the next call on the rig).
   */
  pose(transforms: ArrayLike<number> | readonly AffineMatrix[]): Float64Array {
    const h = this.live();
    this.writeTransforms(h, transforms);
    h.update();
    return h.points();
  }

  /** The fitted points of the last pose() or relax() (a view, as pose()). */
  points(): Float64Array {
    return this.live().points();
  }

  /**
   * Flexible G1 / angle (§4): starting from the rigid fit of the current pose, alternates fixed
   * ratios and fixed directions until the energy stops dropping. Updates points().
   */
  relax(): {
    /** Gauss–Newton iterations taken. */
    iterations: number;
    /** The energy after each iteration. */
    energies: number[];
  } {
    const h = this.live();
    const iterations = h.relax();
    return { iterations, energies: Array.from(h.relaxEnergies()) };
  }

  /** A baseline's control points for the current pose (a view, as pose()). */
  baseline(method: Exclude<SkinMethod, 'fit'>): Float64Array {
    return this.live().baseline(METHOD_CODE[method]);
  }

  /** Distance to the target deformation of the fit (or a baseline) for the current pose. */
  error(method: SkinMethod = 'fit'): SkinError {
    const h = this.live();
    const total = h.error(METHOD_CODE[method]);
    const length = h.totalLength();
    return { total, rms: Math.sqrt(total / (length > 0 ? length : 1)), perCurve: h.perCurveError().slice() };
  }

  /** Rest positions of the curve samples (x,y pairs; `samples` per curve, in curve order). */
  samplePositions(): Float64Array {
    return this.live().samplePoints().slice();
  }

  /** Weight of handle `i` at every curve sample (for showing a handle's influence). */
  handleWeights(i: number): Float64Array {
    if (!(Number.isInteger(i) && i >= 0 && i < this.handleCount)) throw new SplinekitError('invalid-input', `skin: no handle ${i}`);
    const w = this.live().sampleWeights(), h = this.handleCount;
    const out = new Float64Array(w.length / h);
    for (let k = 0; k < out.length; k++) out[k] = w[k * h + i];
    return out;
  }

  /** max |b − ρR(θ)a| over the constrained junctions of the current points (rigid form). */
  constraintResidual(): number {
    return this.live().constraintResidual();
  }

  /** A copy of the document with the current points (or `points`, e.g. a baseline) in its splines. */
  posedDocument(points: Float64Array = this.points()): SvgDocument {
    if (points.length !== 2 * this.pointCount) {
      throw new SplinekitError('invalid-input', `skin: expected ${2 * this.pointCount} coordinates, got ${points.length}`);
    }
    const out = this.doc.clone();
    let at = 0;
    for (const s of out.splines) {
      s.points.set(points.subarray(at, at + s.points.length));
      at += s.points.length;
    }
    return out;
  }

  /** The posed drawing as SVG markup (only shapes that moved are rewritten). */
  toSVG(points?: Float64Array): string {
    return this.posedDocument(points).toSVG();
  }

  /** Frees the rig's wasm memory; the rig cannot be used afterwards (a second call does nothing). */
  dispose(): void {
    this.handle?.delete();
    this.handle = undefined;
  }

  private writeTransforms(h: SkinRigHandle, transforms: ArrayLike<number> | readonly AffineMatrix[]): void {
    const n = this.handleCount;
    const nested = transforms.length === n && typeof (transforms as ArrayLike<unknown>)[0] !== 'number';
    if (!nested && transforms.length !== 6 * n) {
      throw new SplinekitError('invalid-input', `skin: expected ${n} transforms (6 numbers each), got ${transforms.length} values`);
    }
    const value = nested
      ? (k: number) => (transforms as readonly AffineMatrix[])[Math.floor(k / 6)][k % 6]
      : (k: number) => (transforms as ArrayLike<number>)[k];
    // Check everything before writing, so a bad pose leaves the rig as it was.
    for (let k = 0; k < 6 * n; k++) {
      if (!Number.isFinite(value(k))) throw new SplinekitError('invalid-input', `skin: transform ${Math.floor(k / 6)} has a non-finite entry`);
    }
    const t = h.transforms();
    for (let k = 0; k < 6 * n; k++) t[k] = value(k);
  }
}
