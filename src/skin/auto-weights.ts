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

export interface DomainWeightsInput extends DomainOptions {
  outline: Float64Array;
  handles: readonly SkinHandle[];
  kind: DomainWeightKind;
  queries: WeightQueries;
  onProgress?: (stage: string, fraction: number) => void;
}

/**
 * Harmonic or BBW weights at a rig's query positions, from plain arrays: builds the domain,
 * solves on it, evaluates at the queries. Needs nothing but `await init()`, so it runs in a Web
 * Worker as well as in Node.
 */
export function computeDomainWeights(input: DomainWeightsInput): PrecomputedWeights & { triangles: number } {
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
): PrecomputedWeights & { triangles: number } {
  return computeDomainWeights({ ...options, outline: outlineSamples(doc), handles, kind, queries: SkinRig.weightQueries(doc, options.samples ?? 100) });
}
