import type { RigStatus } from './session.js';
import type { SkinTool } from './skin-panel.js';
import { EMPTY_SPEC, type WeightKind } from './spec.js';
import { showsPose, type SkinViewState } from './skin-view.js';

/** What the end-to-end tests read (window.splinekitEditor.skin()). */
export interface SkinTestState {
  active: boolean;
  tool: SkinTool;
  handles: number;
  /** Index of the selected handle, or null. */
  selected: number | null;
  phase: RigStatus['phase'];
  /** The rig matches the handles and weights, and the drawing is posed with it. */
  ready: boolean;
  weights: WeightKind;
  /** Fraction done of a build under way, or null. */
  progress: number | null;
  stage: string | null;
  flexible: boolean;
  keyframes: number;
  /** Keyframe times (seconds). */
  keyTimes: number[];
  time: number;
  duration: number;
  playing: boolean;
  /** Number of coordinates of the posed points, a checksum of them, and whether any is not finite. */
  points: number;
  checksum: number;
  nan: boolean;
  pose: number[][];
  fitRms: number | null;
  naiveRms: number | null;
  /** Segments drawn by each curve layer. */
  layers: { target: number; naive: number; field: number };
  /** No autosave is pending. */
  saved: boolean;
  /** Work under way in the mode (a rig build): the mode's in-flight tracker is not idle. */
  busy: boolean;
}

export function skinTestState(
  st: SkinViewState,
  extra: { active: boolean; layers: SkinTestState['layers']; saved: boolean; busy: boolean },
): SkinTestState {
  const s = st.session, spec = s?.spec ?? EMPTY_SPEC, status = s?.status;
  const points = s?.points ?? null;
  let checksum = 0, nan = false;
  if (points) {
    for (let k = 0; k < points.length; k++) {
      if (!Number.isFinite(points[k])) nan = true;
      else checksum += points[k] * ((k % 7) + 1);
    }
  }
  const errors = s && showsPose(st) ? s.errors() : null;
  return {
    active: extra.active,
    tool: st.tool,
    handles: spec.handles.length,
    selected: s && s.selected !== null ? s.indexOf(s.selected) : null,
    phase: status?.phase ?? 'none',
    ready: s?.ready ?? false,
    weights: spec.weights,
    progress: status?.phase === 'building' ? status.fraction : null,
    stage: status?.phase === 'building' ? status.stage : null,
    flexible: spec.flexible,
    keyframes: spec.keyframes.length,
    keyTimes: spec.keyframes.map((k) => k.time),
    time: s?.time ?? 0,
    duration: spec.duration,
    playing: st.playing,
    points: points?.length ?? 0,
    checksum,
    nan,
    pose: spec.pose.map((m) => [...m]),
    fitRms: errors?.fit.rms ?? null,
    naiveRms: errors?.naive.rms ?? null,
    layers: extra.layers,
    saved: extra.saved,
    busy: extra.busy,
  };
}
