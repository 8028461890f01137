import { readJSON, writeJSON } from '../../app/autosave.js';
import { MAX_LEVELS, MIN_LEVELS, SKIN3D_WEIGHTS, type HandlePose, type Skin3DSpec, type Skin3DWeights } from './spec.js';

/**
 * 3D Skin mode's local autosave (localStorage): the cage last open (its OBJ text and file name)
 * with its spec (handles, pose, keyframes, options) and the playhead, so that a reload comes back
 * to them. Cages too large for localStorage are not saved (the message says so); failures are
 * reported, never thrown.
 */

const SESSION_KEY = 'splinekit:skin3d-session';
/** OBJ text longer than this is not autosaved (localStorage holds about 5 MB per origin). */
const MAX_SAVED_CHARS = 1_500_000;

/** A spec as stored (JSON). */
export interface Spec3DJSON {
  version: 1;
  handles: { id: number; x: number; y: number; z: number }[];
  pose: HandlePose[];
  keyframes: { time: number; transforms: HandlePose[] }[];
  weights: Skin3DWeights;
  levels: number;
  duration: number;
}

export interface SavedSkin3D {
  version: 1;
  file: string;
  obj: string;
  spec: Spec3DJSON;
  time: number;
}

export function spec3DToJSON(spec: Skin3DSpec): Spec3DJSON {
  const pose = (p: HandlePose): HandlePose => ({ t: [...p.t], q: [...p.q], s: [...p.s] });
  return {
    version: 1,
    handles: spec.handles.map((h) => ({ id: h.id, x: h.x, y: h.y, z: h.z })),
    pose: spec.pose.map(pose),
    keyframes: spec.keyframes.map((k) => ({ time: k.time, transforms: k.transforms.map(pose) })),
    weights: spec.weights,
    levels: spec.levels,
    duration: spec.duration,
  };
}

const finite = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);

/** Reads a stored spec; throws an Error naming what is wrong. */
export function spec3DFromJSON(value: unknown): Skin3DSpec {
  const j = value as Partial<Spec3DJSON> | null;
  if (!j || typeof j !== 'object' || j.version !== 1) throw new Error('not a 3D skin rig (version 1)');
  if (!Array.isArray(j.handles) || !j.handles.every((h) => h && Number.isInteger(h.id) && finite(h.x) && finite(h.y) && finite(h.z))) {
    throw new Error('3D rig: handles must be {id, x, y, z} with finite numbers');
  }
  if (new Set(j.handles.map((h) => h.id)).size !== j.handles.length) throw new Error('3D rig: handle ids must be unique');
  const n = j.handles.length;
  const isPose = (p: unknown): p is HandlePose => {
    const q = p as HandlePose | null;
    const nums = (a: unknown, k: number) => Array.isArray(a) && a.length === k && a.every(finite);
    return !!q && nums(q.t, 3) && nums(q.q, 4) && nums(q.s, 3) && Math.hypot(...q.q) > 0.5;
  };
  const poses = (list: unknown, what: string): HandlePose[] => {
    if (!Array.isArray(list) || list.length !== n || !list.every(isPose)) throw new Error(`3D rig: ${what} needs ${n} poses {t: 3, q: 4, s: 3 finite numbers}`);
    return list.map((p) => ({ t: [p.t[0], p.t[1], p.t[2]], q: [p.q[0], p.q[1], p.q[2], p.q[3]], s: [p.s[0], p.s[1], p.s[2]] }));
  };
  const keyframes = (Array.isArray(j.keyframes) ? j.keyframes : []).map((k, i) => {
    if (!k || !finite(k.time) || k.time < 0) throw new Error(`3D rig: keyframe ${i} needs a time ≥ 0`);
    return { time: k.time, transforms: poses(k.transforms, `keyframe ${i}`) };
  });
  keyframes.forEach((k, i) => {
    if (i > 0 && !(k.time > keyframes[i - 1].time)) throw new Error('3D rig: keyframe times must increase');
  });
  if (!Number.isInteger(j.levels) || j.levels! < MIN_LEVELS || j.levels! > MAX_LEVELS) throw new Error(`3D rig: levels must be an integer in ${MIN_LEVELS}..${MAX_LEVELS}`);
  return {
    handles: j.handles.map((h) => ({ id: h.id, x: h.x, y: h.y, z: h.z })),
    pose: poses(j.pose, 'the pose'),
    keyframes,
    weights: SKIN3D_WEIGHTS.includes(j.weights as Skin3DWeights) ? (j.weights as Skin3DWeights) : 'shepard',
    levels: j.levels!,
    duration: finite(j.duration) && j.duration > 0 ? Math.max(j.duration, keyframes.at(-1)?.time ?? 0) : 2,
  };
}

/** Saves the cage and its spec; returns why it was not saved, or null. */
export function saveSkin3D(file: string, obj: string, spec: Skin3DSpec, time: number): string | null {
  if (obj.length > MAX_SAVED_CHARS) return `${file} is too large to keep in the browser’s storage`;
  return writeJSON(SESSION_KEY, { version: 1, file, obj, spec: spec3DToJSON(spec), time } satisfies SavedSkin3D);
}

/** The saved cage and spec, or null (none, or not readable: then `problem` says why). */
export function loadSkin3D(): { file: string; obj: string; spec: Skin3DSpec; time: number } | { problem: string } | null {
  const s = readJSON(SESSION_KEY) as Partial<SavedSkin3D> | null;
  if (!s) return null;
  if (s.version !== 1 || typeof s.file !== 'string' || typeof s.obj !== 'string') return { problem: 'the saved 3D skin session is not readable' };
  try {
    return { file: s.file, obj: s.obj, spec: spec3DFromJSON(s.spec), time: finite(s.time) ? Math.max(0, s.time) : 0 };
  } catch (err) {
    return { problem: `the saved 3D skin session is not readable: ${(err as Error).message}` };
  }
}
