import { SkinRig, outlineSamples, type SvgDocument } from '../../../src/index.js';
import type { SkinSpec, WeightKind } from './spec.js';
import { CancelledError, type WeightsClient } from './weights-client.js';

/** Quadrature samples per curve (the paper's 100): the target and heat map are drawn at them. */
export const SAMPLES = 100;

/** A rig and what it was built from. */
export interface BuiltRig {
  readonly rig: SkinRig;
  /** What it was built from (SkinSession's key: handles, weights, continuity). */
  readonly key: string;
  /** Ids of the handles, in the rig's handle order. */
  readonly ids: readonly number[];
  readonly handles: readonly { x: number; y: number }[];
  readonly kind: WeightKind;
  /** Milliseconds: weights (in the worker, for harmonic/BBW) plus the precompute. */
  readonly ms: number;
}

/** Lets the browser paint before a synchronous step (the handle the user placed shows first). */
export function nextPaint(): Promise<void> {
  return new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
}

/**
 * Builds the rig for `spec`'s handles and weight kind. Shepard weights are evaluated inside
 * SkinRig.create (on the main thread, after a paint); harmonic and BBW weights are computed by the
 * worker at SkinRig.weightQueries, reporting progress, then handed to SkinRig.create.
 * Rejects with CancelledError once `stillWanted()` says a newer build replaced this one.
 */
export async function buildRig(
  doc: SvgDocument,
  spec: Pick<SkinSpec, 'handles' | 'weights'>,
  key: string,
  client: WeightsClient,
  onProgress: (stage: string, fraction: number) => void,
  stillWanted: () => boolean,
): Promise<BuiltRig> {
  const t0 = performance.now();
  const handles = spec.handles.map((h) => ({ x: h.x, y: h.y }));
  const base = { key, ids: spec.handles.map((h) => h.id), handles, kind: spec.weights };
  if (spec.weights === 'shepard') {
    onProgress('precomputing', 0);
    await nextPaint();
    if (!stillWanted()) throw new CancelledError();
    const rig = SkinRig.create(doc, { handles, weights: 'shepard', samples: SAMPLES });
    return { ...base, rig, ms: performance.now() - t0 };
  }
  onProgress('sampling the outline', 0);
  const queries = SkinRig.weightQueries(doc, SAMPLES);
  const outline = outlineSamples(doc);
  const weights = await client.compute({ kind: spec.weights, handles, outline, samples: queries.samples, points: queries.points }, onProgress);
  onProgress('precomputing', 1);
  await nextPaint();
  if (!stillWanted()) throw new CancelledError();
  const rig = SkinRig.create(doc, { handles, weights, samples: SAMPLES });
  return { ...base, rig, ms: performance.now() - t0 };
}
