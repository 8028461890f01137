import { segmentCount, type SvgDocument } from '../../../src/index.js';
import { cubicPointInto } from '../../view2d/cubic.js';
import { flattenSpline } from '../../view2d/tessellate.js';
import { LineCanvas, LineLayer } from '../../view2d/line-canvas.js';
import type { View2D } from '../../view2d/view2d.js';
import { HEAT, Ramp, SKIN_COLORS, WEIGHT } from './colors.js';

/** A position per curve sample (samples `perCurve` per curve, curve order), evaluated on demand. */
export type SampleField = (k: number, out: Float32Array, o: number) => void;

/** The field of an array of x,y pairs. */
function fieldOf(xy: Float64Array): SampleField {
  return (k, out, o) => {
    out[o] = xy[2 * k];
    out[o + 1] = xy[2 * k + 1];
  };
}

/** What the layers show; each is drawn only when on and its data is given. */
export interface CurveLayerData {
  doc: SvgDocument;
  /** Samples per curve of the arrays below. */
  perCurve: number;
  /** Target position at curve sample k (written at out[o], out[o + 1]), dashed. */
  target: SampleField | null;
  /** Per curve error (for the heat map), or null for a plain target. */
  heat: Float64Array | null;
  /** Control points of the naive baseline (all splines), drawn as an outline. */
  naive: Float64Array | null;
  /** Curve positions (x,y pairs at the samples) and the selected handle's weight at each. */
  field: { positions: Float64Array; weights: Float64Array } | null;
}

/** Of the rig's samples per curve, at most every STRIDE-th is drawn (25 of the paper's 100: smooth on screen). */
const STRIDE = 4;
/** Screen length (pixels) a drawn segment aims at: curves small on screen get fewer segments. */
const SEGMENT_PX = 4;

/** The samples drawn along each spline (indices into the per-curve samples), and the segment count. */
interface Picks {
  doc: SvgDocument;
  perCurve: number;
  scale: number;
  lines: number[][];
  total: number;
}

/**
 * Which samples to draw: each curve gets as many points as its control polygon at rest is long on
 * screen in SEGMENT_PX steps (scale: pixels per unit), at least one and at most every STRIDE-th
 * sample, so a detailed drawing seen whole draws no more than the screen shows.
 */
function pickSamples(doc: SvgDocument, perCurve: number, scale: number): Picks {
  const most = Math.ceil(perCurve / STRIDE);
  const picks: number[][] = [];
  let total = 0, curve = 0;
  for (const s of doc.splines) {
    const n = segmentCount(s), p = s.points, count = p.length / 2;
    const line: number[] = [];
    for (let k = 0; k < n; k++, curve++) {
      let length = 0;
      for (let j = 0; j < 3; j++) {
        const a = 2 * (3 * k + j), b = 2 * ((3 * k + j + 1) % count);
        length += Math.hypot(p[b] - p[a], p[b + 1] - p[a + 1]);
      }
      const m = Math.min(most, Math.max(1, Math.ceil((length * scale) / SEGMENT_PX)));
      for (let j = 0; j < m; j++) line.push(curve * perCurve + Math.min(perCurve - 1, Math.floor(((j + 0.5) * perCurve) / m)));
    }
    picks.push(line);
    if (line.length >= 2) total += s.closed ? line.length : line.length - 1;
  }
  return { doc, perCurve, scale, lines: picks, total };
}

/**
 * Polylines through the picked samples along each spline (closed splines wrap around), as
 * segments x0 y0 x1 y1 with a color per end (none when `color` is null: see segmentColors).
 */
function sampleSegments(picks: Picks, at: SampleField, color: ((curve: number, sample: number, out: Float32Array, at: number) => void) | null) {
  const { doc, perCurve, total } = picks;
  const segments = new Float32Array(total * 4), colors = new Float32Array(color ? total * 6 : 0);
  let seg = 0;
  let xy = new Float32Array(0);
  doc.splines.forEach((s, i) => {
    const line = picks.lines[i], m = line.length;
    if (m < 2) return;
    // Each picked point once, then the segments between consecutive ones.
    if (xy.length < 2 * m) xy = new Float32Array(2 * m);
    for (let j = 0; j < m; j++) at(line[j], xy, 2 * j);
    const count = s.closed ? m : m - 1;
    for (let j = 0; j < count; j++) {
      const a = j, b = (j + 1) % m;
      segments[4 * seg] = xy[2 * a];
      segments[4 * seg + 1] = xy[2 * a + 1];
      segments[4 * seg + 2] = xy[2 * b];
      segments[4 * seg + 3] = xy[2 * b + 1];
      if (color) {
        color(Math.floor(line[a] / perCurve), line[a], colors, 6 * seg);
        color(Math.floor(line[b] / perCurve), line[b], colors, 6 * seg + 3);
      }
      seg++;
    }
  });
  return { segments, colors };
}

/** The colors of sampleSegments' segments (6 per segment, in its order), from a color per curve sample. */
function segmentColors(picks: Picks, color: (curve: number, sample: number, out: Float32Array, at: number) => void): Float32Array {
  const { doc, perCurve, total } = picks;
  const colors = new Float32Array(total * 6);
  let seg = 0;
  doc.splines.forEach((s, i) => {
    const line = picks.lines[i], m = line.length;
    if (m < 2) return;
    const count = s.closed ? m : m - 1;
    for (let j = 0; j < count; j++, seg++) {
      const a = line[j], b = line[(j + 1) % m];
      color(Math.floor(a / perCurve), a, colors, 6 * seg);
      color(Math.floor(b / perCurve), b, colors, 6 * seg + 3);
    }
  });
  return colors;
}

/** Positions on the curves given by `points` (all splines) at the rig's sample parameters (k + ½)/S. */
export function curveSamples(doc: SvgDocument, points: Float64Array, perCurve: number): Float64Array {
  let curves = 0;
  for (const s of doc.splines) curves += segmentCount(s);
  const out = new Float64Array(curves * perCurve * 2);
  let at = 0, o = 0;
  for (const s of doc.splines) {
    const n = segmentCount(s), count = s.points.length / 2;
    for (let k = 0; k < n; k++) {
      const i0 = at + 2 * (3 * k), i1 = at + 2 * (3 * k + 1), i2 = at + 2 * (3 * k + 2), i3 = at + 2 * ((3 * k + 3) % count);
      for (let j = 0; j < perCurve; j++, o += 2) cubicPointInto(points, i0, i1, i2, i3, (j + 0.5) / perCurve, out, o);
    }
    at += s.points.length;
  }
  return out;
}

/** sRGB of a '#rrggbb' color. */
function rgb(hex: string): Float32Array {
  const out = new Float32Array(3);
  new Ramp([hex, hex]).srgbInto(0, out, 0);
  return out;
}

/**
 * Skin mode's curves over the drawing, as lines of constant screen width on a 2D canvas: the target (dashed,
 * optionally colored by the per-curve error, red at the maximum … purple at the minimum, as in the
 * paper, here on the scale of RMS distance), the naive baseline's outline, and the selected handle's weight field along the curves.
 */
export class CurveLayers {
  private readonly field = new LineLayer(5, null);
  private readonly naive = new LineLayer(1.75, null);
  private readonly target = new LineLayer(1, { dash: 7, gap: 5 });
  private readonly canvas: LineCanvas;
  /** What is drawn, to draw it again when the zoom changes enough to want other sample counts. */
  private data: CurveLayerData | null = null;
  /** The zoom (log2 of the scale, rounded down) the samples were picked for. */
  private zoomLevel = NaN;

  constructor(private readonly view: View2D) {
    this.canvas = new LineCanvas(view, [this.field, this.naive, this.target]);
    this.viewChanged();
  }

  /** Draws the lines for the new view (and picks other samples when the zoom changed enough). */
  viewChanged(): void {
    if (this.data && Math.floor(Math.log2(this.view.viewport.scale)) !== this.zoomLevel) this.update(this.data);
    else this.canvas.draw();
  }

  update(data: CurveLayerData | null): void {
    this.data = data;
    this.zoomLevel = Math.floor(Math.log2(this.view.viewport.scale));
    this.setTarget(data);
    this.setNaive(data);
    this.setField(data);
    this.canvas.draw();
  }

  /** The target's segment colors and what they were computed for. */
  private targetColors: { picks: Picks; heat: Float64Array | null; max: number; colors: Float32Array } | null = null;

  /** The samples to draw for `data`'s drawing at the current zoom level (picked again when either changes). */
  private picked: Picks | null = null;

  private picksFor(data: CurveLayerData): Picks {
    // The scale samples are picked for: the top of the current zoom level's range.
    const scale = 2 ** (this.zoomLevel + 1);
    const p = this.picked;
    if (p && p.doc === data.doc && p.perCurve === data.perCurve && p.scale === scale) return p;
    return (this.picked = pickSamples(data.doc, data.perCurve, scale));
  }

  /** Drawn segment counts per layer (for tests). */
  get counts(): { target: number; naive: number; field: number } {
    return { target: this.target.count, naive: this.naive.count, field: this.field.count };
  }

  private setTarget(data: CurveLayerData | null): void {
    if (!data?.target) return this.target.hide();
    const heat = data.heat;
    // Normalized by the largest error, but never by less than (1e-6 of the drawing's size)², far
    // above rounding: a pose fitted exactly (at rest) stays at the minimum color, not noise.
    let max = (1e-6 * data.doc.size) ** 2;
    if (heat) for (const e of heat) if (e > max) max = e;
    const picks = this.picksFor(data);
    const { segments } = sampleSegments(picks, data.target, null);
    // The colors stay while the picks and errors do (a drag shows the errors last measured).
    const c = this.targetColors;
    if (!c || c.picks !== picks || c.heat !== heat || c.max !== max) {
      const plain = rgb(SKIN_COLORS.target);
      const colors = segmentColors(picks, (curve, _k, out, at) => {
        // The square root: colors go with the curve's RMS distance, so one bad curve does not
        // leave all the others at the bottom of the scale.
        if (heat) HEAT.srgbInto(Math.sqrt(heat[curve] / max), out, at);
        else out.set(plain, at);
      });
      this.targetColors = { picks, heat, max, colors };
    }
    this.target.set(segments, this.targetColors!.colors);
  }

  private setNaive(data: CurveLayerData | null): void {
    if (!data?.naive) return this.naive.hide();
    const xy: number[] = [];
    let at = 0;
    const tolerance = 0.25 / this.view.viewport.scale;
    for (const s of data.doc.splines) {
      const points = data.naive.subarray(at, at + s.points.length);
      at += s.points.length;
      const line = flattenSpline({ closed: s.closed, points, continuity: [] }, tolerance, 48);
      for (let i = 0; i + 1 < line.length; i++) xy.push(line[i].x, line[i].y, line[i + 1].x, line[i + 1].y);
    }
    const colors = new Float32Array((xy.length / 4) * 6);
    const c = rgb(SKIN_COLORS.naive);
    for (let i = 0; i < colors.length; i += 3) colors.set(c, i);
    this.naive.set(new Float32Array(xy), colors);
  }

  private setField(data: CurveLayerData | null): void {
    const f = data?.field;
    if (!data || !f) return this.field.hide();
    const { segments, colors } = sampleSegments(this.picksFor(data), fieldOf(f.positions), (_c, k, out, at) => WEIGHT.srgbInto(f.weights[k], out, at));
    this.field.set(segments, colors);
  }

  dispose(): void {
    this.canvas.dispose();
  }
}
