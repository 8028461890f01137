/**
 * Request/response over a dedicated worker, the editor's side: each request gets an id, its reply
 * (same id) settles its promise. The messages follow one shape, shared with worker-host.ts:
 *
 * - a request is `{ id, type, ... }`;
 * - a reply is `{ id, type, ... }`; `{ type: 'error', message }` rejects the request with that
 *   message, `{ type: 'progress', ... }` goes to the request's `onProgress` and does not settle it,
 *   any other type resolves it.
 *
 * The worker is started on the first request. When it fails (cannot start, throws outside a
 * request) every request waiting is rejected and the next request starts a fresh one.
 */

/** What every message carries. */
export interface WorkerMessage {
  id: number;
  type: string;
}

/** The request without the id the client adds (a union stays a union). */
export type RequestBody<Request extends WorkerMessage> = Request extends WorkerMessage ? Omit<Request, 'id'> : never;

interface Waiting<Reply> {
  resolve(reply: Reply): void;
  reject(err: Error): void;
  onProgress?: (reply: Reply) => void;
}

export class WorkerClient<Request extends WorkerMessage, Reply extends WorkerMessage> {
  private worker: Worker | null = null;
  private readonly waiting = new Map<number, Waiting<Reply>>();
  private nextId = 1;

  /**
   * @param spawn starts the worker (`new Worker(new URL('./x.worker.ts', import.meta.url), …)`, so
   *   that the bundler sees the worker's entry).
   * @param name what the worker is called in error messages ("the surface worker failed: …").
   */
  constructor(
    private readonly spawn: () => Worker,
    private readonly name: string,
  ) {}

  /** Requests sent and not settled yet. */
  get size(): number {
    return this.waiting.size;
  }

  /**
   * Sends a request. `transfer` lists buffers handed to the worker (not copied; the caller loses
   * them); `onProgress` gets the request's 'progress' replies.
   */
  request(body: RequestBody<Request>, transfer: Transferable[] = [], onProgress?: (reply: Reply) => void): Promise<Reply> {
    const worker = (this.worker ??= this.start());
    const id = this.nextId++;
    return new Promise<Reply>((resolve, reject) => {
      this.waiting.set(id, { resolve, reject, onProgress });
      worker.postMessage({ ...body, id }, transfer);
    });
  }

  /**
   * Stops the worker (a computation in it stops with it) and rejects every request waiting with
   * `reason`. The next request starts a fresh worker.
   */
  terminate(reason: Error): void {
    this.worker?.terminate();
    this.worker = null;
    const waiting = [...this.waiting.values()];
    this.waiting.clear();
    for (const w of waiting) w.reject(reason);
  }

  private start(): Worker {
    const worker = this.spawn();
    worker.addEventListener('message', (e: MessageEvent<Reply>) => {
      const reply = e.data;
      const w = this.waiting.get(reply.id);
      if (!w) return; // a late reply to a request rejected meanwhile
      if (reply.type === 'progress') {
        w.onProgress?.(reply);
        return;
      }
      this.waiting.delete(reply.id);
      if (reply.type === 'error') w.reject(new Error((reply as unknown as { message: string }).message));
      else w.resolve(reply);
    });
    worker.addEventListener('error', (e) => {
      e.preventDefault();
      if (this.worker === worker) this.terminate(new Error(`the ${this.name} worker failed: ${e.message || 'could not start'}`));
    });
    return worker;
  }
}

/** Thrown (as a rejection) when a newer request or cancel() replaced a computation. */
export class CancelledError extends Error {
  constructor() {
    super('cancelled');
    this.name = 'CancelledError';
  }
}

/**
 * A worker for one long computation at a time (e.g. weights): cancel() stops the one running by
 * terminating the worker (a computation is one synchronous call in there, so nothing short of
 * that stops it); the next request starts a fresh one.
 */
export class CancellableWorker<Request extends WorkerMessage, Reply extends WorkerMessage> extends WorkerClient<Request, Reply> {
  /** Whether a computation is running. */
  get busy(): boolean {
    return this.size > 0;
  }

  /** Stops the running computation (its promise rejects with CancelledError). */
  cancel(): void {
    if (this.busy) this.terminate(new CancelledError());
  }

  dispose(): void {
    this.terminate(new CancelledError());
  }
}
