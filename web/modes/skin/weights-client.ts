import type { PrecomputedWeights } from '../../../src/index.js';
import type { WeightsReply, WeightsRequest } from './weights-protocol.js';

/** Thrown (as a rejection) when a newer request or cancel() replaced a computation. */
export class CancelledError extends Error {
  constructor() {
    super('cancelled');
    this.name = 'CancelledError';
  }
}

interface Pending {
  id: number;
  resolve(w: PrecomputedWeights & { ms: number }): void;
  reject(err: Error): void;
  onProgress(stage: string, fraction: number): void;
}

/**
 * The editor's side of the weights worker. One computation at a time: a new request cancels the
 * one running by terminating its worker (the computation is one synchronous call in there, so
 * nothing short of that stops it) and starting a fresh one.
 */
export class WeightsClient {
  private worker: Worker | null = null;
  private pending: Pending | null = null;
  private nextId = 1;

  compute(request: Omit<WeightsRequest, 'type' | 'id'>, onProgress: (stage: string, fraction: number) => void): Promise<PrecomputedWeights & { ms: number }> {
    this.cancel();
    const worker = (this.worker ??= this.spawn());
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      this.pending = { id, resolve, reject, onProgress };
      const message: WeightsRequest = { type: 'compute', id, ...request };
      // The arrays are copies made for this request: hand them over.
      worker.postMessage(message, [message.outline.buffer, message.samples.buffer, message.points.buffer]);
    });
  }

  /** Whether a computation is running. */
  get busy(): boolean {
    return this.pending !== null;
  }

  /** Stops the running computation (its promise rejects with CancelledError). */
  cancel(): void {
    const p = this.pending;
    if (!p) return;
    this.pending = null;
    this.worker?.terminate();
    this.worker = null;
    p.reject(new CancelledError());
  }

  dispose(): void {
    this.cancel();
    this.worker?.terminate();
    this.worker = null;
  }

  private spawn(): Worker {
    const worker = new Worker(new URL('./weights.worker.ts', import.meta.url), { type: 'module', name: 'splinekit-weights' });
    worker.addEventListener('message', (e: MessageEvent<WeightsReply>) => {
      const reply = e.data, p = this.pending;
      if (!p || reply.id !== p.id) return; // a cancelled request's late message
      if (reply.type === 'progress') {
        p.onProgress(reply.stage, reply.fraction);
        return;
      }
      this.pending = null;
      if (reply.type === 'error') p.reject(new Error(reply.message));
      else p.resolve({ handleCount: reply.handleCount, samples: reply.samples, points: reply.points, gradients: reply.gradients ?? undefined, ms: reply.ms });
    });
    worker.addEventListener('error', (e) => {
      const p = this.pending;
      this.pending = null;
      this.worker?.terminate();
      this.worker = null;
      p?.reject(new Error(`the weights worker failed: ${e.message || 'could not start'}`));
      e.preventDefault();
    });
    return worker;
  }
}
