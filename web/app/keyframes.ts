/**
 * Keyframed poses of a rig as immutable values, whatever a handle's pose is (a 2D affine matrix
 * in Skin mode, a translation/rotation/scale in 3D Skin mode): the current pose, keyframes with
 * one pose per handle, and the animation's length. Each edit returns a new spec.
 */

/** Keyframes closer than this (seconds) are the same keyframe. */
export const TIME_EPSILON = 1e-3;

/** What the keyframe edits need of a spec; `P` is one handle's pose. */
export interface Animated<P> {
  /** One pose per handle, in handle order. */
  readonly pose: readonly P[];
  /** Increasing times (seconds); each keyframe has one pose per handle, in handle order. */
  readonly keyframes: readonly { readonly time: number; readonly transforms: readonly P[] }[];
  /** Length of the animation in seconds (the timeline's span). */
  readonly duration: number;
}

/** Stores the current pose as the keyframe at `time` (replacing one at the same time). */
export function setKeyframe<S extends Animated<unknown>>(spec: S, time: number): S {
  const keyframes = spec.keyframes.filter((k) => Math.abs(k.time - time) > TIME_EPSILON);
  keyframes.push({ time, transforms: [...spec.pose] });
  keyframes.sort((a, b) => a.time - b.time);
  return { ...spec, keyframes, duration: Math.max(spec.duration, time) } as S;
}

/** The keyframe at `time` (within TIME_EPSILON), or -1. */
export function keyframeAt(spec: Animated<unknown>, time: number): number {
  return spec.keyframes.findIndex((k) => Math.abs(k.time - time) <= TIME_EPSILON);
}

export function deleteKeyframe<S extends Animated<unknown>>(spec: S, index: number): S {
  return { ...spec, keyframes: spec.keyframes.filter((_, i) => i !== index) } as S;
}

/** Moves keyframe `index` to `time` (kept between its neighbours). */
export function retimeKeyframe<S extends Animated<unknown>>(spec: S, index: number, time: number): S {
  const keyframes = [...spec.keyframes];
  const lo = index > 0 ? keyframes[index - 1].time + TIME_EPSILON * 2 : 0;
  const hi = index < keyframes.length - 1 ? keyframes[index + 1].time - TIME_EPSILON * 2 : Infinity;
  keyframes[index] = { ...keyframes[index], time: Math.min(hi, Math.max(lo, time)) };
  return { ...spec, keyframes, duration: Math.max(spec.duration, keyframes[index].time) } as S;
}

/** Drops handle `index` from the pose and every keyframe (keyframes of a rig with no handles mean nothing). */
export function dropHandlePoses<P, S extends Animated<P>>(spec: S, index: number, remaining: number): S {
  const drop = <T>(list: readonly T[]) => list.filter((_, k) => k !== index);
  return { ...spec, pose: drop(spec.pose), keyframes: remaining === 0 ? [] : spec.keyframes.map((k) => ({ time: k.time, transforms: drop(k.transforms) })) } as S;
}

/** Appends one pose per keyframe and to the current pose for a new handle (`make` sees the pose list it joins). */
export function appendHandlePoses<P, S extends Animated<P>>(spec: S, make: (list: readonly P[]) => P): S {
  return { ...spec, pose: [...spec.pose, make(spec.pose)], keyframes: spec.keyframes.map((k) => ({ time: k.time, transforms: [...k.transforms, make(k.transforms)] })) } as S;
}
