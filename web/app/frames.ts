/**
 * Draws at most once per animation frame, however often a redraw is asked for, and resolves the
 * promises of those waiting for the next drawn frame. Shared by the 2D and 3D views.
 */
export class FrameScheduler {
  private pending = 0;
  private waiting: (() => void)[] = [];

  constructor(private readonly draw: (time: number) => void) {}

  request(): void {
    if (this.pending) return;
    this.pending = requestAnimationFrame((time) => {
      this.pending = 0;
      this.draw(time);
      const waiting = this.waiting;
      this.waiting = [];
      for (const resolve of waiting) resolve();
    });
  }

  /** Resolves once the next frame has been drawn. */
  next(): Promise<void> {
    return new Promise((resolve) => {
      this.waiting.push(resolve);
      this.request();
    });
  }

  cancel(): void {
    cancelAnimationFrame(this.pending);
    this.pending = 0;
  }
}
