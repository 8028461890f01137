import { messageOf } from '../app/errors.js';
import { SHAPE_ATTRIBUTE, fixedFormatter, formatNumber, type Matrix, type SvgDocument } from '../../src/index.js';
import type { Spline } from '../../src/spline/spline.js';
import { invert, isIdentity } from '../../src/svg/matrix.js';
import type { Viewport } from './viewport.js';
import { allFinite, paintLive, planLivePainting, type LivePlan } from './live-canvas.js';
import { sanitizeSvg } from './sanitize.js';

/** A shape the drawing leaves out (its path is left empty), or the whole drawing when it cannot be shown. */
export interface SkippedShape {
  /** The element as a user finds it in the file: `<path id="leg"> at line 12`. */
  element: string;
  /** What was wrong. */
  reason: string;
}

/** What drawing the document took (the view's 'drawing' event). */
export interface DrawingStats {
  /** Shapes drawn from the splines (their paths follow every change of the model). */
  shapes: number;
  /** Shapes whose path was written this time (all of them when the markup is mounted). */
  written: number;
  /** Shapes painted on the live canvas instead (a live show of a drawing it can paint), else 0. */
  painted: number;
  /** Time to mount the markup or write the changed paths, in milliseconds (the browser paints after). */
  ms: number;
  /** Shapes that could not be drawn from their splines; everything else was. */
  skipped: SkippedShape[];
}

interface Target {
  el: Element;
  shape: number;
  /** The points the path was last written from, one array per spline, to skip unchanged shapes. */
  drawn: Float64Array[];
  /** Sets the map its gradients and patterns follow (SvgDocument.paintFollower), or null. */
  follow: ((m: Matrix | null) => void) | null;
  /** The shape's transform (user space → document) the two fields below were computed for. */
  transform: Matrix | null;
  /** Document → the element's user space: undefined for the identity, null when singular. */
  toLocal: Matrix | null | undefined;
  /** The largest stretch of a user-space unit in document units (the transform's largest singular value). */
  stretch: number;
  /**
   * The path was last written during a live change with fewer digits than a still view uses (or
   * not rewritten for a change smaller than a pixel's fraction): the next still view writes it
   * again at full precision.
   */
  coarse: boolean;
}

/** Options of {@link SvgLayer.show}. */
export interface ShowOptions {
  /**
   * A live change (a drag, playback) that another show follows when it ends: paths are written
   * with the digits the current zoom can show (to 1/LIVE_PRECISION of a pixel), and shapes that
   * moved less than SKIP_PX on screen since they were written are left as they are. The next show
   * that is not live writes every such path again exactly as a still view does.
   */
  live?: boolean;
}

/** While live, path numbers are written to 1/LIVE_PRECISION of a screen pixel. */
const LIVE_PRECISION = 20;
/** While live, a shape whose points all moved less than this many screen pixels is not rewritten. */
export const SKIP_PX = 0.05;

/** Live markup written elsewhere (the import worker) for a document, consumed by its first mount. */
const primed = new WeakMap<SvgDocument, string | Element>();

/**
 * Gives the view `doc`'s live markup, `doc.toSVG({ rewrite: 'all', tagShapes: true })`, written
 * elsewhere (the import worker writes it off the main thread), so that mounting `doc` does not
 * write it again. Used once, by the next mount of this very document.
 */
export function primeLiveMarkup(doc: SvgDocument, markup: string): void {
  primed.set(doc, markup);
}

/**
 * Parses and sanitises the live markup primed for `doc` now (a step of its own, so that opening
 * a large file does not do all its work in one task); its mount then imports the result. When
 * the markup does not parse, it stays primed as text, and the mount reports why.
 */
export function parsePrimedMarkup(doc: SvgDocument): void {
  const markup = primed.get(doc);
  if (typeof markup !== 'string') return;
  try {
    primed.set(doc, parsedMarkup(markup));
  } catch {
    // The mount parses it again and says what is wrong.
  }
}

/** The sanitised root element of live markup (in a document of its own). */
function parsedMarkup(markup: string): Element {
  const source = new DOMParser().parseFromString(markup, 'image/svg+xml').documentElement;
  if (source.localName !== 'svg') throw new Error('its markup did not parse back');
  sanitizeSvg(source, (el) => el.hasAttribute(SHAPE_ATTRIBUTE));
  return source;
}

/**
 * The document drawn by the browser from its spline model: the markup the model keeps (gradients,
 * patterns, clip paths, masks, markers, dashes, group opacity, filters, text, images: everything
 * the file has) with every shape rewritten as a path from its splines (as `SvgPuppet` does), in a
 * shadow root so the file's ids and stylesheets stay its own. Showing another version of the same
 * document (a pose, an edit) rewrites only the paths whose splines changed; pan and zoom only move
 * the viewBox, so the browser re-renders at the current zoom.
 *
 * The markup is sanitised (sanitizeSvg, an allow-list of SVG elements and attributes) before it
 * enters the page: scripts, event handler attributes, foreign objects and animations that could
 * set links are dropped, so a hostile file cannot run code in the editor, and references outside
 * the file (links, images, stylesheets and url(…)s on the network) are dropped, so opening it
 * fetches nothing — as when the browser shows a file as an image.
 */
export class SvgLayer {
  /** The element holding the drawing (under the WebGL canvas, which stays transparent). */
  readonly host: HTMLDivElement;
  private readonly root: ShadowRoot;
  private readonly paper: HTMLDivElement;
  private svg: SVGSVGElement | null = null;
  private doc: SvgDocument | null = null;
  private targets: Target[] = [];
  /** Writes path numbers to 1e-7 of the drawing's size: finer than the deepest zoom shows, and quick. */
  private format: (v: number) => string = String;
  /** The decimals `format` writes (more than 9: 12 significant digits). */
  private decimals = 0;
  /** The canvas a live change is painted on, over the (hidden) drawing, when the plan allows. */
  private readonly live: HTMLCanvasElement;
  private liveContext: CanvasRenderingContext2D | null = null;
  /** How the mounted drawing is painted live (made at its first live show), or null. */
  private plan: LivePlan | null = null;
  /** Whether the live canvas shows the drawing now. */
  private painting = false;
  private painted = 0;
  /** The markup was just mounted (its paths written from the splines as they are). */
  private mounted = false;
  private liveFrames = 0;

  constructor(container: HTMLElement) {
    this.host = document.createElement('div');
    this.host.className = 'view2d-drawing';
    this.host.setAttribute('aria-hidden', 'true');
    container.appendChild(this.host);
    this.root = this.host.attachShadow({ mode: 'open' });
    const style = document.createElement('style');
    // `all: initial`: the drawing inherits nothing from the editor's page (currentColor is black,
    // text has the browser's default font), as when the file is opened on its own.
    style.textContent = ':host { all: initial; display: block; position: absolute; inset: 0; overflow: hidden; pointer-events: none; contain: strict; }'
      + ' :host([hidden]) { display: none; }'
      + ' .paper { position: absolute; background: #fff; outline: 1px solid rgba(0, 0, 0, 0.35); }'
      + ' svg.drawing { position: absolute; left: 0; top: 0; }'
      + ' canvas.live { position: absolute; left: 0; top: 0; } canvas.live[hidden] { display: none; }';
    this.paper = document.createElement('div');
    this.paper.className = 'paper';
    this.paper.hidden = true;
    this.live = document.createElement('canvas');
    this.live.className = 'live';
    this.live.hidden = true;
    this.root.append(style, this.paper, this.live);
  }

  /**
   * Shows `doc`: the first time (or for another document's markup) it mounts its markup; for
   * another version of the shown document (a clone, a posed copy) it writes only the paths whose
   * splines changed.
   */
  show(doc: SvgDocument | null, viewport: Viewport, options: ShowOptions = {}): DrawingStats {
    const t0 = performance.now();
    if (!doc) {
      this.unmount();
      return { shapes: 0, written: 0, painted: 0, ms: 0, skipped: [] };
    }
    const mounted = this.doc !== null && this.svg !== null && this.doc.sameMarkup(doc) && this.doc.shapes.length === doc.shapes.length;
    if (!mounted) {
      try {
        this.mount(doc);
      } catch (err) {
        // Nothing is drawn, and the view says why; the document itself is open.
        this.unmount();
        return { shapes: 0, written: 0, painted: 0, ms: performance.now() - t0, skipped: [{ element: '<svg>', reason: `the drawing could not be shown: ${messageOf(err)}` }] };
      }
      const decimals = Math.ceil(Math.log10(1e7 / doc.size));
      this.decimals = Math.max(0, decimals);
      this.format = decimals > 9 ? formatNumber : formatterFor(this.decimals);
    }
    this.doc = doc;
    if (options.live && this.livePlan(doc)) {
      // Painted on the canvas from the splines; the markup is written when the change ends.
      this.setView(viewport);
      return { shapes: this.targets.length, written: 0, painted: this.painted, ms: performance.now() - t0, skipped: [] };
    }
    const result = this.write(doc, options.live ? viewport.scale : null), skipped = result.skipped;
    // A mount writes every path (in its markup).
    const written = this.mounted ? this.targets.length : result.written;
    this.mounted = false;
    // In the same frame as the paths are written: the drawing comes back in place of the canvas.
    if (this.painting) this.stopPainting();
    this.setView(viewport);
    return { shapes: this.targets.length, written, painted: 0, ms: performance.now() - t0, skipped };
  }

  /** Places the drawing for the view: the visible document rectangle becomes the viewBox. */
  setView(viewport: Viewport): void {
    const svg = this.svg, doc = this.doc;
    if (!svg || !doc) return;
    const [left, right, top, bottom] = viewport.planes();
    // Inline style too: a width or height in the file's own style attribute would win over attributes.
    svg.setAttribute('width', String(viewport.width));
    svg.setAttribute('height', String(viewport.height));
    svg.style.width = `${viewport.width}px`;
    svg.style.height = `${viewport.height}px`;
    svg.setAttribute('viewBox', `${left} ${top} ${right - left} ${bottom - top}`);
    const [x, y, w, h] = doc.frame;
    const [sx, sy] = viewport.toScreen(x, y);
    Object.assign(this.paper.style, { left: `${sx}px`, top: `${sy}px`, width: `${w * viewport.scale}px`, height: `${h * viewport.scale}px` });
    if (this.painting) this.paint(viewport);
  }

  /**
   * Whether `doc` can be shown on the live canvas (the plan is made at the first live show of a
   * mounted drawing); when it can, the canvas takes the drawing's place until a still show.
   */
  private livePlan(doc: SvgDocument): boolean {
    const svg = this.svg;
    if (!svg) return false;
    if (this.plan === null) {
      const shapeOf = new Map<Element, number>(this.targets.map((t) => [t.el, t.shape]));
      this.plan = planLivePainting(svg, doc, shapeOf, (id) => this.root.getElementById(id));
      if ('unsupported' in this.plan) console.info(`splinekit: live changes are drawn by the browser (the live canvas cannot draw ${this.plan.unsupported})`);
    }
    if ('unsupported' in this.plan) return false;
    if (!this.painting) {
      this.painting = true;
      this.live.hidden = false;
      svg.style.visibility = 'hidden';
    }
    return true;
  }

  /** Back from the live canvas to the browser's drawing (its paths just written). */
  private stopPainting(): void {
    this.painting = false;
    this.live.hidden = true;
    if (this.svg) this.svg.style.visibility = '';
  }

  /** Paints the live canvas for the view (while painting). */
  private paint(viewport: Viewport): void {
    const plan = this.plan, doc = this.doc;
    if (!plan || 'unsupported' in plan || !doc) return;
    const ratio = window.devicePixelRatio || 1;
    const w = Math.round(viewport.width * ratio), h = Math.round(viewport.height * ratio);
    const c = this.live;
    if (c.width !== w || c.height !== h) {
      c.width = w;
      c.height = h;
      c.style.width = `${viewport.width}px`;
      c.style.height = `${viewport.height}px`;
    }
    this.painted = paintLive(this.liveContext ??= c.getContext('2d')!, plan, doc, viewport, ratio);
    // One attribute per painted frame, for whoever watches what the page shows (the drag benchmark).
    c.dataset.frame = String(++this.liveFrames);
  }

  private unmount(): void {
    if (this.painting) this.stopPainting();
    this.plan = null;
    this.svg?.remove();
    this.svg = null;
    this.doc = null;
    this.targets = [];
    this.paper.hidden = true;
  }

  private mount(doc: SvgDocument): void {
    this.unmount();
    const markup = primed.get(doc) ?? doc.toSVG({ rewrite: 'all', tagShapes: true });
    primed.delete(doc);
    const source = typeof markup === 'string' ? parsedMarkup(markup) : markup;
    const svg = document.importNode(source, true) as unknown as SVGSVGElement;
    // The view decides what is visible; the file's own size and placement no longer apply.
    for (const name of ['x', 'y', 'transform']) svg.removeAttribute(name);
    svg.setAttribute('preserveAspectRatio', 'none');
    svg.classList.add('drawing');
    this.paper.after(svg);
    this.svg = svg;
    this.paper.hidden = false;

    const byIndex = new Map<number, Element>();
    for (const el of Array.from(svg.querySelectorAll(`[${SHAPE_ATTRIBUTE}]`))) byIndex.set(Number(el.getAttribute(SHAPE_ATTRIBUTE)), el);
    doc.shapes.forEach((shape, i) => {
      const el = byIndex.get(i);
      if (!el) return;
      const t: Target = { el, shape: i, drawn: [], follow: doc.paintFollower(i, svg, el), transform: null, toLocal: null, stretch: 1, coarse: false };
      // The markup has every shape's path written from these very splines (and its paint following
      // it): remembered as drawn, not written again. Shapes with a coordinate that is not a finite
      // number are left for write(), which empties them and says so.
      if (allFinite(doc.splines, shape.firstSpline, shape.splineCount)) {
        remember(t, doc.splines, shape.firstSpline, shape.splineCount);
        t.follow?.(doc.paintTransform(i));
      }
      this.targets.push(t);
    });
    this.mounted = true;
  }

  /**
   * Writes the paths whose splines differ from what they were last written from (and, when still,
   * those last written coarsely). `liveScale`: the view's pixels per document unit during a live
   * change, null for a still view.
   */
  private write(doc: SvgDocument, liveScale: number | null): { written: number; skipped: SkippedShape[] } {
    let written = 0;
    const skipped: SkippedShape[] = [];
    const all = doc.splines;
    for (const t of this.targets) {
      const shape = doc.shapes[t.shape];
      const first = shape.firstSpline, count = shape.splineCount;
      if (shape.transform !== t.transform) {
        t.transform = shape.transform;
        const inv = invert(shape.transform);
        t.toLocal = inv && isIdentity(inv) ? undefined : inv;
        t.stretch = largestStretch(shape.transform);
      }
      const moved = liveScale !== null ? largestMove(all, first, count, t.drawn) : sameSplines(all, first, count, t.drawn) ? 0 : Infinity;
      if (moved === 0 && !(t.coarse && liveScale === null)) continue;
      // While live, a change smaller than a pixel's fraction waits for the still view.
      if (liveScale !== null && moved * liveScale < SKIP_PX) {
        t.coarse = true;
        continue;
      }
      if (moved !== 0) remember(t, all, first, count);
      t.coarse = false;
      if (!allFinite(all, first, count)) {
        skipped.push({ element: `<${shape.tag}${shape.id ? ` id="${shape.id}"` : ''}>${shape.line ? ` at line ${shape.line}` : ''}`, reason: 'a coordinate is not a finite number' });
        t.el.setAttribute('d', '');
        continue;
      }
      let format = this.format;
      if (liveScale !== null) {
        // Digits for 1/LIVE_PRECISION of a pixel in the element's own units.
        const decimals = Math.max(0, Math.ceil(Math.log10(LIVE_PRECISION * liveScale * t.stretch)));
        if (decimals < this.decimals || this.decimals > 9) {
          format = formatterFor(Math.min(9, decimals));
          t.coarse = true;
        }
      }
      t.el.setAttribute('d', t.toLocal === null ? '' : writePathData(all, first, count, t.toLocal, format));
      if (moved !== 0 || liveScale === null) t.follow?.(doc.paintTransform(t.shape));
      written++;
    }
    return { written, skipped };
  }
}

/** fixedFormatter(d) for d = 0…9, made once. */
const FORMATTERS: ((v: number) => string)[] = [];
function formatterFor(decimals: number): (v: number) => string {
  return (FORMATTERS[decimals] ??= fixedFormatter(decimals));
}

/**
 * Path data of splines[first … first + count) mapped by `m` (document → user space; undefined for
 * none), numbers written by `format`: the same text as SvgDocument.pathData (splinesToPathData),
 * "M p0 C p1 p2 p3 …" with "Z" after closed splines, written in one pass.
 */
export function writePathData(splines: readonly Pick<Spline, 'closed' | 'points'>[], first: number, count: number, m: Matrix | undefined, format: (v: number) => string): string {
  let d = '';
  for (let s = first; s < first + count; s++) {
    const { closed, points: p } = splines[s];
    const n = p.length / 2;
    if (n === 0) continue;
    const segs = n <= 1 ? 0 : closed ? n / 3 : (n - 1) / 3;
    for (let j = 0, last = 3 * segs; j <= last; j++) {
      const i = j === last && closed && segs > 0 ? 0 : j;
      const x = p[2 * i], y = p[2 * i + 1];
      const sep = j === 0 ? 'M' : j % 3 === 1 ? 'C' : ' ';
      if (m) d += sep + format(m.a * x + m.c * y + m.e) + ' ' + format(m.b * x + m.d * y + m.f);
      else d += sep + format(x) + ' ' + format(y);
    }
    if (closed) d += 'Z';
  }
  return d;
}

/** The largest singular value of a transform's linear part: how far it stretches a unit. */
function largestStretch(m: Matrix): number {
  const sum = m.a * m.a + m.b * m.b + m.c * m.c + m.d * m.d, det = m.a * m.d - m.b * m.c;
  return Math.sqrt((sum + Math.sqrt(Math.max(0, sum * sum - 4 * det * det))) / 2);
}

/** Keeps a copy of the points a path is written from, in the arrays it had when the sizes match. */
function remember(t: Target, all: readonly Spline[], first: number, count: number): void {
  if (t.drawn.length !== count) t.drawn = new Array<Float64Array>(count);
  for (let k = 0; k < count; k++) {
    const points = all[first + k].points, kept = t.drawn[k];
    if (kept?.length === points.length) kept.set(points);
    else t.drawn[k] = Float64Array.from(points);
  }
}

function sameSplines(all: readonly Spline[], first: number, count: number, drawn: readonly Float64Array[]): boolean {
  if (count !== drawn.length) return false;
  for (let k = 0; k < count; k++) {
    const a = all[first + k].points, b = drawn[k];
    if (a.length !== b.length) return false;
    for (let j = 0; j < a.length; j++) if (a[j] !== b[j]) return false;
  }
  return true;
}

/**
 * The largest coordinate change (document units) of the shape's points since they were last
 * written: 0 when none changed, Infinity when the structure did or a change is not finite.
 */
function largestMove(all: readonly Spline[], first: number, count: number, drawn: readonly Float64Array[]): number {
  if (count !== drawn.length) return Infinity;
  let most = 0;
  for (let k = 0; k < count; k++) {
    const a = all[first + k].points, b = drawn[k];
    if (a.length !== b.length) return Infinity;
    for (let j = 0; j < a.length; j++) {
      if (a[j] === b[j]) continue;
      const change = Math.abs(a[j] - b[j]);
      if (!(change <= most)) most = change; // NaN (and Infinity) stay
    }
  }
  return Number.isNaN(most) ? Infinity : most;
}

