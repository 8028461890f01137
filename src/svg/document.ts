import { XMLSerializer } from '@xmldom/xmldom';
import { SplinekitError } from '../core/errors.js';
import { CONTINUITY_KINDS, cloneSpline, segmentCount, type ContinuityKind, type ContinuityTag, type Spline } from '../spline/spline.js';
import { IDENTITY, invert, isIdentity, transformPoints, type Matrix } from './matrix.js';
import { findById, fitAffine, paintFollower, splineBounds } from './paint-follow.js';
import { formatNumber, splinesToPathData } from './path-data.js';
import type { ResolvedStyle } from './style.js';
import { parseXML } from './xml.js';

/** Something the model keeps as is (or could not carry), reported once per kind. */
export interface SvgWarning {
  /** Machine-readable kind, e.g. 'paint-server'; one warning per kind. */
  code: string;
  /** What was kept or dropped, for people (names the first element it happened to). */
  message: string;
  /** How many times this kind occurred in the file. */
  count: number;
}

/** One drawn instance of a shape element (a `use` of a shape gives one more instance). */
export interface SvgShape {
  /** Element name in the file: 'path', 'rect', 'circle', 'ellipse', 'line', 'polyline', 'polygon'. */
  tag: string;
  /** The element's `id` attribute, or null. */
  id: string | null;
  /** Line of the element in the file (1-based), 0 if unknown. */
  line: number;
  /** This shape's splines are splines[firstSpline … firstSpline + splineCount). */
  firstSpline: number;
  /** Number of splines this shape owns (a path with several subpaths has several). */
  splineCount: number;
  /** The element's user space → document space (its own transform and its ancestors'). */
  transform: Matrix;
  /** The paint the shape is drawn with, resolved through CSS and inheritance. */
  style: ResolvedStyle;
  /** Ids (or tag names) of the `use` elements this instance was drawn through, outermost first. */
  via: string[];
}

/** Counts `splinekit info` reports. */
export interface SvgStats {
  /** Drawn shape instances (`shapes.length`). */
  elements: number;
  /** Splines over all shapes. */
  splines: number;
  /** Cubic segments over all splines. */
  segments: number;
  /** Number of junctions with each continuity kind. */
  continuity: Record<ContinuityKind, number>;
  /** Occurrences over all warnings (the sum of their `count`). */
  warnings: number;
}

/** The JSON schema shared by the CLI commands (`splinekit info --json`, skin, …). */
export interface SplinesJSON {
  /** The splines in document order. */
  splines: {
    /** Whether the spline is closed (3n points) or open (3n+1). */
    closed: boolean;
    /** Control points in document space as [x, y] pairs. */
    points: [number, number][];
    /** The kind of each junction's continuity tag. */
    continuity: ContinuityKind[];
  }[];
}

/** Options of {@link SvgDocument.toSVG}. */
export interface ExportOptions {
  /**
   * 'changed' (default) rewrites only shapes whose geometry differs from the file, so untouched
   * markup stays byte-for-byte; 'all' rewrites every shape as a `<path>` from the splines.
   */
  rewrite?: 'changed' | 'all';
  /**
   * Mark every rewritten shape with data-splinekit-shape="<index into shapes>", so a page can find
   * the element to update when the splines move (see skin/puppet.ts).
   */
  tagShapes?: boolean;
}

/** The attribute `tagShapes` writes. */
export const SHAPE_ATTRIBUTE = 'data-splinekit-shape';

/** Where each shape came from in the retained markup (kept out of the public shape record). */
export interface ShapeSource {
  /** The `use` elements it was drawn through (outermost first) with the element each references. */
  uses: { use: Element; ref: Element }[];
  /** The shape element itself. */
  element: Element;
  /** The splines as imported, to tell changed geometry from unchanged. */
  original: Float64Array[];
}

/**
 * An {@link SvgDocument} as plain, structured-clonable data (strings, numbers, plain objects and
 * typed arrays, no DOM), to hand a document from a Web Worker to the page: `toTransfer()` on one
 * side, `SvgDocument.fromTransfer()` on the other. Its fields are an implementation detail: only
 * pass it between the two calls of the same splinekit version.
 */
export interface SvgDocumentTransfer {
  /** The retained markup, serialized (internal entities already expanded). */
  markup: string;
  /**
   * The splines, packed into a few arrays (cloning a hundred thousand small objects costs the
   * receiving page more than the parse it saves): spline k's points are
   * points[pointEnds[k-1] … pointEnds[k]) (0 for k = 0), its tags tags*[tagEnds[k-1] … tagEnds[k]).
   */
  splines: {
    /** Every spline's points, in document order. */
    points: Float64Array;
    /** End of each spline's points in `points`. */
    pointEnds: Uint32Array;
    /** 1 for a closed spline. */
    closed: Uint8Array;
    /** End of each spline's continuity tags in the tag arrays. */
    tagEnds: Uint32Array;
    /** Each tag's kind, as its index in CONTINUITY_KINDS. */
    tagKinds: Uint8Array;
    /** Each tag's ratio. */
    tagRatios: Float64Array;
    /** Each tag's angle. */
    tagAngles: Float64Array;
  };
  /** The shapes (as in {@link SvgDocument.shapes}), packed field by field. */
  shapes: {
    /** Element names. */
    tags: string[];
    /** `id` attributes. */
    ids: (string | null)[];
    /** Lines in the file. */
    lines: Uint32Array;
    /** First spline of each. */
    firstSplines: Uint32Array;
    /** Number of splines of each. */
    splineCounts: Uint32Array;
    /** Transforms, a b c d e f per shape. */
    transforms: Float64Array;
    /** The distinct resolved styles. */
    styles: ResolvedStyle[];
    /** Each shape's style, as an index in `styles`. */
    styleOf: Uint32Array;
    /** Every shape's `via`, concatenated; shape i's ends at viaEnds[i]. */
    via: string[];
    /** End of each shape's `via` in `via`. */
    viaEnds: Uint32Array;
  };
  /**
   * Where each shape came from, with elements as indices in a pre-order walk of the markup's
   * elements (the root element is 0).
   */
  sources: {
    /** The shape element of each shape. */
    elements: Uint32Array;
    /** (use, referenced element) pairs, outermost first, every shape's concatenated. */
    uses: Uint32Array;
    /** End of each shape's pairs in `uses` (in numbers, two per pair). */
    useEnds: Uint32Array;
    /** The splines as imported (document space), every shape's concatenated. */
    original: Float64Array;
    /** End of each original spline's points in `original`. */
    originalEnds: Uint32Array;
    /** End of each shape's original splines in `originalEnds`. */
    originalCounts: Uint32Array;
  };
  /** As in {@link SvgDocument.warnings}. */
  warnings: SvgWarning[];
  /** As in {@link SvgDocument.width}. */
  width: number;
  /** As in {@link SvgDocument.height}. */
  height: number;
  /** As in {@link SvgDocument.viewBox}. */
  viewBox: [number, number, number, number] | null;
  /** As in {@link SvgDocument.bounds}. */
  bounds: [number, number, number, number] | null;
}

export interface SvgDocumentInit {
  dom: Document;
  splines: Spline[];
  shapes: SvgShape[];
  sources: ShapeSource[];
  warnings: SvgWarning[];
  width: number;
  height: number;
  viewBox: [number, number, number, number] | null;
  bounds: [number, number, number, number] | null;
}

const GEOMETRY_ATTRIBUTES = ['d', 'x', 'y', 'width', 'height', 'rx', 'ry', 'cx', 'cy', 'r', 'x1', 'y1', 'x2', 'y2', 'points', 'pathLength'];
const XLINK = 'http://www.w3.org/1999/xlink';

/**
 * An SVG drawing as cubic Bézier splines in document space (the user space of the root `svg`
 * after element transforms, before its viewBox), plus the markup it came from, so that export
 * writes back everything the splines do not describe (styles, gradients, text, metadata).
 *
 * Create with `parseSVG` (svg/import.ts). Splines may be edited in place (points, continuity
 * tags); `toSVG()` writes them back into the markup.
 */
export class SvgDocument {
  /** All splines, in document order. */
  readonly splines: Spline[];
  /** Drawn shapes in document order; each owns a run of `splines`. */
  readonly shapes: SvgShape[];
  /** What the model kept as is or could not carry, one entry per kind. */
  readonly warnings: SvgWarning[];
  /** Viewport size of the root `svg` (its width/height, else its viewBox size, else the bounds). */
  readonly width: number;
  /** Viewport height of the root `svg` (like `width`). */
  readonly height: number;
  /** The root's viewBox, or null: maps document space to the viewport. */
  readonly viewBox: [number, number, number, number] | null;
  /** Bounds of the curves at import, [xmin, ymin, xmax, ymax], or null for a drawing with none. */
  readonly bounds: [number, number, number, number] | null;

  private readonly dom: Document;
  private readonly sources: ShapeSource[];

  /** @internal use parseSVG */
  constructor(init: SvgDocumentInit) {
    this.dom = init.dom;
    this.splines = init.splines;
    this.shapes = init.shapes;
    this.sources = init.sources;
    this.warnings = init.warnings;
    this.width = init.width;
    this.height = init.height;
    this.viewBox = init.viewBox;
    this.bounds = init.bounds;
  }

  /**
   * This document as plain data that survives `structuredClone` / `postMessage` (e.g. parse in a
   * Web Worker, rebuild on the page with {@link SvgDocument.fromTransfer}). Everything is copied:
   * the buffers of its Float64Arrays may be transferred without affecting this document.
   */
  toTransfer(): SvgDocumentTransfer {
    const index = new Map<Element, number>();
    for (const el of elementsInOrder(this.dom.documentElement!)) index.set(el, index.size);
    const at = (el: Element): number => {
      const i = index.get(el);
      if (i === undefined) throw new SplinekitError('internal', 'toTransfer: a shape refers to an element outside its markup');
      return i;
    };
    const kindIndex = new Map(CONTINUITY_KINDS.map((k, i) => [k, i]));
    const n = this.splines.length;
    let pointCount = 0, tagCount = 0;
    for (const sp of this.splines) {
      pointCount += sp.points.length;
      tagCount += sp.continuity.length;
    }
    const splines = {
      points: new Float64Array(pointCount), pointEnds: new Uint32Array(n), closed: new Uint8Array(n), tagEnds: new Uint32Array(n),
      tagKinds: new Uint8Array(tagCount), tagRatios: new Float64Array(tagCount), tagAngles: new Float64Array(tagCount),
    };
    let p = 0, q = 0;
    this.splines.forEach((sp, k) => {
      splines.points.set(sp.points, p);
      p += sp.points.length;
      splines.pointEnds[k] = p;
      splines.closed[k] = sp.closed ? 1 : 0;
      for (const tag of sp.continuity) {
        splines.tagKinds[q] = kindIndex.get(tag.kind)!;
        splines.tagRatios[q] = tag.ratio;
        splines.tagAngles[q++] = tag.angle;
      }
      splines.tagEnds[k] = q;
    });

    const m = this.shapes.length;
    const styleIndex = new Map<string, number>();
    const shapes = {
      tags: [] as string[], ids: [] as (string | null)[], lines: new Uint32Array(m), firstSplines: new Uint32Array(m),
      splineCounts: new Uint32Array(m), transforms: new Float64Array(6 * m), styles: [] as ResolvedStyle[], styleOf: new Uint32Array(m),
      via: [] as string[], viaEnds: new Uint32Array(m),
    };
    this.shapes.forEach((sh, i) => {
      shapes.tags.push(sh.tag);
      shapes.ids.push(sh.id);
      shapes.lines[i] = sh.line;
      shapes.firstSplines[i] = sh.firstSpline;
      shapes.splineCounts[i] = sh.splineCount;
      const t = sh.transform;
      shapes.transforms.set([t.a, t.b, t.c, t.d, t.e, t.f], 6 * i);
      const key = JSON.stringify(sh.style);
      let si = styleIndex.get(key);
      if (si === undefined) {
        si = shapes.styles.push({ ...sh.style }) - 1;
        styleIndex.set(key, si);
      }
      shapes.styleOf[i] = si;
      shapes.via.push(...sh.via);
      shapes.viaEnds[i] = shapes.via.length;
    });

    const uses: number[] = [], originalEnds: number[] = [];
    let originalLength = 0;
    for (const src of this.sources) for (const o of src.original) originalLength += o.length;
    const sources = {
      elements: new Uint32Array(m), uses: new Uint32Array(0), useEnds: new Uint32Array(m),
      original: new Float64Array(originalLength), originalEnds: new Uint32Array(0), originalCounts: new Uint32Array(m),
    };
    let o = 0;
    this.sources.forEach((src, i) => {
      sources.elements[i] = at(src.element);
      for (const { use, ref } of src.uses) uses.push(at(use), at(ref));
      sources.useEnds[i] = uses.length;
      for (const pts of src.original) {
        sources.original.set(pts, o);
        o += pts.length;
        originalEnds.push(o);
      }
      sources.originalCounts[i] = originalEnds.length;
    });
    sources.uses = Uint32Array.from(uses);
    sources.originalEnds = Uint32Array.from(originalEnds);

    return {
      markup: serialize(this.dom),
      splines,
      shapes,
      sources,
      warnings: this.warnings.map((w) => ({ ...w })),
      width: this.width,
      height: this.height,
      viewBox: this.viewBox && [...this.viewBox],
      bounds: this.bounds && [...this.bounds],
    };
  }

  /**
   * Rebuilds a document from {@link SvgDocument.toTransfer}'s data (after `structuredClone` or
   * `postMessage`): same splines, shapes, warnings and export as the original. Throws
   * SplinekitError('invalid-input') for data that does not fit its markup.
   */
  static fromTransfer(t: SvgDocumentTransfer): SvgDocument {
    const dom = parseXML(t.markup, 'transferred document');
    const elements = elementsInOrder(dom.documentElement!);
    const at = (i: number): Element => {
      const el = elements[i];
      if (!el) throw new SplinekitError('invalid-input', `fromTransfer: element ${i} is not in the markup (${elements.length} elements)`);
      return el;
    };
    const m = t.shapes.tags.length;
    if (t.sources.elements.length !== m) {
      throw new SplinekitError('invalid-input', `fromTransfer: ${m} shapes but ${t.sources.elements.length} sources`);
    }
    const sp = t.splines;
    const splines: Spline[] = [];
    for (let k = 0, p = 0, q = 0; k < sp.pointEnds.length; k++) {
      const continuity: ContinuityTag[] = [];
      for (; q < sp.tagEnds[k]; q++) continuity.push({ kind: CONTINUITY_KINDS[sp.tagKinds[q]], ratio: sp.tagRatios[q], angle: sp.tagAngles[q] });
      splines.push({ closed: sp.closed[k] === 1, points: sp.points.slice(p, sp.pointEnds[k]), continuity });
      p = sp.pointEnds[k];
    }
    const sh = t.shapes, src = t.sources;
    const shapes: SvgShape[] = [];
    const sources: ShapeSource[] = [];
    for (let i = 0, v = 0, u = 0, e = 0, o = 0; i < m; i++) {
      const x = sh.transforms.subarray(6 * i, 6 * i + 6);
      shapes.push({
        tag: sh.tags[i],
        id: sh.ids[i],
        line: sh.lines[i],
        firstSpline: sh.firstSplines[i],
        splineCount: sh.splineCounts[i],
        transform: { a: x[0], b: x[1], c: x[2], d: x[3], e: x[4], f: x[5] },
        style: { ...sh.styles[sh.styleOf[i]] },
        via: sh.via.slice(v, sh.viaEnds[i]),
      });
      v = sh.viaEnds[i];
      const uses: ShapeSource['uses'] = [];
      for (; u + 1 < src.useEnds[i]; u += 2) uses.push({ use: at(src.uses[u]), ref: at(src.uses[u + 1]) });
      u = src.useEnds[i];
      const original: Float64Array[] = [];
      for (; e < src.originalCounts[i]; e++) {
        original.push(src.original.slice(o, src.originalEnds[e]));
        o = src.originalEnds[e];
      }
      sources.push({ uses, element: at(src.elements[i]), original });
    }
    return new SvgDocument({
      dom,
      splines,
      shapes,
      sources,
      warnings: t.warnings,
      width: t.width,
      height: t.height,
      viewBox: t.viewBox,
      bounds: t.bounds,
    });
  }

  /** The drawing's size: the diagonal of its bounds (1 when it has no curves). Tolerances scale with it. */
  get size(): number {
    const b = this.bounds;
    const d = b ? Math.hypot(b[2] - b[0], b[3] - b[1]) : 0;
    return d > 0 ? d : 1;
  }

  /** The region to show: the viewBox, else the viewport, in document units. */
  get frame(): [number, number, number, number] {
    return this.viewBox ?? [0, 0, this.width, this.height];
  }

  /** A copy whose splines can be changed independently (the markup is shared, read-only). */
  clone(): SvgDocument {
    return new SvgDocument({
      dom: this.dom,
      splines: this.splines.map(cloneSpline),
      shapes: this.shapes.map((s) => ({ ...s, via: [...s.via] })),
      sources: this.sources,
      warnings: this.warnings.map((w) => ({ ...w })),
      width: this.width,
      height: this.height,
      viewBox: this.viewBox,
      bounds: this.bounds,
    });
  }

  /**
   * Whether `other` draws from the same markup as this document (it is a clone or a posed copy
   * of it, or this one of it), so only their splines can differ.
   */
  sameMarkup(other: SvgDocument): boolean {
    return this.dom === other.dom;
  }

  /** Counts of shapes, splines, segments, junction kinds and warnings (what `splinekit info` prints). */
  stats(): SvgStats {
    const continuity: Record<ContinuityKind, number> = { none: 0, C0: 0, C1: 0, G1: 0, angle: 0 };
    let segments = 0;
    for (const s of this.splines) {
      segments += segmentCount(s);
      for (const t of s.continuity) continuity[t.kind]++;
    }
    return {
      elements: this.shapes.length,
      splines: this.splines.length,
      segments,
      continuity,
      warnings: this.warnings.reduce((n, w) => n + w.count, 0),
    };
  }

  /** Geometry in the shared CLI schema: control points in document space, document order. */
  toJSON(): SplinesJSON {
    return {
      splines: this.splines.map((s) => {
        const points: [number, number][] = [];
        for (let i = 0; i < s.points.length; i += 2) points.push([s.points[i], s.points[i + 1]]);
        return { closed: s.closed, points, continuity: s.continuity.map((t) => t.kind) };
      }),
    };
  }

  /**
   * A CSS color to paint `paint` with: itself for a color, a gradient's middle stop for
   * `url(#gradient)` (one colour standing in for it, e.g. for a thumbnail or a legend),
   * or null for 'none' and unresolvable references.
   */
  paintColor(paint: string): string | null {
    const p = paint.trim();
    if (p === 'none' || p === '') return null;
    const m = /^url\(\s*['"]?#([^'")\s]+)['"]?\s*\)\s*(.*)$/.exec(p);
    if (!m) return p;
    let el: Element | null = this.byId(m[1]);
    for (let hops = 0; el && hops < 8; hops++) {
      const stops = Array.from(el.childNodes).filter((n): n is Element => n.nodeType === 1 && (n as Element).localName === 'stop');
      if (stops.length > 0) {
        const stop = stops[Math.floor((stops.length - 1) / 2)];
        const style = stop.getAttribute('style') ?? '';
        const fromStyle = /stop-color\s*:\s*([^;]+)/.exec(style)?.[1]?.trim();
        return fromStyle ?? stop.getAttribute('stop-color') ?? 'black';
      }
      const href = el.getAttributeNS(XLINK, 'href') ?? el.getAttribute('href');
      el = href?.startsWith('#') ? this.byId(href.slice(1)) : null;
    }
    return m[2] && m[2] !== 'none' ? m[2] : null;
  }

  private byId(id: string): Element | null {
    return findById(this.dom.documentElement!, id);
  }

  /** The splines of shape i (a view into `splines`). */
  splinesOf(i: number): Spline[] {
    const s = this.shapes[i];
    return this.splines.slice(s.firstSpline, s.firstSpline + s.splineCount);
  }

  /**
   * The affine map of shape i's user space that best carries its splines as imported to its
   * splines now (least squares over the control points), for paint that should follow the shape;
   * null when the shape has not moved or its points no longer pair with the imported ones.
   */
  paintTransform(i: number): Matrix | null {
    const shape = this.shapes[i], original = this.sources[i].original;
    const toLocal = invert(shape.transform);
    if (!toLocal || original.length !== shape.splineCount || !this.changed(i)) return null;
    const from: number[] = [], to: number[] = [];
    for (let k = 0; k < shape.splineCount; k++) {
      const a = original[k], b = this.splines[shape.firstSpline + k].points;
      if (a.length !== b.length) return null;
      for (let j = 0; j < a.length; j += 2) {
        from.push(toLocal.a * a[j] + toLocal.c * a[j + 1] + toLocal.e, toLocal.b * a[j] + toLocal.d * a[j + 1] + toLocal.f);
        to.push(toLocal.a * b[j] + toLocal.c * b[j + 1] + toLocal.e, toLocal.b * b[j] + toLocal.d * b[j + 1] + toLocal.f);
      }
    }
    const m = fitAffine(from, to);
    return Object.values(m).every(Number.isFinite) ? m : null;
  }

  /**
   * Makes the gradients and patterns (in user space units) that paint shape i, whose element is
   * `el` under `root`, follow the shape's deformation (see svg/paint-follow.ts).
   */
  private followPaints(i: number, root: Element, el: Element): void {
    const m = this.paintTransform(i);
    if (m) this.paintFollower(i, root, el)?.(m);
  }

  /**
   * Gives shape i (its element `el`, under `root`, in markup written by `toSVG`) its own copies of
   * the gradients and patterns it is painted with, and returns the function that sets the map they
   * follow (`paintTransform` of a version of this document; null for none); null when its paint
   * cannot follow (a colour, or a pattern in bounding-box units). For pages that keep the markup
   * live (as the editor does).
   */
  paintFollower(i: number, root: Element, el: Element): ((m: Matrix | null) => void) | null {
    const follow: ((m: Matrix) => void)[] = [];
    for (const which of ['fill', 'stroke'] as const) {
      const f = paintFollower(root, el, String(i), which, this.shapes[i].style[which], () => this.importedBounds(i));
      if (f) follow.push(f);
    }
    return follow.length === 0 ? null : (m) => follow.forEach((f) => f(m ?? IDENTITY));
  }

  /**
   * The `d` of shape i's element: its splines in the element's own user space, numbers written by
   * `format` (12 significant digits by default); null when the element's transform is singular.
   */
  pathData(i: number, format?: (v: number) => string): string | null {
    const toLocal = invert(this.shapes[i].transform);
    return toLocal ? splinesToPathData(this.splinesOf(i), isIdentity(toLocal) ? undefined : toLocal, format) : null;
  }

  /** Shape i's bounds [x, y, w, h] as imported, in its element's user space, or null. */
  importedBounds(i: number): [number, number, number, number] | null {
    const toLocal = invert(this.shapes[i].transform);
    if (!toLocal) return null;
    const splines = this.sources[i].original.map((p, k) => ({ closed: this.splines[this.shapes[i].firstSpline + k]?.closed ?? false, points: transformPoints(toLocal, p.slice()) }));
    return splineBounds(splines);
  }

  /** Whether shape i moved: by more than 1e-10 of the drawing's size (float noise is not a change). */
  private changed(i: number): boolean {
    const shape = this.shapes[i], original = this.sources[i].original;
    if (original.length !== shape.splineCount) return true;
    const tol = 1e-10 * this.size;
    for (let k = 0; k < shape.splineCount; k++) {
      const a = this.splines[shape.firstSpline + k].points, b = original[k];
      if (a.length !== b.length) return true;
      for (let j = 0; j < a.length; j++) if (!(Math.abs(a[j] - b[j]) <= tol)) return true;
    }
    return false;
  }

  /**
   * Writes the document as SVG markup that draws the splines: shapes whose geometry changed (or
   * all, with rewrite 'all') become `<path>`s with their attributes kept and their points mapped
   * back into the element's own user space; `use` instances that changed are expanded in place.
   */
  toSVG(options: ExportOptions = {}): string {
    return serialize(this.rewrite(options.rewrite === 'all', Boolean(options.tagShapes)).out);
  }

  /**
   * An animated SVG that plays with no script: every shape becomes a path with a SMIL
   * `<animate attributeName="d">` through the frames (valid because the path structure never
   * changes between frames). `frames[k]` holds the points of all splines (document order, as
   * SkinRig.pose returns them) at time `times[k]` seconds, times increasing from 0.
   */
  toAnimatedSVG(frames: readonly Float64Array[], times: readonly number[], options: { repeat?: number | 'indefinite' } = {}): string {
    if (frames.length < 2 || frames.length !== times.length) {
      throw new SplinekitError('invalid-input', `animated SVG: need at least 2 frames with one time each (got ${frames.length} frames, ${times.length} times)`);
    }
    const total = this.splines.reduce((n, sp) => n + sp.points.length, 0);
    frames.forEach((f, k) => {
      if (f.length !== total) throw new SplinekitError('invalid-input', `animated SVG: frame ${k} has ${f.length} coordinates, expected ${total}`);
      if (!f.every(Number.isFinite)) throw new SplinekitError('invalid-input', `animated SVG: frame ${k} has a non-finite coordinate`);
      if (k > 0 && !(times[k] > times[k - 1])) throw new SplinekitError('invalid-input', 'animated SVG: frame times must increase');
    });
    if (times[0] !== 0) throw new SplinekitError('invalid-input', 'animated SVG: the first frame must be at time 0');
    const duration = times[times.length - 1];
    const keyTimes = times.map((t) => formatNumber(t / duration)).join(';');
    const offsets: number[] = [];
    let at = 0;
    for (const sp of this.splines) {
      offsets.push(at);
      at += sp.points.length;
    }
    offsets.push(at);

    const { out, elements } = this.rewrite(true, false);
    for (const [i, el] of elements) {
      const shape = this.shapes[i];
      const toLocal = invert(shape.transform)!;
      const values = frames.map((f) => {
        const splines = [];
        for (let k = shape.firstSpline; k < shape.firstSpline + shape.splineCount; k++) {
          splines.push({ closed: this.splines[k].closed, points: f.subarray(offsets[k], offsets[k + 1]) });
        }
        return splinesToPathData(splines, isIdentity(toLocal) ? undefined : toLocal);
      });
      el.setAttribute('d', values[0]);
      const animate = out.createElementNS(el.namespaceURI, el.prefix ? `${el.prefix}:animate` : 'animate');
      animate.setAttribute('attributeName', 'd');
      animate.setAttribute('dur', `${formatNumber(duration)}s`);
      animate.setAttribute('repeatCount', String(options.repeat ?? 'indefinite'));
      animate.setAttribute('keyTimes', keyTimes);
      animate.setAttribute('values', values.join(';'));
      el.appendChild(animate);
    }
    return serialize(out);
  }

  /**
   * A copy of the markup with shapes (all, or those whose geometry changed) written back as
   * paths from the splines; `elements` maps shape index → its path in the copy.
   */
  private rewrite(all: boolean, tag: boolean): { out: Document; elements: Map<number, Element> } {
    const out = this.dom.cloneNode(true) as Document;
    const cloneOf = pairElements(this.dom.documentElement!, out.documentElement!);
    const expansions = new Map<Element, Map<Element, Element>>();
    const elements = new Map<number, Element>();

    // Resolves a shape's source to the element to rewrite in `out`, expanding `use`s on the way.
    const target = (source: ShapeSource): Element | undefined => {
      let map = cloneOf;
      for (const { use, ref } of source.uses) {
        const useCopy = map.get(use);
        if (!useCopy) return undefined;
        let inner = expansions.get(useCopy);
        if (!inner) {
          inner = expandUse(out, useCopy, ref, use);
          expansions.set(useCopy, inner);
        }
        map = inner;
      }
      return map.get(source.element);
    };

    this.shapes.forEach((shape, i) => {
      if (!all && !this.changed(i)) return;
      const el = target(this.sources[i]);
      if (!el) return;
      const toLocal = invert(shape.transform);
      if (!toLocal) return; // a collapsed (singular) element draws nothing either way
      const d = splinesToPathData(this.splinesOf(i), isIdentity(toLocal) ? undefined : toLocal);
      if (tag) el.setAttribute(SHAPE_ATTRIBUTE, String(i));
      if (el.localName === 'path') {
        el.setAttribute('d', d);
        el.removeAttribute('pathLength');
        this.followPaints(i, out.documentElement!, el);
        elements.set(i, el);
        return;
      }
      const path = out.createElementNS(el.namespaceURI, el.prefix ? `${el.prefix}:path` : 'path');
      for (const attr of Array.from(el.attributes)) {
        if (!GEOMETRY_ATTRIBUTES.includes(attr.localName ?? attr.name)) path.setAttributeNode(attr.cloneNode(true) as Attr);
      }
      path.setAttribute('d', d);
      while (el.firstChild) path.appendChild(el.firstChild);
      el.parentNode!.replaceChild(path, el);
      this.followPaints(i, out.documentElement!, path);
      elements.set(i, path);
    });
    return { out, elements };
  }
}

function serialize(out: Document): string {
  const xml = new XMLSerializer().serializeToString(out as unknown as Parameters<XMLSerializer['serializeToString']>[0]);
  return xml.startsWith('<?xml') ? xml : `<?xml version="1.0" encoding="UTF-8"?>\n${xml}`;
}

/** The elements under `root` (itself included) in document (pre-)order. */
function elementsInOrder(root: Element): Element[] {
  const out: Element[] = [];
  const visit = (el: Element): void => {
    out.push(el);
    for (let c = el.firstChild; c; c = c.nextSibling) if (c.nodeType === 1) visit(c as Element);
  };
  visit(root);
  return out;
}

/** Maps every element of `a` to the element at the same place in `b` (a structural copy of a). */
function pairElements(a: Element, b: Element, into = new Map<Element, Element>()): Map<Element, Element> {
  into.set(a, b);
  let ca = a.firstChild, cb = b.firstChild;
  while (ca && cb) {
    if (ca.nodeType === 1) pairElements(ca as Element, cb as Element, into);
    ca = ca.nextSibling;
    cb = cb.nextSibling;
  }
  return into;
}

/**
 * Replaces `use` (in the output) by a group holding a copy of the element it references, so its
 * shapes can be written one by one. The group keeps the use's attributes (but its reference and
 * geometry), its transform followed by translate(x, y); ids in the copy are dropped to stay
 * unique. Returns the map from the original referenced subtree to the copy.
 */
function expandUse(out: Document, use: Element, referenced: Element, originalUse: Element): Map<Element, Element> {
  const g = out.createElementNS(use.namespaceURI, use.prefix ? `${use.prefix}:g` : 'g');
  for (const attr of Array.from(use.attributes)) {
    const name = attr.localName ?? attr.name;
    if (['href', 'x', 'y', 'width', 'height', 'transform'].includes(name)) continue;
    g.setAttributeNode(attr.cloneNode(true) as Attr);
  }
  const x = parseFloat(originalUse.getAttribute('x') ?? '0') || 0, y = parseFloat(originalUse.getAttribute('y') ?? '0') || 0;
  const transform = `${use.getAttribute('transform') ?? ''}${x || y ? ` translate(${x} ${y})` : ''}`.trim();
  if (transform) g.setAttribute('transform', transform);
  let copy = out.importNode(referenced, true) as Element;
  const map = pairElements(referenced, copy);
  for (const el of map.values()) el.removeAttribute('id');
  if (referenced.localName === 'symbol') {
    // A symbol draws only when instantiated: its copy becomes a nested svg of the use's size.
    const svg = out.createElementNS(copy.namespaceURI, copy.prefix ? `${copy.prefix}:svg` : 'svg');
    for (const attr of Array.from(copy.attributes)) svg.setAttributeNode(attr.cloneNode(true) as Attr);
    for (const name of ['width', 'height']) svg.setAttribute(name, originalUse.getAttribute(name) ?? '100%');
    while (copy.firstChild) svg.appendChild(copy.firstChild);
    map.set(referenced, svg);
    copy = svg;
  }
  g.appendChild(copy);
  use.parentNode!.replaceChild(g, use);
  return map;
}
