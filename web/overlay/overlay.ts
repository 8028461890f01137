import {
  BufferGeometry,
  Float32BufferAttribute,
  Group,
  LineBasicMaterial,
  LineSegments,
  Points,
  ShaderMaterial,
  type Material,
} from 'three';
import { anchorJunction, type SvgDocument } from '../../src/index.js';
import type { AnchorSelection } from '../app/state.js';
import type { View2D } from '../view2d/view2d.js';
import { CONTINUITY_COLORS, END_COLOR, HANDLE_COLOR, HANDLE_LINE_COLOR, OUTLINE_COLOR, SELECTION_COLOR, hexToRGB } from './colors.js';

/** Marker shapes drawn by the point shader. */
const enum Marker {
  Square = 0,
  Circle = 1,
  /** A hollow square frame: shows the marker under it. */
  Ring = 2,
}

/** Point sprites of constant screen size with a dark outline, colored per point. */
function markerMaterial(marker: Marker, sizePx: number, pixelRatio: number): ShaderMaterial {
  return new ShaderMaterial({
    uniforms: {
      uSize: { value: sizePx * pixelRatio },
      uBorder: { value: Math.max(1, pixelRatio) },
      uOutline: { value: hexToRGB(OUTLINE_COLOR) },
    },
    vertexShader: /* glsl */ `
      attribute vec3 tint;
      uniform float uSize;
      varying vec3 vTint;
      void main() {
        vTint = tint;
        gl_PointSize = uSize;
        gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
      }`,
    fragmentShader: /* glsl */ `
      uniform float uSize;
      uniform float uBorder;
      uniform vec3 uOutline;
      varying vec3 vTint;
      void main() {
        vec2 c = gl_PointCoord * 2.0 - 1.0;
        float d = ${marker === Marker.Circle ? 'length(c)' : 'max(abs(c.x), abs(c.y))'};
        if (d > 1.0) discard;
        float edge = 1.0 - 2.0 * uBorder / uSize;
        bool outline = d > edge;
        ${marker === Marker.Ring ? 'if (d < 0.62 - 2.0 * uBorder / uSize) discard; outline = outline || d < 0.62;' : ''}
        gl_FragColor = vec4(outline ? uOutline : vTint, 1.0);
      }`,
    // Transparent like the drawing, so both sort by render order (opaque objects draw first).
    transparent: true,
    depthTest: false,
    depthWrite: false,
  });
}

/**
 * Walks a document's control points in the order the overlay draws them: each anchor (x, y, its
 * spline and point index) and each handle with the anchor it belongs to (the one before it for
 * point 3k+1, after it for 3k+2).
 */
function forEachControl(
  doc: SvgDocument,
  anchor: (x: number, y: number, spline: number, point: number) => void,
  handle: (hx: number, hy: number, ax: number, ay: number) => void,
): void {
  doc.splines.forEach((s, si) => {
    const p = s.points, n = p.length / 2;
    for (let i = 0; i < n; i++) {
      if (i % 3 === 0) {
        anchor(p[2 * i], p[2 * i + 1], si, i);
        continue;
      }
      const a = i % 3 === 1 ? i - 1 : (i + 1) % n;
      handle(p[2 * i], p[2 * i + 1], p[2 * a], p[2 * a + 1]);
    }
  });
}

const ANCHOR_PX = 8;
const HANDLE_PX = 6;
const SELECTED_PX = 17;
/** How far from an anchor (in screen pixels) a click still picks it. */
const PICK_PX = 8;

/**
 * The control-point overlay: anchors as squares colored by their continuity tag (ends of open
 * splines in white), handles as dots joined to their anchors, the selected anchor framed in a
 * ring and the one under the pointer enlarged.
 * Everything keeps its screen size at any zoom.
 */
export class ControlOverlay {
  readonly group = new Group();
  private doc: SvgDocument | null = null;
  private hover: AnchorSelection | null = null;
  private selection: AnchorSelection | null = null;
  /** Per anchor: its spline and point index (for picking and recoloring). */
  private anchorSpline = new Int32Array(0);
  private anchorPoint = new Int32Array(0);
  private anchorXY = new Float64Array(0);
  private handleCount = 0;
  private readonly anchors: Points;
  private readonly handles: Points;
  private readonly lines: LineSegments;
  private readonly selected: Points;
  private readonly hovered: Points;

  constructor(private readonly view: View2D) {
    const ratio = view.renderer.getPixelRatio();
    this.lines = new LineSegments(new BufferGeometry(), new LineBasicMaterial({ color: HANDLE_LINE_COLOR, transparent: true, opacity: 0.9, depthTest: false, depthWrite: false }));
    this.handles = new Points(new BufferGeometry(), markerMaterial(Marker.Circle, HANDLE_PX, ratio));
    this.anchors = new Points(new BufferGeometry(), markerMaterial(Marker.Square, ANCHOR_PX, ratio));
    this.hovered = new Points(new BufferGeometry(), markerMaterial(Marker.Square, ANCHOR_PX + 3, ratio));
    this.selected = new Points(new BufferGeometry(), markerMaterial(Marker.Ring, SELECTED_PX, ratio));
    [this.lines, this.handles, this.anchors, this.hovered, this.selected].forEach((o, i) => {
      o.frustumCulled = false;
      o.renderOrder = 100 + i;
      this.group.add(o);
    });
    this.group.name = 'control-overlay';
    view.overlayLayer.add(this.group);
  }

  get visible(): boolean {
    return this.group.visible;
  }
  set visible(v: boolean) {
    this.group.visible = v;
    this.view.requestRender();
  }

  /** Number of anchors and handles drawn. */
  get counts(): { anchors: number; handles: number } {
    return { anchors: this.anchorPoint.length, handles: this.handleCount };
  }

  setDocument(doc: SvgDocument | null): void {
    this.doc = doc;
    const anchorXY: number[] = [], spl: number[] = [], pt: number[] = [];
    const handleXYZ: number[] = [], lineXYZ: number[] = [];
    if (doc) {
      forEachControl(
        doc,
        (x, y, si, i) => {
          anchorXY.push(x, y);
          spl.push(si);
          pt.push(i);
        },
        (hx, hy, ax, ay) => {
          handleXYZ.push(hx, hy, 0);
          lineXYZ.push(ax, ay, 0, hx, hy, 0);
        },
      );
    }
    this.anchorXY = Float64Array.from(anchorXY);
    this.anchorSpline = Int32Array.from(spl);
    this.anchorPoint = Int32Array.from(pt);
    const anchorXYZ = new Float32Array(spl.length * 3);
    for (let i = 0; i < spl.length; i++) {
      anchorXYZ[3 * i] = anchorXY[2 * i];
      anchorXYZ[3 * i + 1] = anchorXY[2 * i + 1];
    }
    this.setPositions(this.anchors, anchorXYZ);
    this.anchors.geometry.setAttribute('tint', new Float32BufferAttribute(new Float32Array(spl.length * 3), 3));
    this.handleCount = handleXYZ.length / 3;
    this.setPositions(this.handles, new Float32Array(handleXYZ));
    const handleTint = new Float32Array(handleXYZ.length);
    for (let i = 0; i < handleTint.length; i += 3) handleTint.set(hexToRGB(HANDLE_COLOR), i);
    this.handles.geometry.setAttribute('tint', new Float32BufferAttribute(handleTint, 3));
    this.setPositions(this.lines, new Float32Array(lineXYZ));
    this.recolor();
    this.setSelection(null);
    this.setHover(null);
  }

  /**
   * Follows new positions of the same splines (a pose, a blend): moves the markers and handle
   * lines in place, keeping colours, selection and hover; a document with other splines is set
   * anew (setDocument).
   */
  update(doc: SvgDocument): void {
    const old = this.doc;
    const same = old !== null && old.splines.length === doc.splines.length && old.splines.every((s, i) => s.points.length === doc.splines[i].points.length);
    if (!same) return this.setDocument(doc);
    this.doc = doc;
    const anchors = this.anchors.geometry.getAttribute('position') as Float32BufferAttribute;
    const handles = this.handles.geometry.getAttribute('position') as Float32BufferAttribute;
    const lines = this.lines.geometry.getAttribute('position') as Float32BufferAttribute;
    const a = anchors.array as Float32Array, h = handles.array as Float32Array, l = lines.array as Float32Array;
    let ai = 0, hi = 0;
    forEachControl(
      doc,
      (x, y) => {
        this.anchorXY[2 * ai] = a[3 * ai] = x;
        this.anchorXY[2 * ai + 1] = a[3 * ai + 1] = y;
        ai++;
      },
      (hx, hy, ax, ay) => {
        h[3 * hi] = hx;
        h[3 * hi + 1] = hy;
        l[6 * hi] = ax;
        l[6 * hi + 1] = ay;
        l[6 * hi + 3] = hx;
        l[6 * hi + 4] = hy;
        hi++;
      },
    );
    anchors.needsUpdate = handles.needsUpdate = lines.needsUpdate = true;
    this.setSelection(this.selection);
    this.setHover(this.hover);
    this.view.requestRender();
  }

  /** Re-reads the continuity tags (after an override). */
  recolor(): void {
    const doc = this.doc;
    const tint = this.anchors.geometry.getAttribute('tint') as Float32BufferAttribute | undefined;
    if (!doc || !tint) return;
    const colors = tint.array as Float32Array;
    const end = hexToRGB(END_COLOR);
    const byKind = Object.fromEntries(Object.entries(CONTINUITY_COLORS).map(([k, hex]) => [k, hexToRGB(hex)]));
    for (let i = 0; i < this.anchorPoint.length; i++) {
      const kind = this.kindAt(this.anchorSpline[i], this.anchorPoint[i]);
      colors.set(kind ? byKind[kind] : end, 3 * i);
    }
    tint.needsUpdate = true;
    this.setHover(this.hover);
  }

  setSelection(sel: AnchorSelection | null): void {
    this.selection = sel;
    this.mark(this.selected, sel, hexToRGB(SELECTION_COLOR));
  }

  setHover(sel: AnchorSelection | null): void {
    this.hover = sel;
    const kind = sel ? this.kindAt(sel.spline, sel.anchor) : null;
    this.mark(this.hovered, sel, hexToRGB(kind ? CONTINUITY_COLORS[kind] : END_COLOR));
  }

  /** The anchor nearest to a screen point within the pick radius, or null. */
  pick(sx: number, sy: number): AnchorSelection | null {
    if (!this.group.visible || !this.doc) return null;
    const [x, y] = this.view.viewport.toDoc(sx, sy);
    const r = PICK_PX / this.view.viewport.scale;
    let best = -1, bestD = r * r;
    const xy = this.anchorXY;
    // Later anchors are drawn on top: prefer them on ties.
    for (let i = 0; i < this.anchorPoint.length; i++) {
      const dx = xy[2 * i] - x, dy = xy[2 * i + 1] - y, d = dx * dx + dy * dy;
      if (d <= bestD) {
        bestD = d;
        best = i;
      }
    }
    return best < 0 ? null : { spline: this.anchorSpline[best], anchor: this.anchorPoint[best] };
  }

  /** The continuity kind at an anchor, or null for the end of an open spline. */
  private kindAt(spline: number, anchor: number) {
    const s = this.doc?.splines[spline];
    const j = s ? anchorJunction(s, anchor) : -1;
    return j < 0 ? null : s!.continuity[j].kind;
  }

  private mark(points: Points, sel: AnchorSelection | null, rgb: [number, number, number]): void {
    const p = sel && this.doc?.splines[sel.spline]?.points;
    if (!sel || !p || 2 * sel.anchor + 1 >= p.length) {
      points.visible = false;
    } else {
      this.setPositions(points, new Float32Array([p[2 * sel.anchor], p[2 * sel.anchor + 1], 0]));
      points.geometry.setAttribute('tint', new Float32BufferAttribute(new Float32Array(rgb), 3));
      points.visible = true;
    }
    this.view.requestRender();
  }

  private setPositions(o: Points | LineSegments, xyz: Float32Array): void {
    const old = o.geometry;
    const g = new BufferGeometry();
    g.setAttribute('position', new Float32BufferAttribute(xyz, 3));
    old.dispose();
    o.geometry = g;
  }

  dispose(): void {
    for (const o of [this.lines, this.handles, this.anchors, this.hovered, this.selected]) {
      o.geometry.dispose();
      (o.material as Material).dispose();
    }
    this.group.removeFromParent();
  }
}
