import { IDENTITY_MATRIX, affine } from '../../../src/index.js';
import type { LoadedDocument } from '../../app/state.js';
import { DebouncedSave, readJSON, writeJSON } from '../../app/autosave.js';
import { InFlight } from '../../app/in-flight.js';
import type { Mode, ModeContext } from '../../app/modes.js';
import type { ViewPointer } from '../../view2d/view2d.js';
import { SpecCommand } from './commands.js';
import { exportAnimated, exportPosed } from './export.js';
import { poseFor, readout, type Gesture } from './gestures.js';
import { SKIN_KEYS, keyAction, type SkinAction } from './keymap.js';
import { KeyframeControl } from './keyframe-control.js';
import { nextPaint } from './rig-build.js';
import { SkinSession, type RigStatus } from './session.js';
import type { LayerFlags, LayerName, SkinTool } from './skin-panel.js';
import { SkinView, type SkinViewState } from './skin-view.js';
import {
  EMPTY_SPEC,
  addHandle,
  moveHandle,
  removeHandle,
  setPose,
  type SkinSpec,
  type WeightKind,
} from './spec.js';
import { embedRig, loadRig, saveRig } from './storage.js';
import { skinTestState, type SkinTestState } from './test-state.js';
import { WeightsClient } from './weights-client.js';
import { messageOf } from '../../app/errors.js';

export type { SkinTestState };

const PREFS_KEY = 'splinekit:skin-prefs';
const AUTOSAVE_MS = 300;

const WEIGHT_NAMES: Record<WeightKind, string> = { shepard: 'Shepard', harmonic: 'harmonic', bbw: 'BBW' };

function loadPrefs(): LayerFlags {
  const p = readJSON(PREFS_KEY) as Partial<LayerFlags> | null;
  const flag = (v: unknown, d: boolean) => (typeof v === 'boolean' ? v : d);
  return { target: flag(p?.target, true), heat: flag(p?.heat, true), naive: flag(p?.naive, false), field: flag(p?.field, false) };
}

/**
 * Skin mode (Liu, Jacobson & Gingold 2014): place handles on the drawing, pose them, and the
 * curves follow by linear blend skinning while staying cubic Bézier splines with their continuity.
 * Shows the target (dashed, heat-mapped by error), the naive baseline and weight fields; keys
 * poses on a timeline; exports the deformed and the animated SVG. Every edit is undoable, and the
 * rig is autosaved with the document.
 */
export class SkinMode implements Mode {
  readonly id = 'skin';
  readonly title = 'Skin';
  readonly description = 'Place handles and pose the drawing: the curves deform and stay Bézier splines with their continuity';
  readonly keys = SKIN_KEYS;

  private ctx: ModeContext | null = null;
  private ui: SkinView | null = null;
  private readonly client = new WeightsClient();
  /** The mode's work under way (rig builds): what the test hook's `busy` reads. */
  private readonly work = new InFlight();
  private readonly sessions = new Map<LoadedDocument, SkinSession>();
  private current: LoadedDocument | null = null;
  private session: SkinSession | null = null;
  private tool: SkinTool = 'rig';
  private layers = loadPrefs();
  private gesture: Gesture | null = null;
  private readout: string | null = null;
  private readonly keyframes = new KeyframeControl<SkinSpec>({
    session: () => this.session,
    canKey: () => (this.session?.spec.handles.length ?? 0) > 0,
    busy: () => this.gesture !== null,
    execute: (label, after) => this.execute(label, after),
    refresh: () => this.refreshTimeline(),
    // Relaxes the pose playback stopped at (when flexible).
    stopped: () => this.session?.settle(),
  });
  private frame = 0;
  private readonly autosave = new DebouncedSave(AUTOSAVE_MS, () => this.saveNow());
  /** The control points were shown when the mode took over (hidden meanwhile, shown again after). */
  private overlayWasOn = false;
  /** The rig error this mode put in the status bar, if still there. */
  private shownError: string | null = null;
  private off: (() => void)[] = [];
  private sessionOff: (() => void)[] = [];

  constructor() {
    window.addEventListener('pagehide', () => this.autosave.flush());
  }

  // ---- Mode ------------------------------------------------------------------------------------

  activate(ctx: ModeContext): void {
    this.ctx = ctx;
    this.ui = new SkinView(
      ctx,
      {
        setTool: (t) => this.setTool(t),
        setWeights: (k) => this.setWeights(k),
        setFlexible: (on) => this.edit(on ? 'Flexible G1 on' : 'Flexible G1 off', (s) => ({ ...s, flexible: on })),
        setLayer: (name, on) => this.setLayer(name, on),
        resetPose: () => this.resetPose(),
        removeHandle: () => this.removeSelected(),
        exportPosed: () => this.exportPosed(),
        exportAnimated: () => void this.exportAnimated(),
      },
      this.keyframes.actions,
    );
    this.ui.panel.setLayers(this.layers);
    ctx.view.canvas.classList.add('skin-canvas');
    // Handles and the target read better without every control point: H brings them back.
    this.overlayWasOn = ctx.state.overlay;
    ctx.state.setOverlay(false);
    this.off.push(
      ctx.state.events.on('document', (current) => this.attach(current)),
      ctx.state.events.on('continuity', () => this.session?.refreshContinuity()),
      ctx.state.events.on('overlay', (on) => {
        if (on) this.overlayWasOn = false; // the user chose: leave it as they set it
        this.ui?.invalidate();
        this.requestDraw();
      }),
      ctx.view.events.on('view', () => this.ui?.viewChanged()),
    );
    this.attach(ctx.state.current);
  }

  deactivate(): void {
    const ctx = this.ctx;
    this.keyframes.stop();
    this.autosave.flush();
    this.detach();
    for (const off of this.off) off();
    this.off = [];
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    this.ui?.dispose();
    this.ui = null;
    if (ctx) {
      ctx.view.canvas.classList.remove('skin-canvas', 'over-handle', 'add-handle');
      const doc = ctx.state.doc;
      if (doc) ctx.view.showDrawing(doc);
      ctx.overlay.setDocument(doc);
      ctx.state.setMessage(null);
      if (this.overlayWasOn) ctx.state.setOverlay(true);
    }
    this.current = null;
    this.ctx = null;
  }

  pointerDown(p: ViewPointer): boolean {
    const s = this.session, ui = this.ui;
    if (!s || !ui) return false;
    const hit = ui.handles.pick(p.sx, p.sy);
    if (!hit) return false;
    this.keyframes.stop();
    s.select(hit.id);
    const index = s.indexOf(hit.id);
    const h = s.spec.handles[index];
    if (this.tool === 'rig') {
      if (hit.part !== 'handle') return false;
      this.gesture = { kind: 'rest', id: hit.id, before: s.spec, dx: h.x - p.x, dy: h.y - p.y, x: h.x, y: h.y, moved: false };
      return true;
    }
    const m0 = s.spec.pose[index];
    const op = hit.part === 'ring' ? 'rotate' : hit.part === 'knob' ? 'scale' : p.shiftKey ? 'rotate' : p.altKey ? 'scale' : 'move';
    this.gesture = { kind: 'pose', op, via: hit.part === 'handle' ? 'handle' : 'gizmo', id: hit.id, index, before: s.spec, m0, pivot: affine.apply(m0, h.x, h.y), start: p, moved: false };
    this.readout = op === 'move' ? null : readout(m0);
    this.requestDraw();
    return true;
  }

  pointerMove(p: ViewPointer): void {
    const s = this.session, ui = this.ui, g = this.gesture;
    if (!s || !ui) return;
    if (!g) {
      const hit = ui.handles.pick(p.sx, p.sy);
      ui.handles.setHover(hit);
      const canvas = this.ctx!.view.canvas;
      canvas.classList.toggle('over-handle', hit !== null);
      canvas.classList.toggle('add-handle', hit === null && (this.tool === 'rig' || p.shiftKey));
      return;
    }
    g.moved = true;
    if (g.kind === 'rest') {
      g.x = p.x + g.dx;
      g.y = p.y + g.dy;
      this.requestDraw();
      return;
    }
    const { m, readout } = poseFor(g, p);
    this.readout = readout;
    const pose = [...s.spec.pose];
    pose[g.index] = m;
    s.apply(setPose(s.spec, pose), { live: true });
  }

  pointerUp(): void {
    const s = this.session, g = this.gesture;
    this.gesture = null;
    this.readout = null;
    if (!s || !g) return;
    if (g.kind === 'rest') {
      if (g.moved && (g.x !== g.before.handles[s.indexOf(g.id)]?.x || g.y !== g.before.handles[s.indexOf(g.id)]?.y)) {
        this.execute('Move handle at rest', moveHandle(g.before, g.id, g.x, g.y), g.before);
      } else this.requestDraw();
      return;
    }
    if (g.moved && s.spec !== g.before) {
      const label = g.op === 'move' ? 'Move handle' : g.op === 'rotate' ? 'Turn handle' : 'Scale handle';
      this.execute(label, s.spec, g.before); // do() poses again, not live: relaxes when flexible
    } else this.requestDraw();
  }

  pointerLeave(): void {
    this.ui?.handles.setHover(null);
    this.ctx?.view.canvas.classList.remove('over-handle', 'add-handle');
  }

  click(p: ViewPointer): void {
    const s = this.session;
    if (!s) return;
    if (this.tool === 'rig' || p.shiftKey) this.addHandleAt(p.x, p.y);
    else s.select(null);
  }

  keyDown(e: KeyboardEvent): boolean {
    const action = keyAction(e);
    return action !== null && this.run(action);
  }

    exportDocument(current: LoadedDocument): string | undefined {
    const s = this.sessions.get(current);
    if (!s || s.spec.handles.length === 0) return undefined;
    return embedRig(current.doc.toSVG(), s.spec);
  }

  // ---- the session of the shown document -------------------------------------------------------

  private attach(current: LoadedDocument | null): void {
    if (current === this.current && this.session) return;
    const previous = this.session;
    this.keyframes.stop();
    this.autosave.flush();
    this.detach();
    this.current = current;
    if (previous && (!current || this.sessions.get(current) !== previous)) previous.suspend();
    if (!current) {
      this.session = null;
      this.refreshAll();
      return;
    }
    let s = this.sessions.get(current);
    const fresh = !s;
    if (!s) {
      s = new SkinSession(current.doc, this.client, this.work, EMPTY_SPEC);
      this.sessions.set(current, s);
    }
    this.session = s;
    this.subscribe(s);
    if (fresh) {
      const saved = loadRig(current);
      if (saved) s.restore(saved.spec, saved.time);
    } else {
      s.refreshContinuity(); // tags may have been overridden in Document mode meanwhile
      s.resume();
    }
    this.tool = s.spec.handles.length === 0 ? 'rig' : 'pose';
    this.ui?.invalidate();
    this.refreshAll();
  }

  private detach(): void {
    for (const off of this.sessionOff) off();
    this.sessionOff = [];
    this.gesture = null;
    this.readout = null;
  }

  private subscribe(s: SkinSession): void {
    this.sessionOff.push(
      s.events.on('spec', () => {
        this.refreshPanel();
        this.autosave.schedule();
        this.requestDraw();
      }),
      s.events.on('posed', () => this.requestDraw()),
      s.events.on('selection', () => {
        this.refreshPanel();
        this.requestDraw();
      }),
      s.events.on('time', () => {
        this.refreshTimeline();
        this.autosave.schedule();
      }),
      s.events.on('rig', (status) => this.showStatus(status)),
    );
  }

  private showStatus(status: RigStatus): void {
    const ctx = this.ctx;
    this.ui?.panel.setStatus(status);
    this.refreshPanel();
    if (!ctx) return;
    const slow = status.kind !== 'shepard';
    if (status.phase === 'building' && slow) ctx.state.setMessage(`Computing ${WEIGHT_NAMES[status.kind]} weights… ${Math.round(100 * status.fraction)}%`);
    else if (status.phase === 'ready' && slow && status.ms !== null) ctx.state.setMessage(`${WEIGHT_NAMES[status.kind]} weights ready in ${(status.ms / 1000).toFixed(1)} s`);
    else if (status.phase !== 'building') ctx.state.setMessage(null);
    if (status.phase === 'error' && status.message) {
      ctx.state.setError(status.message);
      this.shownError = status.message;
    } else if (status.phase === 'ready' && this.shownError !== null) {
      // The rig is fine again: take back the error this mode showed (not someone else's).
      if (ctx.state.error === this.shownError) ctx.state.setError(null);
      this.shownError = null;
    }
  }

  /** Does what a key asks; false when it does not apply (the key goes on to the editor). */
  private run(action: SkinAction): boolean {
    const s = this.session;
    switch (action) {
      case 'tool-rig':
      case 'tool-pose':
        this.setTool(action === 'tool-rig' ? 'rig' : 'pose');
        return true;
      case 'remove':
        if (s?.selected == null) return false;
        this.removeSelected();
        return true;
      case 'escape':
        if (this.gesture && s) {
          if (this.gesture.kind === 'pose') s.apply(this.gesture.before);
          this.gesture = null;
          this.readout = null;
          this.requestDraw();
          return true;
        }
        if (s?.selected == null) return false;
        s.select(null);
        return true;
      case 'reset-pose':
        this.resetPose();
        return true;
      case 'toggle-target':
      case 'toggle-heat':
      case 'toggle-naive':
      case 'toggle-field': {
        const name = action.slice('toggle-'.length) as LayerName;
        this.setLayer(name, !this.layers[name]);
        return true;
      }
      case 'play':
      case 'add-key':
      case 'delete-key':
      case 'previous-key':
      case 'next-key':
      case 'start':
      case 'end':
        this.keyframes.runKey(action);
        return true;
    }
  }

  // ---- edits (each one undoable) ---------------------------------------------------------------

  /** Records an edit from `before` (default: the current spec) to `after`. */
  private execute(label: string, after: SkinSpec, before?: SkinSpec, selection?: { do?: number | null; undo?: number | null }): void {
    const s = this.session, ctx = this.ctx;
    if (!s || !ctx) return;
    ctx.history.execute(new SpecCommand(label, s, before ?? s.spec, after, selection));
  }

  private edit(label: string, change: (spec: SkinSpec) => SkinSpec): void {
    const s = this.session;
    if (!s) return;
    const after = change(s.spec);
    if (after !== s.spec) this.execute(label, after);
  }

  private addHandleAt(x: number, y: number): void {
    const s = this.session, ctx = this.ctx;
    if (!s || !ctx) return;
    if (s.doc.splines.length === 0) {
      ctx.state.setError('Nothing to skin: this drawing has no curves');
      return;
    }
    const spec = s.spec, id = s.nextId;
    let after: SkinSpec;
    if (this.tool === 'pose' && spec.handles.length > 0 && !spec.pose.every((m) => affine.isIdentity(m))) {
      // On the posed drawing: follow the handle nearest on screen, with the rest position that
      // its pose brings under the pointer.
      let near = 0, best = Infinity;
      spec.handles.forEach((h, i) => {
        const [px, py] = affine.apply(spec.pose[i], h.x, h.y);
        const d = (px - x) ** 2 + (py - y) ** 2;
        if (d < best) [near, best] = [i, d];
      });
      const inv = affine.invert(spec.pose[near]);
      const [rx, ry] = inv ? affine.apply(inv, x, y) : [x, y];
      after = addHandle(spec, id, rx, ry, near);
    } else {
      after = addHandle(spec, id, x, y);
    }
    this.execute('Add handle', after, spec, { do: id, undo: s.selected });
  }

  private removeSelected(): void {
    const s = this.session;
    if (!s || s.selected === null) return;
    const id = s.selected;
    this.execute('Remove handle', removeHandle(s.spec, id), s.spec, { do: null, undo: id });
  }

  private resetPose(): void {
    const s = this.session;
    if (!s || s.spec.handles.length === 0) return;
    const i = s.indexOf(s.selected);
    const pose = s.spec.pose.map((m, k) => (i < 0 || k === i ? IDENTITY_MATRIX : m));
    if (pose.every((m, k) => affine.sameMatrix(m, s.spec.pose[k]))) return;
    this.execute(i < 0 ? 'Reset pose' : 'Reset handle pose', setPose(s.spec, pose));
  }

  private setWeights(kind: WeightKind): void {
    this.edit(`Use ${WEIGHT_NAMES[kind]} weights`, (s) => (s.weights === kind ? s : { ...s, weights: kind }));
  }

  // ---- tools, layers, time ---------------------------------------------------------------------

  private setTool(tool: SkinTool): void {
    if (this.gesture) return;
    this.tool = tool;
    this.ui?.handles.setHover(null);
    this.refreshPanel();
    this.requestDraw();
  }

  private setLayer(name: LayerName, on: boolean): void {
    this.layers = { ...this.layers, [name]: on };
    writeJSON(PREFS_KEY, this.layers);
    this.ui?.panel.setLayers(this.layers);
    this.requestDraw();
  }

  // ---- export ----------------------------------------------------------------------------------

  private exportPosed(): void {
    const s = this.session, ctx = this.ctx, current = this.current;
    if (!s || !ctx || !current) return;
    try {
      exportPosed(s, current.file);
    } catch (err) {
      ctx.state.setError(messageOf(err));
    }
  }

  private async exportAnimated(): Promise<void> {
    const s = this.session, ctx = this.ctx, current = this.current;
    if (!s || !ctx || !current) return;
    this.keyframes.stop();
    ctx.state.setBusy('Exporting the animation…');
    try {
      await nextPaint();
      exportAnimated(s, current.file);
    } catch (err) {
      ctx.state.setError(messageOf(err));
    } finally {
      ctx.state.setBusy(null);
    }
  }

  // ---- autosave --------------------------------------------------------------------------------

  private saveNow(): void {
    const s = this.session, current = this.current;
    if (!s || !current) return;
    const problem = saveRig(current, s.spec, s.time);
    if (problem) this.ctx?.state.setMessage(`Autosave failed: ${problem}`);
  }

  // ---- drawing ---------------------------------------------------------------------------------

  private requestDraw(): void {
    if (this.frame || !this.ctx) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.draw();
    });
  }

  /** What the view shows now. */
  private get viewState(): SkinViewState {
    return { session: this.session, tool: this.tool, layers: this.layers, gesture: this.gesture, readout: this.readout, playing: this.keyframes.playing };
  }

  private draw(): void {
    this.ui?.draw(this.viewState);
  }

  private refreshAll(): void {
    const s = this.session;
    if (s) this.ui?.panel.setStatus(s.status);
    this.refreshPanel();
    this.refreshTimeline();
    this.requestDraw();
  }

  private refreshPanel(): void {
    this.ui?.refreshPanel(this.viewState);
  }

  private refreshTimeline(): void {
    this.ui?.refreshTimeline(this.viewState);
  }

  // ---- tests -----------------------------------------------------------------------------------

  testState(): SkinTestState {
    return skinTestState(this.viewState, {
      active: this.ctx !== null,
      layers: this.ui?.curves.counts ?? { target: 0, naive: 0, field: 0 },
      saved: !this.autosave.pending,
      busy: this.work.busy,
    });
  }

  /** Where handle `index` is drawn, in canvas pixels, or null. */
  handleOnCanvas(index: number): [number, number] | null {
    const id = this.session?.spec.handles[index]?.id;
    return id === undefined ? null : (this.ui?.handles.screenOf(id) ?? null);
  }

  /** The gizmo (center, knob, ring radius) in canvas pixels, or null. */
  gizmoOnCanvas(): { center: [number, number]; knob: [number, number]; ring: number } | null {
    return this.ui?.handles.gizmoOnScreen() ?? null;
  }
}
