import type { View2D } from './view2d.js';

/**
 * Segments drawn at a constant screen width, optionally dashed, one color per segment end (sRGB
 * 0..1), as a layer of a LineCanvas. Colors are quantized to 64 levels per channel, so segments
 * sharing a color are stroked together.
 */
export class LineLayer {
  private xy: Float32Array = new Float32Array(0);
  private rgb: Float32Array = new Float32Array(0);
  private segments = 0;
  /** Segments by quantized color (for `rgb` and `segments` as they were when grouped). */
  private groups: { rgb: Float32Array; segments: number; byColor: { style: string; indices: Uint32Array }[] } | null = null;

  constructor(
    readonly widthPx: number,
    readonly dash: { dash: number; gap: number } | null,
  ) {}

  /** Segments drawn. */
  get count(): number {
    return this.segments;
  }

  /** Draws segments: `xy` holds x0 y0 x1 y1 per segment (document units), `rgb` a color per end (6 per segment). */
  set(xy: Float32Array, rgb: Float32Array): void {
    this.xy = xy;
    this.rgb = rgb;
    this.segments = xy.length / 4;
  }

  hide(): void {
    this.segments = 0;
  }

  /** Strokes the layer into `ctx` (CSS pixels), mapping document points by the view. */
  stroke(ctx: CanvasRenderingContext2D, view: View2D): void {
    if (this.segments === 0) return;
    const { cx, cy, scale, width, height } = view.viewport;
    const ox = width / 2 - cx * scale, oy = height / 2 - cy * scale;
    const xy = this.xy;
    // One path per color; a segment that starts where the last one of its color ended continues it
    // (so dashes run on along a polyline).
    const paths: { style: string; path: Path2D }[] = [];
    for (const { style, indices } of this.colorGroups()) {
      const path = new Path2D();
      let x = NaN, y = NaN;
      for (let n = 0; n < indices.length; n++) {
        const s = 4 * indices[n];
        const x0 = xy[s] * scale + ox, y0 = xy[s + 1] * scale + oy, x1 = xy[s + 2] * scale + ox, y1 = xy[s + 3] * scale + oy;
        if (x !== x0 || y !== y0) path.moveTo(x0, y0);
        path.lineTo(x1, y1);
        x = x1;
        y = y1;
      }
      paths.push({ style, path });
    }
    ctx.lineWidth = this.widthPx;
    ctx.lineCap = this.dash ? 'butt' : 'round';
    ctx.lineJoin = 'round';
    ctx.setLineDash(this.dash ? [this.dash.dash, this.dash.gap] : []);
    for (const { style, path } of paths) {
      ctx.strokeStyle = style;
      ctx.stroke(path);
    }
  }

  /** The segments grouped by quantized color, in order within each group (kept while the colors are). */
  private colorGroups(): { style: string; indices: Uint32Array }[] {
    const g = this.groups;
    if (g && g.rgb === this.rgb && g.segments === this.segments) return g.byColor;
    const rgb = this.rgb;
    const q = (v: number) => Math.max(0, Math.min(63, Math.round(v * 63)));
    const byKey = new Map<number, number[]>();
    for (let s = 0; s < this.segments; s++) {
      const c = 6 * s;
      const key = (q((rgb[c] + rgb[c + 3]) / 2) << 12) | (q((rgb[c + 1] + rgb[c + 4]) / 2) << 6) | q((rgb[c + 2] + rgb[c + 5]) / 2);
      let list = byKey.get(key);
      if (!list) byKey.set(key, (list = []));
      list.push(s);
    }
    const byColor = [...byKey].map(([key, list]) => {
      const channel = (shift: number) => Math.round((((key >> shift) & 63) / 63) * 255);
      return { style: `rgb(${channel(12)}, ${channel(6)}, ${channel(0)})`, indices: Uint32Array.from(list) };
    });
    this.groups = { rgb, segments: this.segments, byColor };
    return byColor;
  }
}

/**
 * A 2D canvas over the drawing and under the view's WebGL overlay, for line layers that change
 * every frame of a drag (stroking them on the CPU costs less than drawing and reading back a
 * WebGL frame with software rendering). Draw again after the layers or the view change.
 */
export class LineCanvas {
  readonly el: HTMLCanvasElement;
  private readonly ctx: CanvasRenderingContext2D;

  constructor(
    private readonly view: View2D,
    private readonly layers: readonly LineLayer[],
  ) {
    this.el = document.createElement('canvas');
    this.el.className = 'line-canvas';
    this.el.setAttribute('aria-hidden', 'true');
    view.container.insertBefore(this.el, view.canvas);
    this.ctx = this.el.getContext('2d')!;
  }

  draw(): void {
    const { width, height } = this.view.viewport;
    const ratio = window.devicePixelRatio || 1;
    const w = Math.round(width * ratio), h = Math.round(height * ratio);
    if (this.el.width !== w || this.el.height !== h) {
      this.el.width = w;
      this.el.height = h;
    }
    this.ctx.setTransform(1, 0, 0, 1, 0, 0);
    this.ctx.clearRect(0, 0, w, h);
    this.ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    for (const layer of this.layers) layer.stroke(this.ctx, this.view);
  }

  dispose(): void {
    this.el.remove();
  }
}
