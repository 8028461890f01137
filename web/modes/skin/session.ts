import { IDENTITY_MATRIX, poseAt, type AffineMatrix, type SkinError, type SvgDocument, affine } from '../../../src/index.js';
import { KeyedSession, type KeyedSessionEvents } from './keyed-session.js';
import type { InFlight } from '../../app/in-flight.js';
import { buildRig, type BuiltRig } from './rig-build.js';
import { rigKey, setPose, type SkinSpec, type WeightKind } from './spec.js';
import { CancelledError, type WeightsClient } from './weights-client.js';
import { messageOf } from '../../app/errors.js';

/** Where the rig stands: none (no handles), building, ready, or the last build failed. */
export interface RigStatus {
  phase: 'none' | 'building' | 'ready' | 'error';
  /** Weights of the rig being built (building) or in use. */
  kind: WeightKind;
  /** Progress of a build: its stage and 0…1. */
  stage: string | null;
  fraction: number;
  /** Why the last build failed. */
  message: string | null;
  /** Curves and build time of the rig in use. */
  curves: number;
  ms: number | null;
  /** The rig in use was built for other handles or weights (a newer one is coming or failed). */
  stale: boolean;
}

export interface SessionEvents extends KeyedSessionEvents<SkinSpec>, Record<string, unknown> {
  rig: RigStatus;
  /** New posed points (after a pose, a relax, or a new rig). */
  posed: { live: boolean };
}

/** The continuity kinds of every junction, as a string to compare. */
function continuitySignature(doc: SvgDocument): string {
  return doc.splines.map((s) => s.continuity.map((t) => t.kind).join(',')).join(';');
}

/** Fit and naive errors for the current pose. */
export interface PoseErrors {
  fit: SkinError;
  naive: SkinError;
}

/**
 * The skinning work on one document: the spec (handles, pose, keyframes, options), the playhead,
 * the selected handle, and the rig built from the spec. Changing handles or weights rebuilds the
 * rig (Shepard at once, harmonic/BBW in the worker) while the previous rig keeps posing; every
 * pose change poses the rig and, unless a gesture is live, relaxes it when the spec is flexible.
 */
export class SkinSession extends KeyedSession<SkinSpec, SessionEvents> {
  private built: BuiltRig | null = null;
  private buildingKey: string | null = null;
  private failedKey: string | null = null;
  private generation = 0;
  private suspended = false;
  private _points: Float64Array | null = null;
  private _status: RigStatus;
  /** Bumped on every pose: derived data (errors, baselines) caches against it. */
  private poseVersion = 0;
  private cache: { version: number; naive?: Float64Array; errors?: PoseErrors } = { version: -1 };
  private lastErrors: PoseErrors | null = null;
  private weightCache: { built: BuiltRig; rest: Float64Array; weights: Float64Array } | null = null;
  private continuity: string;

  constructor(
    readonly doc: SvgDocument,
    private readonly client: WeightsClient,
    /** Where the rig builds under way are counted (the mode's in-flight tracker). */
    private readonly work: InFlight,
    spec: SkinSpec,
  ) {
    super(spec);
    this.continuity = continuitySignature(doc);
    this._status = { phase: 'none', kind: spec.weights, stage: null, fraction: 0, message: null, curves: 0, ms: null, stale: false };
  }

  get status(): RigStatus {
    return this._status;
  }
  /** The rig in use (possibly stale), or null. */
  get rig(): BuiltRig | null {
    return this.built;
  }
  /** Posed control points of all splines (a copy), or null when there is no rig. */
  get points(): Float64Array | null {
    return this._points;
  }
  /** Whether the rig in use matches the spec's handles and weights. */
  get ready(): boolean {
    return this._spec.handles.length === 0 ? this.built === null : this.built?.key === this.key() && this._points !== null;
  }

  protected posedAt(time: number): SkinSpec {
    return setPose(this._spec, poseAt(this._spec.keyframes, time));
  }

  /** Poses again without a gesture (relaxes when flexible): after a live sequence ends. */
  settle(): void {
    this.repose(false);
  }

  /**
   * Checks the document's continuity tags (overridden in Document mode, or by an undo): the rig
   * keeps them, so new tags mean a new rig.
   */
  refreshContinuity(): void {
    const tags = continuitySignature(this.doc);
    if (tags === this.continuity) return;
    this.continuity = tags;
    this.failedKey = null;
    this.ensureRig();
  }

  /** Releases the rig (the document is not shown); resume() builds it again. */
  suspend(): void {
    this.suspended = true;
    this.cancelBuild();
    this.built?.rig.dispose();
    this.built = null;
    this.weightCache = null;
    this._points = null;
  }

  resume(): void {
    if (!this.suspended) return;
    this.suspended = false;
    this.failedKey = null;
    this.ensureRig();
    this.repose(false);
  }

  dispose(): void {
    this.suspend();
  }

  // ---- derived data for the view ---------------------------------------------------------------

  /** The naive baseline's control points for the current pose (a copy, cached per pose). */
  naivePoints(): Float64Array | null {
    const rig = this.built?.rig;
    if (!rig || !this._points) return null;
    const c = this.currentCache();
    return (c.naive ??= rig.baseline('naive').slice());
  }

  /** Fit and naive errors for the current pose (cached per pose). */
  errors(): PoseErrors | null {
    const rig = this.built?.rig;
    if (!rig || !this._points) return null;
    const c = this.currentCache();
    if (!c.errors) {
      c.naive ??= rig.baseline('naive').slice(); // error('naive') reuses the baseline buffer
      c.errors = { fit: rig.error('fit'), naive: rig.error('naive') };
    }
    return (this.lastErrors = c.errors);
  }

  /**
   * The errors of the current pose when they are known, else those of the last pose they were
   * computed for (a drag shows those until it ends: measuring a pose costs more than posing).
   */
  errorsSoFar(): PoseErrors | null {
    if (!this.built?.rig || !this._points) return null;
    return this.currentCache().errors ?? this.lastErrors;
  }

  /**
   * The target deformation Σ_i w_i T_i p at the curve samples of the current pose, as a function
   * that writes sample k's x, y at out[o], out[o + 1] (samples are `SAMPLES` per curve in curve
   * order); evaluated only where it is asked for, as the layers draw a subset. Null without a pose.
   */
  targetField(): ((k: number, out: Float32Array, o: number) => void) | null {
    const built = this.built;
    if (!built || !this._points) return null;
    const { rest, weights } = this.weightsOf(built);
    const n = built.ids.length, T = Float64Array.from(this.transformsFor(built).flat());
    return (k, out, o) => {
      const x = rest[2 * k], y = rest[2 * k + 1];
      let tx = 0, ty = 0;
      for (let i = 0; i < n; i++) {
        const w = weights[k * n + i];
        if (w === 0) continue;
        const m = 6 * i;
        tx += w * (T[m] * x + T[m + 2] * y + T[m + 4]);
        ty += w * (T[m + 1] * x + T[m + 3] * y + T[m + 5]);
      }
      out[o] = tx;
      out[o + 1] = ty;
    };
  }

  /** Rest positions of the curve samples of the rig in use (x,y pairs). */
  restSamples(): Float64Array | null {
    return this.built ? this.weightsOf(this.built).rest : null;
  }

  /** Weights of handle `id` at every curve sample, or null when the rig in use has no such handle. */
  handleWeights(id: number): Float64Array | null {
    const built = this.built;
    const i = built ? built.ids.indexOf(id) : -1;
    if (!built || i < 0) return null;
    const { weights } = this.weightsOf(built);
    const n = built.ids.length, out = new Float64Array(weights.length / n);
    for (let k = 0; k < out.length; k++) out[k] = weights[k * n + i];
    return out;
  }

  // ---- internals -------------------------------------------------------------------------------

  /** What the rig is built from: handles, weights and the continuity tags. */
  private key(): string {
    return `${rigKey(this._spec)}#${this.continuity}`;
  }

  private currentCache() {
    if (this.cache.version !== this.poseVersion) this.cache = { version: this.poseVersion };
    return this.cache;
  }

  /** All handles' weights at the samples (#samples × #handles), read once per rig. */
  private weightsOf(built: BuiltRig): { rest: Float64Array; weights: Float64Array } {
    if (this.weightCache?.built === built) return this.weightCache;
    const rig = built.rig, n = built.ids.length;
    const rest = rig.samplePositions();
    const weights = new Float64Array((rest.length / 2) * n);
    for (let i = 0; i < n; i++) {
      const w = rig.handleWeights(i);
      for (let k = 0; k < w.length; k++) weights[k * n + i] = w[k];
    }
    this.weightCache = { built, rest, weights };
    return this.weightCache;
  }

  /** The spec's pose for the handles of `built` (by id: handles added since get the identity). */
  private transformsFor(built: BuiltRig): AffineMatrix[] {
    return built.ids.map((id) => {
      const i = this.indexOf(id);
      return i < 0 ? IDENTITY_MATRIX : this._spec.pose[i];
    });
  }

  protected repose(live: boolean): void {
    const built = this.built;
    this.poseVersion++;
    if (!built) {
      this._points = null;
      this.events.emit('posed', { live });
      return;
    }
    const T = this.transformsFor(built);
    try {
      built.rig.pose(T);
      if (this._spec.flexible && !live && !T.every((m) => affine.isIdentity(m))) built.rig.relax();
      this._points = built.rig.points().slice();
    } catch (err) {
      this.setStatus({ phase: 'error', message: `Posing failed: ${messageOf(err)}` });
    }
    this.events.emit('posed', { live });
  }

  private setStatus(patch: Partial<RigStatus>): void {
    this._status = { ...this._status, ...patch };
    this.events.emit('rig', this._status);
  }

  private cancelBuild(): void {
    this.generation++;
    this.buildingKey = null;
    this.client.cancel();
  }

  protected ensureRig(): void {
    if (this.suspended) return;
    const spec = this._spec, key = this.key();
    if (spec.handles.length === 0) {
      this.cancelBuild();
      this.built?.rig.dispose();
      this.built = null;
      this.weightCache = null;
      this.failedKey = null;
      this.setStatus({ phase: 'none', kind: spec.weights, stage: null, fraction: 0, message: null, curves: 0, ms: null, stale: false });
      return;
    }
    if (this.built?.key === key) {
      if (this.buildingKey !== null) this.cancelBuild();
      if (this._status.phase !== 'ready' || this._status.stale) {
        this.setStatus({ phase: 'ready', kind: spec.weights, stage: null, message: null, curves: this.built.rig.curveCount, ms: this.built.ms, stale: false });
      }
      return;
    }
    if (this.buildingKey === key || this.failedKey === key) return;
    this.cancelBuild();
    const generation = this.generation;
    this.buildingKey = key;
    this.failedKey = null;
    this.setStatus({ phase: 'building', kind: spec.weights, stage: 'Starting', fraction: 0, message: null, stale: this.built !== null });
    const wanted = () => generation === this.generation && !this.suspended;
    this.work.track(buildRig(this.doc, spec, key, this.client, (stage, fraction) => wanted() && this.setStatus({ stage, fraction }), wanted)).then(
      (built) => {
        if (!wanted()) {
          built.rig.dispose();
          return;
        }
        this.buildingKey = null;
        this.built?.rig.dispose();
        this.built = built;
        this.weightCache = null;
        this.setStatus({ phase: 'ready', kind: built.kind, stage: null, fraction: 1, message: null, curves: built.rig.curveCount, ms: built.ms, stale: false });
        this.repose(false);
      },
      (err: unknown) => {
        if (err instanceof CancelledError || !wanted()) return;
        this.buildingKey = null;
        this.failedKey = key;
        const message = messageOf(err);
        this.setStatus({ phase: 'error', stage: null, message: `The rig could not be built: ${message}`, stale: this.built !== null });
      },
    );
  }
}
