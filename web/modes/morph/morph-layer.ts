import type { View2D } from '../../view2d/view2d.js';

const NS = 'http://www.w3.org/2000/svg';
/** How far from a pin's end a press still picks it (pixels). */
const PICK_R = 10;

function el<K extends keyof SVGElementTagNameMap>(tag: K, attrs: Record<string, string | number>): SVGElementTagNameMap[K] {
  const e = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  return e;
}

/** Path data of closed/open cubic contours laid out by starts/counts (document space). */
export function contoursToD(points: ArrayLike<number>, starts: ArrayLike<number>, counts: ArrayLike<number>, closed: readonly boolean[]): string {
  let d = '';
  const f = (v: number) => (Math.round(v * 1000) / 1000).toString();
  for (let c = 0; c < starts.length; c++) {
    const s = starts[c], n = counts[c];
    const pt = (i: number) => `${f(points[2 * (s + (i % n))])} ${f(points[2 * (s + (i % n)) + 1])}`;
    d += `M${pt(0)}`;
    const segs = closed[c] ? n / 3 : (n - 1) / 3;
    for (let k = 0; k < segs; k++) d += `C${pt(3 * k + 1)} ${pt(3 * k + 2)} ${pt(3 * k + 3)}`;
    if (closed[c]) d += 'Z';
  }
  return d;
}

/** What the layer shows, in document space. */
export interface MorphMarks {
  /** Outline path data of the first and second key (onion skin), or '' to hide. */
  keyA: string;
  keyB: string;
  /** Matched anchors: x,y pairs on the first key and the second (the correspondence lines), or null. */
  lines: { a: Float64Array; b: Float64Array } | null;
  /** Pins: their two ends. */
  pins: { a: readonly [number, number]; b: readonly [number, number] }[];
  /** A pin being dragged: from its first end to the pointer. */
  rubber: { a: readonly [number, number]; b: readonly [number, number] } | null;
}

/**
 * The morph overlay: the keys' outlines (onion skin), the correspondence as thin lines between
 * matched anchors, and the pins, drawn as an SVG layer over the canvas. Document space maps to
 * the screen by one transform that follows the view, so panning redraws nothing.
 */
export class MorphLayer {
  readonly el: SVGSVGElement;
  private readonly root = el('g', {});
  /** Pin ends, in screen space (a fixed size at any zoom). */
  private readonly ends = el('g', {});
  private marks: MorphMarks | null = null;

  constructor(private readonly view: View2D) {
    this.el = el('svg', { class: 'morph-layer', 'aria-hidden': 'true', 'data-testid': 'morph-layer' });
    this.el.append(this.root, this.ends);
    view.container.append(this.el);
  }

  set(marks: MorphMarks): void {
    this.marks = marks;
    this.draw();
  }

  /** Follows the view (pan, zoom). */
  viewChanged(): void {
    const [x0, y0] = this.view.toScreen(0, 0), [x1, y1] = this.view.toScreen(1, 0), [x2, y2] = this.view.toScreen(0, 1);
    this.root.setAttribute('transform', `matrix(${x1 - x0} ${y1 - y0} ${x2 - x0} ${y2 - y0} ${x0} ${y0})`);
    this.ends.replaceChildren();
    const m = this.marks;
    if (!m) return;
    for (const p of [...m.pins, ...(m.rubber ? [m.rubber] : [])]) {
      for (const [x, y] of [p.a, p.b]) {
        const [sx, sy] = this.view.toScreen(x, y);
        this.ends.append(el('circle', { class: 'pin-end', cx: sx, cy: sy, r: 5 }));
      }
    }
  }

  private draw(): void {
    const m = this.marks;
    this.root.replaceChildren();
    if (!m) return;
    if (m.lines) {
      let d = '';
      for (let k = 0; k < m.lines.a.length; k += 2) d += `M${m.lines.a[k]} ${m.lines.a[k + 1]}L${m.lines.b[k]} ${m.lines.b[k + 1]}`;
      this.root.append(el('path', { class: 'correspondence', d, 'data-testid': 'morph-correspondence', 'data-count': m.lines.a.length / 2 }));
    }
    if (m.keyA) this.root.append(el('path', { class: 'key key-a', d: m.keyA }));
    if (m.keyB) this.root.append(el('path', { class: 'key key-b', d: m.keyB }));
    const pins = el('g', { 'data-testid': 'morph-pins', 'data-count': m.pins.length });
    for (const p of [...m.pins, ...(m.rubber ? [m.rubber] : [])]) {
      pins.append(el('path', { class: 'pin-line', d: `M${p.a[0]} ${p.a[1]}L${p.b[0]} ${p.b[1]}` }));
    }
    this.root.append(pins);
    this.viewChanged();
  }

  /** The pin end under a screen point: [pin index, 'a' | 'b'], or null. */
  pick(sx: number, sy: number): { pin: number; end: 'a' | 'b' } | null {
    const pins = this.marks?.pins ?? [];
    let best: { pin: number; end: 'a' | 'b' } | null = null, bestD = PICK_R;
    pins.forEach((p, i) => {
      for (const end of ['a', 'b'] as const) {
        const [x, y] = this.view.toScreen(p[end][0], p[end][1]);
        const d = Math.hypot(x - sx, y - sy);
        if (d <= bestD) {
          bestD = d;
          best = { pin: i, end };
        }
      }
    });
    return best;
  }

  dispose(): void {
    this.el.remove();
  }
}
