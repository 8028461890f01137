import type { Matrix, SvgDocument } from '../../src/index.js';
import type { Spline } from '../../src/spline/spline.js';
import { IDENTITY, invert, isIdentity, multiply, translation } from '../../src/svg/matrix.js';
import type { Viewport } from './viewport.js';

const SVG_NS = 'http://www.w3.org/2000/svg';

/** A clip path the painter applies: one path in its own coordinates, and those → document space. */
interface Clip {
  path: Path2D;
  rule: CanvasFillRule;
  toDoc: Matrix;
}

/** One shape of the model as the browser would paint it, resolved once from its computed style. */
interface ShapeOp {
  shape: number;
  /** Document → the element's user space (undefined: they are the same). */
  toUser: Matrix | undefined;
  /** The element's user space → document space. */
  toDoc: Matrix;
  fill: string | null;
  fillRule: CanvasFillRule;
  stroke: string | null;
  width: number;
  cap: CanvasLineCap;
  join: CanvasLineJoin;
  miter: number;
  dash: number[];
  dashOffset: number;
  /** Opacities: fill-opacity and stroke-opacity times the element's opacity. */
  fillAlpha: number;
  strokeAlpha: number;
  strokeFirst: boolean;
  /** Clip paths from the outermost ancestor's to the element's own (all apply). */
  clips: readonly Clip[];
}

/** What the live painter draws, or why it cannot draw this markup as the browser does. */
export type LivePlan = { ops: ShapeOp[] } | { unsupported: string };

/** Elements whose content is not drawn where it stands (used by reference, or not graphics). */
const NOT_DRAWN = new Set([
  'defs', 'clipPath', 'mask', 'marker', 'pattern', 'linearGradient', 'radialGradient', 'filter', 'symbol', 'style', 'title', 'desc',
  'metadata', 'script', 'animate', 'animateTransform', 'animateMotion', 'animateColor', 'set', 'mpath', 'view', 'cursor', 'font', 'font-face',
]);

/** A transform attribute's matrix (identity when it has none). */
function ownTransform(el: Element): Matrix {
  const list = (el as SVGGraphicsElement).transform?.baseVal;
  const m = list && list.numberOfItems > 0 ? list.consolidate()?.matrix : null;
  return m ? { a: m.a, b: m.b, c: m.c, d: m.d, e: m.e, f: m.f } : { ...IDENTITY };
}

/** A CSS color the canvas paints as the browser does ('none' and references → null). */
function solidPaint(value: string): string | null | undefined {
  if (value === 'none') return null;
  if (/^(rgb|rgba|hsl|hsla)\(|^#|^[a-z]+$/i.test(value) && !value.startsWith('url(')) return value;
  return undefined; // a paint server: not drawn by this painter
}

function num(value: string, fallback: number): number {
  const v = parseFloat(value);
  return Number.isFinite(v) ? v : fallback;
}

/**
 * Resolves what the browser would paint for the mounted markup under `svg` as canvas operations,
 * from the browser's own computed styles: model shapes (elements in `shapeOf`) filled and stroked
 * with solid colours, with their opacities, fill rules, caps, joins, miters, dashes and paint
 * order, in groups with transforms and clip paths (one path or `use` of a path each). Anything
 * else the drawing shows (gradients, patterns, masks, filters, markers, group opacity, text,
 * images, shapes not drawn from the model) makes the plan unsupported: the browser's own drawing
 * is used then.
 */
export function planLivePainting(svg: SVGSVGElement, doc: SvgDocument, shapeOf: Map<Element, number>, byId: (id: string) => Element | null): LivePlan {
  const ops: ShapeOp[] = [];
  const clipCache = new Map<string, Clip | string>();

  /** The clip a `clip-path` value names, in the space of an element whose user space maps to the document by `toDoc`. */
  const clipFor = (value: string, toDoc: Matrix): Clip | string => {
    const id = /^url\(\s*["']?#([^"')]+)["']?\s*\)$/.exec(value)?.[1];
    const el = id ? byId(id) : null;
    if (!el || el.localName !== 'clipPath') return `clip-path ${value}`;
    if (el.getAttribute('clipPathUnits') === 'objectBoundingBox') return 'a clip path in bounding-box units';
    let local = clipCache.get(id!);
    if (local === undefined) {
      local = clipShape(el);
      clipCache.set(id!, local);
    }
    if (typeof local === 'string') return local;
    return { path: local.path, rule: local.rule, toDoc: multiply(toDoc, local.toDoc) };
  };

  const visit = (parent: Element, clips: readonly Clip[]): string | null => {
    for (let el = parent.firstElementChild; el; el = el.nextElementSibling) {
      if (el.namespaceURI !== SVG_NS || NOT_DRAWN.has(el.localName)) continue;
      const cs = getComputedStyle(el);
      if (cs.display === 'none') continue;
      if (cs.mask !== 'none' || cs.filter !== 'none' || cs.mixBlendMode !== 'normal') return `${el.localName} with a mask, filter or blend mode`;
      const shape = shapeOf.get(el);
      let inner = clips;
      if (cs.clipPath !== 'none') {
        const toDoc = shape !== undefined ? doc.shapes[shape].transform : docTransformOf(el, svg);
        const clip = clipFor(cs.clipPath, toDoc);
        if (typeof clip === 'string') return clip;
        inner = [...clips, clip];
      }
      if (el.localName === 'g' || el.localName === 'a') {
        if (num(cs.opacity, 1) < 1) return 'a group with opacity';
        const why = visit(el, inner);
        if (why) return why;
        continue;
      }
      if (shape === undefined) return `<${el.localName}> (not a shape of the model)`;
      const op = shapeOp(shape, cs, inner);
      if (typeof op === 'string') return op;
      if (op) ops.push(op);
    }
    return null;
  };

  const shapeOp = (shape: number, cs: CSSStyleDeclaration, clips: readonly Clip[]): ShapeOp | string | null => {
    if (cs.visibility !== 'visible') return null;
    if (cs.markerStart !== 'none' || cs.markerMid !== 'none' || cs.markerEnd !== 'none') return 'markers';
    if (cs.vectorEffect !== 'none') return 'vector-effect';
    const fill = solidPaint(cs.fill), stroke = solidPaint(cs.stroke);
    if (fill === undefined || stroke === undefined) return 'a gradient or pattern paint';
    const opacity = num(cs.opacity, 1);
    if (opacity < 1 && fill && stroke) return 'opacity on a filled and stroked shape';
    if (/%|em|ex/.test(cs.strokeWidth)) return 'a stroke width in relative units';
    const join = cs.strokeLinejoin;
    if (join !== 'miter' && join !== 'round' && join !== 'bevel') return `stroke-linejoin ${join}`;
    let dash: number[] = [];
    if (cs.strokeDasharray !== 'none') {
      if (/%|em|ex/.test(cs.strokeDasharray)) return 'a dash array in relative units';
      dash = cs.strokeDasharray.split(/[\s,]+/).map((v) => parseFloat(v));
      // The browser draws a solid stroke for a dash array that sums to zero or has a negative value.
      if (dash.some((v) => !(v >= 0)) || dash.every((v) => v === 0)) dash = [];
    }
    const s = doc.shapes[shape];
    const toUser = invert(s.transform);
    if (!toUser) return null; // a collapsed element draws nothing
    return {
      shape,
      toUser: isIdentity(toUser) ? undefined : toUser,
      toDoc: s.transform,
      fill,
      fillRule: cs.fillRule === 'evenodd' ? 'evenodd' : 'nonzero',
      stroke: num(cs.strokeWidth, 1) > 0 ? stroke : null,
      width: num(cs.strokeWidth, 1),
      cap: cs.strokeLinecap as CanvasLineCap,
      join: join as CanvasLineJoin,
      miter: num(cs.strokeMiterlimit, 4),
      dash,
      dashOffset: num(cs.strokeDashoffset, 0),
      fillAlpha: opacity * num(cs.fillOpacity, 1),
      strokeAlpha: opacity * num(cs.strokeOpacity, 1),
      strokeFirst: strokeFirst(cs.paintOrder),
      clips,
    };
  };

  const rootStyle = getComputedStyle(svg);
  if (rootStyle.mask !== 'none' || rootStyle.filter !== 'none' || rootStyle.clipPath !== 'none' || num(rootStyle.opacity, 1) < 1) return { unsupported: 'the drawing has a mask, filter, clip or opacity of its own' };
  const why = visit(svg, []);
  return why ? { unsupported: why } : { ops };
}

/** Whether `paint-order` strokes before it fills (unlisted parts follow in the order fill, stroke, markers). */
function strokeFirst(order: string): boolean {
  const parts = order.trim().split(/\s+/);
  const f = parts.indexOf('fill'), s = parts.indexOf('stroke');
  return s >= 0 && (f < 0 || s < f);
}

/** An element's user space → document space (the root's user space), from the transform attributes on the way. */
function docTransformOf(el: Element, root: Element): Matrix {
  const chain: Element[] = [];
  for (let e: Element | null = el; e && e !== root; e = e.parentElement) chain.unshift(e);
  return chain.reduce<Matrix>((m, e) => multiply(m, ownTransform(e)), IDENTITY);
}

/** A clipPath's content as one path in its own coordinates, or why the painter cannot use it. */
function clipShape(clip: Element): { path: Path2D; rule: CanvasFillRule; toDoc: Matrix } | string {
  const cs = getComputedStyle(clip);
  if (cs.clipPath !== 'none') return 'a clip path with a clip path';
  const children = Array.from(clip.children).filter((c) => c.namespaceURI === SVG_NS && !NOT_DRAWN.has(c.localName) && getComputedStyle(c).display !== 'none');
  if (children.length !== 1) return 'a clip path of several shapes';
  let shape = children[0], m = multiply(ownTransform(clip), ownTransform(shape));
  const ruleOf = getComputedStyle(shape).clipRule;
  if (shape.localName === 'use') {
    const href = shape.getAttribute('href') ?? shape.getAttributeNS('http://www.w3.org/1999/xlink', 'href') ?? '';
    const ref = href.startsWith('#') ? (shape.getRootNode() as ShadowRoot | Document).getElementById(href.slice(1)) : null;
    if (!ref) return 'a clip path using a missing element';
    if (getComputedStyle(ref).clipRule !== ruleOf) return 'a clip path whose shape sets its own clip rule';
    const u = shape as SVGUseElement;
    m = multiply(m, translation(u.x.baseVal.value, u.y.baseVal.value));
    shape = ref;
    m = multiply(m, ownTransform(shape));
  }
  if (shape.localName !== 'path') return `a clip path of a <${shape.localName}>`;
  if (getComputedStyle(shape).clipPath !== 'none') return 'a clip path with a clipped shape';
  return { path: new Path2D(shape.getAttribute('d') ?? ''), rule: ruleOf === 'evenodd' ? 'evenodd' : 'nonzero', toDoc: m };
}

/** Adds splines[first … first + count) to `path`, mapped by `m` (document → user space) when given. */
function addSplines(path: Path2D, splines: readonly Spline[], first: number, count: number, m: Matrix | undefined): void {
  for (let s = first; s < first + count; s++) {
    const { closed, points: p } = splines[s];
    const n = p.length / 2;
    if (n === 0) continue;
    const segs = n <= 1 ? 0 : closed ? n / 3 : (n - 1) / 3;
    const x = (i: number) => (m ? m.a * p[2 * i] + m.c * p[2 * i + 1] + m.e : p[2 * i]);
    const y = (i: number) => (m ? m.b * p[2 * i] + m.d * p[2 * i + 1] + m.f : p[2 * i + 1]);
    path.moveTo(x(0), y(0));
    for (let k = 0; k < segs; k++) {
      const e = 3 * k + 3 >= n ? 0 : 3 * k + 3;
      path.bezierCurveTo(x(3 * k + 1), y(3 * k + 1), x(3 * k + 2), y(3 * k + 2), x(e), y(e));
    }
    if (closed) path.closePath();
  }
}

/**
 * Paints a plan's shapes from `doc`'s splines into a 2D canvas covering the view (device pixels,
 * `ratio` per CSS pixel), as the browser paints the markup: one Path2D per shape from its control
 * points, no path text to write or parse, no style, layout or paint of the document tree.
 * Consecutive shapes under the same clip paths share one clip.
 */
export function paintLive(ctx: CanvasRenderingContext2D, plan: { ops: ShapeOp[] }, doc: SvgDocument, viewport: Viewport, ratio: number): number {
  const { cx, cy, scale, width, height } = viewport;
  const k = ratio * scale;
  const view: Matrix = { a: k, b: 0, c: 0, d: k, e: ratio * (width / 2 - cx * scale), f: ratio * (height / 2 - cy * scale) };
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.clearRect(0, 0, ctx.canvas.width, ctx.canvas.height);
  let clips: readonly Clip[] = [];
  let saved = 0;
  const splines = doc.splines;
  for (const op of plan.ops) {
    if (op.clips !== clips) {
      if (!sameClips(op.clips, clips)) {
        while (saved > 0) {
          ctx.restore();
          saved--;
        }
        for (const c of op.clips) {
          ctx.save();
          saved++;
          const m = multiply(view, c.toDoc);
          ctx.setTransform(m.a, m.b, m.c, m.d, m.e, m.f);
          ctx.clip(c.path, c.rule);
        }
      }
      clips = op.clips;
    }
    const shape = doc.shapes[op.shape];
    // A shape with a coordinate that is not finite is left out, as the browser's drawing leaves it.
    if (!allFinite(splines, shape.firstSpline, shape.splineCount)) continue;
    const path = new Path2D();
    addSplines(path, splines, shape.firstSpline, shape.splineCount, op.toUser);
    const m = multiply(view, op.toDoc);
    ctx.setTransform(m.a, m.b, m.c, m.d, m.e, m.f);
    if (op.strokeFirst) strokeOp(ctx, op, path);
    if (op.fill && op.fillAlpha > 0) {
      ctx.globalAlpha = op.fillAlpha;
      ctx.fillStyle = op.fill;
      ctx.fill(path, op.fillRule);
    }
    if (!op.strokeFirst) strokeOp(ctx, op, path);
  }
  while (saved > 0) {
    ctx.restore();
    saved--;
  }
  ctx.globalAlpha = 1;
  return plan.ops.length;
}

function strokeOp(ctx: CanvasRenderingContext2D, op: ShapeOp, path: Path2D): void {
  if (!op.stroke || op.strokeAlpha <= 0) return;
  ctx.globalAlpha = op.strokeAlpha;
  ctx.strokeStyle = op.stroke;
  ctx.lineWidth = op.width;
  ctx.lineCap = op.cap;
  ctx.lineJoin = op.join;
  ctx.miterLimit = op.miter;
  ctx.setLineDash(op.dash);
  ctx.lineDashOffset = op.dashOffset;
  ctx.stroke(path);
}

/** Whether every control point of splines[first … first + count) is finite. */
export function allFinite(splines: readonly Spline[], first: number, count: number): boolean {
  for (let k = first; k < first + count; k++) {
    const p = splines[k].points;
    for (let j = 0; j < p.length; j++) if (!Number.isFinite(p[j])) return false;
  }
  return true;
}

function sameClips(a: readonly Clip[], b: readonly Clip[]): boolean {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) {
    const p = a[i], q = b[i];
    if (p.path !== q.path || p.rule !== q.rule) return false;
    const m = p.toDoc, n = q.toDoc;
    if (m.a !== n.a || m.b !== n.b || m.c !== n.c || m.d !== n.d || m.e !== n.e || m.f !== n.f) return false;
  }
  return true;
}
