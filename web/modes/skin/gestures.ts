import { affine } from '../../../src/index.js';
import type { AffineMatrix } from '../../../src/index.js';
import type { ViewPointer } from '../../view2d/view2d.js';
import type { SkinSpec } from './spec.js';

/** Radians per pixel of horizontal motion for Shift+drag, and the scale rate of Alt+drag. */
const TURN_PER_PX = Math.PI / 360;
const SCALE_PER_PX = 0.006;
const SNAP = Math.PI / 12;

export type PoseOp = 'move' | 'rotate' | 'scale';

/** Posing one handle: what was pressed, and the state when it was. */
export interface PoseGesture {
  kind: 'pose';
  op: PoseOp;
  /** Pressed the handle itself (with modifiers) or the gizmo (ring, knob). */
  via: 'handle' | 'gizmo';
  id: number;
  index: number;
  before: SkinSpec;
  /** The handle's matrix at the press, and its posed position (the pivot). */
  m0: AffineMatrix;
  pivot: [number, number];
  start: ViewPointer;
  moved: boolean;
}

/** Moving a handle's rest position (Rig tool); the rig is rebuilt on release. */
export interface RestGesture {
  kind: 'rest';
  id: number;
  before: SkinSpec;
  /** Offset from the pointer to the handle at the press (document units). */
  dx: number;
  dy: number;
  x: number;
  y: number;
  moved: boolean;
}

export type Gesture = PoseGesture | RestGesture;

/** The handle's matrix for the pointer at `p`, and a readout of its rotation and scale. */
export function poseFor(g: PoseGesture, p: ViewPointer): { m: AffineMatrix; readout: string | null } {
  const [cx, cy] = g.pivot;
  let m: AffineMatrix;
  if (g.op === 'move') {
    m = affine.multiply(affine.translation(p.x - g.start.x, p.y - g.start.y), g.m0);
  } else if (g.op === 'rotate') {
    let theta =
      g.via === 'gizmo'
        ? Math.atan2(p.y - cy, p.x - cx) - Math.atan2(g.start.y - cy, g.start.x - cx)
        : (p.sx - g.start.sx) * TURN_PER_PX;
    if (g.via === 'gizmo' && p.shiftKey) {
      // Snap the resulting angle (not the increment) to 15°.
      const total = affine.angleOf(g.m0) + theta;
      theta += Math.round(total / SNAP) * SNAP - total;
    }
    m = affine.multiply(affine.rotationAbout(theta, cx, cy), g.m0);
  } else {
    const k =
      g.via === 'gizmo'
        ? Math.hypot(p.x - cx, p.y - cy) / Math.max(1e-12, Math.hypot(g.start.x - cx, g.start.y - cy))
        : Math.exp(-(p.sy - g.start.sy) * SCALE_PER_PX);
    m = affine.multiply(affine.scalingAbout(Math.min(20, Math.max(0.05, k)), cx, cy), g.m0);
  }
  return { m, readout: g.op === 'move' ? null : readout(m) };
}

export function readout(m: AffineMatrix): string {
  const deg = (affine.angleOf(m) * 180) / Math.PI;
  return `↻ ${deg.toFixed(0)}°  ⤢ ${affine.scaleOf(m).toFixed(2)}×`;
}
