import type { MeshBounds } from '../../view3d/bounds.js';
import type { BVHArrays } from '../../view3d/bvh.js';
import type { MeshInfo, MeshPoint, SurfaceSplineJSON, TraceOptions } from '../../../src/index.js';
import type { ErrorReply } from '../../app/worker-host.js';

/**
 * Messages between the editor and web/modes/surface/surface.worker.ts. The worker owns the
 * SurfaceMesh and the SurfaceSpline objects; the editor sends a spline's control points (JSON)
 * with the edits to apply, and gets back the edited control points and traced polylines as flat
 * typed arrays (transferred, not copied).
 */

/** One edit of a spline, as the SurfaceSpline methods take it. */
export type SplineOp =
  | { op: 'fromPolygon'; anchors: MeshPoint[] }
  | { op: 'append'; p: MeshPoint }
  | { op: 'moveAnchor'; index: number; to: MeshPoint }
  | { op: 'moveHandle'; index: number; to: MeshPoint }
  | { op: 'setSmooth'; anchor: number; smooth: boolean }
  | { op: 'insert'; segment: number; t: number; options?: TraceOptions }
  | { op: 'remove'; anchor: number }
  | { op: 'translate'; from: MeshPoint; to: MeshPoint }
  | { op: 'rotate'; center: MeshPoint; radians: number }
  | { op: 'scale'; center: MeshPoint; factor: number };

/** A traced polyline on the mesh. */
export interface TracedPolyline {
  /** Points on the surface, x y z in the view's coordinates (the mesh's but for displayOrigin). */
  xyz: Float64Array;
  /** The same points lifted a little along the surface normal, for drawing. */
  lifted: Float32Array;
  /** Per point: face, u, v (the mesh point each xyz is). */
  where: Float64Array;
  /** Index of the first point of each Bézier segment. */
  segmentStarts: Int32Array;
}

/** The geodesic segments anchor–handle of a spline (its control polygon), lifted for drawing. */
export interface PolygonPaths {
  lifted: Float32Array;
  /** Index of the first point of each path. */
  starts: Int32Array;
}

export type SurfaceRequest =
  | { type: 'load'; id: number; bytes: ArrayBuffer; name: string }
  | {
      type: 'run';
      id: number;
      /** The spline to start from (null: the first op creates it). */
      json: SurfaceSplineJSON | null;
      ops: SplineOp[];
      /** Trace the result with these options (null: no trace). */
      trace: TraceOptions | null;
      /** Also compute the control polygon's geodesics. */
      polygon: boolean;
    }
  | { type: 'path'; id: number; a: MeshPoint; b: MeshPoint }
  | {
      type: 'map';
      id: number;
      svg: string;
      name: string;
      center: MeshPoint;
      size: number;
      rotation: number;
      /** Where the drawing's up goes (the view's up, so it reads upright on screen). */
      up: [number, number, number];
    };

export type SurfaceReply =
  | {
      /**
       * A 'load' request's first reply: the mesh as built, to show while the worker builds its
       * search structures (requests after the load wait for those); then 'loaded'.
       */
      type: 'progress';
      id: number;
      stage: 'shown';
      /** Without the search structures (bytes, landmarks: see 'loaded'). */
      info: MeshInfo;
      /** In the view's coordinates: the mesh's, less displayOrigin (web/view3d/bounds.ts). */
      positions: Float32Array;
      triangles: Uint32Array;
      /** Smooth vertex normals (area weighted). */
      normals: Float32Array;
      /**
       * A coarse stand-in of a large mesh (web/view3d/proxy.ts), for the view to draw while the
       * mesh moves or is not yet drawn in full; null for a mesh small enough to draw every frame.
       */
      proxy: { positions: Float32Array; triangles: Uint32Array; normals: Float32Array } | null;
      /** Bounding box and sphere of the positions. */
      bounds: MeshBounds;
      /** The picking hierarchy, built here so the editor does not have to (null: in a 'picking' reply next). */
      bvh: BVHArrays | null;
      scale: number;
      ms: number;
    }
  /** A large mesh's picking hierarchy, after 'shown'. */
  | { type: 'progress'; id: number; stage: 'picking'; bvh: BVHArrays }
  /** The load done: info with the search structures; ms from the request to them built. */
  | { type: 'loaded'; id: number; info: MeshInfo; ms: number }
  | { type: 'ran'; id: number; json: SurfaceSplineJSON; trace: TracedPolyline | null; polygon: PolygonPaths | null; traceMs: number; ms: number }
  | { type: 'path'; id: number; lifted: Float32Array; length: number }
  | { type: 'mapped'; id: number; splines: SurfaceSplineJSON[]; ms: number }
  | ErrorReply;
