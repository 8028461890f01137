import type { SurfaceSplineJSON, TraceOptions } from '../../../src/index.js';
import { SupersededError, type Ran } from './client.js';
import { messageOf, type SurfaceContext } from './context.js';
import type { DrawnSpline } from './drawing.js';
import type { PolygonPaths, TracedPolyline } from './protocol.js';

interface TraceEntry {
  key: string;
  trace: TracedPolyline;
}

/** The last trace (one spline), or the last retrace of several together. */
export interface TraceReport {
  /** Milliseconds per spline (the mean over a retrace of several). */
  ms: number;
  points: number;
  count: number;
  sum: number;
}

/**
 * The traced polylines and control polygons of Surface mode's splines, kept per spline state (the
 * immutable JSON of each edit, so an undo finds its trace again), asked of the worker when
 * missing; and the live results a gesture shows instead while it runs.
 */
export class TraceCache {
  private readonly traces = new WeakMap<SurfaceSplineJSON, TraceEntry>();
  private readonly polygons = new WeakMap<SurfaceSplineJSON, PolygonPaths>();
  /** What was asked for a spline state and not answered yet: a trace (its options key), its polygon. */
  private readonly requested = new WeakMap<SurfaceSplineJSON, { trace: string | null; polygon: boolean }>();
  /** Results shown while a gesture runs (spline id → the latest reply). */
  private readonly live = new Map<number, Ran>();
  private batch: { left: number; count: number; sum: number; points: number } | null = null;
  private _last: TraceReport | null = null;

  constructor(private readonly mode: SurfaceContext) {}

  /** The last trace, or null (none yet, or the options changed since). */
  get last(): TraceReport | null {
    return this._last;
  }

  /** Forgets the last trace report (the options changed). */
  resetLast(): void {
    this._last = null;
  }

  /** Identifies the trace options now asked for. */
  key(): string {
    return JSON.stringify(this.mode.traceOptions());
  }

  /** The worker lane of spline `id`: its requests are coalesced, per mesh load. */
  lane(id: number): string {
    return `${this.mode.generation}:${id}`;
  }

  /** Asks the worker for every trace (and the selected or drawn spline's control polygon) not at hand. */
  ensure(): void {
    const mode = this.mode, s = mode.session;
    if (!s || !mode.mesh) return;
    const key = this.key(), gen = mode.generation, options = mode.traceOptions();
    const asks: { run: () => void; trace: boolean }[] = [];
    for (const sp of s.drawing.splines) {
      if (this.live.has(sp.id)) continue;
      const json = sp.json;
      const wantPolygon = mode.selection?.spline === sp.id || mode.drawingId === sp.id;
      const asked = this.requested.get(json) ?? { trace: null, polygon: false };
      const needTrace = this.traces.get(json)?.key !== key && asked.trace !== key;
      const needPolygon = wantPolygon && !this.polygons.has(json) && !asked.polygon;
      if (!needTrace && !needPolygon) continue;
      if (needTrace) asked.trace = key;
      if (needPolygon) asked.polygon = true;
      this.requested.set(json, asked);
      asks.push({ run: () => this.ask(sp.id, json, key, gen, needTrace ? options : null, needPolygon, batch), trace: needTrace });
    }
    // Several traces at once (options changed, a drawing restored): reported together.
    const traces = asks.filter((a) => a.trace).length;
    const batch = traces > 1 ? { left: traces, count: traces, sum: 0, points: 0 } : null;
    if (batch) this.batch = batch;
    for (const ask of asks) ask.run();
  }

  private ask(id: number, json: SurfaceSplineJSON, key: string, gen: number, options: TraceOptions | null, polygon: boolean, batch: TraceCache['batch']): void {
    const mode = this.mode;
    mode.client
      .run(json, [], options, polygon, this.lane(id))
      .then((r) => {
        if (gen !== mode.generation) return;
        if (r.trace) {
          this.traces.set(json, { key, trace: r.trace });
          if (batch && this.batch === batch) {
            batch.sum += r.traceMs;
            batch.points += r.trace.xyz.length / 3;
          } else this.note(r);
        }
        if (r.polygon) this.polygons.set(json, r.polygon);
        mode.requestDraw();
      })
      .catch((err: unknown) => {
        const asked = this.requested.get(json);
        if (asked && options && asked.trace === key) asked.trace = null;
        if (asked && polygon) asked.polygon = false;
        if (err instanceof SupersededError) {
          mode.work.track(new Promise<void>((resolve) => setTimeout(resolve, 0))).then(() => this.ensure());
          return;
        }
        if (gen === mode.generation) mode.setError(`Tracing failed: ${messageOf(err)}`);
      })
      .finally(() => {
        if (options && batch && this.batch === batch && --batch.left === 0) {
          this.batch = null;
          this._last = { ms: batch.sum / batch.count, points: batch.points, count: batch.count, sum: batch.sum };
          mode.refreshStatus();
        }
      });
  }

  /** Keeps an edit's reply as the trace and polygon of the spline state it made. */
  store(r: Ran): void {
    if (r.trace) this.traces.set(r.json, { key: this.key(), trace: r.trace });
    if (r.polygon) this.polygons.set(r.json, r.polygon);
  }

  /** Reports a reply's trace as the last one. */
  note(r: Ran): void {
    if (!r.trace) return;
    this._last = { ms: r.traceMs, points: r.trace.xyz.length / 3, count: 1, sum: r.traceMs };
    this.mode.refreshStatus();
  }

  /**
   * The polyline shown for a spline: a gesture's live result, else its stored trace, whatever
   * options it was traced with (an older one stays shown while the retrace comes).
   */
  traceOf(sp: DrawnSpline): TracedPolyline | null {
    const live = this.live.get(sp.id);
    if (live?.trace) return live.trace;
    return this.traces.get(sp.json)?.trace ?? null;
  }

  polygonOf(sp: DrawnSpline): PolygonPaths | null {
    const live = this.live.get(sp.id);
    if (live) return live.polygon;
    return this.polygons.get(sp.json) ?? null;
  }

  /** A spline's control points as shown: a gesture's live result, else the drawing's. */
  shownJSON(sp: DrawnSpline): SurfaceSplineJSON {
    return this.live.get(sp.id)?.json ?? sp.json;
  }

  /** Shows `r` for spline `id` while a gesture runs. */
  setLive(id: number, r: Ran): void {
    this.live.set(id, r);
  }

  /** Back to the drawing's own state of spline `id` (or of all splines). */
  dropLive(id?: number): void {
    if (id === undefined) this.live.clear();
    else this.live.delete(id);
  }
}
