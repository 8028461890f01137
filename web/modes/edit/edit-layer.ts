import type { CatmullRom } from '../../../src/index.js';
import type { View2D } from '../../view2d/view2d.js';

const NS = 'http://www.w3.org/2000/svg';
/** How far from a mark a press still picks it (pixels). */
export const PICK_R = 10;

function el<K extends keyof SVGElementTagNameMap>(tag: K, attrs: Record<string, string | number>): SVGElementTagNameMap[K] {
  const e = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  return e;
}

/** A control point of a curve. */
export interface PointRef {
  curve: number;
  point: number;
}

/** The active window as previewed: its point indices and drop-off weights, left end first. */
export interface WindowPreview {
  curve: number;
  center: number;
  indices: Int32Array;
  weights: Float64Array;
}

/** What the layer draws. */
export interface EditScene {
  curves: readonly CatmullRom[];
  selected: PointRef | null;
  window: WindowPreview | null;
  /** The stroke being drawn (document x,y pairs). */
  stroke: number[] | null;
  /** Show tangent handles of the selected curve. */
  tangents: boolean;
}

/**
 * Edit mode's marks, drawn as an SVG layer over the canvas: the Catmull-Rom curves, their control
 * points, the active window (ends green and blue as in the paper, the points inside sized by
 * their drop-off weight), the stroke being drawn and tangent handles. Takes no pointer events:
 * the mode picks through `pickPoint`, `pickWindowEnd` and `pickTangent`.
 */
export class EditLayer {
  readonly el: SVGSVGElement;
  private scene: EditScene = { curves: [], selected: null, window: null, stroke: null, tangents: false };

  constructor(private readonly view: View2D) {
    this.el = el('svg', { class: 'edit-layer', 'aria-hidden': 'true', 'data-testid': 'edit-layer' });
    view.container.append(this.el);
  }

  set(scene: EditScene): void {
    this.scene = scene;
    this.draw();
  }

  /** Screen position (canvas pixels) of control point `point` of curve `curve`, or null. */
  pointOnScreen(curve: number, point: number): [number, number] | null {
    const c = this.scene.curves[curve];
    if (!c || point < 0 || point >= c.count) return null;
    const p = c.points();
    return this.view.toScreen(p[2 * point], p[2 * point + 1]);
  }

  /** The nearest control point within PICK_R of a screen point (the selected curve first). */
  pickPoint(sx: number, sy: number): PointRef | null {
    let best: PointRef | null = null, bestD = PICK_R;
    const order = this.scene.curves.map((_, i) => i);
    const sel = this.scene.selected?.curve;
    if (sel !== undefined) order.sort((a, b) => (a === sel ? -1 : b === sel ? 1 : 0));
    for (const ci of order) {
      const p = this.scene.curves[ci].points();
      for (let i = 0; i < p.length / 2; i++) {
        const [x, y] = this.view.toScreen(p[2 * i], p[2 * i + 1]);
        const d = Math.hypot(x - sx, y - sy);
        if (d < bestD) [best, bestD] = [{ curve: ci, point: i }, d];
      }
      if (best && ci === sel) return best;
    }
    return best;
  }

  /** Screen positions of the window's ends, or null without a window. */
  windowEnds(): { left: [number, number]; right: [number, number] } | null {
    const w = this.scene.window;
    if (!w || w.indices.length < 2) return null;
    const left = this.pointOnScreen(w.curve, w.indices[0]), right = this.pointOnScreen(w.curve, w.indices[w.indices.length - 1]);
    return left && right ? { left, right } : null;
  }

  /** Which end of the window is under a screen point. */
  pickWindowEnd(sx: number, sy: number): 'left' | 'right' | null {
    const ends = this.windowEnds();
    const w = this.scene.window;
    if (!ends || !w) return null;
    if (w.indices[0] !== w.center && Math.hypot(ends.left[0] - sx, ends.left[1] - sy) <= PICK_R) return 'left';
    if (w.indices[w.indices.length - 1] !== w.center && Math.hypot(ends.right[0] - sx, ends.right[1] - sy) <= PICK_R) return 'right';
    return null;
  }

  /** Screen position of the forward tangent knob (P + T/3, the Bézier handle) of a control point. */
  tangentKnob(curve: number, point: number): [number, number] | null {
    const c = this.scene.curves[curve];
    if (!c || point < 0 || point >= c.count) return null;
    const p = c.points(), [tx, ty] = c.tangent(point);
    return this.view.toScreen(p[2 * point] + tx / 3, p[2 * point + 1] + ty / 3);
  }

  /** The control point whose tangent knob is under a screen point (selected curve only). */
  pickTangent(sx: number, sy: number): PointRef | null {
    const sel = this.scene.selected;
    if (!this.scene.tangents || !sel) return null;
    const c = this.scene.curves[sel.curve];
    if (!c) return null;
    for (let i = 0; i < c.count; i++) {
      const k = this.tangentKnob(sel.curve, i);
      if (k && Math.hypot(k[0] - sx, k[1] - sy) <= PICK_R) return { curve: sel.curve, point: i };
    }
    return null;
  }

  /** Redraws at the current view transform (after a pan or zoom). */
  draw(): void {
    const { curves, selected, window: w, stroke, tangents } = this.scene;
    const parts: SVGElement[] = [];
    const screen = (x: number, y: number) => this.view.toScreen(x, y);
    curves.forEach((c, ci) => {
      const b = c.toBezier().points;
      let d = '';
      for (let i = 0; i < b.length / 2; i++) {
        const [x, y] = screen(b[2 * i], b[2 * i + 1]);
        d += `${i === 0 ? 'M' : i % 3 === 1 ? 'C' : ' '}${x.toFixed(2)} ${y.toFixed(2)}`;
      }
      if (c.closed) {
        const [x, y] = screen(b[0], b[1]);
        d += ` ${x.toFixed(2)} ${y.toFixed(2)}Z`;
      }
      parts.push(el('path', { class: 'edit-curve-halo', d }));
      parts.push(el('path', { class: `edit-curve${selected?.curve === ci ? ' selected' : ''}`, d, 'data-curve': ci }));
    });
    // Weights of the window's points by control point index.
    const weight = new Map<number, number>();
    if (w) w.indices.forEach((i, k) => weight.set(i, Math.max(weight.get(i) ?? 0, w.weights[k])));
    curves.forEach((c, ci) => {
      const p = c.points();
      for (let i = 0; i < c.count; i++) {
        const [x, y] = screen(p[2 * i], p[2 * i + 1]);
        const inWindow = w?.curve === ci ? weight.get(i) : undefined;
        const r = inWindow !== undefined ? 2.5 + 4 * inWindow : 2.5;
        const cls = ['edit-point'];
        if (inWindow !== undefined) cls.push('in-window');
        if (selected && selected.curve === ci && selected.point === i) cls.push('selected');
        parts.push(el('circle', { class: cls.join(' '), cx: x, cy: y, r }));
      }
    });
    const ends = this.windowEnds();
    if (ends && w) {
      if (w.indices[0] !== w.center) parts.push(el('rect', { class: 'edit-window-end left', x: ends.left[0] - 5, y: ends.left[1] - 5, width: 10, height: 10, 'data-end': 'left' }));
      if (w.indices[w.indices.length - 1] !== w.center) {
        parts.push(el('rect', { class: 'edit-window-end right', x: ends.right[0] - 5, y: ends.right[1] - 5, width: 10, height: 10, 'data-end': 'right' }));
      }
    }
    if (tangents && selected) {
      const c = curves[selected.curve];
      if (c) {
        const p = c.points();
        for (let i = 0; i < c.count; i++) {
          const [tx, ty] = c.tangent(i);
          const [ax, ay] = screen(p[2 * i] - tx / 3, p[2 * i + 1] - ty / 3), [bx, by] = screen(p[2 * i] + tx / 3, p[2 * i + 1] + ty / 3);
          parts.push(el('line', { class: `edit-tangent${c.tangentOverridden(i) ? ' set' : ''}`, x1: ax, y1: ay, x2: bx, y2: by }));
          parts.push(el('circle', { class: 'edit-tangent-knob', cx: bx, cy: by, r: 3.5 }));
        }
      }
    }
    if (stroke && stroke.length >= 4) {
      const pts: string[] = [];
      for (let i = 0; i < stroke.length; i += 2) {
        const [x, y] = screen(stroke[i], stroke[i + 1]);
        pts.push(`${x.toFixed(1)},${y.toFixed(1)}`);
      }
      parts.push(el('polyline', { class: 'edit-stroke', points: pts.join(' ') }));
    }
    this.el.replaceChildren(...parts);
  }

  dispose(): void {
    this.el.remove();
  }
}
