import { SplineSet } from '../spline/spline-set.js';
import type { SvgDocument } from '../svg/document.js';
import { buildDomain, type DomainOptions } from './domain.js';
import { SkinRig, type PrecomputedWeights, type SkinHandle, type WeightQueries } from './rig.js';
import { SkinWeights, type DomainWeightKind } from './weights.js';

export type { DomainWeightKind };

/** Points along the drawing's curves (x,y pairs), `perSegment` per cubic: what a domain is built around. */
export function outlineSamples(doc: SvgDocument, perSegment = 8): Float64Array {
  const set = SplineSet.from(doc.splines);
  try {
    return set.sample(Math.max(2, perSegment));
  } finally {
    set.dispose();
  }
}

/** What {@link computeDomainWeights} needs, as plain data (it can be posted to a Web Worker). */
export interface DomainWeightsInput extends DomainOptions {
  /** Points along the drawing's curves, x,y pairs (see {@link outlineSamples}). */
  outline: Float64Array;
  /** The rig's point handles. */
  handles: readonly SkinHandle[];
  /** Which weights to solve. */
  kind: DomainWeightKind;
  /** Where the rig needs the weights (see `SkinRig.weightQueries`). */
  queries: WeightQueries;
  /** Called with a stage name and the fraction done (0..1) as the work goes on. */
  onProgress?: (stage: string, fraction: number) => void;
}

/**
 * Harmonic or BBW weights at a rig's query positions, from plain arrays: builds the domain,
 * solves on it, evaluates at the queries. Needs nothing but `await init()`, so it runs in a Web
 * Worker as well as in Node.
 */
export function computeDomainWeights(input: DomainWeightsInput): PrecomputedWeights & {
  /** Number of triangles of the domain the weights were solved on. */
  triangles: number;
} {
  const progress = input.onProgress ?? (() => {});
  progress('triangulating', 0);
  const domain = buildDomain(input.outline, input.handles, input);
  progress(input.kind === 'bbw' ? 'solving bounded biharmonic weights' : 'solving harmonic weights', 0.2);
  const weights = SkinWeights.solve(domain, input.kind);
  try {
    progress('evaluating', 0.9);
    const result = {
      handleCount: weights.handleCount,
      samples: weights.weightsAt(input.queries.samples),
      points: weights.weightsAt(input.queries.points),
      gradients: weights.gradientsAt(input.queries.points),
      triangles: weights.triangleCount,
    };
    progress('done', 1);
    return result;
  } finally {
    weights.dispose();
  }
}

/** The same for a document on this thread (CLI, tests). */
export function domainWeights(
  doc: SvgDocument,
  handles: readonly SkinHandle[],
  kind: DomainWeightKind,
  options: DomainOptions & { samples?: number } = {},
): PrecomputedWeights & {
  /** Number of triangles of the domain the weights were solved on. */
  triangles: number;
} {
  return computeDomainWeights({ ...options, outline: outlineSamples(doc), handles, kind, queries: SkinRig.weightQueries(doc, options.samples ?? 100) });
}
