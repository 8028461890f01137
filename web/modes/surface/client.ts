import type { MeshPoint, SurfaceSplineJSON, TraceOptions } from '../../../src/index.js';
import type { SplineOp, SurfaceReply, SurfaceRequest } from './protocol.js';

/** A request another one replaced before it was sent (latest wins). */
export class SupersededError extends Error {
  constructor() {
    super('superseded');
    this.name = 'SupersededError';
  }
}

export type Loaded = Extract<SurfaceReply, { type: 'loaded' }>;
export type Ran = Extract<SurfaceReply, { type: 'ran' }>;
export type Mapped = Extract<SurfaceReply, { type: 'mapped' }>;
export type PathReply = Extract<SurfaceReply, { type: 'path' }>;

/** What the client sends (without the id it adds). */
type Body = SurfaceRequest extends infer R ? (R extends SurfaceRequest ? Omit<R, 'id'> : never) : never;

interface Pending {
  resolve(reply: SurfaceReply): void;
  reject(err: Error): void;
}

interface Lane {
  /** Id of the request in flight, or 0. */
  inFlight: number;
  queued: { body: Body; transfer: Transferable[]; pending: Pending } | null;
}

/**
 * The editor's side of the surface worker. Requests are answered in order. Requests in a named
 * lane (one per spline, one for the rubber band) are coalesced: at most one in flight, and a new
 * one replaces the one waiting to be sent (whose promise rejects with SupersededError) — so a
 * drag sends the newest position and drops the stale ones.
 */
export class SurfaceClient {
  private worker: Worker | null = null;
  private readonly pending = new Map<number, Pending>();
  private readonly lanes = new Map<string, Lane>();
  private nextId = 1;
  /** Requests sent and not answered yet. */
  private outstanding = 0;
  private idleWaiters: (() => void)[] = [];

  /** Loads a mesh (the previous one stays if this fails). */
  load(bytes: Uint8Array, name: string): Promise<Loaded> {
    const copy = bytes.slice().buffer; // the caller keeps its bytes (undo reloads them)
    return this.send({ type: 'load', bytes: copy, name }, [copy]) as Promise<Loaded>;
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

  map(svg: string, name: string, center: MeshPoint, size: number, rotation: number, up: [number, number, number]): Promise<Mapped> {
    return this.send({ type: 'map', svg, name, center, size, rotation, up }) as Promise<Mapped>;
  }

  /** Resolves when no request is outstanding. */
  idle(): Promise<void> {
    if (!this.busy) return Promise.resolve();
    return new Promise((resolve) => this.idleWaiters.push(resolve));
  }

  get busy(): boolean {
    if (this.outstanding > 0) return true;
    for (const lane of this.lanes.values()) if (lane.queued) return true;
    return false;
  }

  dispose(): void {
    this.worker?.terminate();
    this.worker = null;
    for (const p of this.pending.values()) p.reject(new Error('the surface worker was stopped'));
    this.pending.clear();
    this.lanes.clear();
    this.outstanding = 0;
    this.wakeIdle();
  }

  private coalesced(name: string, body: Body): Promise<SurfaceReply> {
    let lane = this.lanes.get(name);
    if (!lane) this.lanes.set(name, (lane = { inFlight: 0, queued: null }));
    if (lane.inFlight === 0) return this.sendInLane(name, lane, body, []);
    return new Promise((resolve, reject) => {
      lane.queued?.pending.reject(new SupersededError());
      lane.queued = { body, transfer: [], pending: { resolve, reject } };
    });
  }

  private sendInLane(name: string, lane: Lane, body: Body, transfer: Transferable[]): Promise<SurfaceReply> {
    const promise = this.send(body, transfer);
    lane.inFlight = this.nextId - 1;
    const next = () => {
      lane.inFlight = 0;
      const q = lane.queued;
      lane.queued = null;
      if (q) this.sendInLane(name, lane, q.body, q.transfer).then(q.pending.resolve, q.pending.reject);
      else this.lanes.delete(name);
    };
    promise.then(next, next);
    return promise;
  }

  private send(body: Body, transfer: Transferable[] = []): Promise<SurfaceReply> {
    const worker = (this.worker ??= this.spawn());
    const id = this.nextId++;
    this.outstanding++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      worker.postMessage({ ...body, id } as SurfaceRequest, transfer);
    });
  }

  private settle(id: number): Pending | undefined {
    const p = this.pending.get(id);
    if (!p) return undefined;
    this.pending.delete(id);
    this.outstanding = Math.max(0, this.outstanding - 1);
    // Resolve after the caller's handlers had a chance to queue follow-ups.
    setTimeout(() => {
      if (!this.busy) this.wakeIdle();
    }, 0);
    return p;
  }

  private wakeIdle(): void {
    const waiters = this.idleWaiters;
    this.idleWaiters = [];
    for (const w of waiters) w();
  }

  private spawn(): Worker {
    const worker = new Worker(new URL('./surface.worker.ts', import.meta.url), { type: 'module', name: 'splinekit-surface' });
    worker.addEventListener('message', (e: MessageEvent<SurfaceReply>) => {
      const reply = e.data;
      const p = this.settle(reply.id);
      if (!p) return;
      if (reply.type === 'error') p.reject(new Error(reply.message));
      else p.resolve(reply);
    });
    worker.addEventListener('error', (e) => {
      e.preventDefault();
      const message = `the surface worker failed: ${e.message || 'could not start'}`;
      this.worker?.terminate();
      this.worker = null;
      const pending = [...this.pending.values()];
      this.pending.clear();
      this.lanes.clear();
      this.outstanding = 0;
      for (const p of pending) p.reject(new Error(message));
      this.wakeIdle();
    });
    return worker;
  }
}
