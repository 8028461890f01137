import { Matrix4, Vector3 } from 'three';
import type { MeshInfo, MeshPoint, SurfaceSplineJSON, TraceOptions } from '../../../src/index.js';
import { DebouncedSave, contentHash } from '../../app/autosave.js';
import { download } from '../../app/download.js';
import { fetchBytes, readFile } from '../../app/loader.js';
import type { Mode, ModeContext } from '../../app/modes.js';
import { h } from '../../ui/dom.js';
import type { Marker } from '../../view3d/points.js';
import { View3D, type Pointer3D, type View3DInput } from '../../view3d/view3d.js';
import { SupersededError, SurfaceClient, type Ran } from './client.js';
import { DrawingCommand, OpenMeshCommand, type SurfaceCommandTarget, type SurfaceSelection } from './commands.js';
import {
  EMPTY_DRAWING,
  addSplines,
  anchorCount,
  anchorOf,
  drawingFile,
  findSpline,
  isAnchor,
  parseDrawingFile,
  parseSplines,
  removeSplines,
  replaceSpline,
  type DrawnSpline,
  type SurfaceDrawing,
} from './drawing.js';
import { SURFACE_KEYS, keyAction, type SurfaceAction } from './keymap.js';
import type { PolygonPaths, SplineOp, TracedPolyline } from './protocol.js';
import { SurfaceSession } from './session.js';
import { SURFACE_COLORS, SurfaceLayers } from './surface-layers.js';
import { MESH_ACCEPT, SurfacePanel, type SampleFile, type SurfaceTool } from './surface-panel.js';
import {
  loadDrawing,
  loadMeshBytes,
  loadPrefs,
  loadSurfaceSession,
  saveDrawing,
  savePrefs,
  saveSurfaceSession,
  storeMeshBytes,
  type SurfacePrefs,
} from './storage.js';
import { surfaceTestState, type SurfaceTestState } from './test-state.js';

export type { SurfaceTestState };

const AUTOSAVE_MS = 300;
/** Screen pixels within which a control point or a curve is hit. */
const POINT_HIT_PX = 10;
const CURVE_HIT_PX = 7;
/** Two clicks closer than this (ms, px) make a double click. */
const DOUBLE_CLICK_MS = 400;
const DOUBLE_CLICK_PX = 6;

const MESH_EXTENSIONS = /\.(obj|off|ply|stl|gltf|glb)$/i;

/** Whether a file name is a mesh Surface mode opens. */
export function isMeshFile(name: string): boolean {
  return MESH_EXTENSIONS.test(name);
}

type Gesture =
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

interface TraceEntry {
  key: string;
  trace: TracedPolyline;
  ms: number;
}

/** A control point drawn on the mesh: spline id, point index, and where it is drawn. */
interface ControlMark {
  id: number;
  index: number;
  xyz: [number, number, number];
}

/** What the last placement of an SVG made (resized or turned again while untouched). */
interface Placement {
  ids: number[];
  jsons: SurfaceSplineJSON[];
  center: MeshPoint;
  svg: { name: string; text: string };
  /** The view's up when it was placed (where the drawing's up went). */
  up: [number, number, number];
}

const TOOL_HINTS: Record<SurfaceTool, string> = {
  draw: 'Click on the mesh to place points: the first click starts a spline, each next one adds a segment; Enter, Esc or a double click finishes. Drag points to edit; Alt+click a curve inserts a point.',
  move: 'Drag on the mesh to move the selected spline along the surface (transported in normal coordinates).',
  rotate: 'Drag around the selected spline to turn it about its centre on the surface (Shift: 15° steps).',
  scale: 'Drag away from the selected spline’s centre to grow it, toward it to shrink it.',
};

function sameMeshPoint(a: MeshPoint, b: MeshPoint): boolean {
  return a.face === b.face && a.uv[0] === b.uv[0] && a.uv[1] === b.uv[1];
}

/**
 * Surface mode (Mancinelli, Nazzaro, Pellacini, Puppo — b/Surf): draw and edit cubic Bézier
 * splines on a triangle mesh in a three.js 3D view. The mesh, the edits and the tracing live in a
 * worker (surface.worker.ts); this side keeps the scene, the drawing (control points as mesh
 * points, an immutable value per edit, undoable) and the traced polylines it gets back.
 */
export class SurfaceMode implements Mode, SurfaceCommandTarget {
  readonly id = 'surface';
  readonly title = 'Surface';
  readonly description = 'Draw and edit Bézier splines on a triangle mesh (b/Surf): geodesic tracing, moving, turning, scaling, SVG placement';
  readonly keys = SURFACE_KEYS;
  /** The mode's part of the status bar (mesh, warnings, trace time): the editor places it. */
  readonly statusEl: HTMLElement;

  private ctx: ModeContext | null = null;
  private view: View3D | null = null;
  private layers: SurfaceLayers | null = null;
  private panel: SurfacePanel | null = null;
  private readonly client = new SurfaceClient();
  private readonly sessions = new Map<string, SurfaceSession>();
  private session: SurfaceSession | null = null;
  private mesh: { info: MeshInfo; scale: number; loadMs: number } | null = null;
  /** Counts mesh loads: replies for an older mesh are dropped. */
  private generation = 0;
  private loads: Promise<unknown> = Promise.resolve();
  private wanted: SurfaceSession | null = null;
  private starting: Promise<void> | null = null;
  private prefs: SurfacePrefs = loadPrefs();
  private tool: SurfaceTool = 'draw';
  private selection: SurfaceSelection | null = null;
  /** The spline that clicks extend, and the first point of one not made yet. */
  private drawingId: number | null = null;
  private pending: MeshPoint | null = null;
  private lastClick: { sx: number; sy: number; time: number } | null = null;
  private gesture: Gesture | null = null;
  private committing = false;
  /** Results shown while a gesture runs (spline id → the latest reply). */
  private readonly live = new Map<number, Ran>();
  private readonly traces = new WeakMap<SurfaceSplineJSON, TraceEntry>();
  private readonly polygons = new WeakMap<SurfaceSplineJSON, PolygonPaths>();
  /** What was asked for a spline state and not answered yet: a trace (its options key), its polygon. */
  private readonly requested = new WeakMap<SurfaceSplineJSON, { trace: string | null; polygon: boolean }>();
  private edits: Promise<void> = Promise.resolve();
  /** Async tasks under way (loads, edits, traces): ready() waits for none. */
  private work = 0;
  private workWaiters: (() => void)[] = [];
  private preview: Float32Array | null = null;
  private placing = false;
  private svg: { name: string; text: string } | null = null;
  private placement: Placement | null = null;
  /** Re-mapping the last placement while a slider moves: one at a time, then once more if asked. */
  private remap: { busy: boolean; again: boolean; commit: boolean; before: SurfaceDrawing | null } = { busy: false, again: false, commit: false, before: null };
  private meshSamples: SampleFile[] = [];
  private svgSamples: SampleFile[] = [];
  /** The last trace (one spline), or the last retrace of several together. */
  private lastTrace: { ms: number; points: number; count: number; sum: number } | null = null;
  private batch: { left: number; count: number; sum: number; points: number } | null = null;
  private readonly autosave = new DebouncedSave(AUTOSAVE_MS, () => this.saveNow());
  private frame = 0;
  private off: (() => void)[] = [];
  private sessionOff: (() => void)[] = [];
  private readonly statusMesh = h('span', { class: 'status-file', 'data-testid': 'surface-status-mesh' });
  private readonly statusWarnings = h('span', { class: 'status-warnings', 'data-testid': 'surface-status-warnings' });
  private readonly statusTrace = h('span', { class: 'status-timing', 'data-testid': 'surface-status-trace' });

  constructor() {
    this.statusEl = h('span', { class: 'surface-status' }, this.statusMesh, this.statusWarnings, this.statusTrace);
    window.addEventListener('pagehide', () => this.autosave.flush());
  }

  // ---- Mode ------------------------------------------------------------------------------------

  activate(ctx: ModeContext): void {
    this.ctx = ctx;
    if (!this.view) {
      this.view = new View3D(ctx.view.container);
      this.layers = new SurfaceLayers(this.view);
      this.view.events.on('view', () => {
        this.layers?.resized();
        this.requestDraw();
      });
    }
    ctx.view.canvas.style.display = 'none';
    this.view.setVisible(true);
    this.view.input = this.input;
    this.view.setFlatShading(this.prefs.flat);
    this.panel = new SurfacePanel({
      openSample: (file) => void this.openSample(file, true),
      openFile: (file) => void this.openFile(file),
      setFlat: (flat) => this.setPrefs({ flat }),
      setTool: (tool) => this.setTool(tool),
      toggleSmooth: () => this.toggleSmooth(),
      insertPoint: () => this.insertAfterSelected(),
      deletePoint: () => this.deleteSelectedPoint(),
      deleteSpline: () => this.deleteSelectedSpline(),
      setTrace: (change) => this.setPrefs(change),
      chooseSvg: (file) => void this.chooseSvgSample(file),
      chooseSvgFile: (file) => void this.chooseSvgFile(file),
      placeSvg: () => this.startPlacing(),
      setSvgPlacement: (change) => this.setSvgPlacement(change),
      endSvgPlacement: () => {
        if (this.remap.busy || this.remap.again) this.remap.commit = true;
        else this.commitRemap();
      },
      saveDrawing: () => this.saveDrawingFile(),
      loadDrawing: (file) => void this.loadDrawingFile(file),
      clearDrawing: () => this.clearDrawing(),
    });
    ctx.panel.append(...this.panel.sections);
    this.panel.setMeshSamples(this.meshSamples, this.session?.sample ? this.session.file : null);
    this.panel.setSvgSamples(this.svgSamples);
    this.panel.setSvgChoice(this.svg?.name ?? null, false);
    document.body.classList.add('mode-surface');
    this.off.push(ctx.state.events.on('overlay', () => this.requestDraw()));
    this.refreshPanel();
    this.refreshStatus();
    if (!this.session && !this.starting) this.starting = this.start();
    this.requestDraw();
  }

  deactivate(): void {
    const ctx = this.ctx;
    this.cancelGesture();
    this.finish();
    this.placing = false;
    this.autosave.flush();
    for (const off of this.off) off();
    this.off = [];
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.view?.setVisible(false);
    if (this.view) this.view.input = null;
    document.body.classList.remove('mode-surface');
    if (ctx) {
      ctx.view.canvas.style.display = 'block';
      ctx.view.requestRender();
    }
    this.panel = null;
    this.ctx = null;
  }

  keyDown(e: KeyboardEvent): boolean {
    const action = keyAction(e);
    return action !== null && this.run(action, e);
  }

  // ---- what the editor calls -------------------------------------------------------------------

  get active(): boolean {
    return this.ctx !== null;
  }

  /** Frames the mesh (F, the toolbar's Fit). */
  fit(): void {
    this.view?.fit();
  }

  zoom(factor: number): void {
    this.view?.zoom(factor);
  }

  /**
   * A file opened or dropped while the mode is active (or a mesh anywhere): a mesh replaces the
   * mesh, an SVG becomes the drawing to place.
   */
  async openFile(file: File): Promise<boolean> {
    const ctx = this.ctx;
    if (!ctx) return false;
    let bytes: Uint8Array;
    try {
      bytes = await readFile(file);
    } catch (err) {
      ctx.state.setError(err instanceof Error ? err.message : String(err));
      return false;
    }
    if (/\.svg$/i.test(file.name) || file.type === 'image/svg+xml') {
      this.useSvg(file.name, new TextDecoder().decode(bytes), true);
      this.startPlacing();
      return true;
    }
    return this.openMeshBytes(bytes, file.name, { sample: false, undoable: true });
  }

  /** Saves the drawing as JSON (Ctrl+S in this mode). */
  saveDrawingFile(): void {
    const s = this.session;
    if (!s) return;
    const text = JSON.stringify(drawingFile(s.file, s.drawing), null, 1);
    download(text, `${s.file.replace(/\.[^.]+$/, '')}.surface.json`, 'application/json');
  }

  // ---- start, meshes ---------------------------------------------------------------------------

  /** Loads the sample lists, then the mesh of the last visit, or the first sample. */
  private async start(): Promise<void> {
    this.work++;
    try {
      await this.loadSampleLists();
      const saved = loadSurfaceSession();
      let restored = false;
      // Unless the user opened a mesh meanwhile: the one of the last visit, else the first sample.
      if (saved && !this.wanted) {
        let bytes: Uint8Array | null = null;
        if (saved.sample && this.meshSamples.some((m) => m.file === saved.file)) {
          bytes = await fetchBytes(`samples/meshes/${saved.file}`, saved.file).catch(() => null);
        } else if (!saved.sample) {
          bytes = await loadMeshBytes(`${saved.hash}:${saved.file}`);
        }
        if (bytes) restored = await this.openMeshBytes(bytes, saved.file, { sample: saved.sample, undoable: false });
      }
      if (!restored && !this.wanted && this.meshSamples.length > 0) await this.openSample(this.meshSamples[0].file, false);
    } catch (err) {
      this.ctx?.state.setError(err instanceof Error ? err.message : String(err));
    } finally {
      this.starting = null;
      this.done();
    }
  }

  private async loadSampleLists(): Promise<void> {
    const read = async (url: string) => JSON.parse(new TextDecoder().decode(await fetchBytes(url, url))) as unknown;
    const [meshes, svgs] = await Promise.all([read('samples/meshes/index.json'), read('samples/index.json').catch(() => ({ samples: [] }))]);
    this.meshSamples = (meshes as { meshes: SampleFile[] }).meshes;
    this.svgSamples = (svgs as { samples: SampleFile[] }).samples;
    this.panel?.setMeshSamples(this.meshSamples, this.session?.sample ? this.session.file : null);
    this.panel?.setSvgSamples(this.svgSamples);
  }

  private async openSample(file: string, undoable: boolean): Promise<boolean> {
    try {
      const bytes = await fetchBytes(`samples/meshes/${file}`, file);
      return await this.openMeshBytes(bytes, file, { sample: true, undoable });
    } catch (err) {
      this.ctx?.state.setError(err instanceof Error ? err.message : String(err));
      this.panel?.setMeshSamples(this.meshSamples, this.session?.sample ? this.session.file : null);
      return false;
    }
  }

  private async openMeshBytes(bytes: Uint8Array, name: string, options: { sample: boolean; undoable: boolean }): Promise<boolean> {
    const key = `${contentHash(bytes)}:${name}`;
    const target = this.sessions.get(key) ?? new SurfaceSession(name, bytes, options.sample);
    const previous = this.session;
    if (target === previous) return true;
    const ok = await this.showSession(target);
    if (!ok) return false;
    if (options.undoable && previous && this.ctx) this.ctx.history.execute(new OpenMeshCommand(this, previous, target));
    if (!target.sample) {
      void storeMeshBytes(target).then((problem) => {
        if (problem) this.ctx?.state.setMessage(`The mesh is not kept for the next visit: ${problem}`);
      });
    }
    return true;
  }

  /**
   * Shows a session: loads its mesh in the worker (the previous one stays if that fails) and in
   * the view, then its drawing. Loads run one after another; only the last one asked for is done.
   */
  showSession(target: SurfaceSession | null): Promise<boolean> {
    this.wanted = target;
    const job = this.loads.then(async () => {
      if (this.wanted !== target) return false;
      if (target === this.session) return true;
      if (!target) {
        this.attach(null);
        return true;
      }
      return this.load(target);
    });
    this.loads = job.catch(() => false);
    return job;
  }

  private async load(target: SurfaceSession): Promise<boolean> {
    const ctx = this.ctx;
    this.work++;
    ctx?.state.setBusy(`Opening ${target.file}…`);
    try {
      const reply = await this.client.load(target.bytes, target.file);
      this.generation++;
      this.view!.setMesh(reply.positions, reply.triangles, { fit: true, normals: reply.normals, bvh: reply.bvh });
      this.mesh = { info: reply.info, scale: reply.scale, loadMs: reply.ms };
      if (!this.sessions.has(target.key)) {
        this.sessions.set(target.key, target);
        this.restoreDrawing(target, reply.info);
      }
      this.attach(target);
      if (ctx?.state.error?.startsWith(target.file)) ctx.state.setError(null);
      return true;
    } catch (err) {
      ctx?.state.setError(err instanceof Error ? err.message : String(err));
      return false;
    } finally {
      ctx?.state.setBusy(null);
      this.done();
    }
  }

  /** The autosaved drawing of a mesh opened for the first time in this page. */
  private restoreDrawing(s: SurfaceSession, info: MeshInfo): void {
    const saved = loadDrawing(s);
    if (!saved) return;
    try {
      const splines = parseSplines(saved, info.faces);
      s.setDrawing({ splines: splines.map((json) => ({ id: s.newId(), json })) });
    } catch (err) {
      this.ctx?.state.setMessage(`The autosaved drawing was not restored: ${err instanceof Error ? err.message : String(err)}`);
    }
  }

  private attach(s: SurfaceSession | null): void {
    for (const off of this.sessionOff) off();
    this.sessionOff = [];
    this.cancelGesture();
    this.autosave.flush();
    this.session = s;
    this.selection = null;
    this.drawingId = null;
    this.pending = null;
    this.preview = null;
    this.placing = false;
    this.placement = null;
    this.remap.before = null;
    this.live.clear();
    if (!s) {
      this.mesh = null;
      this.view?.clearMesh();
    } else {
      this.ctx?.state.setMessage(null);
      this.sessionOff.push(
        s.events.on('drawing', () => {
          this.validateState();
          this.autosave.schedule();
          this.ensureTraces();
          this.refreshPanel();
          this.requestDraw();
        }),
      );
      const problem = saveSurfaceSession(s);
      if (problem) this.ctx?.state.setMessage(`Not autosaved: ${problem}`);
    }
    this.panel?.setMeshSamples(this.meshSamples, s?.sample ? s.file : null);
    this.ensureTraces();
    this.refreshPanel();
    this.refreshStatus();
    this.requestDraw();
  }

  // ---- selection and state ---------------------------------------------------------------------

  select(session: SurfaceSession, selection: SurfaceSelection | null): void {
    if (session !== this.session) return;
    this.setSelection(selection);
  }

  private setSelection(selection: SurfaceSelection | null): void {
    const d = this.session?.drawing;
    if (selection && (!d || !findSpline(d, selection.spline))) selection = null;
    this.selection = selection;
    this.ensureTraces();
    this.refreshPanel();
    this.requestDraw();
  }

  /** After the drawing changed (undo, redo): drop references to splines that are gone. */
  private validateState(): void {
    const d = this.session?.drawing ?? EMPTY_DRAWING;
    if (this.selection) {
      const sp = findSpline(d, this.selection.spline);
      if (!sp) this.selection = null;
      else if (this.selection.point !== null && this.selection.point >= sp.json.points.length) this.selection = { spline: sp.id, point: null };
    }
    if (this.drawingId !== null && !findSpline(d, this.drawingId)) {
      this.drawingId = null;
      this.preview = null;
    }
  }

  private get drawing(): SurfaceDrawing {
    return this.session?.drawing ?? EMPTY_DRAWING;
  }

  /** A spline's control points as shown: a gesture's live result, else the drawing's. */
  private shownJSON(sp: DrawnSpline): SurfaceSplineJSON {
    return this.live.get(sp.id)?.json ?? sp.json;
  }

  // ---- tracing ---------------------------------------------------------------------------------

  private traceOptions(): TraceOptions {
    const p = this.prefs;
    return p.subdivision === 'adaptive' ? { scheme: p.scheme, adaptive: p.angle } : { scheme: p.scheme, levels: p.levels };
  }

  private traceKey(): string {
    return JSON.stringify(this.traceOptions());
  }

  private lane(id: number): string {
    return `${this.generation}:${id}`;
  }

  /** Asks the worker for every trace (and the selected spline's control polygon) not at hand. */
  private ensureTraces(): void {
    const s = this.session;
    if (!s || !this.mesh) return;
    const key = this.traceKey(), gen = this.generation, options = this.traceOptions();
    const asks: { run: () => void; trace: boolean }[] = [];
    for (const sp of s.drawing.splines) {
      if (this.live.has(sp.id)) continue;
      const json = sp.json;
      const wantPolygon = this.selection?.spline === sp.id || this.drawingId === sp.id;
      const asked = this.requested.get(json) ?? { trace: null, polygon: false };
      const needTrace = this.traces.get(json)?.key !== key && asked.trace !== key;
      const needPolygon = wantPolygon && !this.polygons.has(json) && !asked.polygon;
      if (!needTrace && !needPolygon) continue;
      if (needTrace) asked.trace = key;
      if (needPolygon) asked.polygon = true;
      this.requested.set(json, asked);
      asks.push({ run: () => this.askTrace(sp.id, json, key, gen, needTrace ? options : null, needPolygon, batch), trace: needTrace });
    }
    // Several traces at once (options changed, a drawing restored): reported together.
    const traces = asks.filter((a) => a.trace).length;
    const batch = traces > 1 ? { left: traces, count: traces, sum: 0, points: 0 } : null;
    if (batch) this.batch = batch;
    for (const ask of asks) ask.run();
  }

  private askTrace(id: number, json: SurfaceSplineJSON, key: string, gen: number, options: TraceOptions | null, polygon: boolean, batch: SurfaceMode['batch']): void {
    this.work++;
    this.client
      .run(json, [], options, polygon, this.lane(id))
      .then((r) => {
        if (gen !== this.generation) return;
        if (r.trace) {
          this.traces.set(json, { key, trace: r.trace, ms: r.traceMs });
          if (batch && this.batch === batch) {
            batch.sum += r.traceMs;
            batch.points += r.trace.xyz.length / 3;
          } else this.noteTrace(r);
        }
        if (r.polygon) this.polygons.set(json, r.polygon);
        this.requestDraw();
      })
      .catch((err: unknown) => {
        const asked = this.requested.get(json);
        if (asked && options && asked.trace === key) asked.trace = null;
        if (asked && polygon) asked.polygon = false;
        if (err instanceof SupersededError) {
          setTimeout(() => this.ensureTraces(), 0);
          return;
        }
        if (gen === this.generation) this.ctx?.state.setError(`Tracing failed: ${err instanceof Error ? err.message : String(err)}`);
      })
      .finally(() => {
        if (options && batch && this.batch === batch && --batch.left === 0) {
          this.batch = null;
          this.lastTrace = { ms: batch.sum / batch.count, points: batch.points, count: batch.count, sum: batch.sum };
          this.refreshStatus();
        }
        this.done();
      });
  }

  private traceOf(sp: DrawnSpline): TracedPolyline | null {
    const live = this.live.get(sp.id);
    if (live?.trace) return live.trace;
    const t = this.traces.get(sp.json);
    return t?.key === this.traceKey() ? t.trace : (t?.trace ?? null);
  }

  private polygonOf(sp: DrawnSpline): PolygonPaths | null {
    const live = this.live.get(sp.id);
    if (live) return live.polygon;
    return this.polygons.get(sp.json) ?? null;
  }

  private noteTrace(r: Ran): void {
    if (!r.trace) return;
    this.lastTrace = { ms: r.traceMs, points: r.trace.xyz.length / 3, count: 1, sum: r.traceMs };
    this.refreshStatus();
  }

  // ---- edits -----------------------------------------------------------------------------------

  /** Runs `task` after the edits before it (each click's edit builds on the previous one). */
  private enqueue(task: () => Promise<void>): void {
    this.work++;
    this.edits = this.edits
      .then(task)
      .catch((err: unknown) => this.ctx?.state.setError(err instanceof Error ? err.message : String(err)))
      .finally(() => this.done());
  }

  /**
   * Records the result of an edit of spline `id` as an undoable command — unless the mesh or the
   * spline changed meanwhile (then the result is stale and dropped).
   */
  private commit(label: string, session: SurfaceSession, gen: number, id: number, base: SurfaceSplineJSON | null, r: Ran, select: SurfaceSelection | null): boolean {
    if (session !== this.session || gen !== this.generation || !this.ctx) return false;
    const before = session.drawing;
    let after: SurfaceDrawing;
    if (base === null) after = addSplines(before, [{ id, json: r.json }]);
    else {
      const sp = findSpline(before, id);
      if (!sp || sp.json !== base) return false;
      after = replaceSpline(before, id, r.json);
    }
    if (r.trace) this.traces.set(r.json, { key: this.traceKey(), trace: r.trace, ms: r.traceMs });
    if (r.polygon) this.polygons.set(r.json, r.polygon);
    this.noteTrace(r);
    this.ctx.history.execute(new DrawingCommand(label, this, session, before, after, { do: select, undo: this.selection }));
    return true;
  }

  /** Applies ops to spline `id` in the worker and records the result (queued after other edits). */
  private editSpline(id: number, label: string, ops: (json: SurfaceSplineJSON) => SplineOp[] | null, select: (json: SurfaceSplineJSON) => SurfaceSelection | null): void {
    this.enqueue(async () => {
      const s = this.session, gen = this.generation;
      const sp = s && findSpline(s.drawing, id);
      if (!s || !sp) return;
      const list = ops(sp.json);
      if (!list) return;
      const r = await this.client.run(sp.json, list, this.traceOptions(), true);
      this.commit(label, s, gen, id, sp.json, r, select(r.json));
    });
  }

  private replaceDrawing(label: string, after: SurfaceDrawing, select: SurfaceSelection | null = null): void {
    const s = this.session, ctx = this.ctx;
    if (!s || !ctx || after === s.drawing) return;
    ctx.history.execute(new DrawingCommand(label, this, s, s.drawing, after, { do: select, undo: this.selection }));
  }

  /** A click while drawing: the first point waits, the second makes a spline, then each appends. */
  private addPoint(p: MeshPoint): void {
    if (this.drawingId === null && !this.pending) {
      this.pending = p;
      this.setSelection(null);
      return;
    }
    this.enqueue(async () => {
      const s = this.session, gen = this.generation;
      if (!s) return;
      if (this.drawingId !== null) {
        const sp = findSpline(s.drawing, this.drawingId);
        if (sp) {
          const last = sp.json.points[sp.json.points.length - 1];
          if (sameMeshPoint(last, p)) return;
          const r = await this.client.run(sp.json, [{ op: 'append', p }], this.traceOptions(), true);
          this.commit('Add point', s, gen, sp.id, sp.json, r, { spline: sp.id, point: r.json.points.length - 1 });
          return;
        }
        this.drawingId = null;
      }
      const first = this.pending;
      if (!first) {
        this.pending = p;
        this.requestDraw();
        return;
      }
      if (sameMeshPoint(first, p)) return;
      const r = await this.client.run(null, [{ op: 'fromPolygon', anchors: [first, p] }], this.traceOptions(), true);
      const id = s.newId();
      if (this.commit('Draw spline', s, gen, id, null, r, { spline: id, point: r.json.points.length - 1 })) {
        if (this.pending === first) this.pending = null;
        this.drawingId = id;
        this.requestDraw();
      }
    });
  }

  /** Ends the spline being drawn (a lone first point is dropped). */
  private finish(): boolean {
    const was = this.drawingId !== null || this.pending !== null;
    this.drawingId = null;
    this.pending = null;
    this.preview = null;
    if (was) {
      this.refreshPanel();
      this.requestDraw();
    }
    return was;
  }

  private toggleSmooth(): void {
    const sel = this.selection, sp = sel && findSpline(this.drawing, sel.spline);
    if (!sel || !sp || sel.point === null) return;
    const anchor = anchorOf(sel.point, sp.json);
    const smooth = !sp.json.smooth[anchor / 3];
    this.editSpline(sp.id, smooth ? 'Make anchor smooth' : 'Make anchor a corner', () => [{ op: 'setSmooth', anchor, smooth }], () => ({ spline: sp.id, point: anchor }));
  }

  /** Inserts an anchor at parameter t of a segment. */
  private insertPoint(id: number, segment: number, t: number): void {
    const options = this.traceOptions();
    this.editSpline(
      id,
      'Insert point',
      (json) => (segment < (json.points.length - 1) / 3 || (json.closed && segment < json.points.length / 3) ? [{ op: 'insert', segment, t, options }] : null),
      () => ({ spline: id, point: 3 * (segment + 1) }),
    );
  }

  private insertAfterSelected(): void {
    const sel = this.selection, sp = sel && findSpline(this.drawing, sel.spline);
    if (!sel || !sp) return;
    const segments = sp.json.closed ? sp.json.points.length / 3 : (sp.json.points.length - 1) / 3;
    const anchor = sel.point === null ? 0 : anchorOf(sel.point, sp.json);
    const segment = Math.min(anchor / 3, segments - 1);
    this.insertPoint(sp.id, segment, 0.5);
  }

  private deleteSelectedPoint(): void {
    const sel = this.selection, sp = sel && findSpline(this.drawing, sel.spline);
    if (!sel || !sp || sel.point === null || !isAnchor(sel.point)) return;
    if (anchorCount(sp.json) <= 2) {
      this.deleteSelectedSpline();
      return;
    }
    const anchor = sel.point;
    this.editSpline(sp.id, 'Delete point', () => [{ op: 'remove', anchor }], (json) => ({ spline: sp.id, point: Math.min(anchor, json.points.length - 1) }));
  }

  private deleteSelectedSpline(): void {
    const sel = this.selection;
    if (!sel || !findSpline(this.drawing, sel.spline)) return;
    if (this.drawingId === sel.spline) this.finish();
    this.replaceDrawing('Delete spline', removeSplines(this.drawing, [sel.spline]), null);
  }

  private clearDrawing(): void {
    if (this.drawing.splines.length === 0) return;
    this.finish();
    this.replaceDrawing('Clear the drawing', EMPTY_DRAWING, null);
  }

  private async loadDrawingFile(file: File): Promise<void> {
    const s = this.session, ctx = this.ctx;
    if (!s || !ctx || !this.mesh) return;
    try {
      const text = new TextDecoder().decode(await readFile(file));
      const parsed = parseDrawingFile(text, this.mesh.info.faces);
      const splines = parsed.splines.map((json) => ({ id: s.newId(), json }));
      this.finish();
      this.replaceDrawing(`Load ${file.name}`, { splines }, null);
      if (parsed.mesh && parsed.mesh !== s.file) ctx.state.setMessage(`${file.name} was drawn on ${parsed.mesh}; shown on ${s.file}`);
    } catch (err) {
      ctx.state.setError(`${file.name}: ${err instanceof Error ? err.message : String(err)}`);
    }
  }

  // ---- SVG placement ---------------------------------------------------------------------------

  private useSvg(name: string, text: string, fromFile: boolean): void {
    this.svg = { name, text };
    this.panel?.setSvgChoice(name, fromFile);
    this.refreshPanel();
  }

  private async chooseSvgSample(file: string): Promise<void> {
    try {
      const bytes = await fetchBytes(`samples/${file}`, file);
      this.useSvg(file, new TextDecoder().decode(bytes), false);
      this.startPlacing();
    } catch (err) {
      this.ctx?.state.setError(err instanceof Error ? err.message : String(err));
    }
  }

  private async chooseSvgFile(file: File): Promise<void> {
    try {
      const bytes = await readFile(file);
      this.useSvg(file.name, new TextDecoder().decode(bytes), true);
      this.startPlacing();
    } catch (err) {
      this.ctx?.state.setError(err instanceof Error ? err.message : String(err));
    }
  }

  private startPlacing(): void {
    if (!this.svg || !this.session) return;
    this.finish();
    this.placing = true;
    this.ctx?.state.setMessage(`Click on the mesh where the centre of ${this.svg.name} goes`);
    this.refreshPanel();
  }

  private stopPlacing(): void {
    if (!this.placing) return;
    this.placing = false;
    this.ctx?.state.setMessage(null);
    this.refreshPanel();
  }

  private place(center: MeshPoint): void {
    const svg = this.svg;
    if (!svg) return;
    this.stopPlacing();
    this.enqueue(async () => {
      const s = this.session, gen = this.generation, mesh = this.mesh;
      if (!s || !mesh || !this.ctx) return;
      this.ctx.state.setBusy(`Placing ${svg.name}…`);
      try {
        const up = this.screenUp();
        const r = await this.client.map(svg.text, svg.name, center, this.prefs.svgSize * mesh.scale, (this.prefs.svgRotation * Math.PI) / 180, up);
        if (s !== this.session || gen !== this.generation) return;
        const added = r.splines.map((json) => ({ id: s.newId(), json }));
        this.replaceDrawing(`Place ${svg.name}`, addSplines(s.drawing, added), added.length > 0 ? { spline: added[0].id, point: null } : null);
        this.placement = { ids: added.map((a) => a.id), jsons: added.map((a) => a.json), center, svg, up };
        this.ctx.state.setMessage(`${svg.name}: ${added.length} splines placed in ${r.ms.toFixed(0)} ms`);
      } finally {
        this.ctx?.state.setBusy(null);
      }
    });
  }

  /** The screen's up direction in the world (a placed drawing reads upright in the view). */
  private screenUp(): [number, number, number] {
    const q = this.view?.camera.quaternion;
    const up = new Vector3(0, 1, 0);
    if (q) up.applyQuaternion(q);
    return [up.x, up.y, up.z];
  }

  /** The last placement, if its splines are still as it made them. */
  private untouchedPlacement(): Placement | null {
    const p = this.placement;
    if (!p) return null;
    const d = this.drawing;
    return p.ids.every((id, i) => findSpline(d, id)?.json === p.jsons[i]) ? p : null;
  }

  /** Size or rotation changed: the next placement uses it, and the last one (untouched) follows. */
  private setSvgPlacement(change: Partial<Pick<SurfacePrefs, 'svgSize' | 'svgRotation'>>): void {
    this.setPrefs(change);
    const p = this.untouchedPlacement();
    if (!p) return;
    if (this.remap.busy) {
      this.remap.again = true;
      return;
    }
    this.remap.busy = true;
    this.remap.before ??= this.drawing;
    const s = this.session!, gen = this.generation, mesh = this.mesh!;
    this.work++;
    this.client
      .map(p.svg.text, p.svg.name, p.center, this.prefs.svgSize * mesh.scale, (this.prefs.svgRotation * Math.PI) / 180, p.up)
      .then((r) => {
        if (s !== this.session || gen !== this.generation || r.splines.length !== p.ids.length || this.untouchedPlacement() !== p) return;
        let d = s.drawing;
        r.splines.forEach((json, i) => (d = replaceSpline(d, p.ids[i], json)));
        p.jsons = r.splines;
        s.setDrawing(d);
      })
      .catch((err: unknown) => this.ctx?.state.setError(err instanceof Error ? err.message : String(err)))
      .finally(() => {
        this.remap.busy = false;
        this.done();
        if (this.remap.again) {
          this.remap.again = false;
          this.setSvgPlacement({});
        } else if (this.remap.commit) this.commitRemap();
      });
  }

  /** Records the resizing/turning of the last placement as one undoable edit, once it settles. */
  private commitRemap(): void {
    const before = this.remap.before, s = this.session, ctx = this.ctx;
    this.remap.before = null;
    this.remap.commit = false;
    if (!before || !s || !ctx || before === s.drawing) return;
    const after = s.drawing;
    // The drawing already shows `after`: the command's do() sets the same value.
    ctx.history.execute(new DrawingCommand('Resize or turn the placed SVG', this, s, before, after, { do: this.selection, undo: this.selection }));
  }

  // ---- tools and prefs -------------------------------------------------------------------------

  private setTool(tool: SurfaceTool): void {
    if (this.gesture) return;
    this.tool = tool;
    if (tool !== 'draw') this.finish();
    this.stopPlacing();
    this.updateCursor(null);
    this.refreshPanel();
    this.requestDraw();
  }

  private setPrefs(change: Partial<SurfacePrefs>): void {
    const before = this.traceKey();
    this.prefs = { ...this.prefs, ...change };
    savePrefs(this.prefs);
    this.view?.setFlatShading(this.prefs.flat);
    this.panel?.setPrefs(this.prefs, this.mesh?.scale ?? null);
    if (this.traceKey() !== before) {
      this.lastTrace = null;
      this.ensureTraces();
      this.requestDraw();
    }
  }

  /** Does what a key asks; false when it does not apply (the key goes on to the editor). */
  private run(action: SurfaceAction, e: KeyboardEvent): boolean {
    switch (action) {
      case 'finish':
        return this.finish();
      case 'escape':
        if (this.gesture) {
          this.cancelGesture();
          return true;
        }
        if (this.placing) {
          this.stopPlacing();
          return true;
        }
        if (this.finish()) return true;
        if (this.tool !== 'draw') {
          this.setTool('draw');
          return true;
        }
        if (this.selection) {
          this.setSelection(null);
          return true;
        }
        return false;
      case 'delete':
        if (!this.selection) return false;
        if (this.selection.point !== null && isAnchor(this.selection.point)) this.deleteSelectedPoint();
        else if (this.selection.point === null) this.deleteSelectedSpline();
        return true;
      case 'smooth':
        if (this.selection?.point == null) return false;
        this.toggleSmooth();
        return true;
      case 'tool-move':
      case 'tool-rotate':
      case 'tool-scale': {
        if (e.repeat) return true;
        const tool = action === 'tool-move' ? 'move' : action === 'tool-rotate' ? 'rotate' : 'scale';
        this.setTool(this.tool === tool ? 'draw' : tool);
        return true;
      }
    }
  }

  // ---- pointer input ---------------------------------------------------------------------------

  private readonly input: View3DInput = {
    pointerDown: (p) => this.press(p),
    pointerDrag: (p) => this.drag(p),
    pointerUp: (p, moved) => void this.release(p, moved),
    hover: (p) => this.hoverAt(p),
    pointerLeave: () => {
      this.setPreview(null);
      this.updateCursor(null);
    },
    click: (p) => this.clickAt(p),
    doubleClick: () => {
      this.finish();
    },
  };

  private get interactive(): boolean {
    return this.session !== null && this.mesh !== null && !this.committing && this.ctx !== null;
  }

  private meshPointAt(sx: number, sy: number): MeshPoint | null {
    const hit = this.view?.pick(sx, sy);
    return hit ? { face: hit.face, uv: [hit.u, hit.v] } : null;
  }

  private press(p: Pointer3D): boolean {
    if (!this.interactive || this.placing) return false;
    const d = this.drawing;
    if (this.tool === 'draw') {
      if (p.altKey) return false;
      const hit = this.pickControlPoint(p.sx, p.sy);
      if (!hit) return false;
      const sp = findSpline(d, hit.id)!;
      this.setSelection({ spline: hit.id, point: hit.index });
      this.gesture = { kind: 'point', id: hit.id, index: hit.index, base: sp.json, latest: null };
      return true;
    }
    const sp = this.selection && findSpline(d, this.selection.spline);
    if (!sp) return false;
    if (this.tool === 'move') {
      const from = this.meshPointAt(p.sx, p.sy);
      if (!from) return false;
      this.gesture = { kind: 'move', id: sp.id, base: sp.json, from, latest: null };
      return true;
    }
    const c = this.centreOf(sp);
    if (!c) return false;
    this.gesture = { kind: this.tool, id: sp.id, base: sp.json, center: c.point, cx: c.sx, cy: c.sy, sx: p.sx, sy: p.sy, facing: c.facing, latest: null };
    this.requestDraw();
    return true;
  }

  private drag(p: Pointer3D): void {
    const g = this.gesture;
    if (!g) return;
    let op: SplineOp;
    if (g.kind === 'point' || g.kind === 'move') {
      const to = this.meshPointAt(p.sx, p.sy);
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
    const gen = this.generation;
    const promise = this.client.run(g.base, [op], this.traceOptions(), true, this.lane(g.id));
    g.latest = promise;
    promise.then(
      (r) => {
        if (this.gesture !== g || gen !== this.generation) return;
        this.live.set(g.id, r);
        this.noteTrace(r);
        this.requestDraw();
      },
      (err: unknown) => {
        if (err instanceof SupersededError || this.gesture !== g) return;
        this.ctx?.state.setMessage(`Could not follow the pointer: ${err instanceof Error ? err.message : String(err)}`);
      },
    );
  }

  private async release(p: Pointer3D, moved: boolean): Promise<void> {
    const g = this.gesture;
    if (!g) return;
    if (p.button === -1 || !moved || !g.latest) {
      this.cancelGesture();
      return;
    }
    const s = this.session!, gen = this.generation;
    this.committing = true;
    this.work++;
    try {
      const r = await g.latest;
      if (this.gesture !== g) return; // cancelled meanwhile
      const label = g.kind === 'point' ? (isAnchor(g.index) ? 'Move anchor' : 'Move handle') : g.kind === 'move' ? 'Move spline' : g.kind === 'rotate' ? 'Rotate spline' : 'Scale spline';
      const sel = g.kind === 'point' ? { spline: g.id, point: g.index } : { spline: g.id, point: null };
      this.gesture = null;
      this.live.delete(g.id);
      this.commit(label, s, gen, g.id, g.base, r, sel);
    } catch (err) {
      if (!(err instanceof SupersededError)) this.ctx?.state.setError(err instanceof Error ? err.message : String(err));
      if (this.gesture === g) this.cancelGesture();
    } finally {
      this.committing = false;
      this.done();
      this.requestDraw();
    }
  }

  private cancelGesture(): void {
    const g = this.gesture;
    if (!g) return;
    this.gesture = null;
    this.live.delete(g.id);
    this.requestDraw();
  }

  private clickAt(p: Pointer3D): void {
    if (!this.interactive) return;
    if (this.placing) {
      const at = this.meshPointAt(p.sx, p.sy);
      if (at) this.place(at);
      return;
    }
    if (this.tool !== 'draw') {
      const c = this.pickCurve(p.sx, p.sy);
      this.setSelection(c ? { spline: c.id, point: null } : null);
      return;
    }
    const last = this.lastClick;
    this.lastClick = { sx: p.sx, sy: p.sy, time: p.time };
    const drawing = this.drawingId !== null || this.pending !== null;
    if (drawing && last && p.time - last.time < DOUBLE_CLICK_MS && Math.hypot(p.sx - last.sx, p.sy - last.sy) < DOUBLE_CLICK_PX) {
      this.lastClick = null;
      this.finish();
      return;
    }
    if (p.altKey) {
      const c = this.pickCurve(p.sx, p.sy);
      if (c) this.insertPoint(c.id, c.segment, c.t);
      return;
    }
    const at = this.meshPointAt(p.sx, p.sy);
    if (drawing) {
      // Off the mesh (a hole, the background) nothing happens: Enter, Esc or a double click ends.
      if (at) this.addPoint(at);
      return;
    }
    const c = this.pickCurve(p.sx, p.sy);
    if (c) {
      this.setSelection({ spline: c.id, point: null });
      return;
    }
    if (!at) {
      this.setSelection(null);
      return;
    }
    this.addPoint(at);
    this.refreshPanel();
    this.requestDraw();
  }

  private hoverAt(p: Pointer3D): void {
    if (!this.interactive) return;
    if (this.tool === 'draw' && !this.placing && this.pickControlPoint(p.sx, p.sy)) {
      this.updateCursor('grab');
      this.setPreview(null);
      return;
    }
    const at = this.meshPointAt(p.sx, p.sy);
    if (this.placing) {
      this.updateCursor(at ? 'crosshair' : null);
      return;
    }
    if (this.tool !== 'draw') {
      this.updateCursor(this.selection && (at || this.tool !== 'move') ? (this.tool === 'move' ? 'move' : 'ew-resize') : null);
      return;
    }
    const over = !at && !this.pending && this.drawingId === null ? null : at ? 'crosshair' : null;
    this.updateCursor(over ?? (this.pickCurve(p.sx, p.sy) ? 'pointer' : at ? 'crosshair' : null));
    // The rubber band: a geodesic from the last point to the pointer.
    const from = this.lastDrawnPoint();
    if (!from || !at) {
      this.setPreview(null);
      return;
    }
    const gen = this.generation;
    this.client.path(from, at, 'preview').then(
      (r) => {
        if (gen === this.generation && this.lastDrawnPoint()) this.setPreview(r.lifted);
      },
      () => undefined, // superseded, or no path: no rubber band
    );
  }

  private lastDrawnPoint(): MeshPoint | null {
    if (this.drawingId !== null) {
      const sp = findSpline(this.drawing, this.drawingId);
      return sp ? sp.json.points[sp.json.points.length - 1] : null;
    }
    return this.pending;
  }

  private setPreview(lifted: Float32Array | null): void {
    if (lifted === this.preview) return;
    this.preview = lifted;
    this.requestDraw();
  }

  private updateCursor(cursor: string | null): void {
    const c = this.view?.canvas;
    if (c) c.style.cursor = cursor ?? '';
  }

  // ---- picking ---------------------------------------------------------------------------------

  /** Where a mesh point is (on the surface), from the shown mesh's positions. */
  private xyz(p: MeshPoint): [number, number, number] | null {
    const m = this.view?.mesh;
    if (!m || p.face < 0 || 3 * p.face + 2 >= m.triangles.length) return null;
    const P = m.positions, T = m.triangles;
    const a = 3 * T[3 * p.face], b = 3 * T[3 * p.face + 1], c = 3 * T[3 * p.face + 2];
    const [u, v] = p.uv, w = 1 - u - v;
    return [w * P[a] + u * P[b] + v * P[c], w * P[a + 1] + u * P[b + 1] + v * P[c + 1], w * P[a + 2] + u * P[b + 2] + v * P[c + 2]];
  }

  /** The interpolated smooth normal at a mesh point. */
  private normal(p: MeshPoint): Vector3 {
    const m = this.view!.mesh!, N = m.normals, T = m.triangles;
    const a = 3 * T[3 * p.face], b = 3 * T[3 * p.face + 1], c = 3 * T[3 * p.face + 2];
    const [u, v] = p.uv, w = 1 - u - v;
    return new Vector3(w * N[a] + u * N[b] + v * N[c], w * N[a + 1] + u * N[b + 1] + v * N[c + 1], w * N[a + 2] + u * N[b + 2] + v * N[c + 2]).normalize();
  }

  /** The control points drawn now (all anchors; handles of the selected or drawn spline). */
  private controlMarks(): ControlMark[] {
    const out: ControlMark[] = [];
    if (!this.ctx?.state.overlay) return out;
    for (const sp of this.drawing.splines) {
      const json = this.shownJSON(sp);
      const full = this.selection?.spline === sp.id || this.drawingId === sp.id;
      json.points.forEach((mp, index) => {
        if (!full && !isAnchor(index)) return;
        const at = this.xyz(mp);
        if (at) out.push({ id: sp.id, index, xyz: at });
      });
    }
    return out;
  }

  private pickControlPoint(sx: number, sy: number): { id: number; index: number } | null {
    const view = this.view;
    if (!view || !this.mesh) return null;
    let best: ControlMark | null = null, bestD = POINT_HIT_PX;
    const slack = this.mesh.scale * 2e-3;
    const candidates: [ControlMark, number][] = [];
    for (const m of this.controlMarks()) {
      const s = view.project(...m.xyz);
      if (s.depth <= 0) continue;
      const d = Math.hypot(s.sx - sx, s.sy - sy);
      if (d <= POINT_HIT_PX) candidates.push([m, d]);
    }
    // Handles of the selected spline win ties over anchors under them; hidden points do not count.
    candidates.sort((a, b) => a[1] - b[1] || (isAnchor(a[0].index) ? 1 : 0) - (isAnchor(b[0].index) ? 1 : 0));
    for (const [m, d] of candidates) {
      if (!view.isVisible(...m.xyz, slack)) continue;
      best = m;
      bestD = d;
      break;
    }
    return best && bestD <= POINT_HIT_PX ? { id: best.id, index: best.index } : null;
  }

  /** The curve under a canvas point: spline, segment and parameter (by arc length in it). */
  private pickCurve(sx: number, sy: number): { id: number; segment: number; t: number } | null {
    const view = this.view;
    if (!view || !this.mesh) return null;
    view.camera.updateMatrixWorld();
    const m = new Matrix4().multiplyMatrices(view.camera.projectionMatrix, view.camera.matrixWorldInverse).elements;
    const W = view.size.x, H = view.size.y;
    let best: { id: number; i: number; f: number; d: number } | null = null;
    const slack = this.mesh.scale * 2e-3;
    const hits: { id: number; i: number; f: number; d: number }[] = [];
    for (const sp of this.drawing.splines) {
      const tr = this.traceOf(sp);
      if (!tr) continue;
      const L = tr.lifted, n = L.length / 3;
      let px = 0, py = 0, pok = false;
      for (let i = 0; i < n; i++) {
        const x = L[3 * i], y = L[3 * i + 1], z = L[3 * i + 2];
        const w = m[3] * x + m[7] * y + m[11] * z + m[15];
        const ok = w > 0;
        const qx = ((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) * 0.5 * W;
        const qy = (1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) * 0.5 * H;
        if (i > 0 && ok && pok) {
          const dx = qx - px, dy = qy - py, l2 = dx * dx + dy * dy;
          const f = l2 > 0 ? Math.min(1, Math.max(0, ((sx - px) * dx + (sy - py) * dy) / l2)) : 0;
          const d = Math.hypot(px + f * dx - sx, py + f * dy - sy);
          if (d <= CURVE_HIT_PX) hits.push({ id: sp.id, i: i - 1, f, d });
        }
        px = qx;
        py = qy;
        pok = ok;
      }
    }
    hits.sort((a, b) => a.d - b.d);
    for (const hit of hits.slice(0, 24)) {
      const sp = findSpline(this.drawing, hit.id)!;
      const L = this.traceOf(sp)!.lifted, k = 3 * hit.i;
      const x = L[k] + hit.f * (L[k + 3] - L[k]), y = L[k + 1] + hit.f * (L[k + 4] - L[k + 1]), z = L[k + 2] + hit.f * (L[k + 5] - L[k + 2]);
      if (view.isVisible(x, y, z, slack)) {
        best = hit;
        break;
      }
    }
    if (!best) return null;
    const sp = findSpline(this.drawing, best.id)!;
    const tr = this.traceOf(sp)!;
    const starts = tr.segmentStarts, n = tr.xyz.length / 3;
    let segment = 0;
    while (segment + 1 < starts.length && starts[segment + 1] <= best.i) segment++;
    const a = starts[segment], b = segment + 1 < starts.length ? starts[segment + 1] : n - 1;
    // Parameter by arc length along the segment's polyline (a good guess for t).
    const X = tr.xyz;
    const len = (i: number) => Math.hypot(X[3 * i + 3] - X[3 * i], X[3 * i + 4] - X[3 * i + 1], X[3 * i + 5] - X[3 * i + 2]);
    let total = 0, upto = 0;
    for (let i = a; i < b; i++) {
      const l = len(i);
      if (i < best.i) upto += l;
      else if (i === best.i) upto += best.f * l;
      total += l;
    }
    const t = total > 0 ? Math.min(0.98, Math.max(0.02, upto / total)) : 0.5;
    return { id: best.id, segment, t };
  }

  /**
   * The centre of a spline for turning and scaling: the surface under the middle of its traced
   * points as seen on screen (else its nearest control point), with whether it faces the camera.
   */
  private centreOf(sp: DrawnSpline): { point: MeshPoint; sx: number; sy: number; facing: number } | null {
    const view = this.view;
    if (!view) return null;
    const tr = this.traceOf(sp);
    const c = new Vector3();
    let n = 0;
    if (tr) {
      for (let i = 0; i < tr.xyz.length; i += 3, n++) c.add(new Vector3(tr.xyz[i], tr.xyz[i + 1], tr.xyz[i + 2]));
    } else {
      for (const p of sp.json.points) {
        const at = this.xyz(p);
        if (at) {
          c.add(new Vector3(...at));
          n++;
        }
      }
    }
    if (n === 0) return null;
    c.divideScalar(n);
    const s = view.project(c.x, c.y, c.z);
    let point = this.meshPointAt(s.sx, s.sy);
    if (!point) {
      let best = Infinity;
      for (const p of sp.json.points) {
        const at = this.xyz(p);
        if (!at) continue;
        const d = c.distanceToSquared(new Vector3(...at));
        if (d < best) [best, point] = [d, p];
      }
    }
    if (!point) return null;
    const at = this.xyz(point)!;
    const q = view.project(...at);
    const toCamera = view.camera.position.clone().sub(new Vector3(...at));
    const facing = this.normal(point).dot(toCamera) >= 0 ? 1 : -1;
    return { point, sx: q.sx, sy: q.sy, facing };
  }

  // ---- drawing ---------------------------------------------------------------------------------

  private requestDraw(): void {
    if (this.frame || !this.view) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.draw();
    });
  }

  private draw(): void {
    const view = this.view, layers = this.layers;
    if (!view || !layers) return;
    const d = this.drawing;
    const selectedId = this.selection?.spline ?? this.drawingId;
    layers.setCurves(d.splines.map((sp) => ({ id: sp.id, lifted: this.traceOf(sp)?.lifted ?? null, selected: sp.id === selectedId || sp.id === this.drawingId })));
    const sel = selectedId !== null && selectedId !== undefined ? findSpline(d, selectedId) : undefined;
    const polygon = sel && this.ctx?.state.overlay ? this.polygonOf(sel) : null;
    layers.setPolygon(polygon?.lifted ?? null, polygon?.starts ?? null);
    layers.setPreview(this.preview);

    // Markers on the surface (drawn toward the camera by their radius, see MarkerLayer).
    const markers: Marker[] = [];
    const put = (p: MeshPoint, color: string, size: number, shape: 'disc' | 'square') => {
      const at = this.xyz(p);
      if (at) markers.push({ x: at[0], y: at[1], z: at[2], color, size, shape });
    };
    if (this.ctx?.state.overlay !== false) {
      for (const sp of d.splines) {
        const json = this.shownJSON(sp);
        const full = sp.id === selectedId || sp.id === this.drawingId;
        json.points.forEach((mp, i) => {
          const hot = this.selection?.spline === sp.id && this.selection.point === i;
          if (isAnchor(i)) put(mp, hot ? SURFACE_COLORS.hot : SURFACE_COLORS.anchor, full ? (hot ? 12 : 10) : 8, json.smooth[i / 3] ? 'disc' : 'square');
          else if (full) put(mp, hot ? SURFACE_COLORS.hot : SURFACE_COLORS.handle, hot ? 11 : 9, 'disc');
        });
      }
    }
    if (this.pending) put(this.pending, SURFACE_COLORS.pending, 10, 'square');
    const g = this.gesture;
    if (g && (g.kind === 'rotate' || g.kind === 'scale')) put(g.center, SURFACE_COLORS.center, 12, 'disc');
    layers.setMarkers(markers, view.worldPerPixel(1) * 7);
    view.requestRender();
  }

  // ---- panel and status ------------------------------------------------------------------------

  private refreshPanel(): void {
    const panel = this.panel;
    if (!panel) return;
    panel.setPrefs(this.prefs, this.mesh?.scale ?? null);
    panel.setMesh(this.session?.file ?? null, this.mesh?.info ?? null, this.session?.sample ?? false);
    const d = this.drawing, sel = this.selection, sp = sel ? findSpline(d, sel.spline) : undefined;
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
    const drawingNow = this.drawingId !== null || this.pending !== null;
    panel.setTool(this.tool, drawingNow && this.tool === 'draw' ? 'Drawing: click to add points; Enter, Esc or a double click finishes.' : TOOL_HINTS[this.tool]);
    panel.setSelection({
      splines: d.splines.length,
      selected,
      smooth,
      canInsert: !!sp,
      canDeletePoint: !!sp && sel?.point != null && isAnchor(sel.point),
      canDeleteSpline: !!sp,
    });
    panel.setPlacing(this.placing, this.svg !== null && this.session !== null);
    this.refreshTraceFacts();
  }

  private refreshTraceFacts(): void {
    const t = this.lastTrace;
    let points = 0;
    for (const sp of this.drawing.splines) points += (this.traceOf(sp)?.xyz.length ?? 0) / 3;
    this.panel?.setTrace(t ? (t.count > 1 ? `${t.count} splines in ${t.sum.toFixed(1)} ms` : `${t.ms.toFixed(2)} ms`) : '—', points.toLocaleString('en-US'));
  }

  private refreshStatus(): void {
    const s = this.session, m = this.mesh;
    this.statusMesh.textContent = s && m ? `${s.file} · ${m.info.faces.toLocaleString('en-US')} triangles` : 'No mesh';
    this.statusMesh.title = s && m ? `${s.file}: ${m.info.faces} triangles, ${m.info.usedVertices} vertices, loaded and precomputed in ${m.loadMs.toFixed(0)} ms` : '';
    const w = m?.info.warnings ?? [];
    this.statusWarnings.textContent = w.length === 0 ? (m ? 'no warnings' : '') : w.length === 1 ? w[0] : `${w.length} warnings: ${w[0]}…`;
    this.statusWarnings.title = w.join('\n');
    this.statusWarnings.classList.toggle('has-warnings', w.length > 0);
    const t = this.lastTrace;
    this.statusTrace.textContent = t
      ? t.count > 1
        ? `traced ${t.count} splines in ${t.sum.toFixed(1)} ms (${t.points.toLocaleString('en-US')} points)`
        : `traced in ${t.ms.toFixed(2)} ms (${t.points.toLocaleString('en-US')} points)`
      : '';
    this.statusTrace.title = 'Time the core took to trace (geodesic subdivision), per the last edit or retrace';
    this.refreshTraceFacts();
  }

  // ---- autosave --------------------------------------------------------------------------------

  private saveNow(): void {
    const s = this.session;
    if (!s) return;
    const problem = saveDrawing(s, s.drawing);
    if (problem) this.ctx?.state.setMessage(`Autosave failed: ${problem}`);
  }

  // ---- tests -----------------------------------------------------------------------------------

  private done(): void {
    this.work = Math.max(0, this.work - 1);
    if (this.work === 0) {
      const waiters = this.workWaiters;
      this.workWaiters = [];
      setTimeout(() => waiters.forEach((w) => w()), 0);
    }
  }

  /** Resolves when a mesh is shown and no load, edit or trace is under way. */
  async ready(): Promise<void> {
    for (;;) {
      if (this.work === 0 && !this.client.busy && this.session && this.mesh && !this.gesture) {
        await this.view?.nextFrame();
        if (this.work === 0 && !this.client.busy) return;
      }
      await new Promise<void>((resolve) => {
        if (this.work === 0) setTimeout(resolve, 20);
        else this.workWaiters.push(resolve);
      });
    }
  }

  testState(): SurfaceTestState {
    return surfaceTestState({
      active: this.active,
      file: this.session?.file ?? null,
      info: this.mesh?.info ?? null,
      scale: this.mesh?.scale ?? null,
      drawing: this.drawing,
      traceOf: (sp) => this.traceOf(sp),
      selection: this.selection,
      tool: this.tool,
      drawingId: this.drawingId,
      pending: this.pending !== null,
      placing: this.placing,
      lastTraceMs: this.lastTrace?.ms ?? null,
      options: this.traceOptions(),
      saved: !this.autosave.pending,
    });
  }

  /** Where a mesh point is on the canvas (CSS pixels) and whether it is seen, or null. */
  projectOnCanvas(p: MeshPoint): { x: number; y: number; visible: boolean } | null {
    const view = this.view, at = this.xyz(p);
    if (!view || !at || !this.mesh) return null;
    const s = view.project(...at);
    return { x: s.sx, y: s.sy, visible: s.depth > 0 && view.isVisible(...at, this.mesh.scale * 2e-3) };
  }

  /** The mesh point under a canvas point, or null. */
  meshPointOnCanvas(sx: number, sy: number): MeshPoint | null {
    return this.meshPointAt(sx, sy);
  }

  /** Vertex positions of faces (9 numbers each), from the shown mesh. */
  faceVertices(faces: number[]): number[] {
    const m = this.view?.mesh;
    if (!m) return [];
    const out: number[] = [];
    for (const f of faces) for (let c = 0; c < 3; c++) for (let k = 0; k < 3; k++) out.push(m.positions[3 * m.triangles[3 * f + c] + k]);
    return out;
  }

  get canvas(): HTMLCanvasElement | null {
    return this.view?.canvas ?? null;
  }

  /** The accept list of the mesh file input (the toolbar's Open uses it in this mode). */
  static readonly accept = `${MESH_ACCEPT},.svg,image/svg+xml`;
}
