import type { MeshPoint, SurfaceSplineJSON, TraceOptions } from '../../../src/index.js';
import type { InFlight } from '../../app/in-flight.js';
import { WorkerClient, type RequestBody } from '../../app/worker-client.js';
import type { SplineOp, SurfaceReply, SurfaceRequest } from './protocol.js';

/** A request another one replaced before it was sent (latest wins). */
export class SupersededError extends Error {
  constructor() {
    super('superseded');
    this.name = 'SupersededError';
  }
}

export type Loaded = Extract<SurfaceReply, { type: 'loaded' }>;
export type Shown = Extract<SurfaceReply, { type: 'progress'; stage: 'shown' }>;
export type Picking = Extract<SurfaceReply, { type: 'progress'; stage: 'picking' }>;
export type Ran = Extract<SurfaceReply, { type: 'ran' }>;
export type Mapped = Extract<SurfaceReply, { type: 'mapped' }>;
export type PathReply = Extract<SurfaceReply, { type: 'path' }>;

type Body = RequestBody<SurfaceRequest>;

interface Queued {
  body: Body;
  resolve(reply: SurfaceReply): void;
  reject(err: Error): void;
}

interface Lane {
  /** Whether a request of this lane is in flight. */
  sent: boolean;
  /** The newest request waiting for that one to be answered. */
  queued: Queued | null;
}

/**
 * The editor's side of the surface worker. Requests are answered in order. Requests in a named
 * lane (one per spline, one for the rubber band) are coalesced: at most one in flight, and a new
 * one replaces the one waiting to be sent (whose promise rejects with SupersededError) — so a
 * drag sends the newest position and drops the stale ones. Every request counts in `work` until
 * it settles.
 */
export class SurfaceClient {
  private readonly worker = new WorkerClient<SurfaceRequest, SurfaceReply>(
    () => new Worker(new URL('./surface.worker.ts', import.meta.url), { type: 'module', name: 'splinekit-surface' }),
    'surface',
  );
  private readonly lanes = new Map<string, Lane>();

  /** @param work where the requests under way are counted (the mode's in-flight tracker). */
  constructor(private readonly work: InFlight) {}

  /**
   * Loads a mesh (the previous one stays if this fails): `shown` gets the mesh to draw as soon as it
   * is built, `picking` its picking hierarchy when that came later (large meshes), and the promise
   * settles once its search structures are built too.
   */
  load(bytes: Uint8Array, name: string, shown: (reply: Shown) => void, picking: (reply: Picking) => void): Promise<Loaded> {
    const copy = bytes.slice().buffer; // the caller keeps its bytes (undo reloads them)
    const progress = (reply: SurfaceReply) => {
      if (reply.type !== 'progress') return;
      if (reply.stage === 'shown') shown(reply);
      else picking(reply);
    };
    return this.work.track(this.worker.request({ type: 'load', bytes: copy, name }, [copy], progress)) as Promise<Loaded>;
  }

  /** Runs edits on a spline and traces the result; coalesced per `lane` when given. */
  run(json: SurfaceSplineJSON | null, ops: SplineOp[], trace: TraceOptions | null, polygon: boolean, lane?: string): Promise<Ran> {
    const body: Body = { type: 'run', json, ops, trace, polygon };
    return (lane ? this.coalesced(lane, body) : this.send(body)) as Promise<Ran>;
  }

  /** The shortest path between two mesh points (lifted for drawing). */
  path(a: MeshPoint, b: MeshPoint, lane?: string): Promise<PathReply> {
    const body: Body = { type: 'path', a, b };
    return (lane ? this.coalesced(lane, body) : this.send(body)) as Promise<PathReply>;
  }

  /** Maps an SVG drawing onto the mesh around `center` (b/Surf's SVG placement). */
  map(svg: string, name: string, center: MeshPoint, size: number, rotation: number, up: [number, number, number]): Promise<Mapped> {
    return this.send({ type: 'map', svg, name, center, size, rotation, up }) as Promise<Mapped>;
  }

  /** Stops the worker; every request waiting (sent or queued in a lane) rejects. */
  dispose(): void {
    const stopped = new Error('the surface worker was stopped');
    for (const lane of this.lanes.values()) {
      lane.queued?.reject(stopped);
      lane.queued = null; // not sent when the request in flight settles
    }
    this.lanes.clear();
    this.worker.terminate(stopped);
  }

  private coalesced(name: string, body: Body): Promise<SurfaceReply> {
    let lane = this.lanes.get(name);
    if (!lane) this.lanes.set(name, (lane = { sent: false, queued: null }));
    if (!lane.sent) return this.sendInLane(name, lane, body);
    const l = lane;
    return this.work.track(
      new Promise<SurfaceReply>((resolve, reject) => {
        l.queued?.reject(new SupersededError());
        l.queued = { body, resolve, reject };
      }),
    );
  }

  private sendInLane(name: string, lane: Lane, body: Body): Promise<SurfaceReply> {
    const promise = this.send(body);
    lane.sent = true;
    const next = () => {
      lane.sent = false;
      const q = lane.queued;
      lane.queued = null;
      if (q) this.sendInLane(name, lane, q.body).then(q.resolve, q.reject);
      else if (this.lanes.get(name) === lane) this.lanes.delete(name);
    };
    promise.then(next, next);
    return promise;
  }

  private send(body: Body, transfer: Transferable[] = []): Promise<SurfaceReply> {
    return this.work.track(this.worker.request(body, transfer));
  }
}
