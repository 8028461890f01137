import type { DomainWeightKind, SkinHandle } from '../../../src/index.js';
import type { ErrorReply } from '../../app/worker-host.js';

/** Messages between the editor and web/modes/skin/weights.worker.ts (plain arrays only). */
export interface WeightsRequest {
  type: 'compute';
  id: number;
  kind: DomainWeightKind;
  handles: SkinHandle[];
  /** outlineSamples(doc): x,y pairs. */
  outline: Float64Array;
  /** SkinRig.weightQueries(doc): where the rig needs weights. */
  samples: Float64Array;
  points: Float64Array;
}

export type WeightsReply =
  | { type: 'progress'; id: number; stage: string; fraction: number }
  | { type: 'done'; id: number; handleCount: number; samples: Float64Array; points: Float64Array; gradients: Float64Array | null; ms: number }
  | ErrorReply;
