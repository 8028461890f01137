import type { ErrorReply } from '../../app/worker-host.js';

/** Messages between 3D Skin mode and web/modes/skin3d/weights.worker.ts (plain arrays only). */
export interface CageArrays {
  positions: Float64Array;
  faceSizes: Uint32Array;
  faceIndices: Uint32Array;
  creases: { a: number; b: number; sharpness: number }[];
}

export interface Weights3DRequest {
  type: 'solve';
  id: number;
  cage: CageArrays;
  /** Rest positions, 3 per handle. */
  handles: Float64Array;
  levels: number;
  kind: 'shepard' | 'bbw';
}

export type Weights3DReply =
  | { type: 'progress'; id: number; fraction: number }
  | { type: 'done'; id: number; weights: Float64Array; ms: number }
  | ErrorReply;
