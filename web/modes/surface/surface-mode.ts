import type { MeshPoint, TraceOptions } from '../../../src/index.js';
import { DebouncedSave } from '../../app/autosave.js';
import { download } from '../../app/download.js';
import { InFlight } from '../../app/in-flight.js';
import { readFile } from '../../app/loader.js';
import type { Mode, ModeContext } from '../../app/modes.js';
import type { Marker } from '../../view3d/points.js';
import { View3D } from '../../view3d/view3d.js';
import { SurfaceClient } from './client.js';
import type { SurfaceSelection } from './commands.js';
import type { ShownMeshInfo, SurfaceContext } from './context.js';
import { EMPTY_DRAWING, anchorOf, drawingFile, findSpline, isAnchor, type SurfaceDrawing } from './drawing.js';
import { SurfaceEdits } from './edits.js';
import { SurfaceGestures } from './gestures.js';
import { SURFACE_KEYS, keyAction, type SurfaceAction } from './keymap.js';
import { MeshSessions } from './mesh-sessions.js';
import { SurfacePicking } from './picking.js';
import type { SurfaceSession } from './session.js';
import { SURFACE_COLORS, SurfaceLayers } from './surface-layers.js';
import { MESH_ACCEPT, isSvgFile, surfaceFileLimit } from './mesh-files.js';
import { SurfacePanel, type SurfaceTool } from './surface-panel.js';
import { SurfaceStatus } from './surface-status.js';
import { loadPrefs, saveDrawing, savePrefs, saveSurfaceSession, type SurfacePrefs } from './storage.js';
import { SvgPlacement } from './svg-placement.js';
import { surfaceTestState, type SurfaceTestState } from './test-state.js';
import { TraceCache } from './trace-cache.js';
import { messageOf } from '../../app/errors.js';

export type { SurfaceTestState };

const AUTOSAVE_MS = 300;

const TOOL_HINTS: Record<SurfaceTool, string> = {
  draw: 'Click on the mesh to place points: the first click starts a spline, each next one adds a segment; Enter, Esc or a double click finishes. Drag points to edit; Alt+click a curve inserts a point.',
  move: 'Drag on the mesh to move the selected spline along the surface (transported in normal coordinates).',
  rotate: 'Drag around the selected spline to turn it about its centre on the surface (Shift: 15° steps).',
  scale: 'Drag away from the selected spline’s centre to grow it, toward it to shrink it.',
};

/**
 * Surface mode (Mancinelli, Nazzaro, Pellacini, Puppo — b/Surf): draw and edit cubic Bézier
 * splines on a triangle mesh in a three.js 3D view. The mesh, the edits and the tracing live in a
 * worker (surface.worker.ts); this side keeps the scene, the drawing (control points as mesh
 * points, an immutable value per edit, undoable) and the traced polylines it gets back.
 *
 * The mode ties its parts together, each with one job: the meshes opened (MeshSessions), the
 * traces (TraceCache), the edits (SurfaceEdits), SVG placement (SvgPlacement), pointer input
 * (SurfaceGestures), what is under the pointer (SurfacePicking); it keeps the selection, the tool,
 * the preferences, and draws. Its work under way is counted in one InFlight (`ready()`).
 */
export class SurfaceMode implements Mode, SurfaceContext {
  readonly id = 'surface';
  readonly title = 'Surface';
  readonly description = 'Draw and edit Bézier splines on a triangle mesh (b/Surf): geodesic tracing, moving, turning, scaling, SVG placement';
  readonly keys = SURFACE_KEYS;
  /** The mode's work under way: mesh loads, worker requests, queued edits. */
  readonly work = new InFlight();
  readonly client = new SurfaceClient(this.work);

  private _ctx: ModeContext | null = null;
  private _view: View3D | null = null;
  private layers: SurfaceLayers | null = null;
  private _panel: SurfacePanel | null = null;
  private _prefs: SurfacePrefs = loadPrefs();
  private _tool: SurfaceTool = 'draw';
  private _selection: SurfaceSelection | null = null;
  private readonly sessions = new MeshSessions(this, { leaving: () => this.leaving(), attached: (s) => this.attached(s), refreshed: () => this.refreshPanel() });
  private readonly traces = new TraceCache(this);
  private readonly picking = new SurfacePicking(this, this.traces);
  private readonly edits = new SurfaceEdits(this, this.traces);
  private readonly placement = new SvgPlacement(this, this.edits);
  private readonly gestures = new SurfaceGestures(this, this.traces, this.picking, this.edits, this.placement);
  private readonly status = new SurfaceStatus();
  private readonly autosave = new DebouncedSave(AUTOSAVE_MS, () => this.saveNow());
  /** The layers are drawn again just before the view's next frame (its 'prerender'). */
  private drawPending = false;
  private off: (() => void)[] = [];
  private sessionOff: (() => void)[] = [];

  constructor() {
    window.addEventListener('pagehide', () => this.autosave.flush());
  }

  // ---- Mode ------------------------------------------------------------------------------------

  activate(ctx: ModeContext): void {
    this._ctx = ctx;
    if (!this._view) {
      this._view = new View3D(ctx.view.container);
      this.layers = new SurfaceLayers(this._view);
      this._view.events.on('view', () => {
        this.layers?.resized();
        this.requestDraw();
      });
      // The layers are updated in the frame that draws them: updating them in a frame of their own
      // would make the view draw twice (with a 2M-triangle mesh on a software renderer, a second each).
      this._view.events.on('prerender', () => {
        if (!this.drawPending) return;
        this.drawPending = false;
        this.draw();
      });
    }
    ctx.view.setVisible(false);
    this._view.setVisible(true);
    this._view.input = this.gestures.input;
    this._view.setFlatShading(this._prefs.flat);
    this._panel = new SurfacePanel({
      openSample: (file) => void this.sessions.openSample(file, true),
      openFile: (file) => void this.openFile(file),
      setFlat: (flat) => this.setPrefs({ flat }),
      setTool: (tool) => this.setTool(tool),
      toggleSmooth: () => this.edits.toggleSmooth(),
      insertPoint: () => this.edits.insertAfterSelected(),
      deletePoint: () => this.edits.deleteSelectedPoint(),
      deleteSpline: () => this.edits.deleteSelectedSpline(),
      setTrace: (change) => this.setPrefs(change),
      chooseSvg: (file) => void this.placement.chooseSample(file),
      chooseSvgFile: (file) => void this.placement.chooseFile(file),
      placeSvg: () => this.placement.start(),
      setSvgPlacement: (change) => this.placement.setSizeOrRotation(change),
      endSvgPlacement: () => this.placement.end(),
      saveDrawing: () => this.saveDrawingFile(),
      loadDrawing: (file) => void this.edits.loadDrawingFile(file),
      clearDrawing: () => this.edits.clearDrawing(),
    });
    ctx.panel.append(...this._panel.sections);
    this.sessions.showSampleChoice();
    this._panel.setSvgSamples(this.sessions.svgSamples);
    this._panel.setSvgChoice(this.placement.svgName, false);
    document.body.classList.add('mode-surface');
    this.off.push(ctx.state.events.on('overlay', () => this.requestDraw()));
    this.refreshPanel();
    this.refreshStatus();
    this.sessions.startOnce();
    this.requestDraw();
  }

  deactivate(): void {
    const ctx = this._ctx;
    this.gestures.cancel();
    this.edits.finish();
    this.placement.quit();
    this.autosave.flush();
    for (const off of this.off) off();
    this.off = [];
    this.drawPending = false;
    this._view?.setVisible(false);
    if (this._view) this._view.input = null;
    document.body.classList.remove('mode-surface');
    if (ctx) {
      ctx.view.setVisible(true);
      ctx.view.requestRender();
    }
    this._panel = null;
    this._ctx = null;
  }

  keyDown(e: KeyboardEvent): boolean {
    const action = keyAction(e);
    return action !== null && this.run(action, e);
  }

  // ---- what the editor calls -------------------------------------------------------------------

  get active(): boolean {
    return this._ctx !== null;
  }

  /** The mode's part of the status bar (mesh, warnings, trace time): the editor places it. */
  get statusEl(): HTMLElement {
    return this.status.el;
  }

  /** Frames the mesh (F, the toolbar's Fit). */
  fit(): void {
    this._view?.fit();
  }

  zoom(factor: number): void {
    this._view?.zoom(factor);
  }

  /**
   * A file opened or dropped while the mode is active (or a mesh anywhere): a mesh replaces the
   * mesh, an SVG becomes the drawing to place.
   */
  async openFile(file: File): Promise<boolean> {
    const ctx = this._ctx;
    if (!ctx) return false;
    let bytes: Uint8Array;
    try {
      bytes = await readFile(file, surfaceFileLimit(file));
    } catch (err) {
      ctx.state.setError(messageOf(err));
      return false;
    }
    if (isSvgFile(file)) {
      this.placement.use(file.name, new TextDecoder().decode(bytes), true);
      this.placement.start();
      return true;
    }
    return this.sessions.openBytes(bytes, file.name, { sample: false, undoable: true });
  }

  /** Saves the drawing as JSON (Ctrl+S in this mode). */
  saveDrawingFile(): void {
    const s = this.session;
    if (!s) return;
    const text = JSON.stringify(drawingFile(s.file, s.drawing), null, 1);
    download(text, `${s.file.replace(/\.[^.]+$/, '')}.surface.json`, 'application/json');
  }

  // ---- the shared state (SurfaceContext) -------------------------------------------------------

  get ctx(): ModeContext | null {
    return this._ctx;
  }

  get view(): View3D | null {
    return this._view;
  }

  get panel(): SurfacePanel | null {
    return this._panel;
  }

  get session(): SurfaceSession | null {
    return this.sessions.current;
  }

  get mesh(): ShownMeshInfo | null {
    return this.sessions.mesh;
  }

  get generation(): number {
    return this.sessions.generation;
  }

  get drawing(): SurfaceDrawing {
    return this.session?.drawing ?? EMPTY_DRAWING;
  }

  get selection(): SurfaceSelection | null {
    return this._selection;
  }

  get prefs(): SurfacePrefs {
    return this._prefs;
  }

  get drawingId(): number | null {
    return this.edits.drawingId;
  }

  get tool(): SurfaceTool {
    return this._tool;
  }

  traceOptions(): TraceOptions {
    const p = this._prefs;
    return p.subdivision === 'adaptive' ? { scheme: p.scheme, adaptive: p.angle } : { scheme: p.scheme, levels: p.levels };
  }

  setError(message: string): void {
    this._ctx?.state.setError(message);
  }

  // ---- meshes ----------------------------------------------------------------------------------

  /** Shows a session (undo and redo of opening a mesh). */
  showSession(target: SurfaceSession | null): Promise<boolean> {
    return this.sessions.show(target);
  }

  /** Before another session is shown: the gesture ends, the drawing is saved. */
  private leaving(): void {
    for (const off of this.sessionOff) off();
    this.sessionOff = [];
    this.gestures.cancel();
    this.autosave.flush();
  }

  /** Another session is shown: nothing selected or drawn on it yet. */
  private attached(s: SurfaceSession | null): void {
    this._selection = null;
    this.edits.reset();
    this.placement.reset();
    this.traces.dropLive();
    if (s) {
      this._ctx?.state.setMessage(null);
      this.sessionOff.push(
        s.events.on('drawing', () => {
          this.validateState();
          this.autosave.schedule();
          this.traces.ensure();
          this.refreshPanel();
          this.requestDraw();
        }),
      );
      const problem = saveSurfaceSession(s);
      if (problem) this._ctx?.state.setMessage(`Not autosaved: ${problem}`);
    }
    this.sessions.showSampleChoice();
    this.traces.ensure();
    this.refreshPanel();
    this.refreshStatus();
    this.requestDraw();
  }

  // ---- selection and state ---------------------------------------------------------------------

  select(session: SurfaceSession, selection: SurfaceSelection | null): void {
    if (session !== this.session) return;
    this.setSelection(selection);
  }

  setSelection(selection: SurfaceSelection | null): void {
    const d = this.session?.drawing;
    if (selection && (!d || !findSpline(d, selection.spline))) selection = null;
    this._selection = selection;
    this.traces.ensure();
    this.refreshPanel();
    this.requestDraw();
  }

  /** After the drawing changed (undo, redo): drop references to splines that are gone. */
  private validateState(): void {
    const d = this.session?.drawing ?? EMPTY_DRAWING;
    if (this._selection) {
      const sp = findSpline(d, this._selection.spline);
      if (!sp) this._selection = null;
      else if (this._selection.point !== null && this._selection.point >= sp.json.points.length) this._selection = { spline: sp.id, point: null };
    }
    this.edits.validate(d);
  }

  // ---- tools and prefs -------------------------------------------------------------------------

  private setTool(tool: SurfaceTool): void {
    if (this.gestures.gesture) return;
    this._tool = tool;
    if (tool !== 'draw') this.edits.finish();
    this.placement.stop();
    this.gestures.setCursor(null);
    this.refreshPanel();
    this.requestDraw();
  }

  setPrefs(change: Partial<SurfacePrefs>): void {
    const before = this.traces.key();
    this._prefs = { ...this._prefs, ...change };
    savePrefs(this._prefs);
    this._view?.setFlatShading(this._prefs.flat);
    this._panel?.setPrefs(this._prefs, this.mesh?.scale ?? null);
    if (this.traces.key() !== before) {
      this.traces.resetLast();
      this.traces.ensure();
      this.requestDraw();
    }
  }

  /** Does what a key asks; false when it does not apply (the key goes on to the editor). */
  private run(action: SurfaceAction, e: KeyboardEvent): boolean {
    switch (action) {
      case 'finish':
        return this.edits.finish();
      case 'escape':
        if (this.gestures.gesture) {
          this.gestures.cancel();
          return true;
        }
        if (this.placement.placing) {
          this.placement.stop();
          return true;
        }
        if (this.edits.finish()) return true;
        if (this._tool !== 'draw') {
          this.setTool('draw');
          return true;
        }
        if (this._selection) {
          this.setSelection(null);
          return true;
        }
        return false;
      case 'delete':
        if (!this._selection) return false;
        if (this._selection.point !== null && isAnchor(this._selection.point)) this.edits.deleteSelectedPoint();
        else if (this._selection.point === null) this.edits.deleteSelectedSpline();
        return true;
      case 'smooth':
        if (this._selection?.point == null) return false;
        this.edits.toggleSmooth();
        return true;
      case 'tool-move':
      case 'tool-rotate':
      case 'tool-scale': {
        if (e.repeat) return true;
        const tool = action === 'tool-move' ? 'move' : action === 'tool-rotate' ? 'rotate' : 'scale';
        this.setTool(this._tool === tool ? 'draw' : tool);
        return true;
      }
    }
  }

  // ---- drawing ---------------------------------------------------------------------------------

  requestDraw(): void {
    if (!this._view) return;
    this.drawPending = true;
    this._view.requestRender();
  }

  private draw(): void {
    const view = this._view, layers = this.layers;
    if (!view || !layers) return;
    const d = this.drawing, drawingId = this.edits.drawingId;
    const selectedId = this._selection?.spline ?? drawingId;
    layers.setCurves(d.splines.map((sp) => ({ id: sp.id, lifted: this.traces.traceOf(sp)?.lifted ?? null, selected: sp.id === selectedId || sp.id === drawingId })));
    const sel = selectedId !== null && selectedId !== undefined ? findSpline(d, selectedId) : undefined;
    const polygon = sel && this._ctx?.state.overlay ? this.traces.polygonOf(sel) : null;
    layers.setPolygon(polygon?.lifted ?? null, polygon?.starts ?? null);
    layers.setPreview(this.edits.preview);

    // Markers on the surface (drawn toward the camera by their radius, see MarkerLayer).
    const markers: Marker[] = [];
    const put = (p: MeshPoint, color: string, size: number, shape: 'disc' | 'square') => {
      const at = this.picking.xyz(p);
      if (at) markers.push({ x: at[0], y: at[1], z: at[2], color, size, shape });
    };
    if (this._ctx?.state.overlay !== false) {
      for (const sp of d.splines) {
        const json = this.traces.shownJSON(sp);
        const full = sp.id === selectedId || sp.id === drawingId;
        json.points.forEach((mp, i) => {
          const hot = this._selection?.spline === sp.id && this._selection.point === i;
          if (isAnchor(i)) put(mp, hot ? SURFACE_COLORS.hot : SURFACE_COLORS.anchor, full ? (hot ? 12 : 10) : 8, json.smooth[i / 3] ? 'disc' : 'square');
          else if (full) put(mp, hot ? SURFACE_COLORS.hot : SURFACE_COLORS.handle, hot ? 11 : 9, 'disc');
        });
      }
    }
    const pending = this.edits.pending;
    if (pending) put(pending, SURFACE_COLORS.pending, 10, 'square');
    const g = this.gestures.gesture;
    if (g && (g.kind === 'rotate' || g.kind === 'scale')) put(g.center, SURFACE_COLORS.center, 12, 'disc');
    layers.setMarkers(markers, view.worldPerPixel(1) * 7);
  }

  // ---- panel and status ------------------------------------------------------------------------

  refreshPanel(): void {
    const panel = this._panel;
    if (!panel) return;
    panel.setPrefs(this._prefs, this.mesh?.scale ?? null);
    panel.setMesh(this.session?.file ?? null, this.mesh?.info ?? null, this.session?.sample ?? false);
    const d = this.drawing, sel = this._selection, sp = sel ? findSpline(d, sel.spline) : undefined;
    let selected = '—', smooth: boolean | null = null;
    if (sp && sel) {
      const index = d.splines.indexOf(sp) + 1;
      const segs = sp.json.closed ? sp.json.points.length / 3 : (sp.json.points.length - 1) / 3;
      if (sel.point === null) selected = `spline ${index} · ${segs} segment${segs === 1 ? '' : 's'}`;
      else {
        const a = anchorOf(sel.point, sp.json);
        smooth = sp.json.smooth[a / 3] ?? false;
        selected = isAnchor(sel.point) ? `spline ${index} · anchor ${a / 3 + 1} (${smooth ? 'smooth' : 'corner'})` : `spline ${index} · handle of anchor ${a / 3 + 1}`;
      }
    }
    panel.setTool(this._tool, this.edits.drawing && this._tool === 'draw' ? 'Drawing: click to add points; Enter, Esc or a double click finishes.' : TOOL_HINTS[this._tool]);
    panel.setSelection({
      splines: d.splines.length,
      selected,
      smooth,
      canInsert: !!sp,
      canDeletePoint: !!sp && sel?.point != null && isAnchor(sel.point),
      canDeleteSpline: !!sp,
    });
    panel.setPlacing(this.placement.placing, this.placement.hasSvg && this.session !== null);
    this.refreshTraceFacts();
  }

  private refreshTraceFacts(): void {
    const t = this.traces.last;
    let points = 0;
    for (const sp of this.drawing.splines) points += (this.traces.traceOf(sp)?.xyz.length ?? 0) / 3;
    this._panel?.setTrace(t ? (t.count > 1 ? `${t.count} splines in ${t.sum.toFixed(1)} ms` : `${t.ms.toFixed(2)} ms`) : '—', points.toLocaleString('en-US'));
  }

  refreshStatus(): void {
    this.status.show(this.session?.file ?? null, this.mesh, this.traces.last);
    this.refreshTraceFacts();
  }

  // ---- autosave --------------------------------------------------------------------------------

  private saveNow(): void {
    const s = this.session;
    if (!s) return;
    const problem = saveDrawing(s, s.drawing);
    if (problem) this._ctx?.state.setMessage(`Autosave failed: ${problem}`);
  }

  // ---- tests -----------------------------------------------------------------------------------

  /** Resolves when a mesh is shown and no load, edit or trace is under way. */
  async ready(): Promise<void> {
    for (;;) {
      await this.work.idle();
      if (this.session && this.mesh && !this.gestures.gesture) {
        await this._view?.nextFrame();
        if (!this.work.busy) return;
      } else {
        // No mesh yet (the mode not activated) or a drag held: nothing in flight to wait on.
        await new Promise<void>((resolve) => setTimeout(resolve, 20));
      }
    }
  }

  testState(): SurfaceTestState {
    return surfaceTestState({
      active: this.active,
      file: this.session?.file ?? null,
      info: this.mesh?.info ?? null,
      ready: this.mesh?.ready ?? false,
      scale: this.mesh?.scale ?? null,
      drawing: this.drawing,
      traceOf: (sp) => this.traces.traceOf(sp),
      selection: this._selection,
      tool: this._tool,
      drawingId: this.edits.drawingId,
      pending: this.edits.pending !== null,
      placing: this.placement.placing,
      lastTraceMs: this.traces.last?.ms ?? null,
      options: this.traceOptions(),
      saved: !this.autosave.pending,
      pictureTriangles: this._view?.pictureTriangles ?? 0,
    });
  }

  /** Where a mesh point is on the canvas (CSS pixels) and whether it is seen, or null. */
  projectOnCanvas(p: MeshPoint): { x: number; y: number; visible: boolean } | null {
    return this.picking.project(p);
  }

  /** The mesh point under a canvas point, or null. */
  meshPointOnCanvas(sx: number, sy: number): MeshPoint | null {
    return this.picking.meshPointAt(sx, sy);
  }

  /** Vertex positions of faces (9 numbers each), from the shown mesh. */
  faceVertices(faces: number[]): number[] {
    return this.picking.faceVertices(faces);
  }

  get canvas(): HTMLCanvasElement | null {
    return this._view?.canvas ?? null;
  }

  /** The accept list of the mesh file input (the toolbar's Open uses it in this mode). */
  static readonly accept = `${MESH_ACCEPT},.svg,image/svg+xml`;
}
