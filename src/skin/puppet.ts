import { DOMParser as XmlDomParser } from '@xmldom/xmldom';
import { SplinekitError } from '../core/errors.js';
import { SHAPE_ATTRIBUTE, type SvgDocument } from '../svg/document.js';
import { invert, isIdentity, type Matrix } from '../svg/matrix.js';
import { splinesToPathData } from '../svg/path-data.js';
import type { AffineMatrix } from '../core/affine.js';
import type { SkinRig } from './rig.js';

/**
 * Drives an inline `<svg>` with a skinning rig: each pose rewrites the `d` of the paths that
 * draw the document's shapes — no canvas, no three.js. For animating a character from
 * requestAnimationFrame:
 *
 *   const puppet = SvgPuppet.mount(container, doc, rig);
 *   function frame(t) { puppet.pose(transformsAt(t)); requestAnimationFrame(frame); }
 */
export class SvgPuppet {
  /** The `<svg>` element the puppet draws into. */
  readonly svg: Element;
  private readonly targets: { el: Element; first: number; count: number; toLocal: Matrix | undefined }[] = [];
  private readonly offsets: number[] = [];

  private constructor(
    svg: Element,
    private readonly doc: SvgDocument,
    private readonly rig: SkinRig,
  ) {
    this.svg = svg;
    let at = 0;
    for (const s of doc.splines) {
      this.offsets.push(at);
      at += s.points.length;
    }
    this.offsets.push(at);
    const all = svg.getElementsByTagName('*');
    const byIndex = new Map<number, Element>();
    for (let i = 0; i < all.length; i++) {
      const v = all[i].getAttribute(SHAPE_ATTRIBUTE);
      if (v !== null) byIndex.set(Number(v), all[i]);
    }
    doc.shapes.forEach((shape, i) => {
      const el = byIndex.get(i);
      const inv = invert(shape.transform);
      if (!el || !inv) return;
      this.targets.push({ el, first: shape.firstSpline, count: shape.splineCount, toLocal: isIdentity(inv) ? undefined : inv });
    });
  }

  /**
   * Renders `doc` into `container` (replacing its content) as markup whose shapes are all paths
   * tagged for updates, and returns the puppet. Works with the page's DOM in a browser and with
   * any DOM implementation that has `ownerDocument.importNode` (e.g. xmldom in Node).
   */
  static mount(container: Element, doc: SvgDocument, rig: SkinRig): SvgPuppet {
    const markup = doc.toSVG({ rewrite: 'all', tagShapes: true });
    const Parser = (globalThis as unknown as { DOMParser?: typeof XmlDomParser }).DOMParser ?? XmlDomParser;
    const parsed = new Parser().parseFromString(markup, 'image/svg+xml');
    const owner = container.ownerDocument;
    if (!owner || !parsed.documentElement) throw new SplinekitError('invalid-input', 'SvgPuppet: the container is not in a document');
    const svg = owner.importNode(parsed.documentElement as unknown as Node, true) as Element;
    while (container.firstChild) container.removeChild(container.firstChild);
    container.appendChild(svg);
    return new SvgPuppet(svg, doc, rig);
  }

  /** Poses the rig and redraws; returns the fitted points (a view, as SkinRig.pose). */
  pose(transforms: ArrayLike<number> | readonly AffineMatrix[]): Float64Array {
    const points = this.rig.pose(transforms);
    this.draw(points);
    return points;
  }

  /** Relaxes the current pose (flexible G1 / angle) and redraws. */
  relax(): void {
    this.rig.relax();
    this.draw(this.rig.points());
  }

  /** Writes `points` (all splines, document order) into the paths. */
  draw(points: Float64Array): void {
    for (const t of this.targets) {
      const splines = [];
      for (let k = 0; k < t.count; k++) {
        const s = this.doc.splines[t.first + k];
        splines.push({ closed: s.closed, points: points.subarray(this.offsets[t.first + k], this.offsets[t.first + k + 1]) });
      }
      t.el.setAttribute('d', splinesToPathData(splines, t.toLocal));
    }
  }
}
