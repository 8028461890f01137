/**
 * The triangulated domain on which automatic skinning weights (harmonic, BBW) are computed for a
 * 2D drawing. Liu, Jacobson & Gingold 2014 (§5) triangulate a cage or the largest closed curve and
 * add the curve samples as meshing constraints; here the domain is a boundary polygon (a given cage
 * or, by default, the convex hull of the drawing grown by a margin), meshed by a constrained
 * Delaunay triangulation (delaunator + constrainautor) of the boundary, the handles, the curve
 * samples thinned to the mesh spacing and a jittered lattice of interior points.
 */
import Delaunator from 'delaunator';
import ConstrainautorImport from '@kninnug/constrainautor';
import { SplinekitError } from '../core/errors.js';
import { mulberry32 } from '../core/random.js';

// The package's types are its CommonJS-flavoured TypeScript source, read differently under NodeNext
// and bundler resolution; at runtime its ES build's default export is the class itself.
type ConstrainautorClass = new (del: Delaunator<Float64Array>, edges?: readonly [number, number][]) => { constrainAll(edges: readonly [number, number][]): unknown };
const Constrainautor = ConstrainautorImport as unknown as ConstrainautorClass;

/** Options of {@link buildDomain}: the outline and the density of the domain's triangle mesh. */
export interface DomainOptions {
  /**
   * The domain's outline: a closed polygon as x,y pairs (the closing edge is implied), e.g. the
   * largest closed curve of the drawing sampled, or a user cage. Default: the convex hull of the
   * samples and handles, grown by `margin`.
   */
  boundary?: Float64Array;
  /** About how many triangles the mesh should have. Default 8000. */
  targetTriangles?: number;
  /** How far the default boundary lies outside the hull, in drawing units. Default 5% of the diagonal of the bounds of samples and handles. */
  margin?: number;
  /** Seed of the lattice jitter (the mesh is deterministic for a given seed). Default 1. */
  seed?: number;
}

/** A triangle mesh of the domain, ready for `SkinWeights`. */
export interface Domain {
  /** #V by 2: x,y per vertex. */
  vertices: Float64Array;
  /** #F by 3: vertex indices, counter-clockwise (positive area). */
  triangles: Int32Array;
  /** #H: the vertex of each handle (at the handle's exact position). */
  handleVertices: Int32Array;
  /** The lattice spacing the mesh was built with (about the edge length of an interior triangle). */
  spacing: number;
}

export const DEFAULT_DOMAIN = { targetTriangles: 8000, marginFraction: 0.05, seed: 1 } as const;

/** Points closer than this fraction of the spacing are the same point. */
const MERGE = 1e-3;
/** Curve samples and lattice points closer than this fraction of the spacing to a kept point are dropped (mesh quality). */
const CLEARANCE = 0.6;

/**
 * Triangulates the domain of a drawing for skinning weights.
 *
 * @param samples points on the drawing's curves, x,y pairs (e.g. `SplineSet.sample(k)`)
 * @param handlePoints point handles, as x,y pairs or {x, y} objects: each becomes a mesh vertex at
 *   exactly its position
 * @throws SplinekitError('invalid-input') for no handles, non-finite coordinates, coincident
 *   handles, handles outside the boundary, or a boundary that is degenerate or crosses itself
 */
export function buildDomain(
  samples: Float64Array,
  handlePoints: Float64Array | readonly { readonly x: number; readonly y: number }[],
  options: DomainOptions = {},
): Domain {
  const handles = handlePoints instanceof Float64Array ? handlePoints : Float64Array.from(handlePoints.flatMap((p) => [p.x, p.y]));
  checkPoints(samples, 'samples');
  checkPoints(handles, 'handles');
  if (handles.length === 0) throw invalid('at least one handle is needed');
  const target = options.targetTriangles ?? DEFAULT_DOMAIN.targetTriangles;
  if (!Number.isFinite(target) || target < 2) throw invalid(`targetTriangles must be a number ≥ 2, got ${target}`);

  const box = bounds([samples, handles, options.boundary ?? new Float64Array()]);
  const diagonal = Math.hypot(box[2] - box[0], box[3] - box[1]) || 1;
  let outline: Float64Array;
  if (options.boundary) {
    checkPoints(options.boundary, 'boundary');
    outline = dropRepeats(options.boundary, diagonal * 1e-12);
    if (outline.length < 6) throw invalid('the boundary needs at least 3 distinct points');
  } else {
    const margin = options.margin ?? DEFAULT_DOMAIN.marginFraction * diagonal;
    if (!Number.isFinite(margin) || margin < 0) throw invalid(`margin must be a finite number ≥ 0, got ${margin}`);
    outline = grownHull(concat(samples, handles), margin);
  }
  let area = signedArea(outline);
  if (area < 0) outline = reversed(outline);
  area = Math.abs(area);
  if (!(area > 1e-12 * diagonal * diagonal)) throw invalid('the boundary encloses no area');

  const handleCount = handles.length / 2;
  for (let i = 0; i < handleCount; i++) {
    const x = handles[2 * i], y = handles[2 * i + 1];
    if (!insidePolygon(outline, x, y) && distanceToPolygon(outline, x, y) > 1e-9 * diagonal) {
      throw invalid(`handle ${i} at (${x}, ${y}) lies outside the boundary`);
    }
  }

  // Spacing of a triangular lattice with `target` triangles over the area (each lattice point
  // owns two triangles of area √3/4 h²), then corrected once or twice for the vertices that the
  // boundary and the curve samples add.
  let spacing = Math.sqrt((4 * area) / (Math.sqrt(3) * target));
  checkHandleSpacing(handles, spacing);
  let points = placePoints(samples, handles, outline, spacing, options.seed ?? DEFAULT_DOMAIN.seed);
  for (let pass = 0; pass < 3; pass++) {
    const estimate = 2 * (points.xy.length / 2) - points.boundary.length - 2;  // Euler: F = 2V − B − 2
    if (Math.abs(estimate / target - 1) < 0.1) break;
    spacing *= Math.sqrt(estimate / target);
    checkHandleSpacing(handles, spacing);
    points = placePoints(samples, handles, outline, spacing, options.seed ?? DEFAULT_DOMAIN.seed);
  }
  return triangulate(points, handleCount, spacing);
}

// ---------------------------------------------------------------------------------------------
// Points
// ---------------------------------------------------------------------------------------------

interface DomainPoints {
  /** x,y pairs: handles first (point i = handle i), then boundary, samples, lattice. */
  xy: Float64Array;
  /** The boundary polygon as point indices, counter-clockwise (may pass through handles). */
  boundary: Int32Array;
}

function placePoints(samples: Float64Array, handles: Float64Array, outline: Float64Array, h: number, seed: number): DomainPoints {
  const box = bounds([outline]);
  const grid = new PointGrid(box, CLEARANCE * h);
  const handleCount = handles.length / 2;
  for (let i = 0; i < handleCount; i++) grid.add(handles[2 * i], handles[2 * i + 1]);

  // Boundary: resampled to spacing ≤ h, so that any point on it is within h/2 of a boundary vertex
  // (and thus cleared below); vertices that fall on a handle become that handle.
  const ring = resampleClosed(outline, h);
  const boundary: number[] = [];
  const m = ring.length / 2;
  for (let k = 0; k < m; k++) {
    const x = ring[2 * k], y = ring[2 * k + 1];
    const near = grid.nearest(x, y, MERGE * h);
    const index = near >= 0 && near < handleCount ? near : grid.add(x, y);
    if (boundary[boundary.length - 1] !== index) boundary.push(index);
    // A handle on the edge to the next vertex becomes a vertex of the boundary too.
    const nx = ring[(2 * k + 2) % ring.length], ny = ring[(2 * k + 3) % ring.length];
    const on: [number, number][] = [];
    for (let i = 0; i < handleCount; i++) {
      const t = projectOnSegment(handles[2 * i], handles[2 * i + 1], x, y, nx, ny);
      if (t > 0 && t < 1 && distanceToSegment(handles[2 * i], handles[2 * i + 1], x, y, nx, ny) < MERGE * h) on.push([t, i]);
    }
    on.sort((a, b) => a[0] - b[0]);
    for (const [, i] of on) if (boundary[boundary.length - 1] !== i) boundary.push(i);
  }
  while (boundary.length > 1 && boundary[0] === boundary[boundary.length - 1]) boundary.pop();
  if (boundary.length < 3) throw invalid('the boundary is too small for the mesh spacing');

  // Curve samples inside the boundary, then the jittered triangular lattice, each kept only
  // when clear of every point kept so far.
  const clearance = CLEARANCE * h;
  for (let k = 0; k < samples.length; k += 2) {
    const x = samples[k], y = samples[k + 1];
    if (grid.nearest(x, y, clearance) < 0 && insidePolygon(outline, x, y)) grid.add(x, y);
  }
  const random = mulberry32(seed);
  const row = (h * Math.sqrt(3)) / 2;
  for (let j = 0; box[1] + j * row <= box[3]; j++) {
    for (let x = box[0] + (j % 2 ? h / 2 : 0); x <= box[2]; x += h) {
      const px = x + (random() - 0.5) * 0.3 * h, py = box[1] + j * row + (random() - 0.5) * 0.3 * h;
      if (grid.nearest(px, py, clearance) < 0 && insidePolygon(outline, px, py)) grid.add(px, py);
    }
  }
  return { xy: grid.points(), boundary: Int32Array.from(boundary) };
}

function triangulate(points: DomainPoints, handleCount: number, h: number): Domain {
  const { xy, boundary } = points;
  const polygon = new Float64Array(boundary.length * 2);
  boundary.forEach((p, k) => {
    polygon[2 * k] = xy[2 * p];
    polygon[2 * k + 1] = xy[2 * p + 1];
  });
  const crossing = selfIntersection(polygon);
  if (crossing) throw invalid(`the boundary crosses itself near (${crossing[0]}, ${crossing[1]})`);
  // Resampling to the spacing can cut a sharp corner of the boundary off; a handle there is lost.
  for (let i = 0; i < handleCount; i++) {
    const x = xy[2 * i], y = xy[2 * i + 1];
    if (!insidePolygon(polygon, x, y) && distanceToPolygon(polygon, x, y) > MERGE * h) {
      throw invalid(`handle ${i} at (${x}, ${y}) lies outside the boundary as resampled to the mesh spacing ${h}`);
    }
  }

  // Four far corners join the points so that the boundary is never on the convex hull of the
  // triangulation: collinear hull points (the straight edges of a resampled boundary) break the
  // constrained triangulation. Their triangles lie outside the boundary and are dropped below.
  const box = bounds([xy]);
  const far = Math.hypot(box[2] - box[0], box[3] - box[1]);
  const all = new Float64Array(xy.length + 8);
  all.set(xy);
  all.set([box[0] - far, box[1] - far, box[2] + far, box[1] - far, box[2] + far, box[3] + far, box[0] - far, box[3] + far], xy.length);
  const delaunay = new Delaunator(all);
  const edges: [number, number][] = [];
  for (let k = 0; k < boundary.length; k++) edges.push([boundary[k], boundary[(k + 1) % boundary.length]]);
  try {
    new Constrainautor(delaunay, edges);
  } catch (err) {
    throw new SplinekitError('invalid-input', `skin domain: could not triangulate the boundary (${String(err)})`, { cause: err });
  }

  // Keep the triangles inside the boundary (their centroids decide: every triangle lies entirely
  // on one side of the constrained boundary edges), oriented counter-clockwise; drop slivers of
  // zero area that collinear boundary points can produce.
  const tri = delaunay.triangles;
  const kept: number[] = [];
  for (let t = 0; t < tri.length; t += 3) {
    const a = tri[t];
    let b = tri[t + 1], c = tri[t + 2];
    const cx = (all[2 * a] + all[2 * b] + all[2 * c]) / 3, cy = (all[2 * a + 1] + all[2 * b + 1] + all[2 * c + 1]) / 3;
    const twice = (all[2 * b] - all[2 * a]) * (all[2 * c + 1] - all[2 * a + 1]) - (all[2 * c] - all[2 * a]) * (all[2 * b + 1] - all[2 * a + 1]);
    if (Math.abs(twice) <= 1e-12 * h * h || !insidePolygon(polygon, cx, cy)) continue;
    if (twice < 0) [b, c] = [c, b];
    kept.push(a, b, c);
  }

  // Compact the vertices to those used by a triangle.
  const remap = new Int32Array(all.length / 2).fill(-1);
  let count = 0;
  for (const v of kept) if (remap[v] < 0) remap[v] = count++;
  const vertices = new Float64Array(2 * count);
  for (let v = 0; v < remap.length; v++) {
    if (remap[v] < 0) continue;
    vertices[2 * remap[v]] = all[2 * v];
    vertices[2 * remap[v] + 1] = all[2 * v + 1];
  }
  const triangles = Int32Array.from(kept, (v) => remap[v]);
  const handleVertices = new Int32Array(handleCount);
  for (let i = 0; i < handleCount; i++) {
    if (remap[i] < 0) throw new SplinekitError('internal', `skin domain: handle ${i} is in no triangle`);
    handleVertices[i] = remap[i];
  }
  return { vertices, triangles, handleVertices, spacing: h };
}

/** A uniform bucket grid of points for "is anything within r?" queries (r ≤ cell size). */
class PointGrid {
  private readonly xs: number[] = [];
  private readonly ys: number[] = [];
  private readonly next: number[] = [];
  private readonly head: Int32Array;
  private readonly nx: number;
  private readonly ny: number;

  constructor(
    private readonly box: readonly number[],
    private readonly cell: number,
  ) {
    this.nx = Math.max(1, Math.ceil((box[2] - box[0]) / cell) + 1);
    this.ny = Math.max(1, Math.ceil((box[3] - box[1]) / cell) + 1);
    this.head = new Int32Array(this.nx * this.ny).fill(-1);
  }

  private cellOf(x: number, y: number): [number, number] {
    const i = Math.min(this.nx - 1, Math.max(0, Math.floor((x - this.box[0]) / this.cell)));
    const j = Math.min(this.ny - 1, Math.max(0, Math.floor((y - this.box[1]) / this.cell)));
    return [i, j];
  }

  add(x: number, y: number): number {
    const [i, j] = this.cellOf(x, y);
    const index = this.xs.length;
    this.xs.push(x);
    this.ys.push(y);
    this.next.push(this.head[j * this.nx + i]);
    this.head[j * this.nx + i] = index;
    return index;
  }

  /** Index of the nearest point within r (r ≤ cell), or −1. */
  nearest(x: number, y: number, r: number): number {
    const [ci, cj] = this.cellOf(x, y);
    let best = -1, bestD2 = r * r;
    for (let j = Math.max(0, cj - 1); j <= Math.min(this.ny - 1, cj + 1); j++) {
      for (let i = Math.max(0, ci - 1); i <= Math.min(this.nx - 1, ci + 1); i++) {
        for (let p = this.head[j * this.nx + i]; p >= 0; p = this.next[p]) {
          const d2 = (this.xs[p] - x) ** 2 + (this.ys[p] - y) ** 2;
          if (d2 < bestD2) {
            bestD2 = d2;
            best = p;
          }
        }
      }
    }
    return best;
  }

  points(): Float64Array {
    const out = new Float64Array(2 * this.xs.length);
    for (let p = 0; p < this.xs.length; p++) {
      out[2 * p] = this.xs[p];
      out[2 * p + 1] = this.ys[p];
    }
    return out;
  }
}

function checkHandleSpacing(handles: Float64Array, h: number): void {
  const n = handles.length / 2;
  const grid = new PointGrid(bounds([handles]), h);
  for (let i = 0; i < n; i++) {
    const other = grid.nearest(handles[2 * i], handles[2 * i + 1], MERGE * h);
    if (other >= 0) {
      throw invalid(`handles ${other} and ${i} coincide (closer than ${MERGE * h}, a thousandth of the mesh spacing)`);
    }
    grid.add(handles[2 * i], handles[2 * i + 1]);
  }
}

// ---------------------------------------------------------------------------------------------
// Polygons
// ---------------------------------------------------------------------------------------------

function invalid(message: string): SplinekitError {
  return new SplinekitError('invalid-input', `skin domain: ${message}`);
}

function checkPoints(a: Float64Array, name: string): void {
  if (!(a instanceof Float64Array)) throw invalid(`${name} must be a Float64Array of x,y pairs`);
  if (a.length % 2) throw invalid(`${name} has an odd length (${a.length}): expected x,y pairs`);
  for (let k = 0; k < a.length; k++) {
    if (!Number.isFinite(a[k])) throw invalid(`${name} point ${k >> 1} has a non-finite coordinate (${a[k]})`);
  }
}

function bounds(arrays: Float64Array[]): [number, number, number, number] {
  const b: [number, number, number, number] = [Infinity, Infinity, -Infinity, -Infinity];
  for (const a of arrays) {
    for (let k = 0; k < a.length; k += 2) {
      b[0] = Math.min(b[0], a[k]);
      b[1] = Math.min(b[1], a[k + 1]);
      b[2] = Math.max(b[2], a[k]);
      b[3] = Math.max(b[3], a[k + 1]);
    }
  }
  return b;
}

function concat(a: Float64Array, b: Float64Array): Float64Array {
  const out = new Float64Array(a.length + b.length);
  out.set(a);
  out.set(b, a.length);
  return out;
}

function reversed(poly: Float64Array): Float64Array {
  const n = poly.length / 2, out = new Float64Array(poly.length);
  for (let k = 0; k < n; k++) {
    out[2 * k] = poly[2 * (n - 1 - k)];
    out[2 * k + 1] = poly[2 * (n - 1 - k) + 1];
  }
  return out;
}

/** The polygon without consecutive repeated points (and without a closing repeat of the first). */
function dropRepeats(poly: Float64Array, eps: number): Float64Array {
  const out: number[] = [];
  for (let k = 0; k < poly.length; k += 2) {
    const n = out.length;
    if (n >= 2 && Math.hypot(out[n - 2] - poly[k], out[n - 1] - poly[k + 1]) <= eps) continue;
    out.push(poly[k], poly[k + 1]);
  }
  while (out.length >= 4 && Math.hypot(out[0] - out[out.length - 2], out[1] - out[out.length - 1]) <= eps) out.length -= 2;
  return Float64Array.from(out);
}

function signedArea(poly: Float64Array): number {
  const n = poly.length / 2;
  let a = 0;
  for (let k = 0; k < n; k++) {
    const j = (k + 1) % n;
    a += poly[2 * k] * poly[2 * j + 1] - poly[2 * j] * poly[2 * k + 1];
  }
  return a / 2;
}

/** Convex hull (Andrew's monotone chain), counter-clockwise; a lone point is its own hull. */
function convexHull(points: Float64Array): Float64Array {
  const n = points.length / 2;
  if (n < 2) return points.slice();
  const order = Array.from({ length: n }, (_, i) => i).sort(
    (a, b) => points[2 * a] - points[2 * b] || points[2 * a + 1] - points[2 * b + 1],
  );
  const cross = (o: number, a: number, b: number) =>
    (points[2 * a] - points[2 * o]) * (points[2 * b + 1] - points[2 * o + 1]) -
    (points[2 * a + 1] - points[2 * o + 1]) * (points[2 * b] - points[2 * o]);
  const hull: number[] = [];
  for (const pass of [order, [...order].reverse()]) {
    const start = hull.length;
    for (const p of pass) {
      while (hull.length >= start + 2 && cross(hull[hull.length - 2], hull[hull.length - 1], p) <= 0) hull.pop();
      hull.push(p);
    }
    hull.pop();
  }
  return Float64Array.from(hull.flatMap((p) => [points[2 * p], points[2 * p + 1]]));
}

/** The convex hull grown by `margin`: the hull of its vertices moved `margin` in 16 directions. */
function grownHull(points: Float64Array, margin: number): Float64Array {
  const hull = convexHull(points);
  const grown = new Float64Array(hull.length * 16);
  for (let k = 0; k < hull.length; k += 2) {
    for (let d = 0; d < 16; d++) {
      const a = (d * Math.PI) / 8;
      grown[k * 16 + 2 * d] = hull[k] + margin * Math.cos(a);
      grown[k * 16 + 2 * d + 1] = hull[k + 1] + margin * Math.sin(a);
    }
  }
  return convexHull(grown);
}

/**
 * The closed polygon resampled along its length: vertices closer than h/2 to the previous kept
 * one are dropped, and edges longer than h are split evenly.
 */
function resampleClosed(poly: Float64Array, h: number): Float64Array {
  const kept: number[] = [poly[0], poly[1]];
  for (let k = 2; k < poly.length; k += 2) {
    const n = kept.length;
    if (Math.hypot(poly[k] - kept[n - 2], poly[k + 1] - kept[n - 1]) >= h / 2) kept.push(poly[k], poly[k + 1]);
  }
  while (kept.length > 6 && Math.hypot(kept[0] - kept[kept.length - 2], kept[1] - kept[kept.length - 1]) < h / 2) kept.length -= 2;
  const out: number[] = [];
  const m = kept.length / 2;
  for (let k = 0; k < m; k++) {
    const x0 = kept[2 * k], y0 = kept[2 * k + 1], x1 = kept[(2 * k + 2) % kept.length], y1 = kept[(2 * k + 3) % kept.length];
    const pieces = Math.max(1, Math.ceil(Math.hypot(x1 - x0, y1 - y0) / h));
    for (let s = 0; s < pieces; s++) out.push(x0 + ((x1 - x0) * s) / pieces, y0 + ((y1 - y0) * s) / pieces);
  }
  return Float64Array.from(out);
}

/** Even–odd point-in-polygon test. */
function insidePolygon(poly: Float64Array, x: number, y: number): boolean {
  const n = poly.length / 2;
  let inside = false;
  for (let k = 0, j = n - 1; k < n; j = k++) {
    const xk = poly[2 * k], yk = poly[2 * k + 1], xj = poly[2 * j], yj = poly[2 * j + 1];
    if (yk > y !== yj > y && x < ((xj - xk) * (y - yk)) / (yj - yk) + xk) inside = !inside;
  }
  return inside;
}

function projectOnSegment(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const ex = bx - ax, ey = by - ay, l2 = ex * ex + ey * ey;
  return l2 > 0 ? ((px - ax) * ex + (py - ay) * ey) / l2 : 0;
}

function distanceToSegment(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const t = Math.min(1, Math.max(0, projectOnSegment(px, py, ax, ay, bx, by)));
  return Math.hypot(ax + t * (bx - ax) - px, ay + t * (by - ay) - py);
}

function distanceToPolygon(poly: Float64Array, x: number, y: number): number {
  const n = poly.length / 2;
  let d = Infinity;
  for (let k = 0; k < n; k++) {
    const j = (k + 1) % n;
    d = Math.min(d, distanceToSegment(x, y, poly[2 * k], poly[2 * k + 1], poly[2 * j], poly[2 * j + 1]));
  }
  return d;
}

/** A point where two non-adjacent edges of the closed polygon cross, or null. */
function selfIntersection(poly: Float64Array): [number, number] | null {
  const n = poly.length / 2;
  const orient = (ax: number, ay: number, bx: number, by: number, cx: number, cy: number) =>
    Math.sign((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
  for (let a = 0; a < n; a++) {
    const a1 = (a + 1) % n;
    const ax = poly[2 * a], ay = poly[2 * a + 1], bx = poly[2 * a1], by = poly[2 * a1 + 1];
    for (let b = a + 2; b < n; b++) {
      const b1 = (b + 1) % n;
      if (b1 === a) continue;
      const cx = poly[2 * b], cy = poly[2 * b + 1], dx = poly[2 * b1], dy = poly[2 * b1 + 1];
      if (Math.max(ax, bx) < Math.min(cx, dx) || Math.max(cx, dx) < Math.min(ax, bx)) continue;
      if (Math.max(ay, by) < Math.min(cy, dy) || Math.max(cy, dy) < Math.min(ay, by)) continue;
      const o1 = orient(ax, ay, bx, by, cx, cy), o2 = orient(ax, ay, bx, by, dx, dy);
      const o3 = orient(cx, cy, dx, dy, ax, ay), o4 = orient(cx, cy, dx, dy, bx, by);
      if (o1 !== o2 && o3 !== o4) return [cx, cy];
    }
  }
  return null;
}
