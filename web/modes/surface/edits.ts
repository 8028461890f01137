import type { MeshPoint, SurfaceSplineJSON } from '../../../src/index.js';
import { readFile } from '../../app/loader.js';
import type { Ran } from './client.js';
import { DrawingCommand, type SurfaceSelection } from './commands.js';
import { messageOf, type SurfaceContext } from './context.js';
import {
  EMPTY_DRAWING,
  addSplines,
  anchorCount,
  anchorOf,
  findSpline,
  isAnchor,
  parseDrawingFile,
  removeSplines,
  replaceSpline,
  type SurfaceDrawing,
} from './drawing.js';
import type { SplineOp } from './protocol.js';
import type { SurfaceSession } from './session.js';
import type { TraceCache } from './trace-cache.js';

function sameMeshPoint(a: MeshPoint, b: MeshPoint): boolean {
  return a.face === b.face && a.uv[0] === b.uv[0] && a.uv[1] === b.uv[1];
}

/**
 * Surface mode's edits of the drawing, each an undoable command: the spline being drawn (click by
 * click), point and spline edits run in the worker one after another (each builds on the previous
 * one), and whole-drawing changes (delete, clear, load).
 */
export class SurfaceEdits {
  /** The spline that clicks extend, and the first point of one not made yet. */
  private _drawingId: number | null = null;
  private _pending: MeshPoint | null = null;
  /** The rubber band from the last drawn point to the pointer (lifted polyline), or null. */
  private _preview: Float32Array | null = null;
  private queue: Promise<void> = Promise.resolve();

  constructor(
    private readonly mode: SurfaceContext,
    private readonly traces: TraceCache,
  ) {}

  get drawingId(): number | null {
    return this._drawingId;
  }

  /** The first point of a spline not made yet (the second click makes it), or null. */
  get pending(): MeshPoint | null {
    return this._pending;
  }

  get preview(): Float32Array | null {
    return this._preview;
  }

  /** Whether clicks are drawing a spline (its first point placed, or it being extended). */
  get drawing(): boolean {
    return this._drawingId !== null || this._pending !== null;
  }

  setPreview(lifted: Float32Array | null): void {
    if (lifted === this._preview) return;
    this._preview = lifted;
    this.mode.requestDraw();
  }

  /** Forgets the spline being drawn without redrawing (another mesh is shown). */
  reset(): void {
    this._drawingId = null;
    this._pending = null;
    this._preview = null;
  }

  /** After the drawing changed (undo, redo): stop extending a spline that is gone. */
  validate(d: SurfaceDrawing): void {
    if (this._drawingId !== null && !findSpline(d, this._drawingId)) {
      this._drawingId = null;
      this._preview = null;
    }
  }

  /** The point the rubber band starts from: the end of the spline being drawn, or its first point. */
  lastDrawnPoint(): MeshPoint | null {
    if (this._drawingId !== null) {
      const sp = findSpline(this.mode.drawing, this._drawingId);
      return sp ? sp.json.points[sp.json.points.length - 1] : null;
    }
    return this._pending;
  }

  /** Runs `task` after the edits before it (each click's edit builds on the previous one). */
  enqueue(task: () => Promise<void>): void {
    this.queue = this.mode.work.track(this.queue.then(task).catch((err: unknown) => this.mode.setError(messageOf(err))));
  }

  /**
   * Records the result of an edit of spline `id` as an undoable command — unless the mesh or the
   * spline changed meanwhile (then the result is stale and dropped).
   */
  commit(label: string, session: SurfaceSession, gen: number, id: number, base: SurfaceSplineJSON | null, r: Ran, select: SurfaceSelection | null): boolean {
    const mode = this.mode, ctx = mode.ctx;
    if (session !== mode.session || gen !== mode.generation || !ctx) return false;
    const before = session.drawing;
    let after: SurfaceDrawing;
    if (base === null) after = addSplines(before, [{ id, json: r.json }]);
    else {
      const sp = findSpline(before, id);
      if (!sp || sp.json !== base) return false;
      after = replaceSpline(before, id, r.json);
    }
    this.traces.store(r);
    this.traces.note(r);
    ctx.history.execute(new DrawingCommand(label, mode, session, before, after, { do: select, undo: mode.selection }));
    return true;
  }

  /** Applies ops to spline `id` in the worker and records the result (queued after other edits). */
  private editSpline(id: number, label: string, ops: (json: SurfaceSplineJSON) => SplineOp[] | null, select: (json: SurfaceSplineJSON) => SurfaceSelection | null): void {
    this.enqueue(async () => {
      const mode = this.mode, s = mode.session, gen = mode.generation;
      const sp = s && findSpline(s.drawing, id);
      if (!s || !sp) return;
      const list = ops(sp.json);
      if (!list) return;
      const r = await mode.client.run(sp.json, list, mode.traceOptions(), true);
      this.commit(label, s, gen, id, sp.json, r, select(r.json));
    });
  }

  /** Replaces the whole drawing as one undoable command (nothing when it is the same). */
  replaceDrawing(label: string, after: SurfaceDrawing, select: SurfaceSelection | null = null): void {
    const mode = this.mode, s = mode.session, ctx = mode.ctx;
    if (!s || !ctx || after === s.drawing) return;
    ctx.history.execute(new DrawingCommand(label, mode, s, s.drawing, after, { do: select, undo: mode.selection }));
  }

  /** A click while drawing: the first point waits, the second makes a spline, then each appends. */
  addPoint(p: MeshPoint): void {
    const mode = this.mode;
    if (this._drawingId === null && !this._pending) {
      this._pending = p;
      mode.setSelection(null);
      return;
    }
    this.enqueue(async () => {
      const s = mode.session, gen = mode.generation;
      if (!s) return;
      if (this._drawingId !== null) {
        const sp = findSpline(s.drawing, this._drawingId);
        if (sp) {
          const last = sp.json.points[sp.json.points.length - 1];
          if (sameMeshPoint(last, p)) return;
          const r = await mode.client.run(sp.json, [{ op: 'append', p }], mode.traceOptions(), true);
          this.commit('Add point', s, gen, sp.id, sp.json, r, { spline: sp.id, point: r.json.points.length - 1 });
          return;
        }
        this._drawingId = null;
      }
      const first = this._pending;
      if (!first) {
        this._pending = p;
        mode.requestDraw();
        return;
      }
      if (sameMeshPoint(first, p)) return;
      const r = await mode.client.run(null, [{ op: 'fromPolygon', anchors: [first, p] }], mode.traceOptions(), true);
      const id = s.newId();
      if (this.commit('Draw spline', s, gen, id, null, r, { spline: id, point: r.json.points.length - 1 })) {
        if (this._pending === first) this._pending = null;
        this._drawingId = id;
        mode.requestDraw();
      }
    });
  }

  /** Ends the spline being drawn (a lone first point is dropped); false when none was. */
  finish(): boolean {
    const was = this.drawing;
    this.reset();
    if (was) {
      this.mode.refreshPanel();
      this.mode.requestDraw();
    }
    return was;
  }

  /** Makes the selected anchor smooth, or a corner. */
  toggleSmooth(): void {
    const sel = this.mode.selection, sp = sel && findSpline(this.mode.drawing, sel.spline);
    if (!sel || !sp || sel.point === null) return;
    const anchor = anchorOf(sel.point, sp.json);
    const smooth = !sp.json.smooth[anchor / 3];
    this.editSpline(sp.id, smooth ? 'Make anchor smooth' : 'Make anchor a corner', () => [{ op: 'setSmooth', anchor, smooth }], () => ({ spline: sp.id, point: anchor }));
  }

  /** Inserts an anchor at parameter t of a segment. */
  insertPoint(id: number, segment: number, t: number): void {
    const options = this.mode.traceOptions();
    this.editSpline(
      id,
      'Insert point',
      (json) => (segment < (json.points.length - 1) / 3 || (json.closed && segment < json.points.length / 3) ? [{ op: 'insert', segment, t, options }] : null),
      () => ({ spline: id, point: 3 * (segment + 1) }),
    );
  }

  /** Inserts an anchor in the middle of the selected point's segment (the first segment for a spline). */
  insertAfterSelected(): void {
    const sel = this.mode.selection, sp = sel && findSpline(this.mode.drawing, sel.spline);
    if (!sel || !sp) return;
    const segments = sp.json.closed ? sp.json.points.length / 3 : (sp.json.points.length - 1) / 3;
    const anchor = sel.point === null ? 0 : anchorOf(sel.point, sp.json);
    const segment = Math.min(anchor / 3, segments - 1);
    this.insertPoint(sp.id, segment, 0.5);
  }

  /** Deletes the selected anchor (the spline, when it would have fewer than two). */
  deleteSelectedPoint(): void {
    const sel = this.mode.selection, sp = sel && findSpline(this.mode.drawing, sel.spline);
    if (!sel || !sp || sel.point === null || !isAnchor(sel.point)) return;
    if (anchorCount(sp.json) <= 2) {
      this.deleteSelectedSpline();
      return;
    }
    const anchor = sel.point;
    this.editSpline(sp.id, 'Delete point', () => [{ op: 'remove', anchor }], (json) => ({ spline: sp.id, point: Math.min(anchor, json.points.length - 1) }));
  }

  deleteSelectedSpline(): void {
    const sel = this.mode.selection;
    if (!sel || !findSpline(this.mode.drawing, sel.spline)) return;
    if (this._drawingId === sel.spline) this.finish();
    this.replaceDrawing('Delete spline', removeSplines(this.mode.drawing, [sel.spline]), null);
  }

  clearDrawing(): void {
    if (this.mode.drawing.splines.length === 0) return;
    this.finish();
    this.replaceDrawing('Clear the drawing', EMPTY_DRAWING, null);
  }

  /** Replaces the drawing by a saved drawing file (undoable). */
  async loadDrawingFile(file: File): Promise<void> {
    const mode = this.mode, s = mode.session, ctx = mode.ctx;
    if (!s || !ctx || !mode.mesh) return;
    try {
      const text = new TextDecoder().decode(await readFile(file));
      const parsed = parseDrawingFile(text, mode.mesh.info.faces);
      const splines = parsed.splines.map((json) => ({ id: s.newId(), json }));
      this.finish();
      this.replaceDrawing(`Load ${file.name}`, { splines }, null);
      if (parsed.mesh && parsed.mesh !== s.file) ctx.state.setMessage(`${file.name} was drawn on ${parsed.mesh}; shown on ${s.file}`);
    } catch (err) {
      ctx.state.setError(`${file.name}: ${messageOf(err)}`);
    }
  }
}
