import type { MeshInfo, SurfaceSplineJSON, TraceOptions } from '../../../src/index.js';
import type { SurfaceSelection } from './commands.js';
import type { DrawnSpline, SurfaceDrawing } from './drawing.js';
import type { TracedPolyline } from './protocol.js';
import type { SurfaceTool } from './surface-panel.js';

/** One spline as the end-to-end tests read it. */
export interface SurfaceTestSpline {
  id: number;
  json: SurfaceSplineJSON;
  /** The traced polyline on the surface (x y z …), empty while it is traced. */
  polyline: number[];
  /** Per polyline point: face, u, v. */
  where: number[];
  segmentStarts: number[];
}

/** What the end-to-end tests read (window.splinekitEditor.surface.state()). */
export interface SurfaceTestState {
  active: boolean;
  file: string | null;
  meshInfo: MeshInfo | null;
  /** The mesh's search structures are built (it is shown, and traced, before: traces wait for them). */
  meshReady: boolean;
  /** Bounding-box diagonal of the mesh. */
  scale: number | null;
  splines: SurfaceTestSpline[];
  selection: SurfaceSelection | null;
  tool: SurfaceTool;
  /** The spline clicks extend (null: none), and whether a first point waits for the second. */
  drawingId: number | null;
  pending: boolean;
  placing: boolean;
  lastTraceMs: number | null;
  options: TraceOptions;
  /** No autosave is pending. */
  saved: boolean;
  /**
   * Triangles of the mesh picture on screen: the mesh's faces once it is drawn in full, fewer
   * while a large mesh shows its proxy (moving, or not yet drawn in full).
   */
  pictureTriangles: number;
}

export function surfaceTestState(s: {
  active: boolean;
  file: string | null;
  info: MeshInfo | null;
  ready: boolean;
  scale: number | null;
  drawing: SurfaceDrawing;
  traceOf(sp: DrawnSpline): TracedPolyline | null;
  selection: SurfaceSelection | null;
  tool: SurfaceTool;
  drawingId: number | null;
  pending: boolean;
  placing: boolean;
  lastTraceMs: number | null;
  options: TraceOptions;
  saved: boolean;
  pictureTriangles: number;
}): SurfaceTestState {
  return {
    active: s.active,
    file: s.file,
    meshInfo: s.info,
    meshReady: s.ready,
    scale: s.scale,
    splines: s.drawing.splines.map((sp) => {
      const t = s.traceOf(sp);
      return {
        id: sp.id,
        json: sp.json,
        polyline: t ? Array.from(t.xyz) : [],
        where: t ? Array.from(t.where) : [],
        segmentStarts: t ? Array.from(t.segmentStarts) : [],
      };
    }),
    selection: s.selection,
    tool: s.tool,
    drawingId: s.drawingId,
    pending: s.pending,
    placing: s.placing,
    lastTraceMs: s.lastTraceMs,
    options: s.options,
    saved: s.saved,
    pictureTriangles: s.pictureTriangles,
  };
}
