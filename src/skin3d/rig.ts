import { checkStatus, SplinekitError } from '../core/errors.js';
import { HandleLinks } from '../core/handles.js';
import { core } from '../core/module.js';
import type { Skin3dRigHandle } from '../core/splinekit-core.mjs';
import type { Cage } from './cage.js';

/**
 * Linear blend skinning of a Catmull-Clark subdivision surface whose output stays a cage — Liu,
 * Jacobson & Gingold 2014, §3.1 (wasm/core/skin3d/rig.h has the math): the cage is fitted so that
 * its level-k surface is closest to the skinned rest surface.
 *
 *   const cage = parseCage(objText);
 *   const rig = SubdivisionRig.create(cage, { handles: [x0, y0, z0, x1, y1, z1], levels: 3 });
 *   const posed = rig.pose(transforms);   // per frame: one matrix product in wasm
 *   const surface = rig.refined();        // the subdivided posed surface
 */

/**
 * Skinning weights: 'shepard' (inverse squared distance, at the refined vertices), 'bbw' (bounded
 * biharmonic weights on the refined surface, solved at the finest level of at most 5,000 vertices and
 * subdivided to the rig's level), or given per refined vertex or per cage vertex (subdivided like
 * positions). Arrays are row-major: vertex-major, handle-minor.
 */
export type WeightSpec =
  | 'shepard'
  | 'bbw'
  | {
      /** #refined × #handles weights, row-major (vertex-major, handle-minor). */
      perRefinedVertex: Float64Array;
    }
  | {
      /** #cage × #handles weights, row-major; subdivided to the refined vertices like positions. */
      perCageVertex: Float64Array;
    };

/** What SubdivisionRig.create needs. */
export interface SubdivisionRigOptions {
  /** Handle positions, 3 per handle (x, y, z), in the order of pose()'s transforms. At least one. */
  handles: ArrayLike<number>;
  /** Subdivision levels k of the surface the fit integrates over, 1..4. Default 3. */
  levels?: number;
  /** Weights; default 'shepard'. */
  weights?: WeightSpec;
}

/** 'fit' is this rig; 'naive' skins the cage vertices themselves (the paper's baseline). */
export type Skin3dMethod = 'fit' | 'naive';

/** Distance to the target (the skinned refined rest surface). */
export interface Skin3dError {
  /** Distance per refined vertex. */
  perVertex: Float64Array;
  /** Area-weighted RMS of those distances over the rest surface's bounding-box diagonal. */
  rms: number;
}

/** BBW is solved at the finest level with at most this many vertices, then subdivided. */
const BBW_MAX_VERTICES = 5000;

const links = new HandleLinks<Skin3dRigHandle>(() => new SplinekitError('invalid-input', 'SubdivisionRig used after dispose()'));

function checkHandles(handles: ArrayLike<number>): number {
  if (handles.length === 0 || handles.length % 3 !== 0) {
    throw new SplinekitError('invalid-input', `skin3d: handles must be 3 numbers per handle (at least one), got ${handles.length} values`);
  }
  for (let k = 0; k < handles.length; k++) {
    if (!Number.isFinite(handles[k])) throw new SplinekitError('invalid-input', `skin3d: handle ${Math.floor(k / 3)} has a non-finite coordinate`);
  }
  return handles.length / 3;
}

function checkLevels(levels: number): void {
  if (!Number.isInteger(levels) || levels < 1 || levels > 4) throw new SplinekitError('invalid-input', `skin3d: levels must be an integer in 1..4, got ${levels}`);
}

/** A wasm rig handle with the cage's arrays written in. */
function cageHandle(cage: Cage): Skin3dRigHandle {
  const h = new (core().Skin3dRigHandle)();
  h.resize(cage.positions.length / 3, cage.faceIndices.length, cage.faceSizes.length, cage.creases.length);
  h.positionsIn().set(cage.positions);
  h.faceSizesIn().set(cage.faceSizes);
  h.faceIndicesIn().set(cage.faceIndices);
  const edges = h.creaseEdgesIn(), sharpness = h.creaseSharpnessIn();
  cage.creases.forEach((c, k) => ((edges[2 * k] = c.a), (edges[2 * k + 1] = c.b), (sharpness[k] = c.sharpness)));
  const corners = cage.corners ?? [];
  if (corners.length > 0) {
    h.resizeCorners(corners.length);
    const vertices = h.cornerVerticesIn(), cornerSharpness = h.cornerSharpnessIn();
    corners.forEach((c, k) => ((vertices[k] = c.v), (cornerSharpness[k] = c.sharpness)));
  }
  return h;
}

/**
 * The cage's level-`levels` Catmull-Clark refinement as a cage of its own: all quads, vertices in
 * the refinement's order (the cage's vertex points first), crease and corner tags with their
 * sharpness decayed by `levels` (infinitely sharp ones kept). Subdividing it gives the same surface as
 * subdividing the original `levels` more times.
 */
export function refineCage(cage: Cage, levels: number): Cage {
  checkLevels(levels);
  const h = cageHandle(cage);
  try {
    checkStatus(h.refineCage(levels), 'skin3d', () => h.errorMessage());
    const quads = Uint32Array.from(h.refinedCageQuads());
    const edges = h.refinedCageCreaseEdges(), sharpness = h.refinedCageCreaseSharpness();
    const cornerVertices = h.refinedCageCornerVertices(), cornerSharpness = h.refinedCageCornerSharpness();
    const refined: Cage = {
      positions: h.refinedCagePositions().slice(),
      faceSizes: new Uint32Array(quads.length / 4).fill(4),
      faceIndices: quads,
      creases: Array.from(sharpness, (s, k) => ({ a: edges[2 * k], b: edges[2 * k + 1], sharpness: s })),
    };
    if (cornerVertices.length > 0) refined.corners = Array.from(cornerSharpness, (s, k) => ({ v: cornerVertices[k], sharpness: s }));
    return refined;
  } finally {
    h.delete();
  }
}

/** A wasm rig with the cage, levels and handle count set up (weights not yet). */
function setupHandle(cage: Cage, handleCount: number, levels: number): Skin3dRigHandle {
  checkLevels(levels);
  const h = cageHandle(cage);
  try {
    checkStatus(h.setup(levels, handleCount), 'skin3d', () => h.errorMessage());
    return h;
  } catch (err) {
    h.delete();
    throw err;
  }
}

/** Fills the handle's weights per `spec`. */
/**
 * Fills the rig's weights from `spec`. `onHandle(solved, total)`: BBW's progress, called after each
 * handle's solve.
 */
function fillWeights(h: Skin3dRigHandle, handles: ArrayLike<number>, spec: WeightSpec, onHandle?: (solved: number, total: number) => void): void {
  const H = handles.length / 3;
  if (spec === 'shepard' || spec === 'bbw') {
    h.handles().set(Array.from(handles));
    if (spec === 'shepard') h.useShepard(2);
    else checkStatus(h.bbw(h.bbwLevel(BBW_MAX_VERTICES), 100, 3, onHandle), 'skin3d', () => h.errorMessage());
    return;
  }
  const given = 'perRefinedVertex' in spec ? spec.perRefinedVertex : spec.perCageVertex;
  const target = 'perRefinedVertex' in spec ? h.refinedWeights() : h.cageWeights();
  const where = 'perRefinedVertex' in spec ? `${h.refinedVertexCount()} refined vertices` : `${h.cageVertexCount()} cage vertices`;
  if (!(given instanceof Float64Array) || given.length !== target.length) {
    throw new SplinekitError('invalid-input', `skin3d: weights must be a Float64Array of ${target.length} values (${where} × ${H} handles), got ${given?.length ?? 'none'}`);
  }
  if (!given.every(Number.isFinite)) throw new SplinekitError('invalid-input', 'skin3d: the weights contain a non-finite value');
  target.set(given);
  if ('perRefinedVertex' in spec) h.restrictWeights();
  else h.prolongateWeights();
}

/**
 * A skinning rig for a Catmull-Clark cage (Liu, Jacobson & Gingold 2014, §3.1): create() builds the
 * subdivision matrix, the weights and one factorization; pose() fits the cage to the blended handle
 * transforms in one matrix product. Holds wasm memory: dispose() it.
 */
export class SubdivisionRig {
  /** Number of handles (transforms per pose). */
  readonly handleCount: number;
  /** Subdivision levels k. */
  readonly levels: number;
  /** Vertices of the cage. */
  readonly cageVertexCount: number;
  /** Vertices of the level-k surface. */
  readonly refinedVertexCount: number;
  /** Precompute time and the memory of M (the subdivision matrix, stored as its per-level factors) and O (#cage × 4·#handles doubles). */
  readonly stats: {
    /** Milliseconds spent in create() (subdivision, weights, factorization, O). */
    precomputeMs: number;
    /** Bytes held in wasm memory by the rig's two big matrices. */
    memoryBytes: {
      /** The subdivision matrix, stored as its per-level factors S_k ⋯ S_1. */
      M: number;
      /** O = [Ŵ_i Â⁻¹]_i, #cage × 4·#handles doubles. */
      O: number;
    };
  };
  private lastMethod: Skin3dMethod = 'fit';
  private cached: { triangles?: Uint32Array; rest?: Float64Array; weights?: Float64Array } = {};

  private constructor(h: Skin3dRigHandle, handleCount: number, levels: number, precomputeMs: number) {
    links.attach(this, h);
    this.handleCount = handleCount;
    this.levels = levels;
    this.cageVertexCount = h.cageVertexCount();
    this.refinedVertexCount = h.refinedVertexCount();
    this.stats = { precomputeMs, memoryBytes: { M: h.memoryM(), O: h.memoryO() } };
  }

  /** Builds the rig: subdivision matrix, weights, Â = Mᵀ D M, its factorization and O. */
  static create(cage: Cage, options: SubdivisionRigOptions): SubdivisionRig {
    const t0 = performance.now();
    const H = checkHandles(options.handles);
    const levels = options.levels ?? 3;
    const h = setupHandle(cage, H, levels);
    try {
      fillWeights(h, options.handles, options.weights ?? 'shepard');
      checkStatus(h.precompute(), 'skin3d', () => h.errorMessage());
    } catch (err) {
      h.delete();
      throw err;
    }
    return new SubdivisionRig(h, H, levels, performance.now() - t0);
  }

  /**
   * Weights per refined vertex (#refined × #handles, row-major), for computing slow weights in a
   * worker and passing them back to create() as `{ perRefinedVertex }`. `onProgress` gets 0, with
   * BBW 0.95 × the share of handles solved after each handle's solve, and 1 when done.
   */
  static solveWeights(cage: Cage, handles: ArrayLike<number>, levels: number, kind: 'shepard' | 'bbw', onProgress?: (fraction: number) => void): Float64Array {
    const H = checkHandles(handles);
    if (kind !== 'shepard' && kind !== 'bbw') throw new SplinekitError('invalid-input', `skin3d: weights must be 'shepard' or 'bbw', got ${String(kind)}`);
    onProgress?.(0);
    const h = setupHandle(cage, H, levels);
    try {
      // BBW: after each handle's solve, the share of handles solved (carrying the weights to the
      // rig's level is the last twentieth).
      fillWeights(h, handles, kind, (solved, total) => onProgress?.((0.95 * solved) / total));
      const out = h.refinedWeights().slice();
      onProgress?.(1);
      return out;
    } finally {
      h.delete();
    }
  }

  /** The level-k faces split into triangles (3 indices each), for display. */
  get refinedTriangles(): Uint32Array {
    return (this.cached.triangles ??= Uint32Array.from(links.get(this).refinedTriangles()));
  }

  /** The refined rest positions M · cage (3 per refined vertex). */
  get restRefined(): Float64Array {
    return (this.cached.rest ??= links.get(this).restRefined().slice());
  }

  /** The weights per refined vertex (#refined × #handles, row-major). */
  get weights(): Float64Array {
    return (this.cached.weights ??= links.get(this).refinedWeights().slice());
  }

  /**
   * Poses the handles: `transforms` holds a row-major 3×4 [A | t] per handle (x' = A x + t, 12
   * numbers each). Returns the posed cage (3 per vertex, file order): the fit, or with
   * method 'naive' the cage vertices skinned directly. A view into wasm memory, valid until the
   * next call on the rig.
   */
  pose(transforms: ArrayLike<number>, method: Skin3dMethod = 'fit'): Float64Array {
    const h = links.get(this);
    const n = 12 * this.handleCount;
    if (transforms.length !== n) throw new SplinekitError('invalid-input', `skin3d: expected ${this.handleCount} transforms (12 numbers each), got ${transforms.length} values`);
    for (let k = 0; k < n; k++) {
      if (!Number.isFinite(transforms[k])) throw new SplinekitError('invalid-input', `skin3d: transform ${Math.floor(k / 12)} has a non-finite entry`);
    }
    if (method !== 'fit' && method !== 'naive') throw new SplinekitError('invalid-input', `skin3d: method must be 'fit' or 'naive', got ${String(method)}`);
    h.transforms().set(transforms);
    this.lastMethod = method;
    if (method === 'naive') return h.naive();
    h.update();
    return h.cage();
  }

  /** M · cage: the level-k surface of `cagePositions` (3 per cage vertex) or of the last pose (a view, as pose()). */
  refined(cagePositions?: Float64Array): Float64Array {
    const h = links.get(this);
    if (!cagePositions) return h.refine(this.lastMethod === 'fit' ? 0 : 1);
    if (cagePositions.length !== 3 * this.cageVertexCount) {
      throw new SplinekitError('invalid-input', `skin3d: expected ${3 * this.cageVertexCount} cage coordinates, got ${cagePositions.length}`);
    }
    h.cageIn().set(cagePositions);
    return h.refine(2);
  }

  /**
   * The limit positions of the level-k vertices (Catmull-Clark limit masks, creases and corners
   * kept) for `cagePositions` or the last pose: the points of the smooth surface itself (a view, as
   * pose()). The first call builds the masks.
   */
  limit(cagePositions?: Float64Array): Float64Array {
    const h = links.get(this);
    if (!cagePositions) return h.limit(this.lastMethod === 'fit' ? 0 : 1);
    this.refined(cagePositions);
    return h.limit(2);
  }

  /** The target: linear blend skinning of the refined rest surface for the last transforms (a view). */
  target(): Float64Array {
    return links.get(this).target();
  }

  /** Distance of the fit's (or the naive cage's) surface to the target, for the last transforms. */
  error(method: Skin3dMethod): Skin3dError {
    const h = links.get(this);
    if (method !== 'naive') h.update(); // the fit for the current transforms, even after a naive pose
    const rms = h.error(method === 'naive' ? 1 : 0);
    return { perVertex: h.perVertexError().slice(), rms };
  }

  /** Frees the rig's wasm memory; the rig cannot be used afterwards (a second call does nothing). */
  dispose(): void {
    links.release(this);
  }
}
