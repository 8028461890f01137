import type { PrecomputedWeights } from '../../../src/index.js';
import { CancellableWorker, CancelledError } from '../../app/worker-client.js';
import type { WeightsReply, WeightsRequest } from './weights-protocol.js';

export { CancelledError };

/**
 * The editor's side of the weights worker. One computation at a time: a new request cancels the
 * one running (see CancellableWorker) and starts a fresh one.
 */
export class WeightsClient extends CancellableWorker<WeightsRequest, WeightsReply> {
  constructor() {
    super(() => new Worker(new URL('./weights.worker.ts', import.meta.url), { type: 'module', name: 'splinekit-weights' }), 'weights');
  }

  async compute(request: Omit<WeightsRequest, 'type' | 'id'>, onProgress: (stage: string, fraction: number) => void): Promise<PrecomputedWeights & { ms: number }> {
    this.cancel();
    const message: Omit<WeightsRequest, 'id'> = { type: 'compute', ...request };
    // The arrays are copies made for this request: hand them over.
    const reply = await this.request(message, [message.outline.buffer, message.samples.buffer, message.points.buffer], (r) => {
      if (r.type === 'progress') onProgress(r.stage, r.fraction);
    });
    if (reply.type !== 'done') throw new Error(`the weights worker answered ${reply.type}`);
    return { handleCount: reply.handleCount, samples: reply.samples, points: reply.points, gradients: reply.gradients ?? undefined, ms: reply.ms };
  }
}
