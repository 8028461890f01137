import { SubdivisionRig, type Cage } from '../../../src/index.js';
import { messageOf } from '../../app/errors.js';
import { KeyedSession, type KeyedSessionEvents } from '../skin/keyed-session.js';
import type { InFlight } from '../../app/in-flight.js';
import { isRest, poseAt3D, poseTransforms, rigKey3D, setPose3D, type Skin3DSpec } from './spec.js';
import { CancelledError, type Weights3DClient } from './weights-client.js';

/** Where the rig stands: building (weights in the worker), ready, or the last build failed. */
export interface Rig3DStatus {
  phase: 'building' | 'ready' | 'error';
  /** Progress of a weights solve, 0…1. */
  fraction: number;
  /** Why the last build failed. */
  message: string | null;
  /** Time of the last build (weights and precompute), ms. */
  ms: number | null;
  /** The rig in use was built for other handles, weights or levels (a newer one is coming or failed). */
  stale: boolean;
}

export interface Session3DEvents extends KeyedSessionEvents<Skin3DSpec>, Record<string, unknown> {
  rig: Rig3DStatus;
  /** New posed cage and surface. */
  posed: { live: boolean };
}

/** The target, naive and error data of one pose, for the overlays. */
export interface PoseOverlays {
  /** LBS of the refined rest surface (the paper's target), 3 per refined vertex. */
  target: Float64Array;
  /** The naive cage's subdivided surface, 3 per refined vertex. */
  naive: Float64Array;
  /** Distance to the target per refined vertex, for the fit and the naive cage. */
  fitError: Float64Array;
  naiveError: Float64Array;
  /** RMS distance to the target over the bounding-box diagonal. */
  fitRms: number;
  naiveRms: number;
}

/** A rig and the spec key it was built for (with no handles: the display rig of the levels). */
interface BuiltRig {
  rig: SubdivisionRig;
  key: string;
}

/**
 * The skinning work on one cage: the spec (handles, pose, keyframes, options), the playhead, the
 * selected handle, and the SubdivisionRig built from the spec. Changing handles, weights or levels
 * rebuilds the rig (Shepard at once, BBW in the worker) while the previous rig keeps posing when
 * it can; every pose change poses the rig and refreshes the posed cage and surface.
 */
export class Skin3DSession extends KeyedSession<Skin3DSpec, Session3DEvents> {
  private built: BuiltRig | null = null;
  private buildingKey: string | null = null;
  private failedKey: string | null = null;
  private generation = 0;
  private _status: Rig3DStatus = { phase: 'ready', fraction: 0, message: null, ms: null, stale: false };
  private _cage: Float64Array;
  private _surface: Float64Array = new Float64Array(0);
  private poseVersion = 0;
  private _progressReports = 0;
  private _poseMs: number | null = null;
  private transformBuffer = new Float64Array(0);
  private overlayCache: { version: number; data: PoseOverlays } | null = null;

  constructor(
    readonly cage: Cage,
    readonly file: string,
    /** The OBJ text the cage was read from (autosaved with the spec). */
    readonly source: string,
    private readonly client: Weights3DClient,
    /** Where rig builds under way are counted (the mode's in-flight tracker). */
    private readonly work: InFlight,
    spec: Skin3DSpec,
  ) {
    super(spec);
    this._cage = cage.positions.slice();
    this.ensureRig();
    this.repose(false);
  }

  get status(): Rig3DStatus {
    return this._status;
  }
  /** The rig in use (possibly stale, or the display rig with no handles), or null. */
  get rig(): SubdivisionRig | null {
    return this.built?.rig ?? null;
  }
  /** Posed cage positions (3 per cage vertex). */
  get posedCage(): Float64Array {
    return this._cage;
  }
  /** Posed refined surface (3 per refined vertex; empty until a rig exists). */
  get surface(): Float64Array {
    return this._surface;
  }
  /** Time of the last pose (fit the cage, subdivide), ms; null at rest. */
  get poseMs(): number | null {
    return this._poseMs;
  }
  /** Progress messages received from the weights worker so far. */
  get progressReports(): number {
    return this._progressReports;
  }
  /** Whether the rig in use matches the spec (handles, weights, levels). */
  get ready(): boolean {
    return this.built !== null && this.built.key === this.key();
  }

  protected posedAt(time: number): Skin3DSpec {
    return setPose3D(this._spec, poseAt3D(this._spec.keyframes, time));
  }

  /**
   * The refined surface (3 per refined vertex) for a pose of the current handles, with the rig in
   * use; the current pose is posed again afterwards. Null when no rig for these handles exists.
   */
  surfaceFor(pose: Skin3DSpec['pose']): Float64Array | null {
    const rig = this.poseRig();
    if (!rig) return null;
    const out = isRest(pose) ? rig.restRefined.slice() : (rig.pose(poseTransforms(this._spec.handles, pose), 'fit'), rig.refined().slice());
    this.repose(false);
    return out;
  }

  /** Target, naive and error data of the current pose (cached until the next pose), or null. */
  overlays(): PoseOverlays | null {
    const rig = this.poseRig();
    if (!rig) return null;
    if (this.overlayCache?.version === this.poseVersion) return this.overlayCache.data;
    const transforms = poseTransforms(this._spec.handles, this._spec.pose);
    const naiveCage = rig.pose(transforms, 'naive').slice();
    const naive = rig.refined(naiveCage).slice();
    const naiveErr = rig.error('naive');
    const naiveError = naiveErr.perVertex.slice(), naiveRms = naiveErr.rms;
    rig.pose(transforms, 'fit');
    const target = rig.target().slice();
    const fitErr = rig.error('fit');
    const data: PoseOverlays = { target, naive, fitError: fitErr.perVertex.slice(), naiveError, fitRms: fitErr.rms, naiveRms };
    this.overlayCache = { version: this.poseVersion, data };
    return data;
  }

  /** Releases the rig (the session is not shown: an undone open); resume() builds it again. */
  suspend(): void {
    this.cancelBuild();
    this.built?.rig.dispose();
    this.built = null;
    this.failedKey = null;
    this.overlayCache = null;
  }

  resume(): void {
    if (this.built) return;
    this.ensureRig();
    this.repose(false);
  }

  dispose(): void {
    this.suspend();
  }

  // ---- the rig ---------------------------------------------------------------------------------

  private key(): string {
    return this._spec.handles.length === 0 ? `levels ${this._spec.levels}` : rigKey3D(this._spec);
  }

  /** The rig in use when it can pose the current handles (same handle count), else null. */
  private poseRig(): SubdivisionRig | null {
    const b = this.built;
    if (!b || this._spec.handles.length === 0 || b.rig.handleCount !== this._spec.handles.length) return null;
    return b.rig;
  }

  private handlePositions(): Float64Array {
    return Float64Array.from(this._spec.handles.flatMap((h) => [h.x, h.y, h.z]));
  }

  /** Starts a build when the rig in use does not match the spec (and none is under way for it). */
  protected ensureRig(): void {
    const key = this.key();
    if (this.built?.key === key) {
      this.cancelBuild();
      this.setStatus({ phase: 'ready', fraction: 1, message: null, stale: false });
      return;
    }
    if (key === this.buildingKey || key === this.failedKey) return;
    this.cancelBuild();
    const spec = this._spec;
    if (spec.handles.length === 0) {
      // No handles yet: a rig with one handle at the cage's centre only to show the refined
      // surface at rest (subdivision does not depend on handles).
      this.buildNow(key, () => SubdivisionRig.create(this.cage, { handles: centre(this.cage.positions), levels: spec.levels, weights: 'shepard' }));
    } else if (spec.weights === 'shepard') {
      this.buildNow(key, () => SubdivisionRig.create(this.cage, { handles: this.handlePositions(), levels: spec.levels, weights: 'shepard' }));
    } else {
      void this.buildInWorker(key, spec);
    }
  }

  private buildNow(key: string, make: () => SubdivisionRig): void {
    const t0 = performance.now();
    try {
      this.install({ rig: make(), key });
      this.setStatus({ phase: 'ready', fraction: 1, message: null, ms: performance.now() - t0, stale: false });
    } catch (err) {
      this.failedKey = key;
      this.setStatus({ phase: 'error', fraction: 0, message: messageOf(err), stale: this.built !== null });
    }
  }

  private async buildInWorker(key: string, spec: Skin3DSpec): Promise<void> {
    const generation = ++this.generation;
    this.buildingKey = key;
    this.setStatus({ phase: 'building', fraction: 0, message: null, stale: this.built !== null });
    const done = this.work.begin();
    const t0 = performance.now();
    try {
      const handles = this.handlePositions();
      const { weights } = await this.client.solve(this.cage, handles, spec.levels, 'bbw', (fraction) => {
        if (generation !== this.generation) return;
        this._progressReports++;
        this.setStatus({ ...this._status, fraction });
      });
      if (generation !== this.generation) return;
      this.buildingKey = null;
      this.install({ rig: SubdivisionRig.create(this.cage, { handles, levels: spec.levels, weights: { perRefinedVertex: weights } }), key });
      this.setStatus({ phase: 'ready', fraction: 1, message: null, ms: performance.now() - t0, stale: this.built?.key !== this.key() });
      this.repose(false);
    } catch (err) {
      if (err instanceof CancelledError || generation !== this.generation) return;
      this.buildingKey = null;
      this.failedKey = key;
      this.setStatus({ phase: 'error', fraction: 0, message: messageOf(err), stale: this.built !== null });
    } finally {
      done();
    }
  }

  /** A reused array for the transforms of `handles` handles (the update allocates nothing). */
  private transforms(handles: number): Float64Array {
    if (this.transformBuffer.length !== 12 * handles) this.transformBuffer = new Float64Array(12 * handles);
    return this.transformBuffer;
  }

  private install(next: BuiltRig): void {
    this.built?.rig.dispose();
    this.built = next;
    this.failedKey = null;
    if (this._surface.length !== next.rig.restRefined.length) this._surface = new Float64Array(next.rig.restRefined.length);
    this.repose(false);
  }

  private cancelBuild(): void {
    this.generation++;
    this.buildingKey = null;
    this.client.cancel();
  }

  private setStatus(change: Partial<Rig3DStatus>): void {
    this._status = { ...this._status, ...change };
    this.events.emit('rig', this._status);
  }

  /**
   * Poses the rig for the spec's pose into the posed cage and surface (the rest pose is the rest
   * cage and surface exactly). Without a rig for these handles the surface stays as it was.
   */
  protected repose(live: boolean): void {
    const b = this.built;
    if (!b) return;
    this.poseVersion++;
    const pose = this._spec.pose;
    const rig = this.poseRig();
    if (isRest(pose)) {
      this._cage.set(this.cage.positions);
      this._surface.set(b.rig.restRefined);
      this._poseMs = null;
    } else if (rig) {
      const t0 = performance.now();
      this._cage.set(rig.pose(poseTransforms(this._spec.handles, pose, this.transforms(pose.length)), 'fit'));
      this._surface.set(rig.refined());
      this._poseMs = performance.now() - t0;
    } else return;
    this.events.emit('posed', { live });
  }
}

/** The bounding box of points (3 numbers each): min x y z, max x y z. */
export function boundingBox(positions: Float64Array): { lo: number[]; hi: number[] } {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], positions[i]);
    hi[i % 3] = Math.max(hi[i % 3], positions[i]);
  }
  return { lo, hi };
}

/** The centre of a point set's bounding box (3 numbers). */
function centre(positions: Float64Array): Float64Array {
  const { lo, hi } = boundingBox(positions);
  return Float64Array.from([0, 1, 2].map((k) => (lo[k] + hi[k]) / 2));
}
