/** Skin mode's keys: what the panel lists, and which key does what. */

/** [keys, what] rows for the panel's Keys section. */
export const SKIN_KEYS = [
  ['R · P', 'Rig tool (place handles) · Pose tool'],
  ['Click (Rig) · Shift+click', 'add a handle'],
  ['Drag a handle', 'pose it (Pose) · move its rest position (Rig)'],
  ['Shift+drag · Alt+drag', 'turn · scale the handle'],
  ['Ring · square knob', 'turn (Shift snaps 15°) · scale'],
  ['Delete · Esc', 'remove the selected handle · deselect'],
  ['0', 'reset the pose (selected handle, or all)'],
  ['T · E · N · W', 'target · heat map · naive · weight field'],
  ['I · Shift+I', 'key the pose · delete the key at the playhead'],
  ['K · [ · ] · Home · End', 'play/pause · previous, next keyframe · start, end'],
] as const;

export type SkinAction =
  | 'tool-rig'
  | 'tool-pose'
  | 'remove'
  | 'escape'
  | 'reset-pose'
  | 'toggle-target'
  | 'toggle-heat'
  | 'toggle-naive'
  | 'toggle-field'
  | 'play'
  | 'add-key'
  | 'delete-key'
  | 'previous-key'
  | 'next-key'
  | 'start'
  | 'end';

const KEYS: Record<string, SkinAction> = {
  r: 'tool-rig',
  p: 'tool-pose',
  delete: 'remove',
  backspace: 'remove',
  escape: 'escape',
  '0': 'reset-pose',
  t: 'toggle-target',
  e: 'toggle-heat',
  n: 'toggle-naive',
  w: 'toggle-field',
  k: 'play',
  i: 'add-key',
  '[': 'previous-key',
  ']': 'next-key',
  home: 'start',
  end: 'end',
};

/** The action of a key press (modifiers other than Shift are the editor's), or null. */
export function keyAction(e: KeyboardEvent): SkinAction | null {
  const action = KEYS[e.key.toLowerCase()] ?? null;
  return action === 'add-key' && e.shiftKey ? 'delete-key' : action;
}
