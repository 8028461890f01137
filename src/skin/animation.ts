import { SplinekitError } from '../core/errors.js';
import type { AffineMatrix } from '../core/affine.js';
import type { SkinRig } from './rig.js';

/** A pose of every handle at a time (seconds). */
export interface Keyframe {
  /** When this pose is reached, in seconds from the start. */
  time: number;
  /** One affine matrix per handle of the rig, in handle order. */
  transforms: readonly AffineMatrix[];
}

/**
 * Interpolates two affine matrices by their polar decompositions (Shoemake & Duff 1992):
 * L = R(θ)·P with P symmetric; θ takes the short way round, P and the translation go linearly.
 * Unlike a linear blend of matrices, a rotation stays a rotation half way (no shrinking).
 */
export function interpolateMatrix(m0: AffineMatrix, m1: AffineMatrix, t: number): AffineMatrix {
  const polar = (m: AffineMatrix) => {
    const theta = Math.atan2(m[1] - m[2], m[0] + m[3]);
    const c = Math.cos(theta), s = Math.sin(theta);
    // P = R(θ)ᵀ L, with L = [[a c],[b d]].
    return { theta, p: [c * m[0] + s * m[1], c * m[2] + s * m[3], -s * m[0] + c * m[1], -s * m[2] + c * m[3]] };
  };
  const a = polar(m0), b = polar(m1);
  let d = b.theta - a.theta;
  if (d > Math.PI) d -= 2 * Math.PI;
  if (d < -Math.PI) d += 2 * Math.PI;
  const theta = a.theta + t * d, c = Math.cos(theta), s = Math.sin(theta);
  const p = a.p.map((v, k) => v + t * (b.p[k] - v));
  // L = R P with P = [[p0 p1],[p2 p3]]: a = c p0 − s p2, b = s p0 + c p2, c' = c p1 − s p3, d = s p1 + c p3.
  return [c * p[0] - s * p[2], s * p[0] + c * p[2], c * p[1] - s * p[3], s * p[1] + c * p[3], m0[4] + t * (m1[4] - m0[4]), m0[5] + t * (m1[5] - m0[5])];
}

function checkKeyframes(keyframes: readonly Keyframe[], handles: number): void {
  if (keyframes.length === 0) throw new SplinekitError('invalid-input', 'animation: no keyframes');
  keyframes.forEach((k, i) => {
    if (!Number.isFinite(k.time)) throw new SplinekitError('invalid-input', `animation: keyframe ${i} has a non-finite time`);
    if (i > 0 && !(k.time > keyframes[i - 1].time)) throw new SplinekitError('invalid-input', 'animation: keyframe times must increase');
    if (k.transforms.length !== handles) throw new SplinekitError('invalid-input', `animation: keyframe ${i} has ${k.transforms.length} transforms for ${handles} handles`);
  });
}

/**
 * The per-handle values at `time` of keyframes sorted by time (at least one): held before the first
 * and after the last keyframe, `interpolate(a, b, u)` with u in [0, 1] between two. Any kind of
 * handle transform: 2D matrices (poseAt) or the editor's 3D handle poses.
 */
export function keyframesAt<T>(keyframes: readonly { time: number; transforms: readonly T[] }[], time: number, interpolate: (a: T, b: T, u: number) => T): T[] {
  if (time <= keyframes[0].time) return [...keyframes[0].transforms];
  const last = keyframes[keyframes.length - 1];
  if (time >= last.time) return [...last.transforms];
  let i = 0;
  while (keyframes[i + 1].time < time) i++;
  const a = keyframes[i], b = keyframes[i + 1];
  const u = (time - a.time) / (b.time - a.time);
  return a.transforms.map((m, h) => interpolate(m, b.transforms[h], u));
}

/** The pose at `time`: held before the first and after the last keyframe, interpolated between. */
export function poseAt(keyframes: readonly Keyframe[], time: number): AffineMatrix[] {
  return keyframesAt(keyframes, time, interpolateMatrix);
}

/** Options of {@link animatedSVG}. */
export interface AnimationOptions {
  /** Frames per second sampled between keyframes (every keyframe is a frame too). Default 24. */
  fps?: number;
  /** Relax (flexible G1 / angle) every frame. Default false. */
  relax?: boolean;
  /** SMIL repeatCount. Default 'indefinite'. */
  repeat?: number | 'indefinite';
}

/**
 * An animated SVG of `rig` playing `keyframes` (times from the first keyframe, in seconds): the
 * fit is evaluated at `fps` and at every keyframe, and each shape animates its path data with
 * SMIL, so the file plays in a browser with no script.
 */
export function animatedSVG(rig: SkinRig, keyframes: readonly Keyframe[], options: AnimationOptions = {}): string {
  checkKeyframes(keyframes, rig.handleCount);
  if (keyframes.length < 2) throw new SplinekitError('invalid-input', 'animation: needs at least two keyframes');
  const fps = options.fps ?? 24;
  if (!(fps > 0 && fps <= 240)) throw new SplinekitError('invalid-input', `animation: fps must be in (0, 240], got ${fps}`);
  const start = keyframes[0].time, end = keyframes[keyframes.length - 1].time;
  const times = new Set<number>();
  for (let t = start; t < end; t += 1 / fps) times.add(t);
  for (const k of keyframes) times.add(k.time);
  const sorted = [...times].sort((a, b) => a - b).filter((t, i, all) => i === 0 || t - all[i - 1] > 1e-9);
  const frames = sorted.map((t) => {
    rig.pose(poseAt(keyframes, t));
    if (options.relax) rig.relax();
    return rig.points().slice();
  });
  return rig.posedDocument(frames[0]).toAnimatedSVG(frames, sorted.map((t) => t - start), { repeat: options.repeat });
}
