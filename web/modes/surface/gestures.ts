import type { MeshPoint, SurfaceSplineJSON } from '../../../src/index.js';
import type { Pointer3D, View3DInput } from '../../view3d/view3d.js';
import { SupersededError, type Ran } from './client.js';
import { messageOf, type SurfaceContext } from './context.js';
import { findSpline, isAnchor } from './drawing.js';
import type { SurfaceEdits } from './edits.js';
import type { SurfacePicking } from './picking.js';
import type { SplineOp } from './protocol.js';
import type { SvgPlacement } from './svg-placement.js';
import type { TraceCache } from './trace-cache.js';

/** Two clicks closer than this (ms, px) make a double click. */
const DOUBLE_CLICK_MS = 400;
const DOUBLE_CLICK_PX = 6;

/** A drag under way: a control point, or the selected spline moved, turned or scaled. */
export type Gesture =
  | { kind: 'point'; id: number; index: number; base: SurfaceSplineJSON; latest: Promise<Ran> | null }
  | { kind: 'move'; id: number; base: SurfaceSplineJSON; from: MeshPoint; latest: Promise<Ran> | null }
  | {
      kind: 'rotate' | 'scale';
      id: number;
      base: SurfaceSplineJSON;
      center: MeshPoint;
      /** The centre and the press, in canvas pixels. */
      cx: number;
      cy: number;
      sx: number;
      sy: number;
      /** +1 when the surface at the centre faces the camera (screen turns are surface turns). */
      facing: number;
      latest: Promise<Ran> | null;
    };

/**
 * Surface mode's pointer input on the 3D view: clicks (draw, select, insert, place an SVG), drags
 * (a control point, or the selected spline by the tool: move, rotate, scale — each drag step runs
 * in the worker, the newest one wins, the release records the last as one undoable edit), the
 * rubber band and the cursor.
 */
export class SurfaceGestures {
  private _gesture: Gesture | null = null;
  /** A release waits for its last reply: input is ignored meanwhile. */
  private committing = false;
  private lastClick: { sx: number; sy: number; time: number } | null = null;

  /** What the 3D view calls. */
  readonly input: View3DInput = {
    pointerDown: (p) => this.press(p),
    pointerDrag: (p) => this.drag(p),
    pointerUp: (p, moved) => void this.release(p, moved),
    hover: (p) => this.hover(p),
    pointerLeave: () => {
      this.edits.setPreview(null);
      this.setCursor(null);
    },
    click: (p) => this.click(p),
    doubleClick: () => {
      this.edits.finish();
    },
  };

  constructor(
    private readonly mode: SurfaceContext,
    private readonly traces: TraceCache,
    private readonly picking: SurfacePicking,
    private readonly edits: SurfaceEdits,
    private readonly placement: SvgPlacement,
  ) {}

  /** The drag under way, or null. */
  get gesture(): Gesture | null {
    return this._gesture;
  }

  /** Ends the drag under way without an edit (Esc, another mesh, the mode left). */
  cancel(): void {
    const g = this._gesture;
    if (!g) return;
    this._gesture = null;
    this.traces.dropLive(g.id);
    this.mode.requestDraw();
  }

  setCursor(cursor: string | null): void {
    const c = this.mode.view?.canvas;
    if (c) c.style.cursor = cursor ?? '';
  }

  private get interactive(): boolean {
    const mode = this.mode;
    return mode.session !== null && mode.mesh !== null && !this.committing && mode.ctx !== null;
  }

  private press(p: Pointer3D): boolean {
    const mode = this.mode;
    if (!this.interactive || this.placement.placing) return false;
    const d = mode.drawing;
    if (mode.tool === 'draw') {
      if (p.altKey) return false;
      const hit = this.picking.controlPoint(p.sx, p.sy);
      if (!hit) return false;
      const sp = findSpline(d, hit.id)!;
      mode.setSelection({ spline: hit.id, point: hit.index });
      this._gesture = { kind: 'point', id: hit.id, index: hit.index, base: sp.json, latest: null };
      return true;
    }
    const sp = mode.selection && findSpline(d, mode.selection.spline);
    if (!sp) return false;
    if (mode.tool === 'move') {
      const from = this.picking.meshPointAt(p.sx, p.sy);
      if (!from) return false;
      this._gesture = { kind: 'move', id: sp.id, base: sp.json, from, latest: null };
      return true;
    }
    const c = this.picking.centreOf(sp);
    if (!c) return false;
    this._gesture = { kind: mode.tool, id: sp.id, base: sp.json, center: c.point, cx: c.sx, cy: c.sy, sx: p.sx, sy: p.sy, facing: c.facing, latest: null };
    mode.requestDraw();
    return true;
  }

  private drag(p: Pointer3D): void {
    const g = this._gesture, mode = this.mode;
    if (!g) return;
    let op: SplineOp;
    if (g.kind === 'point' || g.kind === 'move') {
      const to = this.picking.meshPointAt(p.sx, p.sy);
      if (!to) return; // off the mesh: stay where it was last
      if (g.kind === 'point') op = isAnchor(g.index) ? { op: 'moveAnchor', index: g.index, to } : { op: 'moveHandle', index: g.index, to };
      else op = { op: 'translate', from: g.from, to };
    } else if (g.kind === 'rotate') {
      const a0 = Math.atan2(-(g.sy - g.cy), g.sx - g.cx), a1 = Math.atan2(-(p.sy - g.cy), p.sx - g.cx);
      let angle = a1 - a0;
      if (p.shiftKey) angle = Math.round(angle / (Math.PI / 12)) * (Math.PI / 12);
      op = { op: 'rotate', center: g.center, radians: angle * g.facing };
    } else {
      const d0 = Math.hypot(g.sx - g.cx, g.sy - g.cy), d1 = Math.hypot(p.sx - g.cx, p.sy - g.cy);
      const factor = Math.min(20, Math.max(0.05, d1 / Math.max(d0, 8)));
      op = { op: 'scale', center: g.center, factor };
    }
    const gen = mode.generation;
    const promise = mode.client.run(g.base, [op], mode.traceOptions(), true, this.traces.lane(g.id));
    g.latest = promise;
    promise.then(
      (r) => {
        if (this._gesture !== g || gen !== mode.generation) return;
        this.traces.setLive(g.id, r);
        this.traces.note(r);
        mode.requestDraw();
      },
      (err: unknown) => {
        if (err instanceof SupersededError || this._gesture !== g) return;
        mode.ctx?.state.setMessage(`Could not follow the pointer: ${messageOf(err)}`);
      },
    );
  }

  private async release(p: Pointer3D, moved: boolean): Promise<void> {
    const g = this._gesture, mode = this.mode;
    if (!g) return;
    if (p.button === -1 || !moved || !g.latest) {
      this.cancel();
      return;
    }
    const s = mode.session!, gen = mode.generation;
    this.committing = true;
    const end = mode.work.begin();
    try {
      const r = await g.latest;
      if (this._gesture !== g) return; // cancelled meanwhile
      const label = g.kind === 'point' ? (isAnchor(g.index) ? 'Move anchor' : 'Move handle') : g.kind === 'move' ? 'Move spline' : g.kind === 'rotate' ? 'Rotate spline' : 'Scale spline';
      const sel = g.kind === 'point' ? { spline: g.id, point: g.index } : { spline: g.id, point: null };
      this._gesture = null;
      this.traces.dropLive(g.id);
      this.edits.commit(label, s, gen, g.id, g.base, r, sel);
    } catch (err) {
      if (!(err instanceof SupersededError)) mode.setError(messageOf(err));
      if (this._gesture === g) this.cancel();
    } finally {
      this.committing = false;
      end();
      mode.requestDraw();
    }
  }

  private click(p: Pointer3D): void {
    const mode = this.mode, edits = this.edits;
    if (!this.interactive) return;
    if (this.placement.placing) {
      const at = this.picking.meshPointAt(p.sx, p.sy);
      if (at) this.placement.place(at);
      return;
    }
    if (mode.tool !== 'draw') {
      const c = this.picking.curve(p.sx, p.sy);
      mode.setSelection(c ? { spline: c.id, point: null } : null);
      return;
    }
    const last = this.lastClick;
    this.lastClick = { sx: p.sx, sy: p.sy, time: p.time };
    const drawing = edits.drawing;
    if (drawing && last && p.time - last.time < DOUBLE_CLICK_MS && Math.hypot(p.sx - last.sx, p.sy - last.sy) < DOUBLE_CLICK_PX) {
      this.lastClick = null;
      edits.finish();
      return;
    }
    if (p.altKey) {
      const c = this.picking.curve(p.sx, p.sy);
      if (c) edits.insertPoint(c.id, c.segment, c.t);
      return;
    }
    const at = this.picking.meshPointAt(p.sx, p.sy);
    if (drawing) {
      // Off the mesh (a hole, the background) nothing happens: Enter, Esc or a double click ends.
      if (at) edits.addPoint(at);
      return;
    }
    const c = this.picking.curve(p.sx, p.sy);
    if (c) {
      mode.setSelection({ spline: c.id, point: null });
      return;
    }
    if (!at) {
      mode.setSelection(null);
      return;
    }
    edits.addPoint(at);
    mode.refreshPanel();
    mode.requestDraw();
  }

  private hover(p: Pointer3D): void {
    const mode = this.mode, edits = this.edits;
    if (!this.interactive) return;
    if (mode.tool === 'draw' && !this.placement.placing && this.picking.controlPoint(p.sx, p.sy)) {
      this.setCursor('grab');
      edits.setPreview(null);
      return;
    }
    const at = this.picking.meshPointAt(p.sx, p.sy);
    if (this.placement.placing) {
      this.setCursor(at ? 'crosshair' : null);
      return;
    }
    if (mode.tool !== 'draw') {
      this.setCursor(mode.selection && (at || mode.tool !== 'move') ? (mode.tool === 'move' ? 'move' : 'ew-resize') : null);
      return;
    }
    const over = !at && !edits.pending && edits.drawingId === null ? null : at ? 'crosshair' : null;
    this.setCursor(over ?? (this.picking.curve(p.sx, p.sy) ? 'pointer' : at ? 'crosshair' : null));
    // The rubber band: a geodesic from the last point to the pointer.
    const from = edits.lastDrawnPoint();
    if (!from || !at) {
      edits.setPreview(null);
      return;
    }
    const gen = mode.generation;
    mode.client.path(from, at, 'preview').then(
      (r) => {
        if (gen === mode.generation && edits.lastDrawnPoint()) edits.setPreview(r.lifted);
      },
      () => undefined, // superseded, or no path: no rubber band
    );
  }
}
