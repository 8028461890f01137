/**
 * Cubic Bézier splines on a mesh (b/Surf §3.5–§5.2): traced by RDC or OLR subdivision, uniform or
 * adaptive, and edited with the gestures of a 2D editor (anchors carry their handles, smooth
 * anchors keep their handles collinear, whole splines move, turn and scale about a mesh point).
 */
import { SplinekitError, checkStatus } from '../core/errors.js';
import type { SurfaceMeshHandle } from '../core/splinekit-core.mjs';
import type { SurfaceMesh } from './mesh.js';
import { readMeshPoints, searchHandle, writeMeshPoints } from './mesh-handle.js';
import type { MeshPoint, MeshPointLike } from './mesh-point.js';
import { traceArgs, type TraceOptions } from './trace-options.js';

export type { SurfaceScheme, TraceOptions } from './trace-options.js';

/** The work counters of a traced curve (summed over its shortest paths): what the curve cost. */
export interface TraceCounters {
  /** Shortest paths found by a search on the mesh's graph. */
  searchedPaths: number;
  /** Shortest paths straightened through known paths instead (no search). */
  seededPaths: number;
  /** Searches run (phase (i)). */
  searches: number;
  /** Graph nodes the searches expanded. */
  visitedNodes: number;
  /** Faces of the strips laid out and straightened. */
  stripFaces: number;
  /** Straightening passes. */
  passes: number;
  /** Flips kept because they shortened a path. */
  flips: number;
  /** Vertices found locally shortest (or not flippable) and frozen. */
  frozenVertices: number;
  /** Chords traced (walks along the line between two apices of a path) ... */
  chordsTried: number;
  /** ... those among the kept flips ... */
  chords: number;
  /** ... and the faces the walks entered, kept or not. */
  walkedFaces: number;
  /** Faces of the strips the passes worked on (a pass costs its strip's faces; a window's pass, its window's). */
  passFaces: number;
  /** Windows of a long path straightened on their own (short stretches where its last bends move). */
  windows: number;
  /** Shortest paths whose strips followed the coarse guide's path (SurfaceMeshOptions.guide). */
  guided: number;
}

/** A curve traced on the mesh, as mesh points and as 3D positions. */
export interface TracedCurve {
  /** The polyline on the surface: P0, every point and edge crossing, P3. */
  points: MeshPoint[];
  /** The same polyline in 3D: x,y,z per point of `points`. */
  xyz: Float64Array;
}

/**
 * Traces one cubic Bézier curve given by 4 control points on the mesh. Throws
 * SplinekitError('invalid-input') when they lie on parts of the mesh that are not connected (a curve
 * cannot cross between them).
 */
export function traceBezier(mesh: SurfaceMesh, controls: readonly MeshPointLike[], options?: TraceOptions): TracedCurve & {
  /** Time the core spent tracing, in milliseconds (measured inside wasm). */
  ms: number;
  /** What the curve cost: shortest paths searched and seeded, graph nodes expanded, strip faces, passes, flips. */
  counters: TraceCounters;
} {
  if (controls.length !== 4) throw new SplinekitError('invalid-input', `a cubic curve needs 4 control points (got ${controls.length})`);
  const handle = writeMeshPoints(mesh, controls.map((p, i) => mesh.resolve(p, `control point ${i}`)));
  checkStatus(handle.trace(1, ...traceArgs(options)), 'trace', () => handle.error());
  return { points: readMeshPoints(mesh), xyz: handle.xyzOut().slice(), ms: handle.curveMilliseconds(0), counters: handle.curveCounters(0) as TraceCounters };
}

/** The point at parameter t of a cubic curve on the mesh (§4.1.2, §4.2.2). */
export function evalBezier(mesh: SurfaceMesh, controls: readonly MeshPointLike[], t: number, options?: TraceOptions): MeshPoint {
  if (controls.length !== 4) throw new SplinekitError('invalid-input', `a cubic curve needs 4 control points (got ${controls.length})`);
  const handle = writeMeshPoints(mesh, controls.map((p, i) => mesh.resolve(p, `control point ${i}`)));
  checkStatus(handle.evalCurve(t, ...traceArgs(options)), 'evaluate', () => handle.error());
  return readMeshPoints(mesh)[0];
}

/** A surface spline as plain data (what `toJSON` writes and `fromJSON` reads). */
export interface SurfaceSplineJSON {
  /** Whether the last segment ends at point 0 (3n points) rather than at its own end (3n+1). */
  closed: boolean;
  /** Control points: anchors at 3k, handles between (3n+1 open, 3n closed). */
  points: MeshPoint[];
  /** Per anchor: its handles stay collinear (C1) when one of them moves. */
  smooth: boolean[];
}

function clonePoint(p: MeshPoint): MeshPoint {
  return { face: p.face, uv: [p.uv[0], p.uv[1]] };
}

/**
 * A cubic Bézier spline on a mesh, edited like a 2D spline: anchors at every third control point
 * with their handles between. Holds no wasm memory of its own (the mesh does).
 */
export class SurfaceSpline {
  /** The mesh the spline lies on. */
  readonly mesh: SurfaceMesh;
  private _points: MeshPoint[];
  private _smooth: boolean[];
  /** Whether the spline is closed (fixed at creation). */
  readonly closed: boolean;

  /** A spline from its control points; throws SplinekitError('invalid-input') for a wrong count or a bad point. */
  constructor(mesh: SurfaceMesh, json: SurfaceSplineJSON) {
    this.mesh = mesh;
    const n = json.points?.length ?? 0;
    const closed = !!json.closed;
    if (closed ? n < 3 || n % 3 !== 0 : n < 4 || n % 3 !== 1)
      throw new SplinekitError('invalid-input', `a ${closed ? 'closed' : 'open'} spline needs ${closed ? '3n' : '3n+1'} control points (got ${n})`);
    this._points = json.points.map((p, i) => clonePoint(mesh.resolve(p, `control point ${i}`)));
    this.closed = closed;
    const anchors = closed ? n / 3 : (n - 1) / 3 + 1;
    this._smooth = Array.from({ length: anchors }, (_, i) => !!json.smooth?.[i]);
  }

  /** The mesh's wasm handle (throws once the mesh is disposed). */
  private get core(): SurfaceMeshHandle {
    return searchHandle(this.mesh);
  }

  /** A spline through the anchors with straight handles: each segment's handles at 1/3 and 2/3 of its geodesic. */
  static fromPolygon(mesh: SurfaceMesh, anchors: readonly MeshPointLike[], closed = false): SurfaceSpline {
    if (anchors.length < 2) throw new SplinekitError('invalid-input', 'a spline needs at least 2 anchors');
    const a = anchors.map((p, i) => mesh.resolve(p, `anchor ${i}`));
    const points: MeshPoint[] = [];
    const segments = closed ? a.length : a.length - 1;
    for (let s = 0; s < segments; s++) {
      const [h1, h2] = thirds(mesh, a[s], a[(s + 1) % a.length]);
      points.push(a[s], h1, h2);
    }
    if (!closed) points.push(a[a.length - 1]);
    return new SurfaceSpline(mesh, { closed, points, smooth: a.map(() => false) });
  }

  /** The spline `toJSON` wrote (the same as `new SurfaceSpline(mesh, json)`). */
  static fromJSON(mesh: SurfaceMesh, json: SurfaceSplineJSON): SurfaceSpline {
    return new SurfaceSpline(mesh, json);
  }

  /** The spline as plain data (copies of its points and smooth flags). */
  toJSON(): SurfaceSplineJSON {
    return { closed: this.closed, points: this._points.map(clonePoint), smooth: [...this._smooth] };
  }

  /** The control points: anchors at 3k, handles between (read-only; edit with the methods). */
  get points(): readonly MeshPoint[] {
    return this._points;
  }

  /** Number of cubic segments. */
  get segmentCount(): number {
    return this.closed ? this._points.length / 3 : (this._points.length - 1) / 3;
  }

  /** The 4 control points of segment s. */
  segment(s: number): MeshPoint[] {
    this.checkSegment(s);
    const n = this._points.length;
    return [0, 1, 2, 3].map((i) => this._points[(3 * s + i) % n]);
  }

  /** Whether the anchor at control point `anchor` (a multiple of 3) keeps its handles collinear. */
  isSmooth(anchor: number): boolean {
    return this._smooth[this.anchorIndex(anchor)];
  }

  /** Makes an anchor smooth (its handles turn to be collinear) or a corner. */
  setSmooth(anchor: number, smooth: boolean): void {
    const k = this.anchorIndex(anchor);
    this._smooth[k] = smooth;
    if (smooth) this.editAround(anchor, (count, at) => this.core.smoothAnchor(count, at), 'smooth anchor');
  }

  /** Moves an anchor; its handles follow by parallel transport (§5.2). */
  moveAnchor(index: number, to: MeshPointLike): void {
    this.anchorIndex(index);
    const p = this.mesh.resolve(to, 'target');
    this.editAround(index, (count, at) => this.core.moveAnchor(count, at, p.face, p.uv[0], p.uv[1]), 'move anchor');
  }

  /** Moves a handle; at a smooth anchor the opposite handle follows along the straightest geodesic. */
  moveHandle(index: number, to: MeshPointLike): void {
    if (index < 0 || index >= this._points.length || index % 3 === 0)
      throw new SplinekitError('invalid-input', `control point ${index} is not a handle of the spline`);
    const p = this.mesh.resolve(to, 'target');
    const anchor = index % 3 === 1 ? index - 1 : index + 1;
    const hasOpposite = this.closed || (anchor > 0 && anchor < this._points.length - 1);
    const smooth = hasOpposite && this._smooth[this.anchorIndex(anchor % this._points.length)];
    this.editAround(anchor % this._points.length, (count, at) =>
      this.core.moveHandle(count, at + (index - anchor), p.face, p.uv[0], p.uv[1], smooth), 'move handle');
  }

  /**
   * Point insertion (§4.1.3/§4.2.3): splits segment s at t into two segments through the curve's
   * point at t, keeping its end tangents. Returns the new anchor's control-point index.
   */
  insert(segment: number, t: number, options?: TraceOptions): number {
    this.checkSegment(segment);
    writeMeshPoints(this.mesh, this.segment(segment));
    checkStatus(this.core.splitCurve(t, ...traceArgs(options)), 'insert point', () => this.core.error());
    const seven = readMeshPoints(this.mesh);
    const at = 3 * segment;
    const n = this._points.length;
    if (this.closed && at + 3 === n) {
      this._points.splice(at, 3, ...seven.slice(0, 6));
      this._points[0] = seven[6];
    } else {
      this._points.splice(at, 4, ...seven);
    }
    this._smooth.splice(segment + 1, 0, true);
    return at + 3;
  }

  /** Deletes an anchor with its handles; the segments on both sides merge. */
  remove(anchor: number): void {
    const k = this.anchorIndex(anchor);
    if (this.segmentCount < 2)
      throw new SplinekitError('invalid-input', 'a spline keeps at least one segment');
    const n = this._points.length;
    if (this.closed) {
      const drop = [(anchor - 1 + n) % n, anchor, (anchor + 1) % n].sort((a, b) => b - a);
      for (const i of drop) this._points.splice(i, 1);
      if (anchor === 0) this._points.push(...this._points.splice(0, 2)); // keep an anchor first
    } else if (anchor === 0) {
      this._points.splice(0, 3);
    } else if (anchor === n - 1) {
      this._points.splice(n - 3, 3);
    } else {
      this._points.splice(anchor - 1, 3);
    }
    this._smooth.splice(k, 1);
  }

  /** Extends an open spline by one segment to `p` (straight handles). */
  appendAnchor(p: MeshPointLike): void {
    if (this.closed) throw new SplinekitError('invalid-input', 'a closed spline has no end to extend');
    const end = this._points[this._points.length - 1];
    const q = this.mesh.resolve(p, 'anchor');
    const [h1, h2] = thirds(this.mesh, end, q);
    this._points.push(h1, h2, q);
    this._smooth.push(false);
  }

  /** Translation that takes `from` to `to`, in normal coordinates about `from` (§5.2). */
  translate(from: MeshPointLike, to: MeshPointLike): void {
    const a = this.mesh.resolve(from, 'from'), b = this.mesh.resolve(to, 'to');
    this.editAll((count) => this.core.translateSpline(count, a.face, a.uv[0], a.uv[1], b.face, b.uv[0], b.uv[1]), 'translate');
  }

  /** Rotation by `radians` (counter-clockwise seen from outside) about `center`. */
  rotate(center: MeshPointLike, radians: number): void {
    const c = this.mesh.resolve(center, 'center');
    this.editAll((count) => this.core.rotateScale(count, c.face, c.uv[0], c.uv[1], radians, 1), 'rotate');
  }

  /** Scaling by `factor` about `center`. */
  scale(center: MeshPointLike, factor: number): void {
    const c = this.mesh.resolve(center, 'center');
    this.editAll((count) => this.core.rotateScale(count, c.face, c.uv[0], c.uv[1], 0, factor), 'scale');
  }

  /** Traces every segment; segmentStarts[s] is the index (in points) where segment s begins. */
  trace(options?: TraceOptions): TracedCurve & {
    /** Index in `points` where each segment begins. */
    segmentStarts: Int32Array;
    /** Time the core spent tracing, in milliseconds (measured inside wasm). */
    ms: number;
  } {
    const segments = this.segmentCount;
    const all: MeshPoint[] = [];
    for (let s = 0; s < segments; s++) all.push(...this.segment(s));
    writeMeshPoints(this.mesh, all);
    checkStatus(this.core.trace(segments, ...traceArgs(options)), 'trace', () => this.core.error());
    let ms = 0;
    for (let s = 0; s < segments; s++) ms += this.core.curveMilliseconds(s);
    const segmentStarts = this.core.offsetsOut().slice(0, segments);
    return { points: readMeshPoints(this.mesh), xyz: this.core.xyzOut().slice(), segmentStarts, ms };
  }

  /** No wasm memory of its own: the mesh holds it. Kept for symmetry with other wrappers. */
  dispose(): void {}

  // ---- internals ----

  private anchorIndex(anchor: number): number {
    const n = this._points.length;
    if (!Number.isInteger(anchor) || anchor < 0 || anchor >= n || anchor % 3 !== 0)
      throw new SplinekitError('invalid-input', `control point ${anchor} is not an anchor of the spline`);
    return anchor / 3;
  }

  private checkSegment(s: number): void {
    if (!Number.isInteger(s) || s < 0 || s >= this.segmentCount)
      throw new SplinekitError('invalid-input', `segment ${s} does not exist (the spline has ${this.segmentCount})`);
  }

  /**
   * Runs an edit on an open run of control points in which `anchor` has both its neighbours where
   * they exist: closed splines are rotated so the anchor sits at index 3 (and unrotated after).
   */
  private editAround(anchor: number, call: (count: number, at: number) => number, what: string): void {
    const n = this._points.length;
    if (!this.closed) {
      writeMeshPoints(this.mesh, this._points);
      checkStatus(call(n, anchor), what, () => this.core.error());
      this._points = readMeshPoints(this.mesh);
      return;
    }
    const shift = (anchor - 3 + n) % n;
    const run = Array.from({ length: n + 1 }, (_, i) => this._points[(shift + i) % n]);
    writeMeshPoints(this.mesh, run);
    checkStatus(call(n + 1, 3), what, () => this.core.error());
    const out = readMeshPoints(this.mesh);
    for (let i = 0; i < n; i++) this._points[(shift + i) % n] = out[i];
  }

  private editAll(call: (count: number) => number, what: string): void {
    writeMeshPoints(this.mesh, this._points);
    checkStatus(call(this._points.length), what, () => this.core.error());
    this._points = readMeshPoints(this.mesh);
  }
}

/** The points at 1/3 and 2/3 of the shortest path from a to b. */
function thirds(mesh: SurfaceMesh, a: MeshPoint, b: MeshPoint): [MeshPoint, MeshPoint] {
  const handle = writeMeshPoints(mesh, [a, b]);
  checkStatus(handle.pathAt(1 / 3, 2 / 3), 'handle placement', () => handle.error());
  const [h1, h2] = readMeshPoints(mesh);
  return [h1, h2];
}
