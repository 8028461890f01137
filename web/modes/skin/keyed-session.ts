import { Emitter } from '../../app/events.js';
import type { Animated } from '../../app/keyframes.js';

/** The events every skin session (2D and 3D) emits. */
export interface KeyedSessionEvents<S> {
  /** The spec changed (any edit, undo, restore); `live` while a gesture is under way. */
  spec: { spec: S; live: boolean };
  /** The selected handle's id, or null. */
  selection: number | null;
  /** The playhead moved (seconds). */
  time: number;
}

/** A spec with keyframed poses and handles that keep an id. */
type KeyedSpec = Animated<unknown> & { readonly handles: readonly { readonly id: number }[] };

/**
 * What Skin's and 3D Skin's sessions share: the spec (an immutable value each edit replaces), the
 * playhead, the selected handle, and what happens when the spec changes: the rig is rebuilt if
 * needed, the pose applied, then 'spec' is emitted. Subclasses build and pose their rig.
 */
export abstract class KeyedSession<S extends KeyedSpec, E extends KeyedSessionEvents<S> & Record<string, unknown>> {
  readonly events = new Emitter<E>();
  protected _spec: S;
  protected _time = 0;
  private _selected: number | null = null;

  constructor(spec: S) {
    this._spec = spec;
  }

  get spec(): S {
    return this._spec;
  }
  get time(): number {
    return this._time;
  }
  get selected(): number | null {
    return this._selected;
  }
  /** The next free handle id. */
  get nextId(): number {
    return this._spec.handles.reduce((m, h) => Math.max(m, h.id + 1), 0);
  }

  /** Index of a handle id in the spec, or -1. */
  indexOf(id: number | null): number {
    return id === null ? -1 : this._spec.handles.findIndex((h) => h.id === id);
  }

  /** Replaces the spec (an edit, an undo, a restore): rebuilds the rig if needed and poses. */
  apply(spec: S, options: { live?: boolean } = {}): void {
    const live = options.live ?? false;
    this._spec = spec;
    if (this._time > spec.duration) this._time = spec.duration;
    if (this._selected !== null && this.indexOf(this._selected) < 0) this.select(null);
    this.ensureRig();
    this.repose(live);
    this.emit('spec', { spec, live });
  }

  /** Starts from a saved spec with the playhead at `time` (the saved pose wins over the animation). */
  restore(spec: S, time: number): void {
    this._time = Math.min(spec.duration, Math.max(0, time));
    this.apply(spec);
    this.emit('time', this._time);
  }

  select(id: number | null): void {
    if (id === this._selected) return;
    this._selected = id;
    this.emit('selection', id);
  }

  /** Moves the playhead; with keyframes, the pose follows the animation. */
  setTime(time: number, options: { live?: boolean } = {}): void {
    const t = Math.min(this._spec.duration, Math.max(0, time));
    this._time = t;
    this.emit('time', t);
    if (this._spec.keyframes.length > 0) this.apply(this.posedAt(t), options);
  }

  /** Starts a rig build when the rig in use does not match the spec. */
  protected abstract ensureRig(): void;
  /** Poses the rig for the spec's pose (`live` during a gesture). */
  protected abstract repose(live: boolean): void;
  /** The spec with the pose its keyframes give at `time`. */
  protected abstract posedAt(time: number): S;

  private emit<K extends keyof KeyedSessionEvents<S>>(name: K, payload: KeyedSessionEvents<S>[K]): void {
    // E extends these events: the cast only forgets the subclass's own.
    (this.events as unknown as Emitter<Record<string, unknown>>).emit(name, payload);
  }
}
