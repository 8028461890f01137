/**
 * Counts a mode's asynchronous work under way (mesh loads, worker requests, queued edits, rig
 * builds): the one place that knows whether a mode is busy. The end-to-end test hook waits on
 * `idle()` to know when a mode has settled.
 *
 *   const work = new InFlight();
 *   const reply = await work.track(client.request(...)); // counted until it settles
 *   const end = work.begin(); try { ... } finally { end(); } // work done by hand
 *   await work.idle();
 */
export class InFlight {
  private count = 0;
  private waiters: (() => void)[] = [];

  /** How many tracked pieces of work have not settled yet. */
  get size(): number {
    return this.count;
  }

  /** Whether any tracked work has not settled yet. */
  get busy(): boolean {
    return this.count > 0;
  }

  /** Counts `work` until it settles (either way) and returns it unchanged. */
  track<T>(work: Promise<T>): Promise<T> {
    const end = this.begin();
    work.then(end, end);
    return work;
  }

  /** Counts one piece of work from now; the returned function ends it (calls after the first do nothing). */
  begin(): () => void {
    this.count++;
    let ended = false;
    return () => {
      if (ended) return;
      ended = true;
      this.count--;
      if (this.count === 0) this.wakeLater();
    };
  }

  /**
   * Resolves once nothing is in flight. When the last piece of work ends, waiters are woken on a
   * later task, so that what its handlers start in reply (a follow-up request) counts first.
   */
  idle(): Promise<void> {
    if (this.count === 0) return Promise.resolve();
    return new Promise((resolve) => this.waiters.push(resolve));
  }

  private wakeLater(): void {
    setTimeout(() => {
      if (this.count !== 0) return;
      const waiters = this.waiters;
      this.waiters = [];
      for (const w of waiters) w();
    }, 0);
  }
}
