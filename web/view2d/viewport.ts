/**
 * The 2D view transform: document space (SVG user units, y down) ↔ screen (CSS pixels of the
 * canvas, y down). `center` is the document point at the middle of the canvas, `scale` the
 * number of screen pixels per document unit. Pure math, no DOM.
 */
export class Viewport {
  cx = 0;
  cy = 0;
  scale = 1;
  width = 1;
  height = 1;
  /** Limits of `scale`, set relative to the document by `fit`. */
  minScale = 1e-6;
  maxScale = 1e6;

  resize(width: number, height: number): void {
    this.width = Math.max(1, width);
    this.height = Math.max(1, height);
  }

  /** Shows the rectangle [x, y, w, h] whole and centered, leaving `margin` pixels around it. */
  fit(frame: readonly [number, number, number, number], margin = 32): void {
    const [x, y, w, h] = frame;
    const sw = Math.max(1, this.width - 2 * margin), sh = Math.max(1, this.height - 2 * margin);
    const s = Math.min(sw / Math.max(w, 1e-9), sh / Math.max(h, 1e-9));
    this.scale = Number.isFinite(s) && s > 0 ? s : 1;
    this.minScale = this.scale / 50;
    this.maxScale = this.scale * 5000;
    this.cx = x + w / 2;
    this.cy = y + h / 2;
  }

  /** Shows the rectangle [x, y, w, h] with its top-left corner at screen (sx, sy), `width` pixels wide. */
  place(frame: readonly [number, number, number, number], sx: number, sy: number, width: number): void {
    const [x, y, w] = frame;
    this.scale = Math.min(this.maxScale, Math.max(this.minScale, width / Math.max(w, 1e-9)));
    this.cx = x + (this.width / 2 - sx) / this.scale;
    this.cy = y + (this.height / 2 - sy) / this.scale;
  }

  /** Multiplies the scale by `factor`, keeping the document point under screen (sx, sy) in place. */
  zoomAt(factor: number, sx: number, sy: number): void {
    const [x, y] = this.toDoc(sx, sy);
    this.scale = Math.min(this.maxScale, Math.max(this.minScale, this.scale * factor));
    this.cx = x - (sx - this.width / 2) / this.scale;
    this.cy = y - (sy - this.height / 2) / this.scale;
  }

  /** Moves the content by (dx, dy) screen pixels. */
  panBy(dx: number, dy: number): void {
    this.cx -= dx / this.scale;
    this.cy -= dy / this.scale;
  }

  toDoc(sx: number, sy: number): [number, number] {
    return [this.cx + (sx - this.width / 2) / this.scale, this.cy + (sy - this.height / 2) / this.scale];
  }

  toScreen(x: number, y: number): [number, number] {
    return [(x - this.cx) * this.scale + this.width / 2, (y - this.cy) * this.scale + this.height / 2];
  }

  /** Visible document rectangle as camera planes: left, right, top (smaller y), bottom. */
  planes(): [number, number, number, number] {
    const hw = this.width / 2 / this.scale, hh = this.height / 2 / this.scale;
    return [this.cx - hw, this.cx + hw, this.cy - hh, this.cy + hh];
  }
}
