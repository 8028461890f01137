/**
 * Maps a 2D drawing onto a mesh (b/Surf §5.2 "Importing SVG drawings"): every control point goes
 * through polar coordinates about the drawing's centre to normal coordinates about a mesh point,
 * traced as a straightest geodesic; the splines are then traced on the surface and stay editable.
 */
import { SplinekitError, checkStatus } from '../core/errors.js';
import type { Spline } from '../spline/spline.js';
import type { SvgDocument } from '../svg/document.js';
import type { MeshPointLike, SurfaceMesh } from './mesh.js';
import { readMeshPoints, searchHandle } from './mesh-handle.js';
import { SurfaceSpline } from './spline.js';

/** Where and how large {@link mapSplines} puts the drawing on the mesh. */
export interface SvgMapOptions {
  /** Where the drawing's centre (the centre of its bounds) goes. */
  center: MeshPointLike;
  /** Width the drawing's bounds get on the surface, in mesh units. */
  size: number;
  /** Counter-clockwise turn (seen from outside the surface), radians. Default 0. */
  rotation?: number;
  /** A 3D direction the drawing's up points to (projected to the surface). Default: the face's own frame. */
  up?: readonly [number, number, number];
}

/** Maps the splines of a drawing (an SvgDocument or splines in one 2D space) onto the mesh. */
export function mapSplines(mesh: SurfaceMesh, drawing: SvgDocument | readonly Spline[], options: SvgMapOptions): SurfaceSpline[] {
  const splines: readonly Spline[] = Array.isArray(drawing) ? drawing : (drawing as SvgDocument).splines;
  const usable = splines.filter((s) => s.points.length >= 4);
  if (usable.length === 0) throw new SplinekitError('invalid-input', 'the drawing has no curves to map');
  if (!(options.size > 0) || !Number.isFinite(options.size)) throw new SplinekitError('invalid-input', `size must be a positive number (got ${options.size})`);
  let xmin = Infinity, ymin = Infinity, xmax = -Infinity, ymax = -Infinity, total = 0;
  for (const s of usable) {
    for (let i = 0; i < s.points.length; i += 2) {
      xmin = Math.min(xmin, s.points[i]);
      xmax = Math.max(xmax, s.points[i]);
      ymin = Math.min(ymin, s.points[i + 1]);
      ymax = Math.max(ymax, s.points[i + 1]);
    }
    total += s.points.length / 2;
  }
  const width = Math.max(xmax - xmin, ymax - ymin);
  if (!(width > 0)) throw new SplinekitError('invalid-input', 'the drawing has no extent');
  const cx = (xmin + xmax) / 2, cy = (ymin + ymax) / 2;
  const c = mesh.resolve(options.center, 'center');
  const up = options.up ?? [0, 0, 0];
  const handle = searchHandle(mesh);
  handle.resizeXY(total);
  const xy = handle.xyIn();
  let at = 0;
  for (const s of usable)
    for (let i = 0; i < s.points.length; i += 2) {
      xy[at++] = s.points[i] - cx;
      xy[at++] = s.points[i + 1] - cy;
    }
  checkStatus(handle.mapPoints(c.face, c.uv[0], c.uv[1], up[0], up[1], up[2], options.rotation ?? 0, options.size / width), 'map drawing', () => handle.error());
  const mapped = readMeshPoints(mesh);
  const out: SurfaceSpline[] = [];
  let first = 0;
  for (const s of usable) {
    const n = s.points.length / 2;
    const points = mapped.slice(first, first + n);
    first += n;
    const anchors = s.closed ? n / 3 : (n - 1) / 3 + 1;
    // Anchors the drawing joins smoothly (C1/G1) stay smooth on the surface.
    const smooth = Array.from({ length: anchors }, (_, k) => {
      const junction = s.closed ? k : k - 1;
      const tag = junction >= 0 ? s.continuity?.[junction] : undefined;
      return tag?.kind === 'C1' || tag?.kind === 'G1';
    });
    out.push(new SurfaceSpline(mesh, { closed: s.closed, points, smooth }));
  }
  return out;
}
