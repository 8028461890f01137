import type { PrecomputedWeights } from '../../../src/index.js';
import { WorkerClient } from '../../app/worker-client.js';
import type { WeightsReply, WeightsRequest } from './weights-protocol.js';

/** Thrown (as a rejection) when a newer request or cancel() replaced a computation. */
export class CancelledError extends Error {
  constructor() {
    super('cancelled');
    this.name = 'CancelledError';
  }
}

/**
 * The editor's side of the weights worker. One computation at a time: a new request cancels the
 * one running by terminating its worker (the computation is one synchronous call in there, so
 * nothing short of that stops it) and starting a fresh one.
 */
export class WeightsClient {
  private readonly worker = new WorkerClient<WeightsRequest, WeightsReply>(
    () => new Worker(new URL('./weights.worker.ts', import.meta.url), { type: 'module', name: 'splinekit-weights' }),
    'weights',
  );

  async compute(request: Omit<WeightsRequest, 'type' | 'id'>, onProgress: (stage: string, fraction: number) => void): Promise<PrecomputedWeights & { ms: number }> {
    this.cancel();
    const message: Omit<WeightsRequest, 'id'> = { type: 'compute', ...request };
    // The arrays are copies made for this request: hand them over.
    const reply = await this.worker.request(message, [message.outline.buffer, message.samples.buffer, message.points.buffer], (r) => {
      if (r.type === 'progress') onProgress(r.stage, r.fraction);
    });
    if (reply.type !== 'done') throw new Error(`the weights worker answered ${reply.type}`);
    return { handleCount: reply.handleCount, samples: reply.samples, points: reply.points, gradients: reply.gradients ?? undefined, ms: reply.ms };
  }

  /** Whether a computation is running. */
  get busy(): boolean {
    return this.worker.size > 0;
  }

  /** Stops the running computation (its promise rejects with CancelledError). */
  cancel(): void {
    if (this.busy) this.worker.terminate(new CancelledError());
  }

  dispose(): void {
    this.worker.terminate(new CancelledError());
  }
}
