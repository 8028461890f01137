/**
 * The wasm handles of SurfaceMeshes, private to the package (see core/handles.ts), and the two
 * ways points cross to and from them. SurfaceSpline, traceBezier, mapSplines and the CLI drive a
 * mesh's handle through these; embedders only see SurfaceMesh.
 */
import { HandleLinks } from '../core/handles.js';
import { SplinekitError } from '../core/errors.js';
import type { SurfaceMeshHandle } from '../core/splinekit-core.mjs';
import type { MeshPoint } from './mesh-point.js';

/** SurfaceMesh → its SurfaceMeshHandle; `get` throws SplinekitError('invalid-input') for a disposed mesh. */
export const meshHandles = new HandleLinks<SurfaceMeshHandle>(() => new SplinekitError('invalid-input', 'the mesh has been disposed'));

/**
 * What a mesh whose search structures were deferred (SurfaceMeshOptions.deferSearch) still has to
 * build before its first query that needs them (SurfaceMesh registers it; it removes itself once run).
 */
export const pendingSearch = new WeakMap<object, () => void>();

/** The handle of `mesh`, with its search structures built (see pendingSearch). */
export function searchHandle(mesh: object): SurfaceMeshHandle {
  const handle = meshHandles.get(mesh);
  pendingSearch.get(mesh)?.();
  return handle;
}

/** Writes mesh points (file space) into the handle's input buffer of `mesh`, and returns the handle. */
export function writeMeshPoints(mesh: object, points: readonly MeshPoint[]): SurfaceMeshHandle {
  const handle = searchHandle(mesh);
  handle.resizePoints(points.length);
  const buf = handle.pointsIn();
  points.forEach((p, i) => {
    buf[3 * i] = p.face;
    buf[3 * i + 1] = p.uv[0];
    buf[3 * i + 2] = p.uv[1];
  });
  return handle;
}

/** Points `from` to `to` (default: all) of the handle's output buffer of `mesh`, as mesh points. */
export function readMeshPoints(mesh: object, from = 0, to?: number): MeshPoint[] {
  const buf = meshHandles.get(mesh).pointsOut();
  const end = to ?? buf.length / 3;
  const out: MeshPoint[] = [];
  for (let i = from; i < end; i++) out.push({ face: buf[3 * i], uv: [buf[3 * i + 1], buf[3 * i + 2]] });
  return out;
}
