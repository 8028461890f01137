/** Surface mode's keys and gestures: what the panel lists, and which key does what. */

export const SURFACE_KEYS = [
  ['Click on the mesh', 'start a spline · add a point to it'],
  ['Enter · Esc · double-click', 'finish the spline'],
  ['Drag a point', 'move an anchor or a handle'],
  ['Click a curve', 'select the spline'],
  ['Alt+click a curve', 'insert a point there'],
  ['C', 'smooth ⇄ corner (selected anchor)'],
  ['Delete', 'delete the point (or the spline)'],
  ['G · R · S, then drag', 'move · rotate · scale the spline (Shift: 15° steps)'],
  ['Drag the background · middle drag', 'orbit'],
  ['Right drag · Shift+drag', 'pan'],
  ['Wheel', 'zoom at the cursor'],
  ['F', 'frame the mesh'],
  ['H', 'show or hide the control points'],
] as const;

export type SurfaceAction = 'finish' | 'escape' | 'delete' | 'smooth' | 'tool-move' | 'tool-rotate' | 'tool-scale';

const KEYS: Record<string, SurfaceAction> = {
  enter: 'finish',
  escape: 'escape',
  delete: 'delete',
  backspace: 'delete',
  c: 'smooth',
  g: 'tool-move',
  r: 'tool-rotate',
  s: 'tool-scale',
};

/** The action of a key press (modifiers other than Shift are the editor's), or null. */
export function keyAction(e: KeyboardEvent): SurfaceAction | null {
  if (e.ctrlKey || e.metaKey || e.altKey) return null;
  return KEYS[e.key.toLowerCase()] ?? null;
}
