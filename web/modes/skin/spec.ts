import { IDENTITY_MATRIX, type AffineMatrix, type Keyframe, affine } from '../../../src/index.js';
import { appendHandlePoses, dropHandlePoses } from '../../app/keyframes.js';

/**
 * What the user builds in skin mode, as an immutable value: handles at their rest positions, the
 * current pose, keyframes, and the rig options. Every edit makes a new spec (sharing what did not
 * change), so undo keeps a before and an after, and autosave writes one out as JSON.
 */

/** Shepard: inverse distance, immediate. Harmonic and BBW: computed on a mesh, in a worker. */
export type WeightKind = 'shepard' | 'harmonic' | 'bbw';
export const WEIGHT_KINDS: readonly WeightKind[] = ['shepard', 'harmonic', 'bbw'];

/** A handle at its rest position (document space); `id` stays with it through edits. */
export interface RigHandle {
  readonly id: number;
  readonly x: number;
  readonly y: number;
}

export interface SkinSpec {
  readonly handles: readonly RigHandle[];
  /** One matrix per handle (rest → posed), in handle order. */
  readonly pose: readonly AffineMatrix[];
  /** Increasing times (seconds); each keyframe has one matrix per handle, in handle order. */
  readonly keyframes: readonly Keyframe[];
  readonly weights: WeightKind;
  /** Relax G1 tangent ratios (and fixed angles) after each edit (§4 of the paper). */
  readonly flexible: boolean;
  /** Length of the animation in seconds (the timeline's span). */
  readonly duration: number;
}

export const EMPTY_SPEC: SkinSpec = { handles: [], pose: [], keyframes: [], weights: 'shepard', flexible: true, duration: 2 };

export { TIME_EPSILON, deleteKeyframe, keyframeAt, retimeKeyframe, setKeyframe } from '../../app/keyframes.js';

/** The handle nearest to (x, y) at rest, or -1. */
function nearest(spec: SkinSpec, x: number, y: number): number {
  let best = -1, bestD = Infinity;
  spec.handles.forEach((h, i) => {
    const d = (h.x - x) ** 2 + (h.y - y) ** 2;
    if (d < bestD) [best, bestD] = [i, d];
  });
  return best;
}

/**
 * Adds a handle at rest position (x, y). It takes the pose (and, in every keyframe, the matrix) of
 * handle `follow` (default: the nearest at rest), so adding one to a posed rig does not tear the
 * drawing apart.
 */
export function addHandle(spec: SkinSpec, id: number, x: number, y: number, follow = nearest(spec, x, y)): SkinSpec {
  return { ...appendHandlePoses<AffineMatrix, SkinSpec>(spec, (list) => (follow < 0 ? IDENTITY_MATRIX : list[follow])), handles: [...spec.handles, { id, x, y }] };
}

export function removeHandle(spec: SkinSpec, id: number): SkinSpec {
  const i = spec.handles.findIndex((h) => h.id === id);
  if (i < 0) return spec;
  const handles = spec.handles.filter((_, k) => k !== i);
  return { ...dropHandlePoses<AffineMatrix, SkinSpec>(spec, i, handles.length), handles };
}

/** Moves a handle's rest position (its pose matrix stays). */
export function moveHandle(spec: SkinSpec, id: number, x: number, y: number): SkinSpec {
  return { ...spec, handles: spec.handles.map((h) => (h.id === id ? { id, x, y } : h)) };
}

export function setPose(spec: SkinSpec, pose: readonly AffineMatrix[]): SkinSpec {
  return { ...spec, pose: [...pose] };
}

/** Handles and weights: what the rig is built from (a change means a new precompute). */
export function rigKey(spec: Pick<SkinSpec, 'handles' | 'weights'>): string {
  return `${spec.weights}|${spec.handles.map((h) => `${h.id}:${h.x},${h.y}`).join(';')}`;
}

// ---- JSON ------------------------------------------------------------------------------------

/** The spec as stored (autosave, SVG metadata). */
export interface SpecJSON {
  version: 1;
  handles: { id: number; x: number; y: number }[];
  pose: number[][];
  keyframes: { time: number; transforms: number[][] }[];
  weights: WeightKind;
  flexible: boolean;
  duration: number;
}

export function specToJSON(spec: SkinSpec): SpecJSON {
  return {
    version: 1,
    handles: spec.handles.map((h) => ({ id: h.id, x: h.x, y: h.y })),
    pose: spec.pose.map((m) => [...m]),
    keyframes: spec.keyframes.map((k) => ({ time: k.time, transforms: k.transforms.map((m) => [...m]) })),
    weights: spec.weights,
    flexible: spec.flexible,
    duration: spec.duration,
  };
}

/** Reads a stored spec; throws an Error naming what is wrong. */
export function specFromJSON(value: unknown): SkinSpec {
  const j = value as Partial<SpecJSON> | null;
  if (!j || typeof j !== 'object' || j.version !== 1) throw new Error('not a splinekit rig (version 1)');
  const finite = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);
  if (!Array.isArray(j.handles) || !j.handles.every((h) => h && Number.isInteger(h.id) && finite(h.x) && finite(h.y))) {
    throw new Error('rig: handles must be {id, x, y} with finite numbers');
  }
  const ids = new Set(j.handles.map((h) => h.id));
  if (ids.size !== j.handles.length) throw new Error('rig: handle ids must be unique');
  const n = j.handles.length;
  const matrices = (list: unknown, what: string): AffineMatrix[] => {
    if (!Array.isArray(list) || list.length !== n || !list.every(affine.isFiniteMatrix)) throw new Error(`rig: ${what} needs ${n} matrices of 6 finite numbers`);
    return list.map((m) => [...m] as unknown as AffineMatrix);
  };
  const keyframes = (Array.isArray(j.keyframes) ? j.keyframes : []).map((k, i) => {
    if (!k || !finite(k.time) || k.time < 0) throw new Error(`rig: keyframe ${i} needs a time ≥ 0`);
    return { time: k.time, transforms: matrices(k.transforms, `keyframe ${i}`) };
  });
  keyframes.forEach((k, i) => {
    if (i > 0 && !(k.time > keyframes[i - 1].time)) throw new Error('rig: keyframe times must increase');
  });
  const weights = WEIGHT_KINDS.includes(j.weights as WeightKind) ? (j.weights as WeightKind) : 'shepard';
  const duration = finite(j.duration) && j.duration > 0 ? j.duration : EMPTY_SPEC.duration;
  return {
    handles: j.handles.map((h) => ({ id: h.id, x: h.x, y: h.y })),
    pose: matrices(j.pose, 'the pose'),
    keyframes,
    weights,
    flexible: j.flexible !== false,
    duration,
  };
}
