import { Vector3 } from 'three';
import { cageToOBJ, parseCage, type SubdivisionRig } from '../../../src/index.js';
import { DebouncedSave } from '../../app/autosave.js';
import { download } from '../../app/download.js';
import { messageOf } from '../../app/errors.js';
import { InFlight } from '../../app/in-flight.js';
import { keyframeAt } from '../../app/keyframes.js';
import { fetchBytes, readFile } from '../../app/loader.js';
import type { Mode, ModeContext } from '../../app/modes.js';
import type { Marker } from '../../view3d/points.js';
import { View3D, type Pointer3D, type View3DInput } from '../../view3d/view3d.js';
import { SpecCommand } from '../skin/commands.js';
import { KeyframeControl } from '../skin/keyframe-control.js';
import { Timeline } from '../skin/timeline.js';
import { niceCeil } from './colormap.js';
import { OpenCageCommand } from './commands.js';
import { animatedGLTF, type SurfaceFrame } from './export.js';
import { SKIN3D_KEYS, keyAction3D, type Skin3DAction } from './keymap.js';
import { SKIN3D_COLORS, Skin3DLayers } from './layers.js';
import { Skin3DSession, boundingBox, type PoseOverlays } from './session.js';
import { Skin3DPanel, type CageSample, type GizmoMode, type Overlay3D, type Overlay3DFlags } from './skin3d-panel.js';
import { EMPTY_SPEC3D, REST_POSE, addHandle3D, isRest, poseAt3D, posedCenter, samePoses, removeHandle3D, setHandlePose, setPose3D, type HandlePose, type Skin3DSpec, type Skin3DWeights } from './spec.js';
import { loadSkin3D, saveSkin3D } from './storage.js';
import { Weights3DClient } from './weights-client.js';

const AUTOSAVE_MS = 300;
/** Frames per second of the exported glTF between keyframes. */
export const GLTF_FPS = 10;

/** How a cage is opened: undoable (a user's open) or not (the starting cage), with a saved spec. */
interface OpenOptions {
  undoable: boolean;
  spec?: Skin3DSpec;
  time?: number;
}

/** Pixels around a handle's marker that pick it. */
const HANDLE_PICK_PX = 12;
const HANDLE_SIZE = 13;

/** What the end-to-end tests read (window.splinekitEditor.skin3d.state()). */
export interface Skin3DTestState {
  active: boolean;
  file: string | null;
  cage: { vertices: number; faces: number; creases: number } | null;
  /** Rest cage positions and posed cage positions (3 per vertex). */
  restCage: number[];
  posedCage: number[];
  refinedVertices: number;
  /** Posed refined surface as shown (3 per vertex). */
  surface: number[];
  handles: { x: number; y: number; z: number }[];
  pose: HandlePose[];
  selected: number | null;
  rig: { phase: string; ready: boolean; message: string | null };
  /** Progress messages the weights worker sent for this cage. */
  progressReports: number;
  keyframes: number[];
  time: number;
  duration: number;
  gizmo: GizmoMode;
  overlays: Overlay3DFlags;
  errors: { fitRms: number; naiveRms: number } | null;
  canUndo: boolean;
  /** Nothing waits to be autosaved. */
  saved: boolean;
}

/**
 * 3D Skin mode (Liu, Jacobson, Gingold 2014, §5: skinning Catmull-Clark subdivision surfaces):
 * open a quad cage, place handles on its refined surface, pose them with a translate/rotate/scale
 * gizmo; the cage is fitted (SubdivisionRig) so that its subdivision surface follows the handles'
 * linear blend skinning. Overlays show the target, the naive cage's surface and the distance to
 * the target as colours (the paper's Fig. 8); poses are keyed on a timeline; the posed cage exports
 * as OBJ and the animation as glTF. BBW weights are solved in a worker with progress.
 */
export class Skin3DMode implements Mode {
  readonly id = 'skin3d';
  readonly title = '3D Skin';
  readonly description = 'Pose a Catmull-Clark subdivision surface with handles (Liu, Jacobson & Gingold 2014 §5): the cage is fitted to the handles’ skinning';
  readonly keys = SKIN3D_KEYS;
  /** Rig builds and file loads under way. */
  readonly work = new InFlight();
  /** The accept list of the file input while this mode is active. */
  static readonly accept = '.obj';

  private readonly client = new Weights3DClient();
  private ctx: ModeContext | null = null;
  private _view: View3D | null = null;
  private layers: Skin3DLayers | null = null;
  private panel: Skin3DPanel | null = null;
  private timeline: Timeline | null = null;
  private _session: Skin3DSession | null = null;
  private samples: CageSample[] = [];
  private gizmoMode: GizmoMode = 'translate';
  private overlays: Overlay3DFlags = { cage: true, target: false, naive: false, errors: false };
  /** A gizmo drag under way: the spec when it started. */
  private drag: { before: Skin3DSpec; index: number } | null = null;
  private starting: Promise<void> | null = null;
  private frame = 0;
  private shownSurface: Float64Array | null = null;
  private lastErrors: { fitRms: number; naiveRms: number } | null = null;
  /** The pose shown is a live one (a gizmo drag, playback): error numbers wait for its end. */
  private livePose = false;
  private diagonalOf: { rig: SubdivisionRig; value: number } | null = null;
  private off: (() => void)[] = [];
  private sessionOff: (() => void)[] = [];
  private readonly autosave = new DebouncedSave(AUTOSAVE_MS, () => this.saveNow());
  private readonly keyframes = new KeyframeControl<Skin3DSpec>({
    session: () => this._session,
    canKey: () => (this._session?.spec.handles.length ?? 0) > 0,
    busy: () => this.drag !== null,
    execute: (label, after) => this.execute(label, after),
    refresh: () => this.refreshTimeline(),
    stopped: () => {
      this.livePose = false;
      this.requestDraw();
    },
  });

  constructor() {
    window.addEventListener('pagehide', () => this.autosave.flush());
  }

  // ---- Mode ------------------------------------------------------------------------------------

  activate(ctx: ModeContext): void {
    this.ctx = ctx;
    if (!this._view) {
      this._view = new View3D(ctx.view.container);
      this._view.canvas.setAttribute('aria-label', '3D view of the cage and its subdivision surface');
      this._view.canvas.dataset.testid = 'skin3d-view';
      this.layers = new Skin3DLayers(this._view);
      this.listenGizmo(this.layers);
      this._view.events.on('view', () => this.requestDraw());
    }
    ctx.view.setVisible(false);
    this._view.setVisible(true);
    this._view.input = this.input;
    this.panel = new Skin3DPanel({
      openSample: (file) => void this.openSample(file),
      openFile: (file) => void this.openFile(file),
      setWeights: (kind) => this.setWeights(kind),
      setLevels: (levels) => this.edit(`Use ${levels} subdivision levels`, (s) => (s.levels === levels ? s : { ...s, levels })),
      setGizmo: (mode) => this.setGizmo(mode),
      setOverlay: (name, on) => this.setOverlay(name, on),
      resetPose: () => this.resetPose(),
      removeHandle: () => this.removeSelected(),
      exportOBJ: () => this.exportOBJ(),
      exportGLTF: () => void this.exportGLTF(),
    });
    ctx.panel.append(...this.panel.sections);
    ctx.view.container.append(this.panel.legend);
    this.timeline = new Timeline(this.keyframes.actions);
    ctx.dock.append(this.timeline.el);
    document.body.classList.add('mode-skin3d');
    this.panel.setSamples(this.samples, this._session?.file ?? null);
    this.panel.setGizmo(this.gizmoMode);
    this.panel.setOverlays(this.overlays);
    this.refreshAll();
    // The sample list, and the first sample when no cage is open (again if a visit left before).
    if (!this._session && !this.starting) this.starting = this.work.track(this.start()).finally(() => (this.starting = null));
  }

  deactivate(): void {
    const ctx = this.ctx;
    this.autosave.flush();
    this.keyframes.stop();
    this.endDrag();
    for (const off of this.off) off();
    this.off = [];
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this._view?.setVisible(false);
    if (this._view) this._view.input = null;
    document.body.classList.remove('mode-skin3d');
    if (ctx) {
      ctx.view.setVisible(true);
      ctx.view.requestRender();
    }
    this.panel?.legend.remove();
    this.panel = null;
    this.timeline = null;
    this.ctx = null;
  }

  keyDown(e: KeyboardEvent): boolean {
    const action = keyAction3D(e);
    return action !== null && this.run(action, e);
  }

  // ---- what the editor calls -------------------------------------------------------------------

  get active(): boolean {
    return this.ctx !== null;
  }

  get session(): Skin3DSession | null {
    return this._session;
  }

  get view(): View3D | null {
    return this._view;
  }

  fit(): void {
    this._view?.fit();
  }

  zoom(factor: number): void {
    this._view?.zoom(factor);
  }

  /** Resolves when no load or rig build is under way. */
  ready(): Promise<void> {
    return this.work.idle();
  }

  /** A file opened or dropped while the mode is active: an OBJ cage replaces the cage. */
  async openFile(file: File): Promise<boolean> {
    const ctx = this.ctx;
    if (!ctx) return false;
    try {
      const bytes = await this.work.track(readFile(file));
      return this.openText(new TextDecoder().decode(bytes), file.name);
    } catch (err) {
      ctx.state.setError(messageOf(err));
      return false;
    }
  }

  /** Opens a sample cage (public/samples/cages). */
  async openSample(file: string, options: OpenOptions = { undoable: true }): Promise<boolean> {
    try {
      const bytes = await this.work.track(fetchBytes(`samples/cages/${file}`, file));
      return this.openText(new TextDecoder().decode(bytes), file, options);
    } catch (err) {
      this.ctx?.state.setError(messageOf(err));
      this.panel?.setSamples(this.samples, this._session?.file ?? null);
      return false;
    }
  }

  /**
   * Opens a cage from OBJ text (undoable, unless it is the starting cage). A cage the parser or
   * the rig rejects is reported in the editor's error line and the cage shown stays.
   */
  openText(text: string, name: string, options: OpenOptions = { undoable: true }): boolean {
    const ctx = this.ctx;
    if (!ctx) return false;
    let next: Skin3DSession;
    try {
      const cage = parseCage(text, name);
      // No handles yet: the surface is built at once (a saved spec's handles and weights follow).
      const levels = options.spec?.levels ?? defaultLevels(cage.faceSizes.length);
      next = new Skin3DSession(cage, name, text, this.client, this.work, { ...EMPTY_SPEC3D, levels });
      if (!next.rig) {
        const message = next.status.message ?? 'the surface could not be built';
        next.dispose();
        throw new Error(`${name}: ${message}`);
      }
    } catch (err) {
      ctx.state.setError(messageOf(err));
      this.panel?.setSamples(this.samples, this._session?.file ?? null);
      return false;
    }
    ctx.state.setError(null);
    if (options.undoable) ctx.history.execute(new OpenCageCommand((s) => this.show(s), this._session, next));
    else this.show(next);
    // A restored session: its pose, keyframes and playhead (after the rig is there).
    if (options.spec) next.restore(options.spec, options.time ?? 0);
    return true;
  }

  /** Downloads the posed cage as OBJ (Ctrl+S in this mode). */
  saveFile(): void {
    this.exportOBJ();
  }

  // ---- sessions --------------------------------------------------------------------------------

  private async start(): Promise<void> {
    if (this.samples.length === 0) {
      try {
        const bytes = await fetchBytes('samples/cages/index.json', 'samples/cages/index.json');
        this.samples = (JSON.parse(new TextDecoder().decode(bytes)) as { cages: CageSample[] }).cages;
      } catch (err) {
        this.ctx?.state.setError(`The sample cages could not be listed: ${messageOf(err)}`);
        return;
      }
      this.panel?.setSamples(this.samples, this._session?.file ?? null);
    }
    if (this._session) return;
    const saved = loadSkin3D();
    if (saved && 'problem' in saved) this.ctx?.state.setMessage(saved.problem);
    else if (saved && this.openText(saved.obj, saved.file, { undoable: false, spec: saved.spec, time: saved.time })) return;
    if (this.samples[0]) await this.openSample(this.samples[0].file, { undoable: false });
  }

  /** Shows a session (open, undo and redo of an open). */
  private show(next: Skin3DSession | null): void {
    this.keyframes.stop();
    this.endDrag();
    for (const off of this.sessionOff) off();
    this.sessionOff = [];
    if (this._session && this._session !== next) this._session.suspend();
    this._session = next;
    this.shownSurface = null;
    this.layers?.clear();
    if (next) {
      next.resume();
      this.sessionOff.push(
        next.events.on('spec', ({ live }) => {
          this.refreshPanel();
          this.refreshTimeline();
          if (!live) this.autosave.schedule();
        }),
        next.events.on('posed', ({ live }) => {
          this.livePose = live;
          this.requestDraw();
        }),
        next.events.on('selection', () => {
          this.refreshPanel();
          this.requestDraw();
        }),
        next.events.on('time', () => {
          this.refreshTimeline();
          this.autosave.schedule();
        }),
        next.events.on('rig', (status) => {
          if (status.phase === 'error' && status.message) this.ctx?.state.setError(`3D Skin: ${status.message}`);
          this.refreshPanel();
          this.requestDraw();
        }),
      );
    }
    this.panel?.setSamples(this.samples, next?.file ?? null);
    if (next) this.autosave.schedule();
    this.refreshAll();
  }

  /** Autosaves the cage shown with its spec and playhead. */
  private saveNow(): void {
    const s = this._session;
    if (!s) return;
    const problem = saveSkin3D(s.file, s.source, s.spec, s.time);
    if (problem) this.ctx?.state.setMessage(`Not autosaved: ${problem}`);
  }

  /** Whether everything is autosaved (for tests). */
  get saved(): boolean {
    return !this.autosave.pending;
  }

  // ---- edits -----------------------------------------------------------------------------------

  private execute(label: string, after: Skin3DSpec, selection: { do?: number | null; undo?: number | null } = {}): void {
    const s = this._session;
    if (!s || after === s.spec) return;
    this.ctx?.history.execute(new SpecCommand(label, s, s.spec, after, selection));
  }

  private edit(label: string, change: (spec: Skin3DSpec) => Skin3DSpec): void {
    const s = this._session;
    if (s) this.execute(label, change(s.spec));
  }

  private setWeights(kind: Skin3DWeights): void {
    this.edit(`Use ${kind === 'bbw' ? 'BBW' : 'Shepard'} weights`, (s) => (s.weights === kind ? s : { ...s, weights: kind }));
  }

  /** Adds a handle at the rest position under a surface point and selects it. */
  private addHandleAt(face: number, u: number, v: number): void {
    const s = this._session, rig = s?.rig;
    if (!s || !rig) return;
    const T = rig.refinedTriangles, R = rig.restRefined;
    const [a, b, c] = [T[3 * face], T[3 * face + 1], T[3 * face + 2]];
    const w = 1 - u - v;
    const rest = [0, 1, 2].map((k) => w * R[3 * a + k] + u * R[3 * b + k] + v * R[3 * c + k]) as [number, number, number];
    const id = s.nextId;
    this.execute('Add handle', addHandle3D(s.spec, id, rest), { do: id, undo: s.selected });
  }

  private removeSelected(): void {
    const s = this._session;
    if (!s || s.selected === null) return;
    this.execute('Remove handle', removeHandle3D(s.spec, s.selected), { do: null, undo: s.selected });
  }

  private resetPose(): void {
    const s = this._session;
    if (!s || s.spec.handles.length === 0) return;
    const i = s.indexOf(s.selected);
    const pose = s.spec.pose.map((p, k) => (i < 0 || k === i ? REST_POSE : p));
    if (pose.every((p, k) => p === s.spec.pose[k])) return;
    this.execute(i < 0 ? 'Reset pose' : 'Reset handle pose', setPose3D(s.spec, pose));
  }

  private setGizmo(mode: GizmoMode): void {
    this.gizmoMode = mode;
    this.layers?.gizmo.setMode(mode);
    this.panel?.setGizmo(mode);
  }

  private setOverlay(name: Overlay3D, on: boolean): void {
    this.overlays = { ...this.overlays, [name]: on };
    this.panel?.setOverlays(this.overlays);
    this.requestDraw();
  }

  // ---- the gizmo -------------------------------------------------------------------------------

  private listenGizmo(layers: Skin3DLayers): void {
    const g = layers.gizmo;
    g.setMode(this.gizmoMode);
    g.addEventListener('dragging-changed', (e) => {
      const s = this._session;
      if (e.value) {
        const i = s?.indexOf(s.selected) ?? -1;
        if (!s || i < 0) return;
        this.keyframes.stop();
        this.drag = { before: s.spec, index: i };
      } else this.endDrag();
    });
    g.addEventListener('objectChange', () => {
      const s = this._session, d = this.drag;
      if (!s || !d || !s.spec.handles[d.index]) return;
      const h = s.spec.handles[d.index], p = layers.proxy;
      const pose: HandlePose = { t: [p.position.x - h.x, p.position.y - h.y, p.position.z - h.z], q: [p.quaternion.x, p.quaternion.y, p.quaternion.z, p.quaternion.w], s: [p.scale.x, p.scale.y, p.scale.z] };
      s.apply(setHandlePose(s.spec, d.index, pose), { live: true });
    });
  }

  /** Ends a gizmo drag: the pose it made is one undoable edit. */
  private endDrag(): void {
    const s = this._session, d = this.drag;
    this.drag = null;
    if (!s || !d || s.spec === d.before) return;
    this.ctx?.history.execute(new SpecCommand(`${this.gizmoMode === 'translate' ? 'Move' : this.gizmoMode === 'rotate' ? 'Turn' : 'Scale'} handle`, s, d.before, s.spec));
  }

  /** Places the proxy the gizmo moves at the selected handle's pose (or takes the gizmo off). */
  private placeGizmo(): void {
    const layers = this.layers, s = this._session;
    if (!layers || this.drag) return;
    const i = s?.indexOf(s.selected) ?? -1;
    if (!s || i < 0) {
      layers.attachGizmo(false);
      return;
    }
    const h = s.spec.handles[i], p = s.spec.pose[i];
    layers.proxy.position.set(...posedCenter(h, p));
    layers.proxy.quaternion.set(p.q[0], p.q[1], p.q[2], p.q[3]);
    layers.proxy.scale.set(p.s[0], p.s[1], p.s[2]);
    layers.proxy.updateMatrixWorld();
    layers.attachGizmo(true);
  }

  // ---- pointer input ---------------------------------------------------------------------------

  private readonly input: View3DInput = {
    // A press on the gizmo is the gizmo's drag (TransformControls follows the pointer itself).
    pointerDown: (p) => this.layers?.gizmoHit(p.sx, p.sy) ?? false,
    pointerDrag: () => undefined,
    pointerUp: () => undefined,
    hover: (p) => this.hover(p),
    pointerLeave: () => undefined,
    click: (p) => this.clickAt(p),
    doubleClick: () => undefined,
  };

  private hover(p: Pointer3D): void {
    const canvas = this._view?.canvas;
    if (!canvas) return;
    canvas.style.cursor = this.layers?.gizmoHit(p.sx, p.sy) ? 'grab' : this.handleAt(p.sx, p.sy) >= 0 ? 'pointer' : '';
  }

  /** The handle whose marker is under a canvas point, or -1. */
  private handleAt(sx: number, sy: number): number {
    const s = this._session, view = this._view;
    if (!s || !view) return -1;
    let best = -1, bestD = HANDLE_PICK_PX;
    s.spec.handles.forEach((h, i) => {
      const q = view.project(...posedCenter(h, s.spec.pose[i]));
      const d = Math.hypot(q.sx - sx, q.sy - sy);
      if (q.depth > 0 && d <= bestD) [best, bestD] = [i, d];
    });
    return best;
  }

  private clickAt(p: Pointer3D): void {
    const s = this._session, view = this._view;
    if (!s || !view) return;
    const i = this.handleAt(p.sx, p.sy);
    if (i >= 0) {
      s.select(s.spec.handles[i].id);
      return;
    }
    const hit = view.pick(p.sx, p.sy);
    if (hit) this.addHandleAt(hit.face, hit.u, hit.v);
    else s.select(null);
  }

  // ---- time ------------------------------------------------------------------------------------

  // ---- keys ------------------------------------------------------------------------------------

  private run(action: Skin3DAction, e: KeyboardEvent): boolean {
    const s = this._session;
    switch (action) {
      case 'translate':
      case 'rotate':
      case 'scale':
        this.setGizmo(action);
        return true;
      case 'remove':
        if (s?.selected == null) return false;
        this.removeSelected();
        return true;
      case 'escape':
        if (s?.selected == null) return false;
        s.select(null);
        return true;
      case 'reset-pose':
        this.resetPose();
        return true;
      case 'toggle-cage':
      case 'toggle-target':
      case 'toggle-naive':
      case 'toggle-errors': {
        const name = action.slice('toggle-'.length) as Overlay3D;
        this.setOverlay(name, !this.overlays[name]);
        return true;
      }
      case 'play':
      case 'add-key':
      case 'delete-key':
      case 'previous-key':
      case 'next-key':
      case 'start':
      case 'end':
        if (!(action === 'play' && e.repeat)) this.keyframes.runKey(action);
        return true;
    }
  }

  // ---- export ----------------------------------------------------------------------------------

  private baseName(): string {
    return (this._session?.file ?? 'cage').replace(/\.obj$/i, '');
  }

  private exportOBJ(): void {
    const s = this._session;
    if (!s) return;
    try {
      download(cageToOBJ(s.cage, s.posedCage), `${this.baseName()}-posed.obj`, 'model/obj');
    } catch (err) {
      this.ctx?.state.setError(`Export failed: ${messageOf(err)}`);
    }
  }

  /**
   * The surface at every keyframe and at GLTF_FPS in between (so that a viewer, which blends
   * neighbouring frames linearly, plays what the timeline plays: turns stay turns), or the current
   * pose when there are no keyframes, for the glTF.
   */
  surfaceFrames(): SurfaceFrame[] {
    const s = this._session;
    if (!s) return [];
    const keys = s.spec.keyframes;
    if (keys.length === 0) return [{ time: 0, positions: s.surface.slice() }];
    const times: number[] = [];
    keys.forEach((k, i) => {
      times.push(k.time);
      const next = keys[i + 1];
      if (!next) return;
      const steps = Math.ceil((next.time - k.time) * GLTF_FPS - 1e-9);
      for (let j = 1; j < steps; j++) times.push(k.time + ((next.time - k.time) * j) / steps);
    });
    return times.map((time) => {
      const positions = s.surfaceFor(poseAt3D(keys, time));
      if (!positions) throw new Error('the rig is not ready for these handles yet');
      return { time, positions };
    });
  }

  /** Builds the animated glTF (binary) of the surface; rejects with a message. */
  async gltfBytes(): Promise<ArrayBuffer> {
    const s = this._session, rig = s?.rig;
    if (!s || !rig) throw new Error('no cage is open');
    if (!s.ready && s.spec.handles.length > 0) throw new Error('the rig is still being built');
    return animatedGLTF(rig.restRefined, rig.refinedTriangles, this.surfaceFrames());
  }

  private async exportGLTF(): Promise<void> {
    try {
      const bytes = await this.work.track(this.gltfBytes());
      download(bytes, `${this.baseName()}-animated.glb`, 'model/gltf-binary');
    } catch (err) {
      this.ctx?.state.setError(`Export failed: ${messageOf(err)}`);
    }
  }

  // ---- drawing ---------------------------------------------------------------------------------

  requestDraw(): void {
    if (this.frame || !this._view || !this.ctx) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.draw();
    });
  }

  private draw(): void {
    const layers = this.layers, s = this._session;
    if (!layers) return;
    const rig = s?.rig;
    if (!s || !rig) {
      if (layers.surfaceCount > 0) layers.clear();
      this.shownSurface = null;
      this.panel?.setErrors(null);
      return;
    }
    // A new surface (another cage, or other levels): new geometry, framed on a new cage.
    if (this.shownSurface !== s.surface || layers.surfaceCount * 3 !== s.surface.length) {
      const fit = this.shownSurface === null;
      layers.setCage(s.cage, rig.restRefined, rig.refinedTriangles, fit);
      this.shownSurface = s.surface;
      this.refreshPanel();
    }
    const t0 = performance.now();
    layers.update(s.posedCage, s.surface);
    layers.setCageVisible(this.overlays.cage);
    this.drawOverlays(layers, s);
    this.panel?.setUpdate(s.poseMs, performance.now() - t0);
    const selected = s.indexOf(s.selected);
    const markers: Marker[] = s.spec.handles.map((h, i) => {
      const [x, y, z] = posedCenter(h, s.spec.pose[i]);
      return { x, y, z, color: i === selected ? SKIN3D_COLORS.selected : SKIN3D_COLORS.handle, size: HANDLE_SIZE, shape: 'disc' };
    });
    layers.setHandles(markers);
    this.placeGizmo();
  }

  private drawOverlays(layers: Skin3DLayers, s: Skin3DSession): void {
    const f = this.overlays;
    const posed = s.spec.handles.length > 0 && !isRest(s.spec.pose);
    // The numbers alone are not worth a naive pose and a target per frame while dragging.
    const data: PoseOverlays | null = posed && (f.target || f.naive || f.errors || !this.livePose) ? s.overlays() : null;
    if (!data && posed) {
      // A live pose with no overlay on: the panel keeps the numbers of the last settled pose.
      layers.setSurfaceErrors(null, 1);
      layers.setOverlays(null, null, null, 1);
      return;
    }
    const diag = this.diagonal(s);
    let max = 0;
    if (data) {
      // The scale covers the surfaces shown: the fit, and the naive one when it is on.
      for (const list of f.naive ? [data.fitError, data.naiveError] : [data.fitError]) for (let i = 0; i < list.length; i++) max = Math.max(max, list[i]);
    }
    // The scale's top in % of the diagonal, rounded up to 1, 2 or 5: both maps share it.
    const top = niceCeil(max / diag) * diag;
    this.lastErrors = data ? { fitRms: data.fitRms, naiveRms: data.naiveRms } : null;
    this.panel?.setErrors(data ? { fitRms: data.fitRms, naiveRms: data.naiveRms, max: top / diag } : null);
    const zeros = !data && f.errors && s.spec.handles.length > 0;
    layers.setSurfaceErrors(f.errors && data ? data.fitError : zeros ? new Float64Array(s.surface.length / 3) : null, top || 1);
    layers.setOverlays(f.target && data ? data.target : null, f.naive && data ? data.naive : null, f.errors && data ? data.naiveError : null, top || 1);
  }

  /** The bounding-box diagonal of the rest surface (the error scale's unit), kept per rig. */
  private diagonal(s: Skin3DSession): number {
    const rig = s.rig;
    if (!rig) return 1;
    if (this.diagonalOf?.rig !== rig) this.diagonalOf = { rig, value: boxDiagonal(rig.restRefined) };
    return this.diagonalOf.value;
  }

  private refreshAll(): void {
    this.refreshPanel();
    this.refreshTimeline();
    this.requestDraw();
  }

  private refreshPanel(): void {
    const panel = this.panel, s = this._session;
    if (!panel) return;
    const rig = s?.rig ?? null;
    panel.setCage(
      s ? { file: s.file, vertices: s.cage.positions.length / 3, faces: s.cage.faceSizes.length, creases: s.cage.creases.length, refinedVertices: rig?.refinedVertexCount ?? 0, triangles: (rig?.refinedTriangles.length ?? 0) / 3 } : null,
    );
    const spec = s?.spec ?? EMPTY_SPEC3D;
    const memory = rig && s && s.spec.handles.length > 0 ? rig.stats.memoryBytes.M + rig.stats.memoryBytes.O : null;
    panel.setRig({ weights: spec.weights, levels: spec.levels, handles: spec.handles.length, selected: s ? (s.indexOf(s.selected) >= 0 ? s.indexOf(s.selected) : null) : null, status: s?.status ?? { phase: 'ready', fraction: 0, message: null, ms: null, stale: false }, memory });
  }

  private refreshTimeline(): void {
    const s = this._session;
    const spec = s?.spec ?? EMPTY_SPEC3D;
    const time = s?.time ?? 0;
    const keyHere = keyframeAt(spec, time);
    const unkeyed = spec.keyframes.length > 0 && !samePoses(spec.pose, poseAt3D(spec.keyframes, time));
    this.timeline?.update({ duration: spec.duration, time, keyframes: spec.keyframes.map((k) => k.time), playing: this.keyframes.playing, canKey: spec.handles.length > 0, keyHere, unkeyed });
  }

  // ---- tests -----------------------------------------------------------------------------------

  testState(): Skin3DTestState {
    const s = this._session, rig = s?.rig;
    const spec = s?.spec ?? EMPTY_SPEC3D;
    return {
      active: this.active,
      file: s?.file ?? null,
      cage: s ? { vertices: s.cage.positions.length / 3, faces: s.cage.faceSizes.length, creases: s.cage.creases.length } : null,
      restCage: s ? [...s.cage.positions] : [],
      posedCage: s ? [...s.posedCage] : [],
      refinedVertices: rig?.refinedVertexCount ?? 0,
      surface: s ? [...s.surface] : [],
      handles: spec.handles.map((h) => ({ x: h.x, y: h.y, z: h.z })),
      pose: spec.pose.map((p) => ({ t: [...p.t], q: [...p.q], s: [...p.s] }) as HandlePose),
      selected: s ? (s.indexOf(s.selected) >= 0 ? s.indexOf(s.selected) : null) : null,
      rig: { phase: s?.status.phase ?? 'ready', ready: s?.ready ?? false, message: s?.status.message ?? null },
      progressReports: s?.progressReports ?? 0,
      keyframes: spec.keyframes.map((k) => k.time),
      time: s?.time ?? 0,
      duration: spec.duration,
      gizmo: this.gizmoMode,
      overlays: { ...this.overlays },
      errors: this.lastErrors,
      canUndo: this.ctx?.history.canUndo ?? false,
      saved: this.saved,
    };
  }

  /** Where a world point is on the 3D canvas (CSS pixels), or null (behind the camera). */
  project(x: number, y: number, z: number): { sx: number; sy: number } | null {
    const q = this._view?.project(x, y, z);
    return q && q.depth > 0 ? { sx: q.sx, sy: q.sy } : null;
  }

  /**
   * A canvas point on the gizmo's `axis` handle (as its own picking reports it), searched along
   * the axis's screen direction from the gizmo's centre; null when the gizmo is off or unseen.
   */
  gizmoAxisOnCanvas(axis: 'X' | 'Y' | 'Z'): { sx: number; sy: number; dx: number; dy: number } | null {
    const layers = this.layers, view = this._view;
    if (!layers || !view || !layers.gizmo.object) return null;
    const c = layers.proxy.position;
    const dir = new Vector3(axis === 'X' ? 1 : 0, axis === 'Y' ? 1 : 0, axis === 'Z' ? 1 : 0);
    const q0 = view.project(c.x, c.y, c.z);
    const step = view.worldPerPixel(q0.depth) * 10;
    const q1 = view.project(c.x + dir.x * step, c.y + dir.y * step, c.z + dir.z * step);
    const len = Math.hypot(q1.sx - q0.sx, q1.sy - q0.sy);
    if (len < 1e-6) return null;
    const dx = (q1.sx - q0.sx) / len, dy = (q1.sy - q0.sy) / len;
    for (let d = 15; d <= 200; d += 3) {
      const sx = q0.sx + dx * d, sy = q0.sy + dy * d;
      if (layers.gizmoHit(sx, sy) && layers.gizmo.axis === axis) return { sx, sy, dx, dy };
    }
    return null;
  }
}

/** Refined vertices the default levels stay under (about 4^levels per cage face). */
const DEFAULT_MAX_REFINED = 60_000;

/** The levels a new cage starts with: the default (3), fewer for large cages. */
function defaultLevels(faces: number): number {
  let levels = EMPTY_SPEC3D.levels;
  while (levels > 1 && faces * 4 ** levels > DEFAULT_MAX_REFINED) levels--;
  return levels;
}

/** The diagonal of the bounding box of points (3 numbers each); 1 for none. */
function boxDiagonal(positions: Float64Array): number {
  const { lo, hi } = boundingBox(positions);
  return positions.length > 0 ? Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1 : 1;
}
