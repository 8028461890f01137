/**
 * Solves the weights of a subdivision rig off the main thread (SubdivisionRig.solveWeights): the
 * cage, the handles and the levels in, one row of weights per refined vertex out, with progress
 * messages on the way (a failure answers with an error reply, see worker-host.ts). One request at
 * a time; the editor terminates the worker to cancel one.
 */
import { SubdivisionRig, init } from '../../../src/index.js';
import { serveRequests, type PostReply } from '../../app/worker-host.js';
import type { Weights3DReply, Weights3DRequest } from './weights-protocol.js';

serveRequests<Weights3DRequest, Weights3DReply>(solve);

async function solve(req: Weights3DRequest, post: PostReply<Weights3DReply>): Promise<void> {
  const t0 = performance.now();
  post({ type: 'progress', id: req.id, fraction: 0 });
  await init();
  let last = 0;
  const solved = SubdivisionRig.solveWeights(req.cage, req.handles, req.levels, req.kind, (fraction) => {
    // At most ~30 messages a second: the main thread only draws a bar.
    const now = performance.now();
    if (now - last < 33 && fraction < 1) return;
    last = now;
    post({ type: 'progress', id: req.id, fraction });
  });
  const weights = Float64Array.from(solved);
  post({ type: 'done', id: req.id, weights, ms: performance.now() - t0 }, [weights.buffer]);
}
