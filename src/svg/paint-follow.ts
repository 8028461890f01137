import type { Matrix } from './matrix.js';

/**
 * Paint that follows a deformed shape. A gradient or pattern in user space units stays where the
 * file put it while a skinned shape moves away from it; here each deformed shape gets its own
 * copy of the paint server (inheriting everything through `href`) whose transform is the affine
 * map that best carries the shape's splines as imported to its splines now, so the paint moves,
 * turns and stretches with the shape. Paint in bounding-box units follows the box by itself.
 */

const SERVERS = new Set(['linearGradient', 'radialGradient', 'pattern']);
const XLINK = 'http://www.w3.org/1999/xlink';

/**
 * The least-squares affine map carrying the points `from` to the points `to` (x,y pairs, same
 * count): minimises Σ |A·p + t − q|². Points that span no area (fewer than three, or all on a
 * line) determine no linear part: the map is then the translation of their centroids.
 */
export function fitAffine(from: ArrayLike<number>, to: ArrayLike<number>): Matrix {
  const n = Math.min(from.length, to.length) / 2;
  if (n === 0) return { a: 1, b: 0, c: 0, d: 1, e: 0, f: 0 };
  let mx = 0, my = 0, nx = 0, ny = 0;
  for (let i = 0; i < n; i++) {
    mx += from[2 * i];
    my += from[2 * i + 1];
    nx += to[2 * i];
    ny += to[2 * i + 1];
  }
  mx /= n;
  my /= n;
  nx /= n;
  ny /= n;
  let sxx = 0, sxy = 0, syy = 0, uxx = 0, uxy = 0, uyx = 0, uyy = 0;
  for (let i = 0; i < n; i++) {
    const x = from[2 * i] - mx, y = from[2 * i + 1] - my, u = to[2 * i] - nx, v = to[2 * i + 1] - ny;
    sxx += x * x;
    sxy += x * y;
    syy += y * y;
    uxx += u * x;
    uxy += u * y;
    uyx += v * x;
    uyy += v * y;
  }
  const det = sxx * syy - sxy * sxy;
  if (!(det > 1e-12 * (sxx + syy) ** 2)) return { a: 1, b: 0, c: 0, d: 1, e: nx - mx, f: ny - my };
  const a = (uxx * syy - uxy * sxy) / det, c = (uxy * sxx - uxx * sxy) / det;
  const b = (uyx * syy - uyy * sxy) / det, d = (uyy * sxx - uyx * sxy) / det;
  return { a, b, c, d, e: nx - a * mx - c * my, f: ny - b * mx - d * my };
}

/**
 * The tight bounds [x, y, w, h] of cubic Bézier splines (control points as x,y pairs, open
 * splines 3n+1 points, closed 3n), from the end points and the zeros of each coordinate's
 * derivative; null for no points.
 */
export function splineBounds(splines: readonly { closed: boolean; points: ArrayLike<number> }[]): [number, number, number, number] | null {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  const add = (x: number, y: number) => {
    x0 = Math.min(x0, x);
    x1 = Math.max(x1, x);
    y0 = Math.min(y0, y);
    y1 = Math.max(y1, y);
  };
  for (const s of splines) {
    const p = s.points, n = p.length / 2;
    if (n === 0) continue;
    add(p[0], p[1]);
    const segments = n <= 1 ? 0 : s.closed ? n / 3 : (n - 1) / 3;
    for (let k = 0; k < segments; k++) {
      const i = 6 * k, j = (6 * k + 6) % (2 * n);
      add(p[j], p[j + 1]);
      for (let c = 0; c < 2; c++) {
        // B'(t)/3 = P(1 − t)² + 2Q(1 − t)t + Rt² = (P − 2Q + R)t² + 2(Q − P)t + P, with P, Q, R
        // the differences of consecutive control values.
        const P = p[i + 2 + c] - p[i + c], Q = p[i + 4 + c] - p[i + 2 + c], R = p[j + c] - p[i + 4 + c];
        const qa = P - 2 * Q + R, qb = 2 * (Q - P), qc = P;
        const roots: number[] = [];
        if (Math.abs(qa) <= 1e-12 * (Math.abs(qb) + Math.abs(qc))) {
          if (qb !== 0) roots.push(-qc / qb);
        } else {
          const disc = qb * qb - 4 * qa * qc;
          if (disc >= 0) roots.push((-qb + Math.sqrt(disc)) / (2 * qa), (-qb - Math.sqrt(disc)) / (2 * qa));
        }
        for (const t of roots) {
          if (!(t > 0 && t < 1)) continue;
          const u = 1 - t;
          const x = u * u * u * p[i] + 3 * u * u * t * p[i + 2] + 3 * u * t * t * p[i + 4] + t * t * t * p[j];
          const y = u * u * u * p[i + 1] + 3 * u * u * t * p[i + 3] + 3 * u * t * t * p[i + 5] + t * t * t * p[j + 1];
          add(x, y);
        }
      }
    }
  }
  return x0 <= x1 ? [x0, y0, x1 - x0, y1 - y0] : null;
}

/** The id a paint refers to (`url(#id)`, with an optional fallback), or null. */
export function paintServerId(paint: string): string | null {
  return /^\s*url\(\s*['"]?#([^'")\s]+)['"]?\s*\)/.exec(paint)?.[1] ?? null;
}

/** The element with `id` under `root` (itself included), depth first, without recursion. */
export function findById(root: Element, id: string): Element | null {
  const stack: Element[] = [root];
  while (stack.length) {
    const el = stack.pop()!;
    if (el.getAttribute('id') === id) return el;
    for (let c = el.lastChild; c; c = c.previousSibling) if (c.nodeType === 1) stack.push(c as Element);
  }
  return null;
}

function hrefOf(el: Element): string | null {
  return el.getAttribute('href') ?? el.getAttributeNS(XLINK, 'href') ?? el.getAttribute('xlink:href');
}

/** An attribute of a paint server, looked up through its `href` chain (at most 16 links). */
function inherited(root: Element, server: Element, name: string): string | null {
  let el: Element | null = server;
  for (let hops = 0; el && hops < 16; hops++) {
    const v = el.getAttribute(name);
    if (v !== null) return v;
    const href = hrefOf(el);
    el = href?.startsWith('#') ? findById(root, href.slice(1)) : null;
  }
  return null;
}

/** Geometry attributes of a gradient and their initial values in bounding-box units. */
const GEOMETRY: Record<string, [string, string][]> = {
  linearGradient: [['x1', '0'], ['y1', '0'], ['x2', '1'], ['y2', '0']],
  radialGradient: [['cx', '0.5'], ['cy', '0.5'], ['r', '0.5'], ['fx', ''], ['fy', ''], ['fr', '0']],
};

/** A number or percentage in bounding-box units (50% = 0.5). */
function fraction(v: string): number {
  const t = v.trim();
  return t.endsWith('%') ? parseFloat(t) / 100 : parseFloat(t);
}

const format = (v: number) => String(Number(v.toPrecision(12)));
const matrixText = (m: Matrix) => `matrix(${format(m.a)} ${format(m.b)} ${format(m.c)} ${format(m.d)} ${format(m.e)} ${format(m.f)})`;

/**
 * Prepares `shape`'s paint (`which`: 'fill' or 'stroke', whose value is `paint`) to follow maps
 * of its user space, and returns the function that sets the map; null, changing nothing, when the
 * paint is not a gradient or user-space pattern under `root` (or is a bounding-box gradient and
 * `box()`, the shape's bounds [x, y, w, h] as imported in its user space, has no area). The shape
 * gets its own copy of the paint server (id `<server>-splinekit-<key>-<which>`, placed after the
 * server, reused when it is there already) and its inline style points at it; the map sets the
 * copy's transform to m followed by the server's own (and, for a bounding-box gradient, by the
 * box's map, the copy being in user space).
 */
export function paintFollower(
  root: Element,
  shape: Element,
  key: string,
  which: 'fill' | 'stroke',
  paint: string,
  box: () => [number, number, number, number] | null,
): ((m: Matrix) => void) | null {
  const id = paintServerId(paint);
  const server = id ? findById(root, id) : null;
  const kind = server?.localName ?? '';
  if (!server || !SERVERS.has(kind)) return null;
  const pattern = kind === 'pattern';
  const userSpace = inherited(root, server, pattern ? 'patternUnits' : 'gradientUnits') === 'userSpaceOnUse';
  let boxMatrix = '';
  const geometry: [string, string][] = [];
  if (!userSpace) {
    const b = pattern ? null : box();
    if (!b || !(b[2] > 0 && b[3] > 0)) return null;
    boxMatrix = `${matrixText({ a: b[2], b: 0, c: 0, d: b[3], e: b[0], f: b[1] })} `;
    const values = new Map<string, string>();
    for (const [name, initial] of GEOMETRY[kind]) {
      const v = inherited(root, server, name);
      // The focus defaults to the centre.
      values.set(name, String(fraction(v ?? (initial || values.get(name === 'fx' ? 'cx' : 'cy')!))));
    }
    geometry.push(...values);
  }
  const transformName = pattern ? 'patternTransform' : 'gradientTransform';
  const copyId = `${id}-splinekit-${key}-${which}`;
  let copy = findById(server.parentNode as Element, copyId);
  if (!copy) {
    const doc = server.ownerDocument!;
    copy = doc.createElementNS(server.namespaceURI, server.prefix ? `${server.prefix}:${kind}` : kind);
    copy.setAttribute('id', copyId);
    copy.setAttributeNS(XLINK, 'xlink:href', `#${id}`);
    if (!userSpace) {
      copy.setAttribute('gradientUnits', 'userSpaceOnUse');
      for (const [name, value] of geometry) copy.setAttribute(name, value);
    }
    server.parentNode!.insertBefore(copy, server.nextSibling);
  }
  const style = shape.getAttribute('style') ?? '';
  if (!style.includes(`url(#${copyId})`)) shape.setAttribute('style', `${style ? `${style.replace(/;\s*$/, '')};` : ''}${which}:url(#${copyId})`);
  const own = inherited(root, server, transformName) ?? '';
  const target = copy;
  return (m) => target.setAttribute(transformName, `${matrixText(m)} ${boxMatrix}${own}`.trim());
}
