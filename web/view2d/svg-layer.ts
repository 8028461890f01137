import DOMPurify from 'dompurify';
import { messageOf } from '../app/errors.js';
import { SHAPE_ATTRIBUTE, fixedFormatter, formatNumber, type Matrix, type SvgDocument } from '../../src/index.js';
import type { Viewport } from './viewport.js';

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
}

/** Live markup written elsewhere (the import worker) for a document, consumed by its first mount. */
const primed = new WeakMap<SvgDocument, string>();

/**
 * Gives the view `doc`'s live markup, `doc.toSVG({ rewrite: 'all', tagShapes: true })`, written
 * elsewhere (the import worker writes it off the main thread), so that mounting `doc` does not
 * write it again. Used once, by the next mount of this very document.
 */
export function primeLiveMarkup(doc: SvgDocument, markup: string): void {
  primed.set(doc, markup);
}

/**
 * The document drawn by the browser from its spline model: the markup the model keeps (gradients,
 * patterns, clip paths, masks, markers, dashes, group opacity, filters, text, images: everything
 * the file has) with every shape rewritten as a path from its splines (as `SvgPuppet` does), in a
 * shadow root so the file's ids and stylesheets stay its own. Showing another version of the same
 * document (a pose, an edit) rewrites only the paths whose splines changed; pan and zoom only move
 * the viewBox, so the browser re-renders at the current zoom.
 *
 * The markup is sanitised (DOMPurify, SVG profiles) before it enters the page: scripts, event
 * handler attributes and foreign objects are dropped, so a hostile file cannot run code in the
 * editor, and references outside the file (links, images, stylesheets on the network) are
 * dropped, so opening it fetches nothing — as when the browser shows a file as an image.
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
      + ' svg.drawing { position: absolute; left: 0; top: 0; }';
    this.paper = document.createElement('div');
    this.paper.className = 'paper';
    this.paper.hidden = true;
    this.root.append(style, this.paper);
  }

  /**
   * Shows `doc`: the first time (or for another document's markup) it mounts its markup; for
   * another version of the shown document (a clone, a posed copy) it writes only the paths whose
   * splines changed.
   */
  show(doc: SvgDocument | null, viewport: Viewport): DrawingStats {
    const t0 = performance.now();
    if (!doc) {
      this.unmount();
      return { shapes: 0, written: 0, ms: 0, skipped: [] };
    }
    const mounted = this.doc !== null && this.svg !== null && this.doc.sameMarkup(doc) && this.doc.shapes.length === doc.shapes.length;
    if (!mounted) {
      try {
        this.mount(doc);
      } catch (err) {
        // Nothing is drawn, and the view says why; the document itself is open.
        this.unmount();
        return { shapes: 0, written: 0, ms: performance.now() - t0, skipped: [{ element: '<svg>', reason: `the drawing could not be shown: ${messageOf(err)}` }] };
      }
      const decimals = Math.ceil(Math.log10(1e7 / doc.size));
      this.format = decimals > 9 ? formatNumber : fixedFormatter(Math.max(0, decimals));
    }
    this.doc = doc;
    const { written, skipped } = this.write(doc);
    this.setView(viewport);
    return { shapes: this.targets.length, written, ms: performance.now() - t0, skipped };
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
  }

  private unmount(): void {
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
    const parsed = new DOMParser().parseFromString(markup, 'image/svg+xml');
    const source = parsed.documentElement;
    if (source.localName !== 'svg') throw new Error('its markup did not parse back');
    DOMPurify.sanitize(source, {
      IN_PLACE: true,
      USE_PROFILES: { svg: true, svgFilters: true },
      ADD_TAGS: ['use'],
      ADD_ATTR: [SHAPE_ATTRIBUTE],
      FORBID_TAGS: ['foreignObject', 'script'],
    });
    cleanMarkup(source);
    const svg = document.importNode(source, true) as unknown as SVGSVGElement;
    // The view decides what is visible; the file's own size and placement no longer apply.
    for (const name of ['x', 'y', 'transform']) svg.removeAttribute(name);
    svg.setAttribute('preserveAspectRatio', 'none');
    svg.classList.add('drawing');
    this.root.append(svg);
    this.svg = svg;
    this.paper.hidden = false;

    const byIndex = new Map<number, Element>();
    for (const el of Array.from(svg.querySelectorAll(`[${SHAPE_ATTRIBUTE}]`))) byIndex.set(Number(el.getAttribute(SHAPE_ATTRIBUTE)), el);
    doc.shapes.forEach((_, i) => {
      const el = byIndex.get(i);
      if (el) this.targets.push({ el, shape: i, drawn: [], follow: doc.paintFollower(i, svg, el) });
    });
  }

  /** Writes the paths whose splines differ from what they were last written from. */
  private write(doc: SvgDocument): { written: number; skipped: SkippedShape[] } {
    let written = 0;
    const skipped: SkippedShape[] = [];
    for (const t of this.targets) {
      const splines = doc.splinesOf(t.shape);
      if (sameSplines(splines, t.drawn)) continue;
      remember(t, splines);
      if (!splines.every((s) => s.points.every(Number.isFinite))) {
        const shape = doc.shapes[t.shape];
        skipped.push({ element: `<${shape.tag}${shape.id ? ` id="${shape.id}"` : ''}>${shape.line ? ` at line ${shape.line}` : ''}`, reason: 'a coordinate is not a finite number' });
        t.el.setAttribute('d', '');
        continue;
      }
      t.el.setAttribute('d', doc.pathData(t.shape, this.format) ?? '');
      t.follow?.(doc.paintTransform(t.shape));
      written++;
    }
    return { written, skipped };
  }
}

/** Keeps a copy of the points a path is written from, in the arrays it had when the sizes match. */
function remember(t: Target, splines: readonly { points: ArrayLike<number> }[]): void {
  if (t.drawn.length !== splines.length) t.drawn = new Array<Float64Array>(splines.length);
  splines.forEach((s, k) => {
    const kept = t.drawn[k];
    if (kept?.length === s.points.length) kept.set(s.points);
    else t.drawn[k] = Float64Array.from(s.points);
  });
}

function sameSplines(splines: readonly { points: ArrayLike<number> }[], drawn: readonly Float64Array[]): boolean {
  if (splines.length !== drawn.length) return false;
  for (let k = 0; k < splines.length; k++) {
    const a = splines[k].points, b = drawn[k];
    if (a.length !== b.length) return false;
    for (let j = 0; j < a.length; j++) if (a[j] !== b[j]) return false;
  }
  return true;
}

/** Attributes holding numbers, lengths or lists of them, which the browser parses as 32-bit floats. */
const NUMERIC_ATTRIBUTES = new Set([
  'd', 'points', 'transform', 'gradientTransform', 'patternTransform', 'viewBox', 'x', 'y', 'width', 'height', 'r', 'rx', 'ry',
  'cx', 'cy', 'fx', 'fy', 'fr', 'x1', 'y1', 'x2', 'y2', 'offset', 'stroke-width', 'stroke-dasharray', 'stroke-dashoffset',
  'stroke-miterlimit', 'opacity', 'fill-opacity', 'stroke-opacity', 'stop-opacity', 'refX', 'refY', 'markerWidth', 'markerHeight',
  'font-size', 'stdDeviation', 'dx', 'dy', 'rotate',
]);
/** Largest finite 32-bit float. */
const FLOAT32_MAX = 3.4028234663852886e38;

/** A reference inside the file (`#id`) or embedded in it (a data: image). */
const LOCAL_REFERENCE = /^\s*(#|data:image\/)/i;

/** CSS with its references outside the file removed (url(…) to other places, @import). */
function localCSS(text: string): string {
  return text.replace(/@import[^;]*;?/gi, '').replace(/url\(\s*(['"]?)([^)'"]*)\1\s*\)/gi, (all, _q: string, target: string) => (LOCAL_REFERENCE.test(target) ? all : 'none'));
}

/**
 * One pass over the sanitised markup, before it enters the page:
 * - references to anything outside the file go (href attributes that are not `#id` or a data:
 *   image, url(…) to other places and @import in style attributes and style sheets), so opening
 *   a file fetches nothing;
 * - numeric attributes with a number a 32-bit float cannot hold go (the model leaves such shapes
 *   as they are and warns): the browser would refuse them with a console error and draw nothing of
 *   them anyway. The path data of shapes drawn from the splines is not read: it is rewritten next.
 */
function cleanMarkup(root: Element): void {
  for (const el of [root, ...Array.from(root.getElementsByTagName('*'))]) {
    const fromSplines = el.hasAttribute(SHAPE_ATTRIBUTE);
    for (const attr of Array.from(el.attributes)) {
      const name = attr.localName;
      if (name === 'href') {
        if (!LOCAL_REFERENCE.test(attr.value)) el.removeAttributeNode(attr);
      } else if (name === 'style') {
        if (/url\(|@import/i.test(attr.value)) attr.value = localCSS(attr.value);
      } else if (NUMERIC_ATTRIBUTES.has(name) && !(fromSplines && name === 'd')) {
        const numbers = attr.value.match(/[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?/g) ?? [];
        if (numbers.some((n) => !(Math.abs(Number(n)) <= FLOAT32_MAX))) el.removeAttributeNode(attr);
      }
    }
    if (el.localName === 'style' && el.textContent) el.textContent = localCSS(el.textContent);
  }
}
