import type { View2D, ViewPointer } from '../view2d/view2d.js';
import type { ControlOverlay } from '../overlay/overlay.js';
import { Emitter } from './events.js';
import type { History } from './history.js';
import type { EditorState, LoadedDocument } from './state.js';

/** What a mode gets to work with while it is active. */
export interface ModeContext {
  state: EditorState;
  history: History;
  view: View2D;
  overlay: ControlOverlay;
  /** The side panel's body: the mode owns its content while active. */
  panel: HTMLElement;
  /** A strip under the view (e.g. a timeline): the mode owns its content while active. */
  dock: HTMLElement;
}

/**
 * A capability of the editor (Document today; skin, surface, morph, edit later). A mode is
 * registered only once it works: the mode switcher lists exactly the registered modes.
 */
export interface Mode {
  readonly id: string;
  readonly title: string;
  /** One line shown as the switcher's tooltip. */
  readonly description: string;
  /** The mode's own keys and gestures, listed first in the panel's Keys section: [keys, what]. */
  readonly keys?: readonly (readonly [string, string])[];
  /** Called when the mode becomes active: build the panel, subscribe to state. */
  activate(ctx: ModeContext): void;
  /** Called when another mode takes over: unsubscribe, release what activate() made. */
  deactivate(): void;
  /** A pointer went down on the view; return true to own the gesture (otherwise it pans). */
  pointerDown?(p: ViewPointer): boolean;
  /** The pointer moved over the view (hover, or a drag the mode owns). */
  pointerMove?(p: ViewPointer): void;
  /** The pointer of a gesture the mode owns went up. */
  pointerUp?(p: ViewPointer): void;
  /** The pointer left the view. */
  pointerLeave?(): void;
  /** A click (down and up without dragging) on the view that no gesture claimed. */
  click?(p: ViewPointer): void;
  /** A key the editor did not use itself; return true when handled. */
  keyDown?(e: KeyboardEvent): boolean;
  /**
   * The markup the toolbar's Export writes for `current` while this mode is active (e.g. with the
   * mode's data embedded); undefined leaves the default (the document as it is).
   */
  exportDocument?(current: LoadedDocument): string | undefined;
}

export class ModeRegistry {
  readonly events = new Emitter<{ change: Mode }>();
  private readonly modes: Mode[] = [];
  private _active: Mode | null = null;

  constructor(private readonly context: () => ModeContext) {}

  register(mode: Mode): void {
    if (this.modes.some((m) => m.id === mode.id)) throw new Error(`mode ${mode.id} is registered twice`);
    this.modes.push(mode);
  }

  get list(): readonly Mode[] {
    return this.modes;
  }

  get active(): Mode | null {
    return this._active;
  }

  activate(id: string): void {
    const mode = this.modes.find((m) => m.id === id);
    if (!mode) throw new Error(`unknown mode ${id}`);
    if (mode === this._active) return;
    this._active?.deactivate();
    const ctx = this.context();
    ctx.panel.replaceChildren();
    ctx.dock.replaceChildren();
    this._active = mode;
    mode.activate(ctx);
    this.events.emit('change', mode);
  }
}
