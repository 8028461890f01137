import { keyframesAt } from '../../../src/index.js';
import { appendHandlePoses, dropHandlePoses, type Animated } from '../../app/keyframes.js';

/**
 * What the user builds in 3D Skin mode, as an immutable value: handles at their rest positions on
 * the surface, the current pose (one translation/rotation/scale per handle, about the handle),
 * keyframes, and the rig options. Every edit makes a new spec, so undo keeps a before and an after.
 */

/** Shepard: inverse distance, immediate. BBW: bounded biharmonic, solved in a worker. */
export type Skin3DWeights = 'shepard' | 'bbw';
export const SKIN3D_WEIGHTS: readonly Skin3DWeights[] = ['shepard', 'bbw'];

/** Subdivision levels the rig offers (the refined surface has about 4^levels faces per cage quad). */
export const MIN_LEVELS = 1;
export const MAX_LEVELS = 4;

/** A handle at its rest position on the surface; `id` stays with it through edits. */
export interface Handle3D {
  readonly id: number;
  readonly x: number;
  readonly y: number;
  readonly z: number;
}

/**
 * One handle's pose, about its rest position c: x ↦ c + t + R(q)·S(s)·(x − c), with t a
 * translation, q a unit quaternion [x, y, z, w] and s per-axis scales (what the gizmo edits).
 */
export interface HandlePose {
  readonly t: readonly [number, number, number];
  readonly q: readonly [number, number, number, number];
  readonly s: readonly [number, number, number];
}

export const REST_POSE: HandlePose = Object.freeze({ t: [0, 0, 0], q: [0, 0, 0, 1], s: [1, 1, 1] } as const);

export interface Skin3DSpec extends Animated<HandlePose> {
  readonly handles: readonly Handle3D[];
  readonly weights: Skin3DWeights;
  readonly levels: number;
}

export const EMPTY_SPEC3D: Skin3DSpec = { handles: [], pose: [], keyframes: [], weights: 'shepard', levels: 3, duration: 2 };

/** Whether two poses of the same handles are equal (within `eps` per number). */
export function samePoses(a: readonly HandlePose[], b: readonly HandlePose[], eps = 1e-9): boolean {
  const near = (x: readonly number[], y: readonly number[]) => x.every((v, k) => Math.abs(v - y[k]) <= eps);
  return a.length === b.length && a.every((p, i) => near(p.t, b[i].t) && near(p.q, b[i].q) && near(p.s, b[i].s));
}

/** Whether a pose is the rest pose (every handle where it was, unturned, unscaled). */
export function isRest(pose: readonly HandlePose[]): boolean {
  return pose.every((p) => p.t.every((v) => v === 0) && p.q[0] === 0 && p.q[1] === 0 && p.q[2] === 0 && p.s.every((v) => v === 1));
}

/**
 * The 3×4 matrix [A | b] (row-major) of a handle's pose: x' = A x + b with A = R(q) S(s) and
 * b = c + t − A c. Written into `out` at `offset`.
 */
export function poseMatrix(h: Handle3D, p: HandlePose, out: Float64Array, offset = 0): void {
  const [qx, qy, qz, qw] = p.q;
  // Rotation matrix of the unit quaternion (normalised here: interpolation keeps it close to 1).
  const n = Math.hypot(qx, qy, qz, qw) || 1;
  const x = qx / n, y = qy / n, z = qz / n, w = qw / n;
  const R = [
    1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
    2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
    2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y),
  ];
  const c = [h.x, h.y, h.z];
  for (let r = 0; r < 3; r++) {
    let Ac = 0;
    for (let k = 0; k < 3; k++) {
      const a = R[3 * r + k] * p.s[k];
      out[offset + 4 * r + k] = a;
      Ac += a * c[k];
    }
    out[offset + 4 * r + 3] = c[r] + p.t[r] - Ac;
  }
}

/** The transforms the rig takes for a pose: 12 numbers (3×4, row-major) per handle. */
export function poseTransforms(handles: readonly Handle3D[], pose: readonly HandlePose[], out: Float64Array = new Float64Array(12 * handles.length)): Float64Array {
  handles.forEach((h, i) => poseMatrix(h, pose[i], out, 12 * i));
  return out;
}

/** Where a posed handle is: its rest position moved by its translation. */
export function posedCenter(h: Handle3D, p: HandlePose): [number, number, number] {
  return [h.x + p.t[0], h.y + p.t[1], h.z + p.t[2]];
}

/**
 * The pose of a handle at rest position `c` that moves space exactly as `p` moves it for `h`
 * (same linear part; the translation that sends c where h's transform sends it).
 */
export function followPose(h: Handle3D, p: HandlePose, c: readonly [number, number, number]): HandlePose {
  const m = new Float64Array(12);
  poseMatrix(h, p, m);
  const moved = [0, 1, 2].map((r) => m[4 * r] * c[0] + m[4 * r + 1] * c[1] + m[4 * r + 2] * c[2] + m[4 * r + 3]);
  return { t: [moved[0] - c[0], moved[1] - c[1], moved[2] - c[2]], q: p.q, s: p.s };
}

/** Spherical interpolation of unit quaternions, the short way round. */
function slerp(a: HandlePose['q'], b: HandlePose['q'], u: number): [number, number, number, number] {
  let dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const sign = dot < 0 ? -1 : 1;
  dot *= sign;
  let wa: number, wb: number;
  if (dot > 0.9995) {
    // Nearly the same rotation: a normalised lerp is exact enough and stable.
    wa = 1 - u;
    wb = u;
  } else {
    const theta = Math.acos(Math.min(1, dot)), s = Math.sin(theta);
    wa = Math.sin((1 - u) * theta) / s;
    wb = Math.sin(u * theta) / s;
  }
  const q = [0, 1, 2, 3].map((k) => wa * a[k] + sign * wb * b[k]);
  const n = Math.hypot(...q) || 1;
  return [q[0] / n, q[1] / n, q[2] / n, q[3] / n];
}

/** The pose between two poses (u ∈ [0, 1]): translation and scale linearly, rotation by slerp. */
export function interpolatePose(a: HandlePose, b: HandlePose, u: number): HandlePose {
  const lerp3 = (x: readonly number[], y: readonly number[]): [number, number, number] => [0, 1, 2].map((k) => x[k] + u * (y[k] - x[k])) as [number, number, number];
  return { t: lerp3(a.t, b.t), q: slerp(a.q, b.q, u), s: lerp3(a.s, b.s) };
}

/** The pose at `time`: held before the first and after the last keyframe, interpolated between. */
export function poseAt3D(keyframes: Skin3DSpec['keyframes'], time: number): HandlePose[] {
  return keyframes.length === 0 ? [] : keyframesAt(keyframes, time, interpolatePose);
}

/** The handle nearest to `c` at rest, or -1. */
function nearest(spec: Skin3DSpec, c: readonly [number, number, number]): number {
  let best = -1, bestD = Infinity;
  spec.handles.forEach((h, i) => {
    const d = (h.x - c[0]) ** 2 + (h.y - c[1]) ** 2 + (h.z - c[2]) ** 2;
    if (d < bestD) [best, bestD] = [i, d];
  });
  return best;
}

/**
 * Adds a handle at rest position `c`. It follows the handle nearest at rest (in the pose and in
 * every keyframe), so adding one to a posed rig does not tear the surface apart.
 */
export function addHandle3D(spec: Skin3DSpec, id: number, c: readonly [number, number, number]): Skin3DSpec {
  const follow = nearest(spec, c);
  const made = appendHandlePoses<HandlePose, Skin3DSpec>(spec, (list) => (follow < 0 ? REST_POSE : followPose(spec.handles[follow], list[follow], c)));
  return { ...made, handles: [...spec.handles, { id, x: c[0], y: c[1], z: c[2] }] };
}

export function removeHandle3D(spec: Skin3DSpec, id: number): Skin3DSpec {
  const i = spec.handles.findIndex((h) => h.id === id);
  if (i < 0) return spec;
  const handles = spec.handles.filter((_, k) => k !== i);
  return { ...dropHandlePoses<HandlePose, Skin3DSpec>(spec, i, handles.length), handles };
}

/** Replaces one handle's pose. */
export function setHandlePose(spec: Skin3DSpec, index: number, pose: HandlePose): Skin3DSpec {
  return { ...spec, pose: spec.pose.map((p, i) => (i === index ? pose : p)) };
}

export function setPose3D(spec: Skin3DSpec, pose: readonly HandlePose[]): Skin3DSpec {
  return { ...spec, pose: [...pose] };
}

/** What the rig is built from: handles at rest, weights and levels (a change means a new precompute). */
export function rigKey3D(spec: Pick<Skin3DSpec, 'handles' | 'weights' | 'levels'>): string {
  return `${spec.weights}|${spec.levels}|${spec.handles.map((h) => `${h.id}:${h.x},${h.y},${h.z}`).join(';')}`;
}
