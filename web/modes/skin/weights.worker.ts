/**
 * Computes harmonic or BBW weights off the main thread: plain arrays in (outline, handles, query
 * positions), plain arrays out, with progress messages on the way (a failure answers with an
 * error reply, see worker-host.ts). One request at a time; the editor terminates the worker to
 * cancel one.
 */
import { computeDomainWeights, init } from '../../../src/index.js';
import { serveRequests, type PostReply } from '../../app/worker-host.js';
import type { WeightsReply, WeightsRequest } from './weights-protocol.js';

serveRequests<WeightsRequest, WeightsReply>(compute);

async function compute(req: WeightsRequest, post: PostReply<WeightsReply>): Promise<void> {
  const t0 = performance.now();
  post({ type: 'progress', id: req.id, stage: 'loading the core', fraction: 0 });
  await init();
  let last = 0;
  const w = computeDomainWeights({
    outline: req.outline,
    handles: req.handles,
    kind: req.kind,
    queries: { samples: req.samples, points: req.points },
    onProgress: (stage, fraction) => {
      // At most ~30 messages a second: the main thread only draws a bar.
      const now = performance.now();
      if (now - last < 33 && fraction < 1) return;
      last = now;
      post({ type: 'progress', id: req.id, stage, fraction });
    },
  });
  const samples = Float64Array.from(w.samples), points = Float64Array.from(w.points);
  const gradients = w.gradients ? Float64Array.from(w.gradients) : null;
  const transfer: Transferable[] = [samples.buffer, points.buffer];
  if (gradients) transfer.push(gradients.buffer);
  post({ type: 'done', id: req.id, handleCount: w.handleCount, samples, points, gradients, ms: performance.now() - t0 }, transfer);
}
