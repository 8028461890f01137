/**
 * SVG basic shapes as their path equivalents (SVG 1.1 §9): rect (rounded too), circle,
 * ellipse, line, polyline and polygon. Each returns path data, or '' when the shape does not
 * render (zero size), and may report a problem through `warn`.
 */

export interface Viewport {
  width: number;
  height: number;
}

/** A length attribute in user units; percentages resolve against the viewport. */
export function length(el: Element, name: string, vp: Viewport, axis: 'x' | 'y' | 'd', fallback = 0): number {
  const raw = el.getAttribute(name);
  if (raw === null || raw.trim() === '' || raw.trim() === 'auto') return fallback;
  const m = /^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(px|%)?\s*$/.exec(raw);
  if (!m) throw new Error(`${name}="${raw}" is not a length`);
  const v = parseFloat(m[1]);
  if (!Number.isFinite(v)) throw new Error(`${name}="${raw}" is not finite`);
  if (m[2] !== '%') return v;
  const ref = axis === 'x' ? vp.width : axis === 'y' ? vp.height : Math.hypot(vp.width, vp.height) / Math.SQRT2;
  return (v / 100) * ref;
}

function arcTo(rx: number, ry: number, x: number, y: number): string {
  return `A${rx} ${ry} 0 0 1 ${x} ${y}`;
}

export function rectPath(el: Element, vp: Viewport): string {
  const x = length(el, 'x', vp, 'x'), y = length(el, 'y', vp, 'y');
  const w = length(el, 'width', vp, 'x'), h = length(el, 'height', vp, 'y');
  if (!(w > 0 && h > 0)) return '';
  const hasRx = el.hasAttribute('rx') && el.getAttribute('rx') !== 'auto';
  const hasRy = el.hasAttribute('ry') && el.getAttribute('ry') !== 'auto';
  let rx = hasRx ? length(el, 'rx', vp, 'x') : 0;
  let ry = hasRy ? length(el, 'ry', vp, 'y') : 0;
  if (hasRx && !hasRy) ry = rx;
  if (hasRy && !hasRx) rx = ry;
  rx = Math.min(Math.max(rx, 0), w / 2);
  ry = Math.min(Math.max(ry, 0), h / 2);
  if (rx === 0 || ry === 0) return `M${x} ${y}H${x + w}V${y + h}H${x}Z`;
  return (
    `M${x + rx} ${y}H${x + w - rx}${arcTo(rx, ry, x + w, y + ry)}V${y + h - ry}${arcTo(rx, ry, x + w - rx, y + h)}` +
    `H${x + rx}${arcTo(rx, ry, x, y + h - ry)}V${y + ry}${arcTo(rx, ry, x + rx, y)}Z`
  );
}

export function ellipsePath(cx: number, cy: number, rx: number, ry: number): string {
  if (!(rx > 0 && ry > 0)) return '';
  return (
    `M${cx + rx} ${cy}${arcTo(rx, ry, cx, cy + ry)}${arcTo(rx, ry, cx - rx, cy)}` +
    `${arcTo(rx, ry, cx, cy - ry)}${arcTo(rx, ry, cx + rx, cy)}Z`
  );
}

export function circlePath(el: Element, vp: Viewport): string {
  const r = length(el, 'r', vp, 'd');
  return ellipsePath(length(el, 'cx', vp, 'x'), length(el, 'cy', vp, 'y'), r, r);
}

export function ellipseElementPath(el: Element, vp: Viewport): string {
  let rx = length(el, 'rx', vp, 'x', NaN), ry = length(el, 'ry', vp, 'y', NaN);
  if (Number.isNaN(rx)) rx = ry;
  if (Number.isNaN(ry)) ry = rx;
  return ellipsePath(length(el, 'cx', vp, 'x'), length(el, 'cy', vp, 'y'), rx, ry);
}

export function linePath(el: Element, vp: Viewport): string {
  return `M${length(el, 'x1', vp, 'x')} ${length(el, 'y1', vp, 'y')}L${length(el, 'x2', vp, 'x')} ${length(el, 'y2', vp, 'y')}`;
}

/** polyline / polygon; an odd coordinate count drops the last one, as SVG renderers do, with a warning. */
export function polyPath(el: Element, closed: boolean, warn: (message: string) => void): string {
  const raw = (el.getAttribute('points') ?? '').trim();
  if (raw === '') return '';
  const tokens = raw.split(/[\s,]+|(?<=\d)(?=-)/).filter((t) => t !== '');
  const nums = tokens.map(Number);
  const bad = nums.findIndex((v) => !Number.isFinite(v));
  if (bad >= 0) throw new Error(`points has "${tokens[bad]}", which is not a finite number`);
  if (nums.length % 2 === 1) warn(`points has an odd number of coordinates (${nums.length}); the last is ignored`);
  if (nums.length < 4) return '';
  let d = `M${nums[0]} ${nums[1]}`;
  for (let i = 2; i + 1 < nums.length; i += 2) d += `L${nums[i]} ${nums[i + 1]}`;
  return closed ? `${d}Z` : d;
}
