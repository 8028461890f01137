import { Morph, parseSVG, type MorphInterpolation, type SvgDocument } from '../../../src/index.js';
import { download, derivedName } from '../../app/download.js';
import { messageOf } from '../../app/errors.js';
import type { Command } from '../../app/history.js';
import type { Mode, ModeContext } from '../../app/modes.js';
import type { LoadedDocument } from '../../app/state.js';
import type { ViewPointer } from '../../view2d/view2d.js';
import { fontGlyphSVG } from './font-glyph.js';
import { contoursToD, MorphLayer } from './morph-layer.js';
import { MorphPanel } from './morph-panel.js';
import { MORPH_SAMPLES } from './samples.js';
import { DEFAULT_SPEC, type KeyChoice, type MorphSpec } from './spec.js';
import { loadSpec, saveSpec } from './storage.js';

/** How close (pixels) a press must be to an anchor of the first key to start a pin. */
const PIN_PICK = 14;
/** Seconds from the first key to the second while playing. */
const PLAY_SECONDS = 2;

/** One undoable change of the morph set-up: the spec before and after. */
class MorphSpecCommand implements Command {
  constructor(
    readonly label: string,
    private readonly mode: MorphMode,
    private readonly before: MorphSpec,
    private readonly after: MorphSpec,
  ) {}
  do(): void {
    this.mode.apply(this.after);
  }
  undo(): void {
    this.mode.apply(this.before);
  }
}

/** What the end-to-end tests read (window.splinekitEditor.morph()). */
export interface MorphTestState {
  active: boolean;
  t: number;
  interpolation: MorphInterpolation;
  keyA: string;
  keyB: string;
  contours: number;
  work: number | null;
  pins: number;
  /** Correspondence lines drawn. */
  lines: number;
  playing: boolean;
  error: string | null;
  /** A checksum of the in-between's control points (changes when t or the blend changes). */
  checksum: number;
}

/**
 * Morph mode: blend two drawings (the open one, samples of the mode's own, or files) with the least
 * work of bending and stretching (Sederberg & Greenwood); scrub or play t, see both keys as onion
 * skins and the correspondence as lines, pin points of the first key to points of the second
 * (undoably), switch linear / intrinsic interpolation, export frames and an animated SVG.
 */
export class MorphMode implements Mode {
  readonly id = 'morph';
  readonly title = 'Morph';
  readonly description = 'Blend two drawings with the least work of bending and stretching; every in-between stays Bézier splines';
  readonly keys = [
    ['Drag from the blue key to the orange', 'pin two points together'],
    ['Space', 'play or pause'],
    ['← →', 'step t by 0.05'],
  ] as const;

  private ctx: ModeContext | null = null;
  private panel: MorphPanel | null = null;
  private layer: MorphLayer | null = null;
  private off: (() => void)[] = [];
  private spec: MorphSpec = DEFAULT_SPEC;
  private morph: Morph | null = null;
  /** The in-between's markup, written once per morph: showing another t only moves its paths. */
  private inBetween: SvgDocument | null = null;
  private error: string | null = null;
  private stats = { ms: 0, frameMs: 0 };
  private layers = { onion: true, lines: true };
  private keyD = { a: '', b: '' };
  private fitted = false;
  private playing = false;
  private raf = 0;
  private lastTime = 0;
  private direction = 1;
  private drag: { pin: number; end: 'a' | 'b'; from: readonly [number, number]; to: [number, number] } | null = null;
  private saveTimer = 0;
  private overlayWasOn = false;
  private checksum = 0;

  activate(ctx: ModeContext): void {
    this.ctx = ctx;
    this.panel = new MorphPanel({
      chooseKey: (which, source) => this.chooseKey(which, { source }),
      openKey: (which, file) => void this.openKey(which, file),
      openFont: (which, file, char) => void this.openFont(which, file, char),
      setInterpolation: (m) => this.edit(`Interpolation ${m}`, (s) => ({ ...s, interpolation: m })),
      seek: (t, live) => this.seek(t, live),
      togglePlay: () => this.togglePlay(),
      setLayer: (name, on) => {
        this.layers[name] = on;
        this.drawMarks();
      },
      clearPins: () => {
        if (this.spec.pins.length) this.edit('Clear pins', (s) => ({ ...s, pins: [] }));
      },
      exportAnimated: (format) => this.exportAnimated(format),
      exportFrames: () => this.exportFrames(),
    });
    ctx.panel.append(...this.panel.sections);
    this.layer = new MorphLayer(ctx.view);
    this.overlayWasOn = ctx.state.overlay;
    ctx.state.setOverlay(false);
    this.off.push(
      ctx.state.events.on('document', (current) => this.attach(current)),
      ctx.view.events.on('view', () => this.layer?.viewChanged()),
    );
    this.attach(ctx.state.current);
  }

  deactivate(): void {
    this.stop();
    this.flushSave();
    for (const off of this.off) off();
    this.off = [];
    this.layer?.dispose();
    this.layer = null;
    this.morph?.dispose();
    this.morph = null;
    this.inBetween = null;
    const ctx = this.ctx;
    if (ctx) {
      ctx.view.setDocument(ctx.state.doc);
      ctx.overlay.setDocument(ctx.state.doc);
      if (this.overlayWasOn) ctx.state.setOverlay(true);
    }
    this.ctx = null;
    this.panel = null;
  }

  /** The open document changed: its autosaved set-up, or the default. */
  private attach(current: LoadedDocument | null): void {
    this.spec = loadSpec(current) ?? DEFAULT_SPEC;
    this.fitted = false;
    this.rebuild();
  }

  /** Applies a spec (undo/redo and edits): rebuilds the morph when keys, pins or interpolation changed. */
  apply(spec: MorphSpec): void {
    const before = this.spec;
    this.spec = spec;
    const sameKeys = JSON.stringify([before.a, before.b]) === JSON.stringify([spec.a, spec.b]);
    if (!sameKeys) this.fitted = false;
    if (sameKeys && JSON.stringify(before.pins) === JSON.stringify(spec.pins) && before.interpolation === spec.interpolation) this.show();
    else this.rebuild();
    this.scheduleSave();
  }

  private edit(label: string, change: (s: MorphSpec) => MorphSpec): void {
    const before = this.spec, after = change(before);
    this.ctx?.history.execute(new MorphSpecCommand(label, this, before, after));
  }

  private chooseKey(which: 'a' | 'b', choice: KeyChoice): void {
    this.edit(`${which === 'a' ? 'First' : 'Second'} key`, (s) => ({ ...s, [which]: choice, pins: [] }));
  }

  private async openKey(which: 'a' | 'b', file: File): Promise<void> {
    try {
      const text = await file.text();
      parseSVG(text, { name: file.name }); // refuse bad files here, keeping the morph as it was
      this.chooseKey(which, { source: 'file', name: file.name, text });
    } catch (err) {
      this.ctx?.state.setError(messageOf(err));
    }
  }

  private async openFont(which: 'a' | 'b', file: File, char: string): Promise<void> {
    try {
      const { name, svg } = fontGlyphSVG(await file.arrayBuffer(), char, file.name);
      parseSVG(svg, { name });
      this.chooseKey(which, { source: 'file', name, text: svg });
    } catch (err) {
      this.ctx?.state.setError(messageOf(err));
    }
  }

  private keyDoc(choice: KeyChoice): SvgDocument | null {
    if (choice.source === 'current') return this.ctx?.state.doc ?? null;
    if (choice.source === 'file') return parseSVG(choice.text!, { name: choice.name });
    const sample = MORPH_SAMPLES.find((s) => s.id === choice.source) ?? MORPH_SAMPLES[0];
    return parseSVG(sample.svg, { name: sample.title });
  }

  private rebuild(): void {
    this.morph?.dispose();
    this.morph = null;
    this.inBetween = null;
    this.error = null;
    try {
      const a = this.keyDoc(this.spec.a), b = this.keyDoc(this.spec.b);
      if (!a) throw new Error('The first key is the open drawing, and no drawing is open');
      if (!b) throw new Error('The second key has no drawing');
      const t0 = performance.now();
      const m = Morph.create(a, b, { pins: this.spec.pins, interpolation: this.spec.interpolation });
      this.stats.ms = performance.now() - t0;
      const t1 = performance.now();
      for (let i = 0; i < 50; i++) m.at(i / 49);
      this.stats.frameMs = (performance.now() - t1) / 50;
      this.morph = m;
      const k0 = m.at(0).slice(), k1 = m.at(1).slice();
      this.keyD = { a: contoursToD(k0, m.starts, m.counts, m.closed), b: contoursToD(k1, m.starts, m.counts, m.closed) };
    } catch (err) {
      this.error = messageOf(err);
      this.keyD = { a: '', b: '' };
    }
    this.panel?.setKeys(this.spec.a, this.spec.b);
    this.panel?.setInterpolation(this.spec.interpolation);
    this.show();
  }

  /**
   * The in-between at t as a document: a copy of the first one written (same markup, so the view
   * rewrites only the paths' data) with this t's splines; written anew if the structure differs.
   */
  /** The copy of `inBetween` shown for other t's. */
  private working: { base: SvgDocument; doc: SvgDocument } | null = null;

  private inBetweenAt(m: Morph, t: number): SvgDocument {
    const base = this.inBetween;
    const splines = m.splines(t);
    if (base && base.splines.length === splines.length && base.splines.every((s, i) => s.points.length === splines[i].points.length)) {
      // One copy of it per morph, its points replaced for every t (not copied per frame).
      if (this.working?.base !== base) this.working = { base, doc: base.clone() };
      const doc = this.working.doc;
      doc.splines.forEach((s, i) => s.points.set(splines[i].points));
      return doc;
    }
    return (this.inBetween = m.document(t));
  }

  /**
   * Draws the in-between at the spec's t, the keys, the correspondence and the pins; `live` while
   * the slider is dragged or the morph plays (a still show follows when that ends).
   */
  private show(live = false): void {
    const ctx = this.ctx;
    if (!ctx) return;
    const m = this.morph;
    this.panel?.setT(this.spec.t);
    this.panel?.setInfo(m ? { contours: m.contourCount, work: m.work, ms: this.stats.ms, frameMs: this.stats.frameMs, pins: this.spec.pins.length } : null, this.error);
    if (m) {
      const points = m.at(this.spec.t);
      let sum = 0;
      for (let i = 0; i < points.length; i++) sum += points[i] * ((i % 7) + 1);
      this.checksum = sum;
      const doc = this.inBetweenAt(m, this.spec.t);
      if (this.fitted) ctx.view.showDrawing(doc, { live });
      else ctx.view.setDocument(doc);
      this.fitted = true;
    }
    this.drawMarks();
  }

  private drawMarks(): void {
    const m = this.morph;
    const pins = this.spec.pins.map((p, i) => (this.drag && this.drag.pin === i ? { a: this.drag.end === 'a' ? this.drag.to : p.a, b: this.drag.end === 'b' ? this.drag.to : p.b } : p));
    const rubber = this.drag && this.drag.pin < 0 ? { a: this.drag.from, b: this.drag.to } : null;
    this.layer?.set({
      keyA: this.layers.onion ? this.keyD.a : '',
      keyB: this.layers.onion ? this.keyD.b : '',
      lines: m && this.layers.lines ? { a: m.correspondence.a, b: m.correspondence.b } : null,
      pins,
      rubber,
    });
  }

  private seek(t: number, live: boolean): void {
    this.spec = { ...this.spec, t: Math.min(1, Math.max(0, t)) };
    this.show(live);
    if (!live) this.scheduleSave();
  }

  private togglePlay(): void {
    if (this.playing) this.stop();
    else {
      this.playing = true;
      this.lastTime = performance.now();
      this.panel?.setPlaying(true);
      const step = (now: number) => {
        if (!this.playing) return;
        let t = this.spec.t + (this.direction * (now - this.lastTime)) / 1000 / PLAY_SECONDS;
        this.lastTime = now;
        if (t >= 1) {
          t = 1;
          this.direction = -1;
        }
        if (t <= 0) {
          t = 0;
          this.direction = 1;
        }
        this.seek(t, true);
        this.raf = requestAnimationFrame(step);
      };
      this.raf = requestAnimationFrame(step);
    }
  }

  private stop(): void {
    if (!this.playing) return;
    this.playing = false;
    cancelAnimationFrame(this.raf);
    this.panel?.setPlaying(false);
    this.show(); // the still drawing of where it stopped
    this.scheduleSave();
  }

  /** Nearest matched anchor of key `which` to a screen point: its document position and pixel distance. */
  private nearestAnchor(which: 'a' | 'b', sx: number, sy: number): { x: number; y: number; d: number } | null {
    const m = this.morph, view = this.ctx?.view;
    if (!m || !view) return null;
    const pts = which === 'a' ? m.correspondence.a : m.correspondence.b;
    let best: { x: number; y: number; d: number } | null = null;
    for (let k = 0; k < pts.length; k += 2) {
      const [x, y] = view.toScreen(pts[k], pts[k + 1]);
      const d = Math.hypot(x - sx, y - sy);
      if (!best || d < best.d) best = { x: pts[k], y: pts[k + 1], d };
    }
    return best;
  }

  pointerDown(p: ViewPointer): boolean {
    if (!this.morph || !this.layer) return false;
    const hit = this.layer.pick(p.sx, p.sy);
    if (hit) {
      const pin = this.spec.pins[hit.pin];
      const other = hit.end === 'a' ? pin.b : pin.a;
      this.drag = { pin: hit.pin, end: hit.end, from: other, to: [p.x, p.y] };
      this.stop();
      return true;
    }
    const a = this.nearestAnchor('a', p.sx, p.sy);
    if (a && a.d <= PIN_PICK) {
      this.drag = { pin: -1, end: 'b', from: [a.x, a.y], to: [p.x, p.y] };
      this.stop();
      this.drawMarks();
      return true;
    }
    return false;
  }

  pointerMove(p: ViewPointer): void {
    if (!this.drag) return;
    this.drag.to = [p.x, p.y];
    this.drawMarks();
  }

  pointerUp(p: ViewPointer): void {
    const drag = this.drag;
    this.drag = null;
    if (!drag) return;
    const snapped = this.nearestAnchor(drag.end, p.sx, p.sy);
    if (!snapped) return this.drawMarks();
    const at = [snapped.x, snapped.y] as const;
    if (drag.pin < 0) {
      this.edit('Add pin', (s) => ({ ...s, pins: [...s.pins, { a: drag.from, b: at }] }));
    } else {
      this.edit('Move pin', (s) => ({ ...s, pins: s.pins.map((q, i) => (i === drag.pin ? { ...q, [drag.end]: at } : q)) }));
    }
  }

  pointerLeave(): void {
    if (this.drag) {
      this.drag = null;
      this.drawMarks();
    }
  }

  keyDown(e: KeyboardEvent): boolean {
    if (e.key === ' ') {
      this.togglePlay();
      return true;
    }
    if (e.key === 'ArrowRight' || e.key === 'ArrowLeft') {
      this.stop();
      this.seek(this.spec.t + (e.key === 'ArrowRight' ? 0.05 : -0.05), false);
      return true;
    }
    if (e.key === 'Escape' && this.drag) {
      this.drag = null;
      this.drawMarks();
      return true;
    }
    return false;
  }

  /** The toolbar's Export writes the in-between shown. */
  exportDocument(): string | undefined {
    return this.morph?.toSVG(this.spec.t);
  }

  private name(suffix: string): string {
    const n = (k: KeyChoice) => (k.source === 'file' ? (k.name ?? 'file').replace(/\.svg$/i, '').replace(/[^\w.-]+/g, '_') : k.source === 'current' ? (this.ctx?.state.current?.file ?? 'drawing').replace(/\.svg$/i, '') : k.source);
    return derivedName(`${n(this.spec.a)}-to-${n(this.spec.b)}.svg`, suffix);
  }

  private exportAnimated(format: 'smil' | 'css'): void {
    if (!this.morph) return;
    download(this.morph.animatedSVG({ frames: 25, duration: PLAY_SECONDS, format }), this.name(format === 'css' ? 'animated-css' : 'animated'));
  }

  /** Eleven frames side by side in one SVG (a filmstrip). */
  private exportFrames(): void {
    const m = this.morph;
    if (!m) return;
    const [x0, y0, x1, y1] = m.frame;
    const w = x1 - x0, hgt = y1 - y0, gap = 0.1 * w;
    const frames: string[] = [];
    for (let i = 0; i <= 10; i++) {
      const svg = m.toSVG(i / 10);
      const path = /<path [^>]*\/>/.exec(svg)![0];
      frames.push(`<g transform="translate(${i * (w + gap) - x0} ${-y0})">${path}</g>`);
    }
    const width = 11 * w + 10 * gap;
    download(`<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${width} ${hgt}" width="${width}" height="${hgt}">\n${frames.join('\n')}\n</svg>\n`, this.name('frames'));
  }

  private scheduleSave(): void {
    window.clearTimeout(this.saveTimer);
    this.saveTimer = window.setTimeout(() => this.flushSave(), 300);
  }

  private flushSave(): void {
    window.clearTimeout(this.saveTimer);
    this.saveTimer = 0;
    if (!this.ctx) return;
    const problem = saveSpec(this.ctx.state.current, this.spec);
    if (problem) this.ctx.state.setMessage(problem);
  }

  /** For the end-to-end tests. */
  testState(): MorphTestState {
    const m = this.morph;
    return {
      active: this.ctx !== null,
      t: this.spec.t,
      interpolation: this.spec.interpolation,
      keyA: this.spec.a.source,
      keyB: this.spec.b.source,
      contours: m?.contourCount ?? 0,
      work: m?.work ?? null,
      pins: this.spec.pins.length,
      lines: m && this.layers.lines ? m.correspondence.a.length / 2 : 0,
      playing: this.playing,
      error: this.error,
      checksum: this.checksum,
    };
  }

  /** Canvas position of matched anchor k of the first or second key, or null. */
  anchorOnCanvas(which: 'a' | 'b', k: number): [number, number] | null {
    const m = this.morph, view = this.ctx?.view;
    if (!m || !view) return null;
    const pts = which === 'a' ? m.correspondence.a : m.correspondence.b;
    if (2 * k + 1 >= pts.length) return null;
    return view.toScreen(pts[2 * k], pts[2 * k + 1]);
  }
}
