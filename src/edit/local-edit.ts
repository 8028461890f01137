/**
 * One localized drag of a Catmull-Rom control point (Eyiyurekli & Breen §3.1, §3.3, §3.4): the
 * dragged point's displacement spreads over an active window of control points around it, with a
 * drop-off from 1 at the dragged point to 0 at the window's ends (linear, Gaussian or cos^α of the
 * arc-length distance), optionally turning towards the curve normals at the window's ends.
 *
 *   const edit = LocalEdit.begin(curve, 12, { left: 6, right: 9, falloff: 'cosine', alpha: 1 });
 *   edit.move(dx, dy);  // per pointer move: allocation-free, returns every control point
 *   edit.end();         // the curve takes the result
 */
import { SplinekitError, checkStatus } from '../core/errors.js';
import { HandleLinks } from '../core/handles.js';
import { core } from '../core/module.js';
import type { LocalEditHandle } from '../core/splinekit-core.mjs';
import type { CatmullRom } from './catmull-rom.js';
import { curveHandles } from './curve-handle.js';

/** The drop-off S(u), u = d / W: 'linear' 1 − u, 'gaussian' exp(−u²/2σ²)·f(u), 'cosine' cos(πu/2)^α. */
export type Falloff = 'linear' | 'gaussian' | 'cosine';

/** Every {@link Falloff}, in the order of the core's enum. */
export const FALLOFFS: readonly Falloff[] = ['linear', 'gaussian', 'cosine'];

/** Defaults of {@link LocalEditOptions}: a window of 5 on each side (the paper's examples), cosine with α = 1. */
export const DEFAULT_EDIT_OPTIONS: Readonly<Required<LocalEditOptions>> = Object.freeze({
  left: 5,
  right: 5,
  falloff: 'cosine' as Falloff,
  alpha: 1,
  sigma: 1 / 3,
  normals: false,
});

/** Options of {@link LocalEdit.begin}. */
export interface LocalEditOptions {
  /** mL: control points on the left of the dragged one (clamped at an open curve's start). Default 5. */
  left?: number;
  /** nR: control points on the right (clamped at an open curve's end). Default 5. */
  right?: number;
  /** The drop-off. Default 'cosine' (the paper's preferred, §3.3). */
  falloff?: Falloff;
  /** Exponent α of the cosine drop-off (> 0; < 1 squares the bump off, > 1 sharpens it). Default 1. */
  alpha?: number;
  /** Width σ of the Gaussian drop-off as a fraction of the side's extent (> 0). Default 1/3. */
  sigma?: number;
  /** §3.4: turn each point's direction from the drag towards the normal at its side's window end. Default false. */
  normals?: boolean;
}

/** The active window of a drag, as resolved (clamped or wrapped). */
export interface ActiveWindowInfo {
  /** The dragged control point. */
  center: number;
  /** Control points on the left after clamping. */
  left: number;
  /** Control points on the right after clamping. */
  right: number;
  /** Index of the left end (stays put). */
  first: number;
  /** Index of the right end (stays put). */
  last: number;
  /** The control point indices of the window, left end to right end. */
  indices: Int32Array;
  /** The drop-off weight of each window point (1 at the center, 0 at both ends). */
  weights: Float64Array;
}

const editHandles = new HandleLinks<LocalEditHandle>(() => new SplinekitError('invalid-input', 'LocalEdit used after end() or dispose()'));

function positive(v: number, what: string): number {
  if (!(typeof v === 'number' && Number.isFinite(v) && v > 0)) throw new SplinekitError('invalid-input', `${what} must be a positive number, got ${String(v)}`);
  return v;
}

function side(v: number, what: string): number {
  if (!Number.isInteger(v) || v < 0) throw new SplinekitError('invalid-input', `the window's ${what} side must be an integer >= 0, got ${String(v)}`);
  return v;
}

/**
 * A drag in progress. Weights are fixed when it begins, so the curve for a displacement does not
 * depend on the path the pointer took. Holds wasm memory until `end()`, `cancel()` or `dispose()`.
 */
export class LocalEdit {
  /** The curve being edited. */
  readonly curve: CatmullRom;
  /** The resolved window with its weights. */
  readonly window: ActiveWindowInfo;
  /** The options in effect (defaults filled in). */
  readonly options: Readonly<Required<LocalEditOptions>>;

  private constructor(curve: CatmullRom, handle: LocalEditHandle, center: number, options: Required<LocalEditOptions>) {
    editHandles.attach(this, handle);
    this.curve = curve;
    this.options = options;
    const indices = handle.indices().slice();
    this.window = {
      center,
      left: handle.left(),
      right: handle.right(),
      first: indices[0],
      last: indices[indices.length - 1],
      indices,
      weights: handle.weights().slice(),
    };
  }

  /** Begins dragging control point `index` of `curve`. Bad input (index out of range, negative side, α ≤ 0) throws a SplinekitError. */
  static begin(curve: CatmullRom, index: number, options: LocalEditOptions = {}): LocalEdit {
    const o: Required<LocalEditOptions> = { ...DEFAULT_EDIT_OPTIONS, ...Object.fromEntries(Object.entries(options).filter(([, v]) => v !== undefined)) };
    const falloff = FALLOFFS.indexOf(o.falloff);
    if (falloff < 0) throw new SplinekitError('invalid-input', `falloff must be linear, gaussian or cosine, got "${String(o.falloff)}"`);
    if (!Number.isInteger(index)) throw new SplinekitError('invalid-input', `the dragged control point must be an integer index, got ${String(index)}`);
    const h = new (core().LocalEditHandle)();
    try {
      const status = h.begin(curveHandles.get(curve), index, side(o.left, 'left'), side(o.right, 'right'), falloff, positive(o.alpha, 'alpha'), positive(o.sigma, 'sigma'), !!o.normals);
      checkStatus(status, 'edit', () => h.error());
    } catch (err) {
      h.delete();
      throw err;
    }
    return new LocalEdit(curve, h, index, o);
  }

  /**
   * Places the window for a displacement (dx, dy) of the dragged point from where it was at
   * begin. Returns every control point (x,y pairs) as a view into wasm memory: read or copy it
   * before the next call into the package. No allocation.
   */
  move(dx: number, dy: number): Float64Array {
    if (!(Math.abs(dx) <= 1e150 && Math.abs(dy) <= 1e150)) throw new SplinekitError('invalid-input', `a displacement needs finite numbers within ±1e150, got (${dx}, ${dy})`);
    const h = editHandles.get(this);
    h.move(dx, dy);
    return h.points();
  }

  /**
   * The curve takes the last `move`'s points now (for drawing it mid-drag); the drag goes on from
   * the positions at begin, so later moves are unaffected. Tangent overrides are kept.
   */
  apply(): void {
    const h = editHandles.get(this);
    const c = curveHandles.get(this.curve);
    checkStatus(c.applyEdit(h), 'edit', () => c.error());
  }

  /** Ends the drag: the curve takes the last `move`'s points, and the edit's wasm memory is freed. */
  end(): void {
    this.apply();
    editHandles.release(this);
  }

  /** Ends the drag with the curve as it was at begin (undoing any `apply`). */
  cancel(): void {
    const h = editHandles.get(this);
    h.move(0, 0);
    this.apply();
    editHandles.release(this);
  }

  /** Same as `cancel()`; safe to call after `end()`. */
  dispose(): void {
    editHandles.release(this);
  }
}
