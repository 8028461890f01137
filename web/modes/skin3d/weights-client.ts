import type { Cage } from '../../../src/index.js';
import { CancellableWorker, CancelledError } from '../../app/worker-client.js';
import type { Weights3DReply, Weights3DRequest } from './weights-protocol.js';

export { CancelledError };

/**
 * 3D Skin mode's side of its weights worker. One solve at a time: a new request cancels the one
 * running (see CancellableWorker) and starts a fresh one.
 */
export class Weights3DClient extends CancellableWorker<Weights3DRequest, Weights3DReply> {
  constructor() {
    super(() => new Worker(new URL('./weights.worker.ts', import.meta.url), { type: 'module', name: 'splinekit-skin3d-weights' }), 'skin3d weights');
  }

  /** Weights per refined vertex (vertex-major, handle-minor) and the time the worker took. */
  async solve(cage: Cage, handles: Float64Array, levels: number, kind: 'shepard' | 'bbw', onProgress: (fraction: number) => void): Promise<{ weights: Float64Array; ms: number }> {
    this.cancel();
    // Copies for the worker (the cage stays with the session): hand them over.
    const message: Omit<Weights3DRequest, 'id'> = {
      type: 'solve',
      cage: { positions: cage.positions.slice(), faceSizes: cage.faceSizes.slice(), faceIndices: cage.faceIndices.slice(), creases: cage.creases.map((c) => ({ ...c })) },
      handles: handles.slice(),
      levels,
      kind,
    };
    const transfer = [message.cage.positions.buffer, message.cage.faceSizes.buffer, message.cage.faceIndices.buffer, message.handles.buffer];
    const reply = await this.request(message, transfer, (r) => {
      if (r.type === 'progress') onProgress(r.fraction);
    });
    if (reply.type !== 'done') throw new Error(`the skin3d weights worker answered ${reply.type}`);
    return { weights: reply.weights, ms: reply.ms };
  }
}
