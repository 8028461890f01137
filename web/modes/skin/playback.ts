/**
 * Plays the timeline: calls `advance(seconds)` every animation frame with the time since the
 * previous one (at most 0.1 s, so a stalled tab does not jump) until stopped.
 */
export class Playback {
  private raf = 0;
  private last = 0;

  constructor(private readonly advance: (dt: number) => void) {}

  get playing(): boolean {
    return this.raf !== 0;
  }

  start(): void {
    if (this.raf) return;
    this.last = performance.now();
    const step = (now: number) => {
      const dt = Math.min(0.1, Math.max(0, (now - this.last) / 1000));
      this.last = now;
      this.raf = requestAnimationFrame(step);
      this.advance(dt);
    };
    this.raf = requestAnimationFrame(step);
  }

  /** Stops; returns whether it was playing. */
  stop(): boolean {
    if (!this.raf) return false;
    cancelAnimationFrame(this.raf);
    this.raf = 0;
    return true;
  }
}
