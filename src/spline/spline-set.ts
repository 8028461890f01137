import { core } from '../core/module.js';
import { checkStatus } from '../core/errors.js';
import type { SplineSetHandle } from '../core/splinekit-core.mjs';
import { splineSetHandles } from './spline-set-handle.js';
import { CONTINUITY_KINDS, type ContinuityTag, type Spline } from './spline.js';

/** Tolerances for continuity detection (see wasm/core/common/continuity.h). */
export interface ContinuityOptions {
  /** Handle length below which a handle counts as degenerate, as a fraction of the drawing's size. Default 1e-6. */
  relativeTolerance?: number;
  /**
   * |sin| of the angle between in and out tangents that still counts as smooth (G1). Default 1e-2
   * (≈0.57°): smooth nodes in real files are off by up to ~1e-3 after coordinate rounding.
   */
  angleTolerance?: number;
  /** |ratio − 1| of tangent lengths that still counts as C1 rather than G1. Default 1e-3. */
  ratioTolerance?: number;
}

/** The tolerances `parseSVG` and {@link SplineSet.classify} use where options leave one out. */
export const DEFAULT_CONTINUITY: Required<ContinuityOptions> = {
  relativeTolerance: 1e-6,
  angleTolerance: 1e-2,
  ratioTolerance: 1e-3,
};

/**
 * A batch of splines copied into wasm memory for queries that run over all of them at once
 * (bounds, continuity, sampling, arc lengths). Create, query, dispose.
 */
export class SplineSet {
  /** Number of splines in the set. */
  readonly splineCount: number;

  private constructor(handle: SplineSetHandle, splineCount: number) {
    splineSetHandles.attach(this, handle);
    this.splineCount = splineCount;
  }

  /** Copies `splines` into wasm memory. Throws SplinekitError('invalid-input') if any is malformed. */
  static from(splines: readonly Pick<Spline, 'closed' | 'points'>[]): SplineSet {
    const handle = new (core().SplineSetHandle)();
    let total = 0;
    for (const s of splines) total += s.points.length / 2;
    handle.resize(splines.length, total);
    const points = handle.points(), starts = handle.starts(), counts = handle.counts(), closed = handle.closed();
    let at = 0;
    splines.forEach((s, i) => {
      starts[i] = at;
      counts[i] = s.points.length / 2;
      closed[i] = s.closed ? 1 : 0;
      points.set(s.points, 2 * at);
      at += s.points.length / 2;
    });
    const status = handle.validate();
    if (status !== 0) {
      const message = handle.error();
      handle.delete();
      checkStatus(status, 'invalid splines', () => message);
    }
    return new SplineSet(handle, splines.length);
  }

  private live(): SplineSetHandle {
    return splineSetHandles.get(this);
  }

  /** Number of cubic segments over all splines of the set. */
  get segmentCount(): number {
    return this.live().segmentCount();
  }

  /** Per-spline bounds of the curves (not their hulls): xmin, ymin, xmax, ymax per spline. */
  bounds(): Float64Array {
    const h = this.live();
    checkStatus(h.bounds(), 'bounds', () => h.error());
    return h.resultF64().slice();
  }

  /** Bounds of all splines together, or null when there are none. */
  totalBounds(): [number, number, number, number] | null {
    const b = this.bounds();
    if (b.length === 0) return null;
    const out: [number, number, number, number] = [Infinity, Infinity, -Infinity, -Infinity];
    for (let i = 0; i < b.length; i += 4) {
      out[0] = Math.min(out[0], b[i]);
      out[1] = Math.min(out[1], b[i + 1]);
      out[2] = Math.max(out[2], b[i + 2]);
      out[3] = Math.max(out[3], b[i + 3]);
    }
    return out;
  }

  /**
   * Continuity tags of every junction, per spline. `size` is the drawing's size (bounding-box
   * diagonal) that the relative tolerance scales.
   */
  classify(size: number, options: ContinuityOptions = {}): ContinuityTag[][] {
    const o = { ...DEFAULT_CONTINUITY, ...options };
    const h = this.live();
    const scale = Number.isFinite(size) && size > 0 ? size : 1;
    checkStatus(h.classify(o.relativeTolerance * scale, o.angleTolerance, o.ratioTolerance), 'continuity', () => h.error());
    const kinds = h.resultI32(), values = h.resultF64();
    const counts = h.counts(), closed = h.closed();
    const out: ContinuityTag[][] = [];
    let j = 0;
    for (let s = 0; s < this.splineCount; s++) {
      const n = counts[s] <= 1 ? 0 : closed[s] ? counts[s] / 3 : (counts[s] - 1) / 3;
      const m = n === 0 ? 0 : closed[s] ? n : n - 1;
      const tags: ContinuityTag[] = new Array(m);
      for (let k = 0; k < m; k++, j++) tags[k] = { kind: CONTINUITY_KINDS[kinds[j]], ratio: values[2 * j], angle: values[2 * j + 1] };
      out.push(tags);
    }
    return out;
  }

  /** `perSegment` points on every segment (t = k/(perSegment−1)), segment after segment: x,y pairs. */
  sample(perSegment: number): Float64Array {
    const h = this.live();
    checkStatus(h.sample(perSegment), 'sample', () => h.error());
    return h.resultF64().slice();
  }

  /** Arc length of every segment, to an absolute tolerance. */
  segmentLengths(tolerance = 1e-9): Float64Array {
    const h = this.live();
    checkStatus(h.segmentLengths(tolerance), 'segment lengths', () => h.error());
    return h.resultF64().slice();
  }

  /** Frees the set's wasm memory; the set cannot be used afterwards (a second call does nothing). */
  dispose(): void {
    splineSetHandles.release(this);
  }
}
