import { animatedSVG, type Keyframe } from '../../../src/index.js';
import { derivedName, download } from '../../app/download.js';
import type { SkinSession } from './session.js';
import type { SkinSpec } from './spec.js';

/** Frames per second of exported animations. */
export const EXPORT_FPS = 24;

/** The keyframes spanning [0, duration] as the timeline plays them (held before the first, after the last). */
export function playedKeyframes(spec: SkinSpec): Keyframe[] {
  const k = [...spec.keyframes];
  if (k.length === 0) return k;
  if (k[0].time > 1e-9) k.unshift({ time: 0, transforms: k[0].transforms });
  const last = k[k.length - 1];
  if (last.time < spec.duration - 1e-9) k.push({ time: spec.duration, transforms: last.transforms });
  return k;
}

/** Downloads the posed drawing as `<name>-posed.svg`. Throws an Error with a user-facing message. */
export function exportPosed(session: SkinSession, file: string): void {
  if (!session.rig || !session.points) throw new Error('Place at least one handle to export a deformed drawing');
  download(session.rig.rig.toSVG(session.points), derivedName(file, 'posed'));
}

/**
 * Downloads the keyframed animation as `<name>-animated.svg`: path data animated with SMIL, so
 * it plays in a browser with no script (relaxed frame by frame when the rig is flexible). Leaves
 * the rig posed as before. Throws an Error with a user-facing message.
 */
export function exportAnimated(session: SkinSession, file: string): void {
  const spec = session.spec;
  if (spec.keyframes.length < 2) throw new Error('Key at least two poses on the timeline (I) to export an animation');
  if (!session.ready || !session.rig) throw new Error('The rig is still being built: export when it is ready');
  try {
    const svg = animatedSVG(session.rig.rig, playedKeyframes(spec), { fps: EXPORT_FPS, relax: spec.flexible });
    download(svg, derivedName(file, 'animated'));
  } finally {
    session.settle(); // the export posed the rig frame by frame: back to the current pose
  }
}
