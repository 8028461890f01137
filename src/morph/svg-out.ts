/**
 * SVG markup for morph in-betweens: one path per frame, and animated files whose frames share
 * one command structure ("M C C … Z" per contour), so SMIL or CSS can interpolate the path data.
 */
import { SplinekitError } from '../core/errors.js';
import type { Spline } from '../spline/spline.js';
import { formatNumber, splinesToPathData } from '../svg/path-data.js';

/** Paint of a morph's SVG output. */
export interface MorphStyle {
  /** CSS color or 'none'. */
  fill: string;
  /** Fill rule of the path. */
  fillRule: 'nonzero' | 'evenodd';
  /** CSS color of the outline, if any. */
  stroke?: string;
  /** Width of the outline in document units. */
  strokeWidth?: number;
}

/** Options of {@link Morph.animatedSVG}. */
export interface MorphAnimationOptions {
  /** Frames sampled at t = i/(frames−1). Default 25. */
  frames?: number;
  /** Seconds from the first key to the second. Default 2. */
  duration?: number;
  /** Play back to the first key after reaching the second (a loop that does not jump). Default true. */
  alternate?: boolean;
  /** 'smil' (`<animate>`, default) or 'css' (`@keyframes` of `d: path(...)`). */
  format?: 'smil' | 'css';
  /** Repetitions, or 'indefinite'. Default 'indefinite'. */
  repeat?: number | 'indefinite';
}

function escapeAttr(s: string): string {
  return s.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
}

function header(frame: readonly number[]): string {
  const pad = 0.05 * Math.max(frame[2] - frame[0], frame[3] - frame[1], 1e-9);
  const vb = [frame[0] - pad, frame[1] - pad, frame[2] - frame[0] + 2 * pad, frame[3] - frame[1] + 2 * pad].map(formatNumber).join(' ');
  return `<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" viewBox="${vb}" width="${formatNumber(frame[2] - frame[0] + 2 * pad)}" height="${formatNumber(frame[3] - frame[1] + 2 * pad)}">\n`;
}

function paint(style: MorphStyle): string {
  let s = `fill="${escapeAttr(style.fill)}" fill-rule="${style.fillRule}"`;
  if (style.stroke) s += ` stroke="${escapeAttr(style.stroke)}" stroke-width="${formatNumber(style.strokeWidth ?? 1)}"`;
  return s;
}

/** One in-between as an SVG document. */
export function morphFrameSVG(splines: readonly Spline[], style: MorphStyle, frame: readonly number[]): string {
  return `${header(frame)}  <path ${paint(style)} d="${splinesToPathData(splines)}"/>\n</svg>\n`;
}

/** Frames (each the splines of one in-between, same structure) as an animated SVG. */
export function morphAnimatedSVG(frames: readonly (readonly Spline[])[], style: MorphStyle, frame: readonly number[], options: MorphAnimationOptions): string {
  const duration = options.duration ?? 2;
  if (!(Number.isFinite(duration) && duration > 0)) throw new SplinekitError('invalid-input', `morph animation: duration must be a positive number of seconds, got ${duration}`);
  const repeat = options.repeat ?? 'indefinite';
  const format = options.format ?? 'smil';
  if (format !== 'smil' && format !== 'css') throw new SplinekitError('invalid-input', `morph animation: format must be smil or css, got "${String(format)}"`);
  let values = frames.map((f) => splinesToPathData(f));
  if (options.alternate ?? true) values = [...values, ...values.slice(0, -1).reverse()];
  const total = (options.alternate ?? true) ? 2 * duration : duration;
  const times = values.map((_, i) => formatNumber(i / (values.length - 1)));
  if (format === 'smil') {
    return `${header(frame)}  <path ${paint(style)} d="${values[0]}">\n    <animate attributeName="d" dur="${formatNumber(total)}s" repeatCount="${repeat}" keyTimes="${times.join(';')}" values="${values.join(';')}"/>\n  </path>\n</svg>\n`;
  }
  const keyframes = values.map((v, i) => `${formatNumber(100 * i / (values.length - 1))}% { d: path("${v}"); }`).join('\n    ');
  const count = repeat === 'indefinite' ? 'infinite' : String(repeat);
  return `${header(frame)}  <style>\n    @keyframes splinekit-morph {\n    ${keyframes}\n    }\n    .splinekit-morph { animation: splinekit-morph ${formatNumber(total)}s linear ${count}; }\n  </style>\n  <path class="splinekit-morph" ${paint(style)} d="${values[0]}"/>\n</svg>\n`;
}
