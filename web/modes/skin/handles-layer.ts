import type { View2D } from '../../view2d/view2d.js';

const NS = 'http://www.w3.org/2000/svg';
/** Radius of a handle's circle, and how far from its center a press still picks it (pixels). */
const HANDLE_R = 7;
const PICK_R = 12;
/** The gizmo: a rotation ring and, on an arm that turns with the handle, a scale knob. */
export const RING_R = 52;
const RING_BAND = 7;
export const KNOB_R = RING_R + 22;
const KNOB_PICK = 10;

/** A handle as drawn: where (document space) and its label. */
export interface HandleMark {
  id: number;
  x: number;
  y: number;
  label: string;
}

/** The gizmo around the selected handle: its center (document space) and the handle's rotation. */
export interface GizmoMark {
  id: number;
  x: number;
  y: number;
  angle: number;
  /** Shown beside the gizmo while a gesture runs, e.g. "↻ 30°  ⤢ 1.20×". */
  readout: string | null;
}

export type HandlePart = { part: 'handle' | 'ring' | 'knob'; id: number };

function el<K extends keyof SVGElementTagNameMap>(tag: K, attrs: Record<string, string | number>): SVGElementTagNameMap[K] {
  const e = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  return e;
}

/**
 * Skin handles and the pose gizmo, drawn as an SVG layer over the canvas (crisp at any zoom; a
 * rig has few handles). It takes no pointer events: the mode picks through `pick()`.
 */
export class HandlesLayer {
  readonly el: SVGSVGElement;
  private handles: HandleMark[] = [];
  private selected: number | null = null;
  private hover: HandlePart | null = null;
  private gizmo: GizmoMark | null = null;

  constructor(private readonly view: View2D) {
    this.el = el('svg', { class: 'skin-layer', 'aria-hidden': 'true', 'data-testid': 'skin-layer' });
    view.container.append(this.el);
  }

  set(handles: HandleMark[], selected: number | null, gizmo: GizmoMark | null): void {
    this.handles = handles;
    this.selected = selected;
    this.gizmo = gizmo;
    this.draw();
  }

  setHover(hover: HandlePart | null): void {
    const same = hover?.part === this.hover?.part && hover?.id === this.hover?.id;
    if (same) return;
    this.hover = hover;
    this.draw();
  }

  /** Screen position (canvas pixels) of a handle, or null. */
  screenOf(id: number): [number, number] | null {
    const h = this.handles.find((m) => m.id === id);
    return h ? this.view.toScreen(h.x, h.y) : null;
  }

  /** The gizmo's center and knob on screen (canvas pixels), or null without a gizmo. */
  gizmoOnScreen(): { center: [number, number]; knob: [number, number]; ring: number } | null {
    const g = this.gizmo;
    if (!g) return null;
    const [cx, cy] = this.view.toScreen(g.x, g.y);
    return { center: [cx, cy], knob: [cx + KNOB_R * Math.cos(g.angle), cy + KNOB_R * Math.sin(g.angle)], ring: RING_R };
  }

  /** What is under a screen point: a handle first (nearest), then the gizmo's knob and ring. */
  pick(sx: number, sy: number): HandlePart | null {
    let best: HandlePart | null = null, bestD = PICK_R;
    for (const h of this.handles) {
      const [x, y] = this.view.toScreen(h.x, h.y);
      const d = Math.hypot(x - sx, y - sy);
      if (d <= bestD) [best, bestD] = [{ part: 'handle', id: h.id }, d];
    }
    if (best) return best;
    const g = this.gizmoOnScreen();
    if (!g || !this.gizmo) return null;
    if (Math.hypot(g.knob[0] - sx, g.knob[1] - sy) <= KNOB_PICK) return { part: 'knob', id: this.gizmo.id };
    if (Math.abs(Math.hypot(g.center[0] - sx, g.center[1] - sy) - RING_R) <= RING_BAND) return { part: 'ring', id: this.gizmo.id };
    return null;
  }

  /** Redraws at the current view transform (after a pan or zoom). */
  draw(): void {
    const parts: SVGElement[] = [];
    const hover = this.hover;
    const g = this.gizmoOnScreen();
    if (g && this.gizmo) {
      const [cx, cy] = g.center, [kx, ky] = g.knob;
      const hot = (part: HandlePart['part']) => (hover?.part === part ? ' hot' : '');
      const gizmo = el('g', { class: 'gizmo' });
      gizmo.append(
        el('circle', { class: 'gizmo-halo', cx, cy, r: RING_R }),
        el('circle', { class: `gizmo-ring${hot('ring')}`, cx, cy, r: RING_R }),
        el('line', { class: 'gizmo-arm', x1: cx + HANDLE_R * Math.cos(this.gizmo.angle), y1: cy + HANDLE_R * Math.sin(this.gizmo.angle), x2: kx, y2: ky }),
        el('rect', { class: `gizmo-knob${hot('knob')}`, x: kx - 5, y: ky - 5, width: 10, height: 10, rx: 2 }),
      );
      if (this.gizmo.readout) {
        const text = el('text', { class: 'gizmo-readout', x: cx + RING_R + 10, y: cy - RING_R + 4 });
        text.textContent = this.gizmo.readout;
        gizmo.append(text);
      }
      parts.push(gizmo);
    }
    for (const h of this.handles) {
      const [x, y] = this.view.toScreen(h.x, h.y);
      const classes = ['handle'];
      if (h.id === this.selected) classes.push('selected');
      if (hover?.part === 'handle' && hover.id === h.id) classes.push('hot');
      const group = el('g', { class: classes.join(' '), 'data-handle': h.id });
      const label = el('text', { class: 'handle-label', x: x + HANDLE_R + 3, y: y - HANDLE_R - 1 });
      label.textContent = h.label;
      group.append(el('circle', { class: 'handle-halo', cx: x, cy: y, r: HANDLE_R + 2 }), el('circle', { class: 'handle-body', cx: x, cy: y, r: HANDLE_R }), el('circle', { class: 'handle-dot', cx: x, cy: y, r: 2 }), label);
      parts.push(group);
    }
    this.el.replaceChildren(...parts);
  }

  dispose(): void {
    this.el.remove();
  }
}
