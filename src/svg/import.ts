import { SplinekitError } from '../core/errors.js';
import { SplineSet, type ContinuityOptions } from '../spline/spline-set.js';
import type { Spline } from '../spline/spline.js';
import { SvgDocument, type ShapeSource, type SvgShape, type SvgWarning } from './document.js';
import { expandEntities } from './entities.js';
import { parseXML } from './xml.js';
import { IDENTITY, multiply, parseTransform, transformPoints, translation, viewBoxTransform, type Matrix } from './matrix.js';
import { pathDataToSplines, type RawSpline } from './path-data.js';
import { circlePath, ellipseElementPath, length, linePath, polyPath, rectPath, type Viewport } from './shapes.js';
import { ROOT_STYLE, StyleSheet, declarationsOf, inherit, resolve, type StyleContext } from './style.js';

/** Options of {@link parseSVG}; every field is optional. */
export interface ParseOptions {
  /** Name of the input in error messages (e.g. the file name). Default 'SVG'. */
  name?: string;
  /** Inputs larger than this many bytes are refused with SplinekitError('file-too-large'). Default 32 MiB. */
  maxBytes?: number;
  /** Tolerances for detecting continuity at junctions (relative to the drawing's size). */
  continuity?: ContinuityOptions;
  /**
   * Elements drawn at most, counting every copy a `<use>` makes; a file over it (e.g. `<use>`s that
   * double at every level) is refused with SplinekitError('too-complex'). Default 200,000.
   */
  maxElements?: number;
  /** Elements nested deeper than this are refused with SplinekitError('too-complex'). Default 1,000. */
  maxDepth?: number;
}

/** The largest input `parseSVG` accepts by default: 32 MiB. */
export const DEFAULT_MAX_BYTES = 32 * 1024 * 1024;
/** Default of {@link ParseOptions.maxElements}. */
export const DEFAULT_MAX_ELEMENTS = 200_000;
/** Default of {@link ParseOptions.maxDepth}. */
export const DEFAULT_MAX_DEPTH = 1_000;

const SVG_NS = 'http://www.w3.org/2000/svg';
const XLINK_NS = 'http://www.w3.org/1999/xlink';
const SHAPES = new Set(['path', 'rect', 'circle', 'ellipse', 'line', 'polyline', 'polygon']);
const CONTAINERS = new Set(['g', 'a', 'switch', 'svg']);
/** Elements that never draw by themselves (they are referenced, or are metadata). */
const NOT_DRAWN = new Set([
  'defs', 'symbol', 'clipPath', 'mask', 'marker', 'pattern', 'linearGradient', 'radialGradient', 'filter',
  'style', 'title', 'desc', 'metadata', 'script', 'view', 'cursor', 'font', 'font-face', 'color-profile',
]);
/** Drawn content the spline model does not carry: kept in the markup as it is, with a warning. */
const KEPT = new Set(['text', 'image', 'foreignObject', 'video', 'audio', 'iframe', 'canvas', 'animate', 'animateMotion', 'animateTransform', 'set']);

/**
 * Reads an SVG into splines. Every path command and basic shape becomes cubic Bézier splines in
 * document space, with continuity detected at each junction; `use`/`defs`, nested transforms and
 * nested `svg` viewports are resolved; content the model cannot carry is kept and reported in
 * `warnings`. Bad input throws a SplinekitError whose message names the problem and where it is.
 * Requires `await init()`.
 */
export function parseSVG(input: string | Uint8Array | ArrayBuffer, options: ParseOptions = {}): SvgDocument {
  const name = options.name ?? 'SVG';
  const decoded = decode(input, name, options.maxBytes ?? DEFAULT_MAX_BYTES);
  const { text, droppedExternal } = expandEntities(decoded, name);
  const dom = parseXML(text, name);
  const root = dom.documentElement!;
  if (root.localName !== 'svg') {
    throw new SplinekitError('invalid-svg', `${name}: the root element is <${root.nodeName}>, not <svg>`);
  }
  const builder = new Builder(dom, name, options.maxElements ?? DEFAULT_MAX_ELEMENTS, options.maxDepth ?? DEFAULT_MAX_DEPTH);
  builder.checkSize(root);
  for (const entity of droppedExternal) {
    builder.warn(`entity:${entity}`, () => `the external entity &${entity}; is not loaded (external entities never are): its references are left empty`);
  }
  const { width, height, viewBox } = rootViewport(root, name);
  builder.viewports.push(viewBox ? { width: viewBox[2], height: viewBox[3] } : { width, height });
  builder.walk(root, IDENTITY, ROOT_STYLE, true);

  const set = SplineSet.from(builder.raw);
  let splines: Spline[];
  let bounds: [number, number, number, number] | null;
  try {
    bounds = set.totalBounds();
    const size = bounds ? Math.hypot(bounds[2] - bounds[0], bounds[3] - bounds[1]) : 1;
    const tags = set.classify(size, options.continuity);
    splines = builder.raw.map((r, i) => ({ closed: r.closed, points: r.points, continuity: tags[i] }));
  } finally {
    set.dispose();
  }
  const fallback = bounds ?? [0, 0, 1, 1];
  return new SvgDocument({
    dom,
    splines,
    shapes: builder.shapes,
    sources: builder.sources,
    warnings: builder.warningList(),
    width: width || viewBox?.[2] || fallback[2] - fallback[0] || 1,
    height: height || viewBox?.[3] || fallback[3] - fallback[1] || 1,
    viewBox,
    bounds,
  });
}

function decode(input: string | Uint8Array | ArrayBuffer, name: string, maxBytes: number): string {
  const bytes = typeof input === 'string' ? null : input instanceof Uint8Array ? input : new Uint8Array(input);
  const size = bytes ? bytes.length : (input as string).length; // a string's UTF-16 length is a lower bound of its bytes
  if (size > maxBytes) {
    throw new SplinekitError('file-too-large', `${name}: ${(size / 2 ** 20).toFixed(1)} MiB is larger than the ${(maxBytes / 2 ** 20).toFixed(0)} MiB limit`);
  }
  if (bytes && bytes.length >= 2 && bytes[0] === 0x1f && bytes[1] === 0x8b) {
    throw new SplinekitError('invalid-svg', `${name}: gzip-compressed data (.svgz): decompress it first`);
  }
  const text = bytes ? new TextDecoder('utf-8').decode(bytes) : (input as string);
  if (text.trim() === '') throw new SplinekitError('invalid-svg', `${name}: the file is empty`);
  // eslint-disable-next-line no-control-regex -- control characters are what tells binary data from text
  if (/[\u0000-\u0008\u000e-\u001f]/.test(text.slice(0, 4096))) {
    throw new SplinekitError('invalid-svg', `${name}: binary data, not an SVG (XML) file`);
  }
  return text;
}

const UNITS: Record<string, number> = { '': 1, px: 1, pt: 4 / 3, pc: 16, mm: 96 / 25.4, cm: 96 / 2.54, in: 96, em: 16, ex: 8 };

function rootViewport(root: Element, name: string) {
  let viewBox: [number, number, number, number] | null = null;
  const vb = root.getAttribute('viewBox');
  if (vb && vb.trim() !== '') {
    const v = vb.trim().split(/[\s,]+/).map(Number);
    if (v.length === 4 && v.every(Number.isFinite) && v[2] > 0 && v[3] > 0) viewBox = v as [number, number, number, number];
  }
  const dim = (attr: string): number => {
    const raw = root.getAttribute(attr);
    if (!raw || raw.trim().endsWith('%')) return 0;
    const m = /^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*([a-z]*)\s*$/.exec(raw);
    if (!m || !(m[2] in UNITS)) throw new SplinekitError('invalid-svg', `${name}: <svg ${attr}="${raw}"> is not a length`);
    const v = parseFloat(m[1]) * UNITS[m[2]];
    return Number.isFinite(v) && v > 0 ? v : 0;
  };
  return { width: dim('width'), height: dim('height'), viewBox };
}

/** Line of an element in its file (xmldom's locator), 0 if unknown. */
function lineOf(el: Element): number {
  return (el as unknown as { lineNumber?: number }).lineNumber ?? 0;
}

/** A `<use>`'s reference: href, or the older xlink:href. */
function hrefOf(el: Element): string | null {
  return el.getAttribute('href') ?? el.getAttributeNS(XLINK_NS, 'href') ?? el.getAttribute('xlink:href');
}

function describe(el: Element): string {
  const id = el.getAttribute('id');
  const line = lineOf(el);
  return `<${el.localName}${id ? ` id="${id}"` : ''}>${line ? ` at line ${line}` : ''}`;
}

class Builder {
  readonly raw: RawSpline[] = [];
  readonly shapes: SvgShape[] = [];
  readonly sources: ShapeSource[] = [];
  readonly viewports: Viewport[] = [];
  private readonly sheet = new StyleSheet();
  private readonly ids = new Map<string, Element>();
  private readonly uses: { use: Element; ref: Element }[] = [];
  private readonly warnings = new Map<string, { message: (n: number) => string; count: number }>();
  private readonly svgRoot: boolean;
  /** The current nesting depth of walk(), `<use>` references included. */
  private depth = 0;

  constructor(
    dom: Document,
    private readonly name: string,
    private readonly maxElements: number,
    private readonly maxDepth: number,
  ) {
    const root = dom.documentElement!;
    this.svgRoot = root.namespaceURI === SVG_NS;
    const all = root.getElementsByTagName('*');
    for (let i = 0; i < all.length; i++) {
      const el = all[i];
      const id = el.getAttribute('id');
      if (id && !this.ids.has(id)) this.ids.set(id, el);
      if (el.localName === 'style' && this.isSvg(el)) this.sheet.add(el.textContent ?? '');
    }
    for (const selector of this.sheet.unsupportedSelectors) {
      this.warn(`css:${selector}`, () => `CSS selector "${selector}" is not supported: its rules are ignored when painting (kept in the file)`);
    }
  }

  /**
   * Refuses a document that would draw more than `maxElements` elements (every `<use>` copy
   * counted) or nest deeper than `maxDepth`, before anything is drawn: the count per element is
   * memoised, so `<use>`s that double at each of 24 levels are found in microseconds, not after
   * millions of copies.
   */
  checkSize(root: Element): void {
    const counts = new Map<Element, number>();
    const visiting = new Set<Element>();
    const count = (el: Element, depth: number): number => {
      if (depth > this.maxDepth) {
        this.tooDeep(el);
      }
      const known = counts.get(el);
      if (known !== undefined) return known;
      if (visiting.has(el)) return 0; // a <use> cycle: walk() names it
      visiting.add(el);
      let n = 0;
      const tag = el.localName;
      if (this.isSvg(el) && !NOT_DRAWN.has(tag)) {
        n = 1;
        if (tag === 'use') {
          const ref = this.referenced(el);
          if (ref && ref.localName === 'symbol') n += this.countChildren(ref, depth, count);
          else if (ref) n += count(ref, depth + 1);
        } else if (CONTAINERS.has(tag)) n += this.countChildren(el, depth, count);
      }
      visiting.delete(el);
      counts.set(el, n);
      if (n > this.maxElements) {
        throw new SplinekitError(
          'too-complex',
          `${this.name}: ${describe(el)} draws more than ${this.maxElements.toLocaleString('en-US')} elements (counting the copies <use> makes): refused`,
        );
      }
      return n;
    };
    count(root, 1);
  }

  private countChildren(el: Element, depth: number, count: (el: Element, depth: number) => number): number {
    let n = 0;
    for (let c = el.firstChild; c; c = c.nextSibling) if (c.nodeType === 1) n += count(c as Element, depth + 1);
    return n;
  }

  /** The element a `<use>` refers to in this file, if any. */
  private referenced(use: Element): Element | undefined {
    const href = hrefOf(use);
    return href?.startsWith('#') ? this.ids.get(href.slice(1)) : undefined;
  }

  private tooDeep(el: Element): never {
    throw new SplinekitError('too-complex', `${this.name}: ${describe(el)} is nested deeper than ${this.maxDepth.toLocaleString('en-US')} levels: refused`);
  }

  private isSvg(el: Element): boolean {
    return this.svgRoot ? el.namespaceURI === SVG_NS : !el.prefix;
  }

  warn(code: string, message: (count: number) => string): void {
    const w = this.warnings.get(code);
    if (w) w.count++;
    else this.warnings.set(code, { message, count: 1 });
  }

  warningList(): SvgWarning[] {
    return [...this.warnings].map(([code, w]) => ({ code, message: w.message(w.count), count: w.count }));
  }

  private fail(el: Element, reason: string): never {
    throw new SplinekitError('invalid-svg', `${this.name}: ${describe(el)}: ${reason}`);
  }

  private transformOf(el: Element): Matrix {
    const t = el.getAttribute('transform');
    if (!t) return IDENTITY;
    try {
      return parseTransform(t);
    } catch (err) {
      this.fail(el, `bad transform "${t}": ${err instanceof Error ? err.message : String(err)}`);
    }
  }

  walk(el: Element, parentCtm: Matrix, parentStyle: StyleContext, isRoot = false): void {
    if (!this.isSvg(el)) return; // editor metadata (sodipodi:namedview, rdf, …)
    // checkSize() counted the elements; depth is checked again here because a subtree it counted
    // once near the root can be drawn again, through <use>, much deeper.
    if (this.depth >= this.maxDepth) {
      this.tooDeep(el);
    }
    this.depth++;
    try {
      this.walkElement(el, parentCtm, parentStyle, isRoot);
    } finally {
      this.depth--;
    }
  }

  private walkElement(el: Element, parentCtm: Matrix, parentStyle: StyleContext, isRoot: boolean): void {
    const tag = el.localName;
    if (NOT_DRAWN.has(tag)) return;
    if (KEPT.has(tag)) {
      this.warn(`kept:${tag}`, (n) => `${n} <${tag}> element${n > 1 ? 's' : ''} kept as ${n > 1 ? 'they are' : 'it is'}: the spline model does not carry ${tag}`);
      return;
    }
    const style = inherit(parentStyle, declarationsOf(el, this.sheet));
    let ctm = multiply(parentCtm, this.transformOf(el));
    if (SHAPES.has(tag)) return this.shape(el, tag, ctm, style);
    if (tag === 'use') return this.use(el, ctm, style);
    if (!CONTAINERS.has(tag)) {
      this.warn(`unknown:${tag}`, (n) => `${n} unknown <${tag}> element${n > 1 ? 's' : ''} ignored (kept in the file)`);
      return;
    }
    let pushed = false;
    if (tag === 'svg' && !isRoot) {
      const vp = this.viewports[this.viewports.length - 1];
      const w = length(el, 'width', vp, 'x', vp.width), h = length(el, 'height', vp, 'y', vp.height);
      ctm = multiply(ctm, translation(length(el, 'x', vp, 'x'), length(el, 'y', vp, 'y')));
      const vb = el.getAttribute('viewBox')?.trim().split(/[\s,]+/).map(Number);
      if (vb && vb.length === 4 && vb.every(Number.isFinite) && vb[2] > 0 && vb[3] > 0) {
        ctm = multiply(ctm, viewBoxTransform(vb as [number, number, number, number], w, h, el.getAttribute('preserveAspectRatio') ?? undefined));
        this.viewports.push({ width: vb[2], height: vb[3] });
      } else this.viewports.push({ width: w, height: h });
      pushed = true;
    }
    if (tag === 'switch') {
      // The first child whose conditions hold; splinekit supports no required extensions.
      for (let c = el.firstChild; c; c = c.nextSibling) {
        if (c.nodeType !== 1) continue;
        const child = c as Element;
        if (!this.isSvg(child) || child.hasAttribute('requiredExtensions')) continue;
        this.walk(child, ctm, style);
        break;
      }
    } else {
      for (let c = el.firstChild; c; c = c.nextSibling) if (c.nodeType === 1) this.walk(c as Element, ctm, style);
    }
    if (pushed) this.viewports.pop();
  }

  private use(el: Element, ctm: Matrix, style: StyleContext): void {
    const ref = this.referenced(el);
    if (!ref) {
      this.warn('use:missing', (n) => `${n} <use> element${n > 1 ? 's' : ''} reference${n > 1 ? '' : 's'} nothing in this file (external or missing ids): nothing drawn for ${n > 1 ? 'them' : 'it'}`);
      return;
    }
    if (this.uses.some((u) => u.use === el || u.ref === ref)) this.fail(el, `a <use> cycle through "${hrefOf(el)}"`);
    const vp = this.viewports[this.viewports.length - 1];
    let m = multiply(ctm, translation(length(el, 'x', vp, 'x'), length(el, 'y', vp, 'y')));
    this.uses.push({ use: el, ref });
    try {
      if (ref.localName === 'symbol') {
        const w = length(el, 'width', vp, 'x', vp.width), h = length(el, 'height', vp, 'y', vp.height);
        const vb = ref.getAttribute('viewBox')?.trim().split(/[\s,]+/).map(Number);
        if (vb && vb.length === 4 && vb.every(Number.isFinite) && vb[2] > 0 && vb[3] > 0) {
          m = multiply(m, viewBoxTransform(vb as [number, number, number, number], w, h, ref.getAttribute('preserveAspectRatio') ?? undefined));
        }
        const symbolStyle = inherit(style, declarationsOf(ref, this.sheet));
        for (let c = ref.firstChild; c; c = c.nextSibling) if (c.nodeType === 1) this.walk(c as Element, m, symbolStyle);
      } else {
        this.walk(ref, m, style);
      }
    } finally {
      this.uses.pop();
    }
  }

  private shape(el: Element, tag: string, ctm: Matrix, style: StyleContext): void {
    const vp = this.viewports[this.viewports.length - 1];
    const where = `${this.name}: ${describe(el)}`;
    let d: string;
    try {
      switch (tag) {
        case 'path': d = el.getAttribute('d') ?? ''; break;
        case 'rect': d = rectPath(el, vp); break;
        case 'circle': d = circlePath(el, vp); break;
        case 'ellipse': d = ellipseElementPath(el, vp); break;
        case 'line': d = linePath(el, vp); break;
        default:
          d = polyPath(el, tag === 'polygon', (message) => this.warn(`points:${describe(el)}`, () => `${describe(el)}: ${message}`));
      }
    } catch (err) {
      this.fail(el, err instanceof Error ? err.message : String(err));
    }
    const raw = d.trim() === '' ? [] : pathDataToSplines(d, where);
    const resolved = resolve(style);
    for (const attr of ['clip-path', 'mask', 'filter', 'marker-start', 'marker-mid', 'marker-end']) {
      const v = el.getAttribute(attr) ?? (el.getAttribute('style') ?? '').match(new RegExp(`${attr}\\s*:\\s*url`))?.[0];
      if (v && v !== 'none') this.warn(`ref:${attr}`, (n) => `${n} shape${n > 1 ? 's' : ''} use${n > 1 ? '' : 's'} ${attr}: kept as it is, not deformed with the splines`);
    }
    if (resolved.fill.startsWith('url(') || resolved.stroke.startsWith('url(')) {
      this.warn('paint-server', (n) => `${n} shape${n > 1 ? 's are' : ' is'} painted with a gradient or pattern: a deformed shape gets its own copy that follows it (the affine map closest to its deformation)`);
    }
    for (const r of raw) transformPoints(ctm, r.points);
    if (!raw.every((r) => r.points.every(Number.isFinite))) {
      // Finite path data under a transform that overflows it (e.g. scale(2) of 1e308): nothing a
      // browser can draw either. The element stays in the file; the rest of the drawing imports.
      this.warn(`overflow:${describe(el)}`, () => `${describe(el)}: its coordinates overflow under its transform: skipped (kept in the file)`);
      return;
    }
    const original: Float64Array[] = [];
    const first = this.raw.length;
    for (const r of raw) {
      original.push(r.points.slice());
      this.raw.push(r);
    }
    const id = el.getAttribute('id');
    this.shapes.push({
      tag,
      id: this.uses.length ? null : id,
      line: lineOf(el),
      firstSpline: first,
      splineCount: raw.length,
      transform: ctm,
      style: resolved,
      via: this.uses.map((u) => u.use.getAttribute('id') ?? 'use'),
    });
    this.sources.push({ uses: [...this.uses], element: el, original });
  }
}
