/**
 * A triangle mesh to draw curves on (b/Surf §5.1), held in the wasm core with its adjacency and
 * search graph, and the geodesic primitives over it. Indices and barycentric coordinates always
 * refer to the file's vertex and face order, whatever the core repaired inside (welded duplicate
 * positions, dropped unused vertices, re-oriented faces, split non-manifold vertices, faces and
 * vertices renumbered so that neighbours on the surface are neighbours in memory).
 */
import { core } from '../core/module.js';
import { SplinekitError, checkStatus } from '../core/errors.js';
import type { SurfaceMeshHandle } from '../core/splinekit-core.mjs';
import { parseMesh, type MeshParseOptions } from './mesh-io.js';
import { GUIDE_MIN_FACES, guideTriangles } from './coarse-guide.js';
import { meshHandles, pendingSearch, readMeshPoints, searchHandle, writeMeshPoints } from './mesh-handle.js';
import { meshPointPosition, type MeshPoint, type MeshPointLike } from './mesh-point.js';

export type { MeshPoint, MeshPointLike } from './mesh-point.js';

/** What building the mesh found and repaired; counts are in file space unless noted. */
export interface MeshInfo {
  /** Vertices as in the file. */
  vertices: number;
  /** Faces (triangles after fan triangulation) as in the file. */
  faces: number;
  /** Vertices the algorithms use: after welding and dropping unused ones, plus non-manifold splits. */
  usedVertices: number;
  /** File vertices merged into an earlier one at the same position. */
  weldedVertices: number;
  /** File vertices no face uses. */
  unreferencedVertices: number;
  /** Faces with a repeated vertex (after welding): kept, but curves do not cross them. */
  degenerateFaces: number;
  /**
   * Faces on the vertices of an earlier face (after welding), such as the second side of a
   * double-sided mesh: the earlier face stands for them (a point on one is that point on it).
   */
  duplicateFaces: number;
  /** Edges with more than two faces: left as boundaries. */
  nonManifoldEdges: number;
  /** Vertices whose faces form several fans: given one copy per fan. */
  nonManifoldVertices: number;
  /** Faces whose winding was reversed to agree with their neighbours. */
  flippedFaces: number;
  /** Closed loops of boundary edges. */
  boundaryLoops: number;
  /** Connected parts (a face with a repeated vertex is a part of its own). */
  components: number;
  /** Bytes of wasm memory the mesh structures hold (positions, faces, adjacency, search graph, landmark distances). */
  bytes: number;
  /** Landmarks of the shortest-path search (see SurfaceMeshOptions.landmarks; 0 when no connected part has 16,384 faces). */
  landmarks: number;
  /** Faces of the coarse guide of long paths (see SurfaceMeshOptions.guide; 0 without one). */
  guideFaces: number;
  /** Milliseconds the core spent building the mesh and its search structures. */
  buildMs: MeshBuildTimes;
  /** One line per repair or oddity, e.g. "welded 57,653 vertices that share a position". */
  warnings: string[];
}

/** Milliseconds the core spent building a mesh (MeshInfo.buildMs). */
export interface MeshBuildTimes {
  /** Welding, orientation, adjacency, locality order. */
  mesh: number;
  /** The shortest-path search's graph and landmarks. */
  search: number;
  /** The coarse guide: the simplification and the guide's own search structures. */
  guide: number;
}

/** Options of SurfaceMesh.fromArrays and SurfaceMesh.load. */
export interface SurfaceMeshOptions {
  /**
   * Landmark faces whose distances (2 bytes per face each) bound the shortest-path search from below
   * along the surface, so that searches on coiled or folded shapes follow the path instead of
   * flooding the mesh; placed in the connected parts of 16,384 faces or more (the largest first; a
   * scan's specks of debris get none). Default 8; 0 saves the memory and the precompute (about one
   * dual-graph Dijkstra search per landmark). Default 8, or GUIDED_LANDMARKS on a mesh with a coarse guide.
   */
  landmarks?: number;
  /**
   * A coarse guide of long paths: the mesh simplified to about a sixteenth of its faces (meshoptimizer),
   * with its own search structures; a shortest path between far points is found on it first and
   * followed on the mesh, so that on coiled, folded or limbed shapes tracing takes time that follows
   * the path rather than the mesh (about 11 bytes per face, and ~0.7 µs per face to build, with the
   * search structures). Default: on meshes of GUIDE_MIN_FACES (65,536) faces or more. Not built when
   * the simplifier cannot reach a quarter of the faces within 1% of the mesh's extent.
   */
  guide?: boolean;
  /**
   * Leave the shortest-path search structures (search graph, landmarks) to `buildSearch()` or the
   * first call that needs them, so that a viewer can show the mesh sooner (on a 2M-triangle mesh
   * they are about half of the build). Until then `info.bytes` and `info.landmarks` leave them out.
   * Default false.
   */
  deferSearch?: boolean;
}

/** Landmarks of a SurfaceMesh when SurfaceMeshOptions.landmarks is not given. */
export const DEFAULT_LANDMARKS = 8;

/**
 * Landmarks of a SurfaceMesh with a coarse guide when SurfaceMeshOptions.landmarks is not given: the
 * guide finds the long paths, for which the other four paid (2026-12-05, native, the benchmark's
 * coil, knotted tube and folded body with their guides: 30 random curves each took 0.95-1.01 times as
 * long with 4 as with 8, 8 bytes per face less).
 */
export const GUIDED_LANDMARKS = 4;

/** A geodesic path on the mesh: its start, every edge crossing, its end. */
export interface GeodesicPath {
  /** Its length (sum of the segment lengths in 3D). */
  length: number;
  /** The start, every edge crossing, the end (file order). */
  points: MeshPoint[];
  /** x, y, z of each point. */
  xyz: Float64Array;
}

/**
 * The counts of the core's mesh report, under the names the core gives them
 * (wasm/core/surface/mesh.h, `report_fields`): the binding hands them on by name, so their order
 * is written down once, in the core.
 */
export const MESH_REPORT_FIELDS = [
  'file_vertices',
  'file_faces',
  'used_vertices',
  'welded_vertices',
  'unreferenced_vertices',
  'degenerate_faces',
  'duplicate_faces',
  'non_manifold_edges',
  'non_manifold_vertices',
  'flipped_faces',
  'non_orientable_cuts',
  'boundary_edges',
  'boundary_loops',
  'components',
] as const;

/** One count of the core's mesh report (see MESH_REPORT_FIELDS). */
export type MeshReportField = (typeof MESH_REPORT_FIELDS)[number];

/** The built mesh's report from the core, checked to hold every field this package reads. */
function readReport(handle: SurfaceMeshHandle): Record<MeshReportField, number> {
  const fields = handle.reportFields();
  for (const name of MESH_REPORT_FIELDS) {
    if (typeof fields[name] !== 'number') throw new SplinekitError('internal', `the core's mesh report has no count '${name}'`);
  }
  return fields as Record<MeshReportField, number>;
}

function count(n: number, what: string): string {
  return `${n.toLocaleString('en-US')} ${what}`;
}

/**
 * A triangle mesh in the wasm core, with its search structures; load with `SurfaceMesh.load` or
 * `SurfaceMesh.fromArrays`, free with `dispose()`. The wasm object behind it is private to the
 * package (see surface/mesh-handle.ts).
 */
export class SurfaceMesh {
  private readonly _info: MeshInfo;
  /** File positions (3 per vertex) and triangles (3 per face). */
  readonly positions: Float64Array;
  /** Three file vertex indices per face (#F by 3). */
  readonly triangles: Int32Array;
  /** Bounding-box diagonal. */
  readonly scale: number;
  /**
   * The faces (file indices, ascending) that repeat an earlier face's vertices, such as the second
   * side of a double-sided mesh: the core takes the earlier face for them (a point given on one is
   * that point on it, and no result lies on them). A view draws and picks without them.
   */
  readonly duplicateFaces: Int32Array;
  private vertexCorner: Int32Array | null = null;

  private constructor(handle: SurfaceMeshHandle, positions: Float64Array, triangles: Int32Array) {
    meshHandles.attach(this, handle);
    this.positions = positions;
    this.triangles = triangles;
    this.scale = handle.scale();
    this.duplicateFaces = handle.duplicateFaces().slice();
    const r = readReport(handle);
    const info: MeshInfo = {
      vertices: r.file_vertices,
      faces: r.file_faces,
      usedVertices: r.used_vertices,
      weldedVertices: r.welded_vertices,
      unreferencedVertices: r.unreferenced_vertices,
      degenerateFaces: r.degenerate_faces,
      duplicateFaces: r.duplicate_faces,
      nonManifoldEdges: r.non_manifold_edges,
      nonManifoldVertices: r.non_manifold_vertices,
      flippedFaces: r.flipped_faces,
      boundaryLoops: r.boundary_loops,
      components: r.components,
      bytes: handle.bytes(),
      landmarks: handle.landmarkCount(),
      guideFaces: 0,
      buildMs: { mesh: handle.buildMilliseconds(0), search: handle.buildMilliseconds(1), guide: 0 },
      warnings: [],
    };
    const w = info.warnings;
    if (info.weldedVertices) w.push(`welded ${count(info.weldedVertices, 'vertices')} that share a position with an earlier one`);
    if (info.unreferencedVertices) w.push(`ignored ${count(info.unreferencedVertices, 'vertices')} that no face uses`);
    if (info.degenerateFaces) w.push(`${count(info.degenerateFaces, 'faces')} repeat a vertex: curves do not cross them`);
    if (info.duplicateFaces) w.push(`${count(info.duplicateFaces, 'faces')} repeat an earlier face (a double-sided mesh?): taken as that face`);
    if (info.nonManifoldEdges) w.push(`${count(info.nonManifoldEdges, 'edges')} have more than two faces: treated as boundaries`);
    if (info.nonManifoldVertices) w.push(`${count(info.nonManifoldVertices, 'vertices')} join separate fans of faces: split`);
    if (info.flippedFaces) w.push(`${count(info.flippedFaces, 'faces')} were wound against their neighbours: re-oriented`);
    if (r.non_orientable_cuts) w.push(`the surface is not orientable: cut along ${count(r.non_orientable_cuts, 'edges')}`);
    if (info.components > 1) w.push(`the mesh has ${info.components} separate parts: curves cannot cross between them`);
    this._info = info;
  }

  /** What building the mesh found and repaired (with the search structures once they are built). */
  get info(): MeshInfo {
    const handle = meshHandles.has(this) ? meshHandles.get(this) : null;
    if (handle && this._info.buildMs.search === 0 && handle.searchBuilt()) this.readSearch(handle);
    return this._info;
  }

  /** Whether the search structures are built (see SurfaceMeshOptions.deferSearch). */
  get searchBuilt(): boolean {
    return meshHandles.get(this).searchBuilt();
  }

  /** Builds the search structures (and the coarse guide) now if SurfaceMeshOptions.deferSearch left them; returns info. */
  buildSearch(): MeshInfo {
    const handle = searchHandle(this);
    handle.buildSearch();
    this.readSearch(handle);
    return this._info;
  }

  private readSearch(handle: SurfaceMeshHandle): void {
    this._info.bytes = handle.bytes();
    this._info.landmarks = handle.landmarkCount();
    this._info.guideFaces = handle.guideFaces();
    this._info.buildMs.search = handle.buildMilliseconds(1);
  }

  /**
   * Simplifies the mesh, builds the search structures (deferred by fromArrays until now) and gives the
   * core its coarse guide (SurfaceMeshOptions.guide). Where the simplifier cannot make a guide, the
   * search gets DEFAULT_LANDMARKS unless `landmarks` were asked for.
   */
  private buildGuide(landmarksAsked: boolean): void {
    const handle = meshHandles.get(this);
    const start = performance.now();
    const kept = guideTriangles(this.positions, this.triangles);
    const simplifyMs = performance.now() - start;
    if (!kept && !landmarksAsked) handle.setLandmarks(DEFAULT_LANDMARKS);
    handle.buildSearch();
    if (kept) {
      handle.resizeGuide(kept.length / 3);
      handle.guideIn().set(kept);
      checkStatus(handle.buildGuide(), 'coarse guide', () => handle.error());
    }
    this.readSearch(handle);
    this._info.buildMs.guide = kept ? simplifyMs + handle.buildMilliseconds(2) : simplifyMs;
  }

  /** A mesh from flat arrays (3 numbers per vertex, 3 vertex indices per triangle). */
  static fromArrays(positions: ArrayLike<number>, triangles: ArrayLike<number>, options: SurfaceMeshOptions = {}): SurfaceMesh {
    const guide = options.guide ?? triangles.length / 3 >= GUIDE_MIN_FACES;
    const landmarks = options.landmarks ?? (guide ? GUIDED_LANDMARKS : DEFAULT_LANDMARKS);
    if (!Number.isInteger(landmarks) || landmarks < 0 || landmarks > 64) throw new SplinekitError('invalid-input', `landmarks must be an integer from 0 to 64 (got ${landmarks})`);
    if (positions.length % 3 !== 0) throw new SplinekitError('invalid-input', `positions: ${positions.length} numbers is not a multiple of 3`);
    if (triangles.length % 3 !== 0) throw new SplinekitError('invalid-input', `triangles: ${triangles.length} indices is not a multiple of 3`);
    const m = core();
    const handle = new m.SurfaceMeshHandle();
    try {
      handle.resizeMesh(positions.length / 3, triangles.length / 3);
      handle.positionsIn().set(positions);
      const t = handle.trianglesIn();
      for (let i = 0; i < triangles.length; i++) {
        const v = triangles[i];
        if (!Number.isInteger(v)) throw new SplinekitError('invalid-input', `triangle ${Math.floor(i / 3)} has a vertex index that is not an integer (${v})`);
        t[i] = v;
      }
      // (with a guide, the search waits for the simplification, which decides its landmarks)
      checkStatus(handle.build(landmarks, guide || options.deferSearch === true), 'invalid mesh', () => handle.error());
    } catch (err) {
      handle.delete();
      throw err;
    }
    const mesh = new SurfaceMesh(handle, Float64Array.from(positions), Int32Array.from(triangles));
    const landmarksAsked = options.landmarks !== undefined;
    if (guide && options.deferSearch === true) {
      pendingSearch.set(mesh, () => {
        pendingSearch.delete(mesh);
        mesh.buildGuide(landmarksAsked);
      });
    } else if (guide) {
      try {
        mesh.buildGuide(landmarksAsked);
      } catch (err) {
        mesh.dispose();
        throw err;
      }
    }
    return mesh;
  }

  /** Parses a mesh file (OBJ, OFF, PLY, STL, glTF, GLB) and builds it. */
  static async load(data: ArrayBuffer | Uint8Array | string, fileName: string, options?: MeshParseOptions & SurfaceMeshOptions): Promise<SurfaceMesh> {
    const arrays = await parseMesh(data, fileName, options);
    try {
      return SurfaceMesh.fromArrays(arrays.positions, arrays.triangles, options);
    } catch (err) {
      if (err instanceof SplinekitError) throw new SplinekitError(err.code, `${fileName}: ${err.message}`, { cause: err });
      throw err;
    }
  }

  /** Number of faces (file order, after fan triangulation). */
  get faceCount(): number {
    return this.triangles.length / 3;
  }

  /** A validated mesh point. */
  point(face: number, u: number, v: number): MeshPoint {
    const p: MeshPoint = { face, uv: [u, v] };
    this.check(p, 'point');
    return p;
  }

  /** The point at vertex `v` (file index), on the first face that uses it. */
  vertexPoint(v: number): MeshPoint {
    if (!Number.isInteger(v) || v < 0 || v >= this.positions.length / 3)
      throw new SplinekitError('invalid-input', `vertex ${v} does not exist (the mesh has ${this.positions.length / 3} vertices)`);
    if (!this.vertexCorner) {
      const corner = new Int32Array(this.positions.length / 3).fill(-1);
      for (let i = this.triangles.length - 1; i >= 0; i--) corner[this.triangles[i]] = i;
      this.vertexCorner = corner;
    }
    const at = this.vertexCorner[v];
    if (at < 0) throw new SplinekitError('invalid-input', `vertex ${v} is not used by any face`);
    const k = at % 3;
    return { face: (at - k) / 3, uv: [k === 1 ? 1 : 0, k === 2 ? 1 : 0] };
  }

  /** A mesh point from a point or a vertex index. */
  resolve(p: MeshPointLike, what = 'point'): MeshPoint {
    if (typeof p === 'number') return this.vertexPoint(p);
    this.check(p, what);
    return p;
  }

  /** The position in space of a mesh point or vertex. */
  xyz(p: MeshPointLike): [number, number, number] {
    return meshPointPosition(this.positions, this.triangles, this.resolve(p));
  }

  /** Unit normal of the point's face (as wound in the file). */
  normal(p: MeshPointLike): [number, number, number] {
    const q = this.resolve(p);
    const t = this.triangles, x = this.positions, f = 3 * q.face;
    const a = 3 * t[f], b = 3 * t[f + 1], c = 3 * t[f + 2];
    const e1 = [x[b] - x[a], x[b + 1] - x[a + 1], x[b + 2] - x[a + 2]];
    const e2 = [x[c] - x[a], x[c + 1] - x[a + 1], x[c + 2] - x[a + 2]];
    const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const len = Math.hypot(n[0], n[1], n[2]) || 1;
    return [n[0] / len, n[1] / len, n[2] / len];
  }

  /** The locally shortest geodesic path from a to b (b/Surf §5.1). */
  shortestPath(a: MeshPointLike, b: MeshPointLike): GeodesicPath {
    const handle = writeMeshPoints(this, [this.resolve(a, 'start'), this.resolve(b, 'end')]);
    checkStatus(handle.shortestPath(), 'shortest path', () => handle.error());
    return { length: handle.length(), points: readMeshPoints(this), xyz: handle.xyzOut().slice() };
  }

  /** The straightest geodesic from a point in a direction (projected to the surface) for a length. */
  straightest(from: MeshPointLike, direction: readonly [number, number, number], length: number): GeodesicPath {
    const handle = writeMeshPoints(this, [this.resolve(from, 'start')]);
    checkStatus(handle.straightest(direction[0], direction[1], direction[2], length), 'straightest geodesic', () => handle.error());
    return { length: handle.length(), points: readMeshPoints(this), xyz: handle.xyzOut().slice() };
  }

  /** Frees the wasm memory. The mesh (and splines on it) cannot be used afterwards. */
  dispose(): void {
    meshHandles.release(this);
  }

  /** True after dispose(). */
  get isDisposed(): boolean {
    return !meshHandles.has(this);
  }

  private check(p: MeshPoint, what: string): void {
    const faces = this.triangles.length / 3;
    if (!p || !Number.isInteger(p.face) || p.face < 0 || p.face >= faces)
      throw new SplinekitError('invalid-input', `${what}: face ${p?.face} is not a face of the mesh (it has ${faces})`);
    const [u, v] = p.uv ?? [];
    const eps = 1e-9;
    if (!Number.isFinite(u) || !Number.isFinite(v) || u < -eps || v < -eps || u + v > 1 + eps)
      throw new SplinekitError('invalid-input', `${what}: barycentric coordinates (${u}, ${v}) lie outside face ${p.face}`);
  }
}
