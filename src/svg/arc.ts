/**
 * SVG elliptical arcs as cubic Béziers (SVG 1.1 implementation notes F.6.5–F.6.6).
 *
 * The arc is split into n equal pieces of at most 90° of sweep, each approximated by the
 * classic cubic with handle length (4/3)·tan(θ/4) on the unit circle, mapped through the
 * ellipse's radii and rotation. A 90° piece strays from the circle by 2.7e-4 of the radius,
 * so n is raised until the error (the radial deviation measured on samples of each piece,
 * mapped to a distance normal to the ellipse) is at most `relativeTolerance` of the size of
 * what contains the arc (the larger of
 * `referenceSize`, e.g. the diagonal of the path's on-curve points, and the arc's own bounds):
 * the arc then stays within that fraction of any drawing containing it. Circles and rounded
 * corners keep their usual 90° pieces; only arcs that are large and eccentric get more.
 */

export interface ArcCommand {
  rX: number;
  rY: number;
  xRot: number; // degrees
  lArcFlag: 0 | 1 | boolean;
  sweepFlag: 0 | 1 | boolean;
  x: number;
  y: number;
}

/**
 * Control points (x1 y1 x2 y2 x y per piece) of the cubics drawing the arc from (x0, y0).
 * A zero radius gives a straight line (one cubic with handles at thirds); coincident end
 * points give nothing, as SVG specifies.
 */
export function arcToCubics(x0: number, y0: number, arc: ArcCommand, referenceSize = 0, relativeTolerance = 1e-4): number[] {
  const { x, y } = arc;
  if (x0 === x && y0 === y) return [];
  let rx = Math.abs(arc.rX), ry = Math.abs(arc.rY);
  if (rx === 0 || ry === 0) return [x0 + (x - x0) / 3, y0 + (y - y0) / 3, x0 + (2 * (x - x0)) / 3, y0 + (2 * (y - y0)) / 3, x, y];

  // F.6.5: endpoint → centre parameterization.
  const phi = ((arc.xRot % 360) * Math.PI) / 180;
  const cos = Math.cos(phi), sin = Math.sin(phi);
  const dx = (x0 - x) / 2, dy = (y0 - y) / 2;
  const x1p = cos * dx + sin * dy, y1p = -sin * dx + cos * dy;
  // F.6.6: scale radii up when no ellipse of the given size reaches both end points.
  const lambda = (x1p * x1p) / (rx * rx) + (y1p * y1p) / (ry * ry);
  if (lambda > 1) {
    const s = Math.sqrt(lambda);
    rx *= s;
    ry *= s;
  }
  const rx2 = rx * rx, ry2 = ry * ry;
  const num = rx2 * ry2 - rx2 * y1p * y1p - ry2 * x1p * x1p;
  const den = rx2 * y1p * y1p + ry2 * x1p * x1p;
  let coef = Math.sqrt(Math.max(0, num / den));
  if (Boolean(arc.lArcFlag) === Boolean(arc.sweepFlag)) coef = -coef;
  const cxp = (coef * rx * y1p) / ry, cyp = (-coef * ry * x1p) / rx;
  const cx = cos * cxp - sin * cyp + (x0 + x) / 2, cy = sin * cxp + cos * cyp + (y0 + y) / 2;

  const angle = (ux: number, uy: number, vx: number, vy: number) => Math.atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  const ux = (x1p - cxp) / rx, uy = (y1p - cyp) / ry, vx = (-x1p - cxp) / rx, vy = (-y1p - cyp) / ry;
  const theta1 = angle(1, 0, ux, uy);
  let sweep = angle(ux, uy, vx, vy);
  if (!arc.sweepFlag && sweep > 0) sweep -= 2 * Math.PI;
  else if (arc.sweepFlag && sweep < 0) sweep += 2 * Math.PI;

  // The arc's own size: the diagonal of its bounds, from dense samples of the true arc.
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (let k = 0; k <= 64; k++) {
    const t = theta1 + (sweep * k) / 64;
    const px = cx + rx * Math.cos(t) * cos - ry * Math.sin(t) * sin, py = cy + rx * Math.cos(t) * sin + ry * Math.sin(t) * cos;
    minX = Math.min(minX, px); maxX = Math.max(maxX, px);
    minY = Math.min(minY, py); maxY = Math.max(maxY, py);
  }
  const size = Math.max(referenceSize, Math.hypot(maxX - minX, maxY - minY));
  let n = Math.max(1, Math.ceil(Math.abs(sweep) / (Math.PI / 2) - 1e-9));
  while (n < 64 && arcError(theta1, sweep / n, n, rx, ry) > relativeTolerance * size) n++;

  const out: number[] = [];
  const d = sweep / n, k = (4 / 3) * Math.tan(d / 4);
  const map = (ex: number, ey: number) => [cx + rx * ex * cos - ry * ey * sin, cy + rx * ex * sin + ry * ey * cos];
  for (let i = 0; i < n; i++) {
    const a = theta1 + i * d, b = a + d;
    const [h1x, h1y] = map(Math.cos(a) - k * Math.sin(a), Math.sin(a) + k * Math.cos(a));
    const [h2x, h2y] = map(Math.cos(b) + k * Math.sin(b), Math.sin(b) - k * Math.cos(b));
    const [ex, ey] = i === n - 1 ? [x, y] : map(Math.cos(b), Math.sin(b));
    out.push(h1x, h1y, h2x, h2y, ex, ey);
  }
  return out;
}

/**
 * Largest distance from n cubic pieces of angle d (from theta1) to the ellipse of radii rx, ry.
 * On the unit circle the cubic deviates radially by ρ at angle τ; the ellipse map turns that
 * into a displacement whose component normal to the ellipse is ρ·rx·ry / |(−rx sin τ, ry cos τ)|.
 */
function arcError(theta1: number, d: number, n: number, rx: number, ry: number): number {
  const k = (4 / 3) * Math.tan(d / 4);
  let worst = 0;
  for (let i = 0; i < n; i++) {
    const a = theta1 + i * d, b = a + d;
    const p0x = Math.cos(a), p0y = Math.sin(a), p3x = Math.cos(b), p3y = Math.sin(b);
    const p1x = p0x - k * p0y, p1y = p0y + k * p0x, p2x = p3x + k * p3y, p2y = p3y - k * p3x;
    for (let j = 1; j < 16; j++) {
      const t = j / 16, s = 1 - t;
      const w0 = s * s * s, w1 = 3 * s * s * t, w2 = 3 * s * t * t, w3 = t * t * t;
      const x = w0 * p0x + w1 * p1x + w2 * p2x + w3 * p3x, y = w0 * p0y + w1 * p1y + w2 * p2y + w3 * p3y;
      const rho = Math.abs(Math.hypot(x, y) - 1), tau = Math.atan2(y, x);
      worst = Math.max(worst, (rho * rx * ry) / Math.hypot(rx * Math.sin(tau), ry * Math.cos(tau)));
    }
  }
  return worst;
}
