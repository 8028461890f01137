import { CatmullRom, LocalEdit, segmentCount, segmentOf, type StrokeSample } from '../../../src/index.js';
import { DebouncedSave, readJSON, writeJSON } from '../../app/autosave.js';
import { messageOf } from '../../app/errors.js';
import type { Mode, ModeContext } from '../../app/modes.js';
import type { LoadedDocument } from '../../app/state.js';
import type { ViewPointer } from '../../view2d/view2d.js';
import { CurvesCommand } from './commands.js';
import { EditCurves, type CurveSnapshot } from './curves.js';
import { EditLayer, type PointRef, type WindowPreview } from './edit-layer.js';
import { DEFAULT_SETTINGS, EditPanel, type EditSettings, type EditTool } from './edit-panel.js';
import { loadCurves, saveCurves } from './storage.js';

const PREFS_KEY = 'splinekit:edit-prefs';
const AUTOSAVE_MS = 300;
/** Screen distance within which a click picks a path of the drawing to convert (pixels). */
const CONVERT_PICK = 8;

type Gesture =
  | { kind: 'stroke'; samples: StrokeSample[]; start: number }
  | { kind: 'drag'; edit: LocalEdit; x0: number; y0: number; before: CurveSnapshot[] }
  | { kind: 'window'; side: 'left' | 'right' }
  | { kind: 'tangent'; at: PointRef; before: CurveSnapshot[] };

/** What end-to-end tests read (window.splinekitEditor.edit()). */
export interface EditTestState {
  tool: EditTool;
  settings: EditSettings;
  curves: { closed: boolean; points: number[]; tangents: number; pressure: number[] | null }[];
  selected: PointRef | null;
  window: { curve: number; indices: number[]; weights: number[] } | null;
  dragging: boolean;
}

function loadPrefs(): EditSettings {
  const p = readJSON(PREFS_KEY) as Partial<EditSettings> | null;
  const s = { ...DEFAULT_SETTINGS };
  if (p && Number.isInteger(p.left) && p.left! >= 0) s.left = p.left!;
  if (p && Number.isInteger(p.right) && p.right! >= 0) s.right = p.right!;
  if (p && (p.falloff === 'linear' || p.falloff === 'gaussian' || p.falloff === 'cosine')) s.falloff = p.falloff;
  if (p && typeof p.alpha === 'number' && p.alpha > 0 && p.alpha <= 10) s.alpha = p.alpha;
  if (p && typeof p.normals === 'boolean') s.normals = p.normals;
  if (p && typeof p.evenStroke === 'boolean') s.evenStroke = p.evenStroke;
  return s;
}

const EDIT_KEYS: readonly (readonly [string, string])[] = [
  ['D · E · T · C', 'draw, edit, tangent, convert a path'],
  ['Drag a point', 'move it; the window follows the drop-off'],
  ['[ · ]', 'narrow, widen the window on both sides'],
  ['N', 'interpolate normals on or off'],
  ['R', 'resample the selected curve evenly'],
  ['Delete', 'remove the selected curve'],
];

/**
 * Edit mode (Eyiyurekli & Breen, localized editing of Catmull-Rom splines): sketch a stroke with
 * the mouse or a pen and get a curve through it; drag a control point and the move spreads over
 * an active window with a chosen drop-off (the window's ends highlighted and draggable, the
 * weights previewed); interpolate normals; resample the curve or the window; edit tangents; turn
 * a path of the drawing into a curve. Every change is undoable and autosaved with the document;
 * Export adds the curves to the SVG.
 */
export class EditMode implements Mode {
  readonly id = 'edit';
  readonly title = 'Edit';
  readonly description = 'Sketch curves and reshape them locally: a dragged point moves a window of the curve (Catmull-Rom, Eyiyurekli & Breen)';
  readonly keys = EDIT_KEYS;

  private ctx: ModeContext | null = null;
  private layer: EditLayer | null = null;
  private panel: EditPanel | null = null;
  private readonly sessions = new Map<LoadedDocument | null, EditCurves>();
  private current: LoadedDocument | null = null;
  private curves = new EditCurves();
  private tool: EditTool = 'draw';
  private settings = loadPrefs();
  private selected: PointRef | null = null;
  private preview: WindowPreview | null = null;
  private gesture: Gesture | null = null;
  private off: (() => void)[] = [];
  private overlayWasOn = false;
  /** The last native pointer event's pressure, for pens (mice report none). */
  private pen: { pressure: number | undefined } = { pressure: undefined };
  private readonly autosave = new DebouncedSave(AUTOSAVE_MS, () => this.saveNow());
  private readonly onPointer = (e: PointerEvent) => {
    this.pen.pressure = e.pointerType === 'pen' || e.pointerType === 'touch' ? e.pressure : undefined;
  };

  constructor() {
    window.addEventListener('pagehide', () => this.autosave.flush());
  }

  // ---- Mode ------------------------------------------------------------------------------------

  activate(ctx: ModeContext): void {
    this.ctx = ctx;
    this.layer = new EditLayer(ctx.view);
    this.panel = new EditPanel({
      setTool: (t) => this.setTool(t),
      setSettings: (c) => this.setSettings(c),
      resampleCurve: () => this.resampleCurve(),
      resampleWindow: (f) => this.resampleWindow(f),
      clearTangents: () => this.clearTangents(),
      toggleClosed: () => this.toggleClosed(),
      deleteCurve: () => this.deleteCurve(),
    });
    ctx.panel.append(...this.panel.sections);
    this.overlayWasOn = ctx.state.overlay;
    ctx.state.setOverlay(false);
    ctx.view.canvas.addEventListener('pointerdown', this.onPointer, true);
    ctx.view.canvas.addEventListener('pointermove', this.onPointer, true);
    this.off.push(
      ctx.state.events.on('document', (current) => this.attach(current)),
      ctx.view.events.on('view', () => this.layer?.draw()),
    );
    this.panel.setTool(this.tool);
    this.panel.setSettings(this.settings);
    this.attach(ctx.state.current);
  }

  deactivate(): void {
    const ctx = this.ctx;
    this.cancelGesture();
    this.autosave.flush();
    for (const off of this.off) off();
    this.off = [];
    this.layer?.dispose();
    this.layer = null;
    this.panel = null;
    if (ctx) {
      ctx.view.canvas.removeEventListener('pointerdown', this.onPointer, true);
      ctx.view.canvas.removeEventListener('pointermove', this.onPointer, true);
      if (this.overlayWasOn) ctx.state.setOverlay(true);
    }
    this.ctx = null;
  }

  pointerDown(p: ViewPointer): boolean {
    const layer = this.layer;
    if (!layer || p.button !== 0) return false;
    if (this.tool === 'draw') {
      this.gesture = { kind: 'stroke', samples: [this.sample(p, 0)], start: performance.now() };
      return true;
    }
    if (this.tool === 'edit') {
      const end = layer.pickWindowEnd(p.sx, p.sy);
      if (end) {
        this.gesture = { kind: 'window', side: end };
        return true;
      }
      const hit = layer.pickPoint(p.sx, p.sy);
      if (!hit) return false;
      this.select(hit);
      const curve = this.curves.curve(hit.curve)!;
      try {
        const edit = LocalEdit.begin(curve, hit.point, this.settings);
        this.gesture = { kind: 'drag', edit, x0: p.x, y0: p.y, before: this.curves.snapshot() };
      } catch (err) {
        this.ctx?.state.setError(messageOf(err));
      }
      return true;
    }
    if (this.tool === 'tangent') {
      const knob = layer.pickTangent(p.sx, p.sy);
      if (knob) {
        this.gesture = { kind: 'tangent', at: knob, before: this.curves.snapshot() };
        return true;
      }
      const hit = layer.pickPoint(p.sx, p.sy);
      if (hit) {
        this.select(hit);
        return true;
      }
    }
    return false;
  }

  pointerMove(p: ViewPointer): void {
    const g = this.gesture;
    if (!g) return;
    if (g.kind === 'stroke') {
      g.samples.push(this.sample(p, performance.now() - g.start));
      this.draw(g.samples.flatMap((s) => [s.x, s.y]));
    } else if (g.kind === 'drag') {
      g.edit.move(p.x - g.x0, p.y - g.y0);
      g.edit.apply();
      this.draw();
    } else if (g.kind === 'window') {
      this.dragWindowEnd(g.side, p);
    } else if (g.kind === 'tangent') {
      const c = this.curves.curve(g.at.curve);
      if (!c) return;
      const pts = c.points();
      c.setTangent(g.at.point, [3 * (p.x - pts[2 * g.at.point]), 3 * (p.y - pts[2 * g.at.point + 1])]);
      this.draw();
    }
  }

  pointerUp(): void {
    const g = this.gesture;
    this.gesture = null;
    if (!g) return;
    if (g.kind === 'stroke') this.finishStroke(g.samples);
    else if (g.kind === 'drag') {
      g.edit.end();
      this.record(`Drag point ${this.selected?.point ?? ''}`, g.before);
    } else if (g.kind === 'tangent') this.record(`Set tangent at point ${g.at.point}`, g.before);
    else this.refresh();
  }

  click(p: ViewPointer): void {
    if (this.tool === 'convert') this.convertAt(p);
    else if (this.tool === 'edit' || this.tool === 'tangent') this.select(null);
  }

  keyDown(e: KeyboardEvent): boolean {
    const key = e.key.toLowerCase();
    const tools: Record<string, EditTool> = { d: 'draw', e: 'edit', t: 'tangent', c: 'convert' };
    if (tools[key]) this.setTool(tools[key]);
    else if (key === '[') this.setSettings({ left: Math.max(0, this.settings.left - 1), right: Math.max(0, this.settings.right - 1) });
    else if (key === ']') this.setSettings({ left: this.settings.left + 1, right: this.settings.right + 1 });
    else if (key === 'n') this.setSettings({ normals: !this.settings.normals });
    else if (key === 'r') this.resampleCurve();
    else if (key === 'delete' || key === 'backspace') this.deleteCurve();
    else return false;
    return true;
  }

  exportDocument(current: LoadedDocument): string | undefined {
    const curves = this.sessions.get(current);
    const svg = current.doc.toSVG();
    if (!curves || curves.count === 0) return undefined;
    const paths = curves.curves.map((c, i) => `  <path id="splinekit-edit-${i}" d="${c.toPathData()}"/>`).join('\n');
    const group = `<g id="splinekit-edit" fill="none" stroke="#1f6feb" stroke-width="1.5" vector-effect="non-scaling-stroke">\n${paths}\n</g>\n`;
    const at = svg.lastIndexOf('</svg>');
    return at < 0 ? svg : `${svg.slice(0, at)}${group}${svg.slice(at)}`;
  }

  // ---- Test hooks ------------------------------------------------------------------------------

  testState(): EditTestState {
    return {
      tool: this.tool,
      settings: { ...this.settings },
      curves: this.curves.curves.map((c, i) => {
        let tangents = 0;
        for (let k = 0; k < c.count; k++) tangents += c.tangentOverridden(k) ? 1 : 0;
        return { closed: c.closed, points: Array.from(c.points()), tangents, pressure: this.curves.pressure(i) ?? null };
      }),
      selected: this.selected ? { ...this.selected } : null,
      window: this.preview ? { curve: this.preview.curve, indices: Array.from(this.preview.indices), weights: Array.from(this.preview.weights) } : null,
      dragging: this.gesture !== null,
    };
  }

  /** Canvas pixels of a control point, or of the window's left/right end. */
  pointOnCanvas(curve: number, point: number): [number, number] | null {
    return this.layer?.pointOnScreen(curve, point) ?? null;
  }

  windowEndOnCanvas(side: 'left' | 'right'): [number, number] | null {
    return this.layer?.windowEnds()?.[side] ?? null;
  }

  // ---- Sessions --------------------------------------------------------------------------------

  private attach(current: LoadedDocument | null): void {
    this.cancelGesture();
    this.autosave.flush();
    this.current = current;
    let curves = this.sessions.get(current);
    if (!curves) {
      curves = new EditCurves();
      if (current) {
        try {
          curves.restore(loadCurves(current));
        } catch {
          curves.restore([]); // damaged autosave: start empty
        }
      }
      this.sessions.set(current, curves);
    }
    this.curves = curves;
    this.selected = null;
    this.refresh();
  }

  private saveNow(): void {
    const current = this.current;
    if (!current) return;
    const curves = this.sessions.get(current);
    if (!curves) return;
    const problem = saveCurves(current, curves.snapshot());
    if (problem) this.ctx?.state.setMessage(`Edit curves not autosaved: ${problem}`);
  }

  /** Records an undoable change made in place since `before` (nothing when nothing changed). */
  private record(label: string, before: CurveSnapshot[]): void {
    const after = this.curves.snapshot();
    if (JSON.stringify(after) === JSON.stringify(before)) {
      this.refresh();
      return;
    }
    const curves = this.curves;
    this.ctx?.history.execute(new CurvesCommand(label, curves, before, after, (c) => this.applied(c)));
  }

  private applied(curves: EditCurves): void {
    if (this.selected && (!curves.curve(this.selected.curve) || this.selected.point >= curves.curve(this.selected.curve)!.count)) this.selected = null;
    this.autosave.schedule();
    if (curves === this.curves) this.refresh();
  }

  /** A change that is one undo step: snapshot, run, record. */
  private change(label: string, run: () => void): void {
    const before = this.curves.snapshot();
    try {
      run();
    } catch (err) {
      this.curves.restore(before);
      this.ctx?.state.setError(messageOf(err));
      this.refresh();
      return;
    }
    this.record(label, before);
  }

  // ---- Actions ---------------------------------------------------------------------------------

  private setTool(tool: EditTool): void {
    this.cancelGesture();
    this.tool = tool;
    this.panel?.setTool(tool);
    this.ctx?.view.canvas.classList.toggle('edit-drawing', tool === 'draw');
    this.refresh();
  }

  private setSettings(change: Partial<EditSettings>): void {
    this.settings = { ...this.settings, ...change };
    writeJSON(PREFS_KEY, this.settings);
    this.panel?.setSettings(this.settings);
    this.refresh();
  }

  private select(at: PointRef | null): void {
    this.selected = at;
    this.refresh();
  }

  private sample(p: ViewPointer, time: number): StrokeSample {
    return { x: p.x, y: p.y, time, ...(this.pen.pressure !== undefined ? { pressure: this.pen.pressure } : {}) };
  }

  private finishStroke(samples: StrokeSample[]): void {
    const view = this.ctx?.view;
    if (!view) return;
    // Half a screen pixel, in document units: samples closer than that carry no shape.
    const [ax, ay] = view.toScreen(0, 0), [bx, by] = view.toScreen(1, 0);
    const minSpacing = 0.5 / Math.max(Math.hypot(bx - ax, by - ay), 1e-12);
    const penned = samples.some((s) => s.pressure !== undefined);
    this.change('Draw a curve', () => {
      let curve: CatmullRom;
      try {
        curve = CatmullRom.fromStroke(samples, { minSpacing, resample: this.settings.evenStroke });
      } catch {
        return; // a click, not a stroke: nothing to draw
      }
      const index = this.curves.add(curve, penned && curve.pressure ? Array.from(curve.pressure) : undefined);
      this.selected = { curve: index, point: Math.floor(curve.count / 2) };
    });
  }

  private dragWindowEnd(side: 'left' | 'right', p: ViewPointer): void {
    const w = this.preview, layer = this.layer;
    if (!w || !layer) return;
    const c = this.curves.curve(w.curve);
    if (!c) return;
    const n = c.count;
    let best = -1, bestD = Infinity;
    for (let i = 0; i < n; i++) {
      const [x, y] = layer.pointOnScreen(w.curve, i)!;
      const d = Math.hypot(x - p.sx, y - p.sy);
      if (d < bestD) [best, bestD] = [i, d];
    }
    if (best < 0) return;
    let extent: number;
    if (c.closed) extent = side === 'left' ? (w.center - best + n) % n : (best - w.center + n) % n;
    else extent = side === 'left' ? w.center - best : best - w.center;
    if (extent < 1) return; // the end cannot cross the dragged point
    this.setSettings(side === 'left' ? { left: extent } : { right: extent });
  }

  private resampleCurve(): void {
    const at = this.selected ?? (this.curves.count > 0 ? { curve: this.curves.count - 1, point: 0 } : null);
    if (!at) return;
    this.change('Resample the curve', () => this.curves.curve(at.curve)!.resample());
  }

  private resampleWindow(factor: number): void {
    const w = this.preview;
    if (!w || w.indices.length < 2) {
      this.ctx?.state.setMessage('Select a control point with Edit to resample its window');
      return;
    }
    const first = w.indices[0], last = w.indices[w.indices.length - 1];
    const inner = Math.max(0, Math.round((w.indices.length - 2) * factor));
    this.change(factor > 1 ? 'Finer window' : 'Coarser window', () => {
      const c = this.curves.curve(w.curve)!;
      const ends = c.resampleRange(first, last, inner);
      // Select the point nearest the middle of the new window.
      const span = c.closed ? (ends.last - ends.first + c.count) % c.count || c.count : ends.last - ends.first;
      this.selected = { curve: w.curve, point: (ends.first + Math.floor(span / 2)) % c.count };
    });
  }

  private clearTangents(): void {
    const at = this.selected;
    if (!at) return;
    this.change('Reset tangents', () => {
      const c = this.curves.curve(at.curve)!;
      for (let i = 0; i < c.count; i++) if (c.tangentOverridden(i)) c.clearTangent(i);
    });
  }

  private toggleClosed(): void {
    const at = this.selected;
    if (!at) return;
    const before = this.curves.snapshot();
    const s = before[at.curve];
    if (!s || (!s.closed && s.points.length < 6)) {
      this.ctx?.state.setMessage('A closed curve needs at least 3 control points');
      return;
    }
    const after = before.map((c, i) => (i === at.curve ? { ...c, closed: !c.closed } : c));
    this.ctx?.history.execute(new CurvesCommand(s.closed ? 'Open the curve' : 'Close the curve', this.curves, before, after, (c) => this.applied(c)));
  }

  private deleteCurve(): void {
    const at = this.selected;
    if (!at) return;
    const before = this.curves.snapshot();
    const after = before.filter((_, i) => i !== at.curve);
    this.selected = null;
    this.ctx?.history.execute(new CurvesCommand('Delete the curve', this.curves, before, after, (c) => this.applied(c)));
  }

  /** Turns the path of the drawing nearest the click into a curve through points along it. */
  private convertAt(p: ViewPointer): void {
    const doc = this.ctx?.state.doc, view = this.ctx?.view;
    if (!doc || !view) return;
    let best = -1, bestD = CONVERT_PICK;
    const seg = new Float64Array(8);
    for (let si = 0; si < doc.splines.length; si++) {
      const s = doc.splines[si];
      for (let k = 0; k < segmentCount(s); k++) {
        segmentOf(s, k, seg);
        for (let j = 0; j <= 16; j++) {
          const [x, y] = cubic(seg, j / 16);
          const [sx, sy] = view.toScreen(x, y);
          const d = Math.hypot(sx - p.sx, sy - p.sy);
          if (d <= bestD) [best, bestD] = [si, d];
        }
      }
    }
    if (best < 0) {
      this.ctx?.state.setMessage('Click on a path of the drawing to turn it into a curve');
      return;
    }
    const spline = doc.splines[best];
    // Four points per Bézier segment (anchors and three between), then even spacing.
    const pts: number[] = [];
    for (let k = 0; k < segmentCount(spline); k++) {
      segmentOf(spline, k, seg);
      for (let j = 0; j < 4; j++) pts.push(...cubic(seg, j / 4));
    }
    if (!spline.closed) pts.push(spline.points[spline.points.length - 2], spline.points[spline.points.length - 1]);
    this.change('Convert a path to a curve', () => {
      const curve = CatmullRom.create(dedupe(pts), { closed: spline.closed });
      curve.resample();
      const index = this.curves.add(curve);
      this.selected = { curve: index, point: Math.floor(curve.count / 2) };
      this.setTool('edit');
    });
  }

  private cancelGesture(): void {
    const g = this.gesture;
    this.gesture = null;
    if (g?.kind === 'drag') g.edit.cancel();
    if (g?.kind === 'tangent') this.curves.restore(g.before);
  }

  // ---- Drawing ---------------------------------------------------------------------------------

  private computePreview(): WindowPreview | null {
    const at = this.selected;
    if (!at || this.tool === 'draw' || this.tool === 'convert') return null;
    const c = this.curves.curve(at.curve);
    if (!c || at.point >= c.count) return null;
    let e: LocalEdit | null = null;
    try {
      e = LocalEdit.begin(c, at.point, this.settings);
      return { curve: at.curve, center: at.point, indices: e.window.indices, weights: e.window.weights };
    } catch {
      return null;
    } finally {
      e?.dispose();
    }
  }

  private refresh(): void {
    this.preview = this.computePreview();
    this.draw();
    const panel = this.panel;
    if (!panel) return;
    const at = this.selected, c = at ? this.curves.curve(at.curve) : undefined;
    const w = this.preview;
    const pressure = at ? this.curves.pressure(at.curve) : undefined;
    panel.setInfo(
      this.curves.count,
      at && c ? `curve ${at.curve + 1}, point ${at.point} of ${c.count}` : '—',
      w ? `${w.indices[0]}..${w.indices[w.indices.length - 1]} (${w.indices.length} points)` : '—',
      pressure ? `${Math.min(...pressure).toFixed(2)}–${Math.max(...pressure).toFixed(2)}` : '—',
      this.curves.count > 0,
    );
    panel.setWeights(w?.weights ?? null);
  }

  private draw(stroke: number[] | null = null): void {
    this.layer?.set({ curves: this.curves.curves, selected: this.selected, window: this.preview, stroke, tangents: this.tool === 'tangent' });
  }
}

function cubic(c: ArrayLike<number>, t: number): [number, number] {
  const u = 1 - t, a = u * u * u, b = 3 * u * u * t, d = 3 * u * t * t, e = t * t * t;
  return [a * c[0] + b * c[2] + d * c[4] + e * c[6], a * c[1] + b * c[3] + d * c[5] + e * c[7]];
}

/** Drops consecutive repeats (and a closing repeat of the first point). */
function dedupe(xy: number[]): number[] {
  const out: number[] = [];
  for (let i = 0; i < xy.length; i += 2) {
    const n = out.length;
    if (n >= 2 && out[n - 2] === xy[i] && out[n - 1] === xy[i + 1]) continue;
    out.push(xy[i], xy[i + 1]);
  }
  if (out.length >= 4 && out[0] === out[out.length - 2] && out[1] === out[out.length - 1]) out.length -= 2;
  return out;
}
