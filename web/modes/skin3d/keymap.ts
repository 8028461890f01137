/** 3D Skin mode's keys: what the panel lists, and which key does what. */

/** [keys, what] rows for the panel's Keys section. */
export const SKIN3D_KEYS = [
  ['Click the surface', 'add a handle there'],
  ['Click a handle · Esc', 'select it (the gizmo appears) · deselect'],
  ['Drag the gizmo', 'move, turn or scale the selected handle'],
  ['G · R · S', 'gizmo: move · turn · scale'],
  ['Delete · 0', 'remove the selected handle · reset the pose'],
  ['C · T · N · E', 'cage · target · naive · error colours'],
  ['I · Shift+I', 'key the pose · delete the key at the playhead'],
  ['K · [ · ] · Home · End', 'play/pause · previous, next keyframe · start, end'],
  ['Drag elsewhere', 'orbit (right button: pan)'],
] as const;

export type Skin3DAction =
  | 'translate'
  | 'rotate'
  | 'scale'
  | 'remove'
  | 'escape'
  | 'reset-pose'
  | 'toggle-cage'
  | 'toggle-target'
  | 'toggle-naive'
  | 'toggle-errors'
  | 'play'
  | 'add-key'
  | 'delete-key'
  | 'previous-key'
  | 'next-key'
  | 'start'
  | 'end';

const KEYS: Record<string, Skin3DAction> = {
  g: 'translate',
  r: 'rotate',
  s: 'scale',
  delete: 'remove',
  backspace: 'remove',
  escape: 'escape',
  '0': 'reset-pose',
  c: 'toggle-cage',
  t: 'toggle-target',
  n: 'toggle-naive',
  e: 'toggle-errors',
  k: 'play',
  i: 'add-key',
  '[': 'previous-key',
  ']': 'next-key',
  home: 'start',
  end: 'end',
};

/** The action of a key press (modifiers other than Shift are the editor's), or null. */
export function keyAction3D(e: KeyboardEvent): Skin3DAction | null {
  const action = KEYS[e.key.toLowerCase()] ?? null;
  return action === 'add-key' && e.shiftKey ? 'delete-key' : action;
}
