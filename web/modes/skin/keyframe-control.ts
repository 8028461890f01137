import { deleteKeyframe, keyframeAt, retimeKeyframe, setKeyframe, type Animated } from '../../app/keyframes.js';
import { Playback } from './playback.js';
import type { TimelineActions } from './timeline.js';

/** What the timeline edits: a session's keyframed spec and its playhead. */
export interface KeyedSession<S extends Animated<unknown>> {
  readonly spec: S;
  readonly time: number;
  /** Moves the playhead; with keyframes the pose follows (`live` during scrubbing and playback). */
  setTime(time: number, options?: { live?: boolean }): void;
}

/** The timeline's keys (K, I, Shift+I, [, ], Home, End in both skin modes). */
export type TimelineKey = 'play' | 'add-key' | 'delete-key' | 'previous-key' | 'next-key' | 'start' | 'end';

/** What a mode lends the keyframe controls. */
export interface KeyframeHost<S extends Animated<unknown>> {
  session(): KeyedSession<S> | null;
  /** Whether there is something to key (handles). */
  canKey(): boolean;
  /** Whether a gesture is under way (playback does not start then). */
  busy(): boolean;
  /** Records an edit of the spec (undoable). */
  execute(label: string, after: S): void;
  /** The timeline needs redrawing. */
  refresh(): void;
  /** Playback stopped at the session's time (e.g. relax the pose it stopped at). */
  stopped(): void;
}

/**
 * The keyframe edits and playback of a timeline (Skin and 3D Skin modes): add, replace, delete
 * and move keyframes, the animation's length, seeking, jumping between keyframes, play/pause.
 * Every spec edit goes through the host (so it is undoable); the playhead is the session's.
 */
export class KeyframeControl<S extends Animated<unknown>> {
  private readonly playback = new Playback((dt) => {
    const s = this.host.session();
    if (s) s.setTime((s.time + dt) % s.spec.duration, { live: true });
  });

  constructor(private readonly host: KeyframeHost<S>) {}

  /** The timeline's actions, wired to these controls. */
  get actions(): TimelineActions {
    return {
      togglePlay: () => this.togglePlay(),
      seek: (time, live) => this.seek(time, live),
      addKeyframe: () => this.addKeyframe(),
      deleteKeyframe: () => this.deleteKeyframe(),
      moveKeyframe: (index, time) => this.moveKeyframe(index, time),
      setDuration: (seconds) => this.setDuration(seconds),
    };
  }

  get playing(): boolean {
    return this.playback.playing;
  }

  /** Does what a timeline key asks. */
  runKey(key: TimelineKey): void {
    const s = this.host.session();
    if (key === 'play') this.togglePlay();
    else if (key === 'add-key') this.addKeyframe();
    else if (key === 'delete-key') this.deleteKeyframe();
    else if (key === 'previous-key' || key === 'next-key') this.jump(key === 'next-key' ? 1 : -1);
    else this.seek(key === 'start' ? 0 : (s?.spec.duration ?? 0), false);
  }

  addKeyframe(): void {
    const s = this.host.session();
    if (!s || !this.host.canKey()) return;
    this.stop();
    this.host.execute(keyframeAt(s.spec, s.time) < 0 ? 'Add keyframe' : 'Replace keyframe', setKeyframe(s.spec, s.time));
  }

  deleteKeyframe(): void {
    const s = this.host.session();
    if (!s) return;
    const i = keyframeAt(s.spec, s.time);
    if (i >= 0) this.host.execute('Delete keyframe', deleteKeyframe(s.spec, i));
  }

  moveKeyframe(index: number, time: number): void {
    const s = this.host.session();
    if (!s || !s.spec.keyframes[index]) return;
    const after = retimeKeyframe(s.spec, index, time);
    if (Math.abs(after.keyframes[index].time - s.spec.keyframes[index].time) < 1e-9) return this.host.refresh();
    this.host.execute('Move keyframe', after);
    s.setTime(after.keyframes[index].time);
  }

  setDuration(seconds: number): void {
    const s = this.host.session();
    if (!s) return;
    const d = Math.max(seconds, s.spec.keyframes.at(-1)?.time ?? 0, 0.1);
    if (Math.abs(s.spec.duration - d) >= 1e-9) this.host.execute('Set animation length', { ...s.spec, duration: d });
    this.host.refresh();
  }

  seek(time: number, live: boolean): void {
    const s = this.host.session();
    if (!s) return;
    this.stop();
    s.setTime(time, { live });
    this.host.refresh();
  }

  /** To the next (1) or previous (−1) keyframe from the playhead. */
  jump(direction: 1 | -1): void {
    const s = this.host.session();
    if (!s || s.spec.keyframes.length === 0) return;
    const times = s.spec.keyframes.map((k) => k.time);
    const next = direction > 0 ? times.find((t) => t > s.time + 1e-6) : [...times].reverse().find((t) => t < s.time - 1e-6);
    if (next !== undefined) this.seek(next, false);
  }

  togglePlay(): void {
    if (this.playback.playing) this.stop();
    else this.play();
  }

  play(): void {
    const s = this.host.session();
    if (!s || s.spec.keyframes.length < 2 || this.playback.playing || this.host.busy()) return;
    if (s.time >= s.spec.duration - 1e-6) s.setTime(0, { live: true });
    this.playback.start();
    this.host.refresh();
  }

  /** Stops playing (the host settles the pose it stopped at). */
  stop(): void {
    if (!this.playback.stop()) return;
    this.host.stopped();
    this.host.refresh();
  }
}
