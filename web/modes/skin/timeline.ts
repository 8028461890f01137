import { h, noFocusOnClick } from '../../ui/dom.js';

export interface TimelineActions {
  togglePlay(): void;
  /** Moves the playhead; `live` while the pointer drags it. */
  seek(time: number, live: boolean): void;
  addKeyframe(): void;
  deleteKeyframe(): void;
  /** Keyframe `index` was dragged to `time`. */
  moveKeyframe(index: number, time: number): void;
  setDuration(seconds: number): void;
}

export interface TimelineView {
  duration: number;
  time: number;
  keyframes: readonly number[];
  playing: boolean;
  /** Whether there are handles to key. */
  canKey: boolean;
  /** Index of the keyframe at the playhead, or -1. */
  keyHere: number;
  /** The pose differs from the animation at the playhead (not keyed yet). */
  unkeyed: boolean;
}

/** Snap distance to a keyframe while scrubbing (pixels). */
const SNAP_PX = 6;

function fmt(t: number): string {
  return `${t.toFixed(2)} s`;
}

/**
 * The skin timeline along the bottom of the canvas: play/pause, the playhead over a ruler in
 * seconds with the keyframes as diamonds, add/delete keyframe and the animation's length.
 */
export class Timeline {
  readonly el: HTMLElement;
  private readonly play: HTMLButtonElement;
  private readonly clock = h('span', { class: 'tl-clock', 'data-testid': 'timeline-time' });
  private readonly track = h('div', { class: 'tl-track', 'data-testid': 'timeline-track', role: 'slider', 'aria-label': 'Time', tabindex: '-1' });
  private readonly ruler = h('div', { class: 'tl-ruler' });
  private readonly keys = h('div', { class: 'tl-keys' });
  private readonly head = h('div', { class: 'tl-head' });
  private readonly addKey: HTMLButtonElement;
  private readonly deleteKey: HTMLButtonElement;
  private readonly length: HTMLInputElement;
  private view: TimelineView = { duration: 2, time: 0, keyframes: [], playing: false, canKey: false, keyHere: -1, unkeyed: false };
  private rulerFor = -1;

  constructor(private readonly actions: TimelineActions) {
    this.play = noFocusOnClick(h('button', { type: 'button', class: 'tl-play', 'data-testid': 'timeline-play', title: 'Play / pause (K)', 'aria-label': 'Play' }));
    this.play.addEventListener('click', () => actions.togglePlay());
    this.addKey = noFocusOnClick(h('button', { type: 'button', class: 'tl-button', 'data-testid': 'keyframe-add', title: 'Key the current pose at the playhead (I)' }, '◆ Key'));
    this.addKey.addEventListener('click', () => actions.addKeyframe());
    this.deleteKey = noFocusOnClick(h('button', { type: 'button', class: 'tl-button', 'data-testid': 'keyframe-delete', title: 'Delete the keyframe at the playhead (Shift+I)' }, 'Delete key'));
    this.deleteKey.addEventListener('click', () => actions.deleteKeyframe());
    this.length = h('input', { type: 'number', class: 'tl-length', min: '0.1', max: '600', step: '0.1', 'aria-label': 'Length in seconds', title: 'Length of the animation (seconds)', 'data-testid': 'timeline-length' });
    this.length.addEventListener('change', () => {
      const v = Number(this.length.value);
      if (Number.isFinite(v) && v >= 0.1) actions.setDuration(Math.min(600, v));
      else this.length.value = String(this.view.duration);
      this.length.blur();
    });
    this.track.append(this.ruler, this.keys, this.head);
    this.listen();
    this.el = h(
      'div',
      { class: 'timeline', 'data-testid': 'timeline' },
      this.play,
      this.clock,
      this.track,
      this.addKey,
      this.deleteKey,
      h('label', { class: 'tl-length-label' }, 'Length', this.length, 's'),
    );
  }

  update(view: TimelineView): void {
    this.view = view;
    this.play.textContent = view.playing ? '❚❚' : '▶';
    this.play.setAttribute('aria-label', view.playing ? 'Pause' : 'Play');
    this.play.disabled = view.keyframes.length < 2;
    this.play.title = view.keyframes.length < 2 ? 'Key at least two poses to play them (I)' : 'Play / pause (K)';
    this.clock.textContent = fmt(view.time);
    this.clock.classList.toggle('unkeyed', view.unkeyed);
    this.clock.title = view.unkeyed ? 'The pose here is not keyed: press I to key it' : '';
    this.addKey.disabled = !view.canKey;
    this.deleteKey.disabled = view.keyHere < 0;
    if (document.activeElement !== this.length) this.length.value = String(+view.duration.toFixed(3));
    if (this.rulerFor !== view.duration) this.drawRuler();
    const x = (t: number) => `${(100 * t) / Math.max(view.duration, 1e-9)}%`;
    this.head.style.left = x(view.time);
    this.track.setAttribute('aria-valuenow', view.time.toFixed(2));
    this.keys.replaceChildren(
      ...view.keyframes.map((t, i) =>
        h('i', { class: `tl-key${i === view.keyHere ? ' here' : ''}`, style: `left:${x(t)}`, 'data-index': i, title: `Keyframe at ${fmt(t)}: click to go there, drag to move it` }),
      ),
    );
  }

  private drawRuler(): void {
    const d = this.view.duration;
    this.rulerFor = d;
    const step = d <= 2 ? 0.25 : d <= 5 ? 0.5 : d <= 20 ? 1 : d <= 60 ? 5 : 30;
    const ticks: HTMLElement[] = [];
    for (let t = 0; t <= d + 1e-9; t += step) {
      const major = Math.abs(t / (step * 2) - Math.round(t / (step * 2))) < 1e-6;
      ticks.push(h('span', { class: `tl-tick${major ? ' major' : ''}`, style: `left:${(100 * t) / d}%` }, major ? `${+t.toFixed(2)}` : ''));
    }
    this.ruler.replaceChildren(...ticks);
  }

  /** The time under a client x; snapped to keyframes (but `except`) within a few pixels. */
  private timeAt(clientX: number, except = -1): number {
    const r = this.track.getBoundingClientRect();
    const f = Math.min(1, Math.max(0, (clientX - r.left) / Math.max(1, r.width)));
    let t = f * this.view.duration;
    const px = r.width / Math.max(this.view.duration, 1e-9);
    this.view.keyframes.forEach((k, i) => {
      if (i !== except && Math.abs(k - t) * px <= SNAP_PX) t = k;
    });
    return t;
  }

  private listen(): void {
    // Scrubbing (a press on the track) or moving a keyframe (a press on its diamond).
    let drag: { pointer: number; key: number; x: number; moved: boolean } | null = null;
    this.track.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      const key = e.target instanceof HTMLElement && e.target.dataset.index !== undefined ? Number(e.target.dataset.index) : -1;
      drag = { pointer: e.pointerId, key, x: e.clientX, moved: false };
      this.track.setPointerCapture(e.pointerId);
      this.actions.seek(key >= 0 ? this.view.keyframes[key] : this.timeAt(e.clientX), true);
      e.preventDefault();
    });
    this.track.addEventListener('pointermove', (e) => {
      if (!drag || drag.pointer !== e.pointerId) return;
      drag.moved ||= Math.abs(e.clientX - drag.x) > 3;
      if (drag.key < 0) this.actions.seek(this.timeAt(e.clientX), true);
      else if (drag.moved) {
        // Preview: move the diamond; the keyframe moves (undoably) on release.
        const el = this.keys.children[drag.key] as HTMLElement | undefined;
        if (el) el.style.left = `${(100 * this.timeAt(e.clientX, drag.key)) / Math.max(this.view.duration, 1e-9)}%`;
      }
    });
    const end = (e: PointerEvent) => {
      const d = drag;
      if (!d || d.pointer !== e.pointerId) return;
      drag = null;
      if (d.key >= 0 && d.moved) this.actions.moveKeyframe(d.key, this.timeAt(e.clientX, d.key));
      else this.actions.seek(d.key >= 0 ? this.view.keyframes[d.key] : this.timeAt(e.clientX), false);
    };
    this.track.addEventListener('pointerup', end);
    this.track.addEventListener('pointercancel', end);
  }
}
