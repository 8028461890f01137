import { Matrix4, Vector3 } from 'three';
import { meshPointNormal, meshPointPosition, type MeshPoint } from '../../../src/index.js';
import type { SurfaceContext } from './context.js';
import { findSpline, isAnchor, type DrawnSpline } from './drawing.js';
import type { TraceCache } from './trace-cache.js';

/** Screen pixels within which a control point or a curve is hit. */
const POINT_HIT_PX = 10;
const CURVE_HIT_PX = 7;

/** A control point drawn on the mesh: spline id, point index, and where it is drawn. */
export interface ControlMark {
  id: number;
  index: number;
  xyz: [number, number, number];
}

/**
 * What is under the pointer in Surface mode, and where things are: mesh points on the shown mesh
 * (position, smooth normal), control points and curves on screen (hidden ones do not count), the
 * centre a spline turns and scales about.
 */
export class SurfacePicking {
  constructor(
    private readonly mode: SurfaceContext,
    private readonly traces: TraceCache,
  ) {}

  /** The mesh point under a canvas point, or null (off the mesh). */
  meshPointAt(sx: number, sy: number): MeshPoint | null {
    const hit = this.mode.view?.pick(sx, sy);
    return hit ? { face: hit.face, uv: [hit.u, hit.v] } : null;
  }

  /** Where a mesh point is (on the surface), from the shown mesh's positions; null for a face it does not have. */
  xyz(p: MeshPoint): [number, number, number] | null {
    const m = this.mode.view?.mesh;
    if (!m || p.face < 0 || 3 * p.face + 2 >= m.triangles.length) return null;
    return meshPointPosition(m.positions, m.triangles, p);
  }

  /** The interpolated smooth normal at a mesh point of the shown mesh. */
  normal(p: MeshPoint): Vector3 {
    const m = this.mode.view!.mesh!;
    const [x, y, z] = meshPointNormal(m.normals, m.triangles, p);
    return new Vector3(x, y, z);
  }

  /** Whether a spline shows its handles (selected, or being drawn). */
  private full(id: number): boolean {
    return this.mode.selection?.spline === id || this.mode.drawingId === id;
  }

  /** The control points drawn now (all anchors; handles of the selected or drawn spline). */
  controlMarks(): ControlMark[] {
    const out: ControlMark[] = [];
    if (!this.mode.ctx?.state.overlay) return out;
    for (const sp of this.mode.drawing.splines) {
      const json = this.traces.shownJSON(sp);
      const full = this.full(sp.id);
      json.points.forEach((mp, index) => {
        if (!full && !isAnchor(index)) return;
        const at = this.xyz(mp);
        if (at) out.push({ id: sp.id, index, xyz: at });
      });
    }
    return out;
  }

  /** The control point under a canvas point, or null. */
  controlPoint(sx: number, sy: number): { id: number; index: number } | null {
    const view = this.mode.view, mesh = this.mode.mesh;
    if (!view || !mesh) return null;
    let best: ControlMark | null = null, bestD = POINT_HIT_PX;
    const slack = mesh.scale * 2e-3;
    const candidates: [ControlMark, number][] = [];
    for (const m of this.controlMarks()) {
      const s = view.project(...m.xyz);
      if (s.depth <= 0) continue;
      const d = Math.hypot(s.sx - sx, s.sy - sy);
      if (d <= POINT_HIT_PX) candidates.push([m, d]);
    }
    // Handles of the selected spline win ties over anchors under them; hidden points do not count.
    candidates.sort((a, b) => a[1] - b[1] || (isAnchor(a[0].index) ? 1 : 0) - (isAnchor(b[0].index) ? 1 : 0));
    for (const [m, d] of candidates) {
      if (!view.isVisible(...m.xyz, slack)) continue;
      best = m;
      bestD = d;
      break;
    }
    return best && bestD <= POINT_HIT_PX ? { id: best.id, index: best.index } : null;
  }

  /** The curve under a canvas point: spline, segment and parameter (by arc length in it). */
  curve(sx: number, sy: number): { id: number; segment: number; t: number } | null {
    const view = this.mode.view, mesh = this.mode.mesh, drawing = this.mode.drawing;
    if (!view || !mesh) return null;
    view.camera.updateMatrixWorld();
    const m = new Matrix4().multiplyMatrices(view.camera.projectionMatrix, view.camera.matrixWorldInverse).elements;
    const W = view.size.x, H = view.size.y;
    let best: { id: number; i: number; f: number; d: number } | null = null;
    const slack = mesh.scale * 2e-3;
    const hits: { id: number; i: number; f: number; d: number }[] = [];
    for (const sp of drawing.splines) {
      const tr = this.traces.traceOf(sp);
      if (!tr) continue;
      const L = tr.lifted, n = L.length / 3;
      let px = 0, py = 0, pok = false;
      for (let i = 0; i < n; i++) {
        const x = L[3 * i], y = L[3 * i + 1], z = L[3 * i + 2];
        const w = m[3] * x + m[7] * y + m[11] * z + m[15];
        const ok = w > 0;
        const qx = ((m[0] * x + m[4] * y + m[8] * z + m[12]) / w + 1) * 0.5 * W;
        const qy = (1 - (m[1] * x + m[5] * y + m[9] * z + m[13]) / w) * 0.5 * H;
        if (i > 0 && ok && pok) {
          const dx = qx - px, dy = qy - py, l2 = dx * dx + dy * dy;
          const f = l2 > 0 ? Math.min(1, Math.max(0, ((sx - px) * dx + (sy - py) * dy) / l2)) : 0;
          const d = Math.hypot(px + f * dx - sx, py + f * dy - sy);
          if (d <= CURVE_HIT_PX) hits.push({ id: sp.id, i: i - 1, f, d });
        }
        px = qx;
        py = qy;
        pok = ok;
      }
    }
    hits.sort((a, b) => a.d - b.d);
    for (const hit of hits.slice(0, 24)) {
      const sp = findSpline(drawing, hit.id)!;
      const L = this.traces.traceOf(sp)!.lifted, k = 3 * hit.i;
      const x = L[k] + hit.f * (L[k + 3] - L[k]), y = L[k + 1] + hit.f * (L[k + 4] - L[k + 1]), z = L[k + 2] + hit.f * (L[k + 5] - L[k + 2]);
      if (view.isVisible(x, y, z, slack)) {
        best = hit;
        break;
      }
    }
    if (!best) return null;
    const sp = findSpline(drawing, best.id)!;
    const tr = this.traces.traceOf(sp)!;
    const starts = tr.segmentStarts, n = tr.xyz.length / 3;
    let segment = 0;
    while (segment + 1 < starts.length && starts[segment + 1] <= best.i) segment++;
    const a = starts[segment], b = segment + 1 < starts.length ? starts[segment + 1] : n - 1;
    // Parameter by arc length along the segment's polyline (a good guess for t).
    const X = tr.xyz;
    const len = (i: number) => Math.hypot(X[3 * i + 3] - X[3 * i], X[3 * i + 4] - X[3 * i + 1], X[3 * i + 5] - X[3 * i + 2]);
    let total = 0, upto = 0;
    for (let i = a; i < b; i++) {
      const l = len(i);
      if (i < best.i) upto += l;
      else if (i === best.i) upto += best.f * l;
      total += l;
    }
    const t = total > 0 ? Math.min(0.98, Math.max(0.02, upto / total)) : 0.5;
    return { id: best.id, segment, t };
  }

  /**
   * The centre of a spline for turning and scaling: the surface under the middle of its traced
   * points as seen on screen (else its nearest control point), with whether it faces the camera.
   */
  centreOf(sp: DrawnSpline): { point: MeshPoint; sx: number; sy: number; facing: number } | null {
    const view = this.mode.view;
    if (!view) return null;
    const tr = this.traces.traceOf(sp);
    const c = new Vector3();
    let n = 0;
    if (tr) {
      for (let i = 0; i < tr.xyz.length; i += 3, n++) c.add(new Vector3(tr.xyz[i], tr.xyz[i + 1], tr.xyz[i + 2]));
    } else {
      for (const p of sp.json.points) {
        const at = this.xyz(p);
        if (at) {
          c.add(new Vector3(...at));
          n++;
        }
      }
    }
    if (n === 0) return null;
    c.divideScalar(n);
    const s = view.project(c.x, c.y, c.z);
    let point = this.meshPointAt(s.sx, s.sy);
    if (!point) {
      let best = Infinity;
      for (const p of sp.json.points) {
        const at = this.xyz(p);
        if (!at) continue;
        const d = c.distanceToSquared(new Vector3(...at));
        if (d < best) [best, point] = [d, p];
      }
    }
    if (!point) return null;
    const at = this.xyz(point)!;
    const q = view.project(...at);
    const toCamera = view.camera.position.clone().sub(new Vector3(...at));
    const facing = this.normal(point).dot(toCamera) >= 0 ? 1 : -1;
    return { point, sx: q.sx, sy: q.sy, facing };
  }

  /** Where a mesh point is on the canvas (CSS pixels) and whether it is seen, or null. */
  project(p: MeshPoint): { x: number; y: number; visible: boolean } | null {
    const view = this.mode.view, at = this.xyz(p), mesh = this.mode.mesh;
    if (!view || !at || !mesh) return null;
    const s = view.project(...at);
    return { x: s.sx, y: s.sy, visible: s.depth > 0 && view.isVisible(...at, mesh.scale * 2e-3) };
  }

  /** Vertex positions of faces (9 numbers each), from the shown mesh. */
  faceVertices(faces: number[]): number[] {
    const m = this.mode.view?.mesh;
    if (!m) return [];
    const out: number[] = [];
    for (const f of faces) for (let c = 0; c < 3; c++) for (let k = 0; k < 3; k++) out.push(m.positions[3 * m.triangles[3 * f + c] + k]);
    return out;
  }
}
