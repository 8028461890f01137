import type { MeshPoint, SurfaceSplineJSON } from '../../../src/index.js';
import { messageOf } from '../../app/errors.js';

/**
 * What the user draws on a mesh, as an immutable value: splines of mesh points, each with an id
 * that stays with it through edits. Every edit makes a new drawing (sharing the splines that did
 * not change), so undo keeps a before and an after, and a spline's JSON object identifies its
 * state (traces are cached by it).
 */
export interface DrawnSpline {
  readonly id: number;
  readonly json: SurfaceSplineJSON;
}

export interface SurfaceDrawing {
  readonly splines: readonly DrawnSpline[];
}

export const EMPTY_DRAWING: SurfaceDrawing = { splines: [] };

export function findSpline(d: SurfaceDrawing, id: number): DrawnSpline | undefined {
  return d.splines.find((s) => s.id === id);
}

export function replaceSpline(d: SurfaceDrawing, id: number, json: SurfaceSplineJSON): SurfaceDrawing {
  return { splines: d.splines.map((s) => (s.id === id ? { id, json } : s)) };
}

export function addSplines(d: SurfaceDrawing, added: readonly DrawnSpline[]): SurfaceDrawing {
  return { splines: [...d.splines, ...added] };
}

export function removeSplines(d: SurfaceDrawing, ids: readonly number[]): SurfaceDrawing {
  return { splines: d.splines.filter((s) => !ids.includes(s.id)) };
}

/** Number of anchors (3n+1 control points open, 3n closed). */
export function anchorCount(json: SurfaceSplineJSON): number {
  return json.closed ? json.points.length / 3 : (json.points.length - 1) / 3 + 1;
}

/** A control point index's role. */
export function isAnchor(index: number): boolean {
  return index % 3 === 0;
}

/** The anchor a handle belongs to (itself for an anchor). */
export function anchorOf(index: number, json: SurfaceSplineJSON): number {
  const r = index % 3;
  if (r === 0) return index;
  if (r === 1) return index - 1;
  const a = index + 1;
  return json.closed && a >= json.points.length ? 0 : a;
}

// ---- files -------------------------------------------------------------------------------------

/** The JSON a drawing is saved as: the mesh's file name and the splines' mesh points. */
export interface DrawingFile {
  mesh: string;
  splines: SurfaceSplineJSON[];
}

export function drawingFile(mesh: string, d: SurfaceDrawing): DrawingFile {
  return { mesh, splines: d.splines.map((s) => s.json) };
}

function fail(message: string): never {
  throw new Error(`Not a surface drawing: ${message}`);
}

function meshPoint(v: unknown, where: string, faces: number): MeshPoint {
  const p = v as { face?: unknown; uv?: unknown } | null;
  if (!p || typeof p !== 'object') fail(`${where} is not a mesh point`);
  const { face, uv } = p;
  if (typeof face !== 'number' || !Number.isInteger(face) || face < 0) fail(`${where} has no face index`);
  if (face >= faces) fail(`${where} is on face ${face}, but the mesh has ${faces} faces`);
  if (!Array.isArray(uv) || uv.length !== 2 || !uv.every((x) => typeof x === 'number' && Number.isFinite(x))) fail(`${where} has no uv pair`);
  return { face, uv: [uv[0], uv[1]] };
}

/** Validates the splines of a drawing (from a file or the autosave) against a mesh's face count. */
export function parseSplines(list: unknown, faces: number): SurfaceSplineJSON[] {
  if (!Array.isArray(list)) fail('"splines" is not a list');
  return list.map((v, i) => {
    const s = v as Partial<SurfaceSplineJSON> | null;
    if (!s || typeof s !== 'object' || !Array.isArray(s.points)) fail(`spline ${i} has no points`);
    const closed = s.closed === true;
    const n = s.points.length;
    if (closed ? n < 3 || n % 3 !== 0 : n < 4 || (n - 1) % 3 !== 0) fail(`spline ${i} has ${n} control points (3n+1 for an open spline, 3n closed)`);
    const points = s.points.map((p, k) => meshPoint(p, `point ${k} of spline ${i}`, faces));
    const anchors = closed ? n / 3 : (n - 1) / 3 + 1;
    const smooth = Array.isArray(s.smooth) ? s.smooth.map((x) => x === true) : [];
    while (smooth.length < anchors) smooth.push(false);
    return { closed, points, smooth: smooth.slice(0, anchors) };
  });
}

export function parseDrawingFile(text: string, faces: number): DrawingFile {
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch (err) {
    fail(`the JSON does not parse (${messageOf(err)})`);
  }
  const d = data as Partial<DrawingFile> | null;
  if (!d || typeof d !== 'object') fail('expected an object { mesh, splines }');
  return { mesh: typeof d.mesh === 'string' ? d.mesh : '', splines: parseSplines(d.splines, faces) };
}
