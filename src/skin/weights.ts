import { SplinekitError, checkStatus } from '../core/errors.js';
import { core } from '../core/module.js';
import type { SkinWeightsHandle } from '../core/splinekit-core.mjs';
import type { Domain } from './domain.js';
import type { WeightSource } from './rig.js';

/** Weights solved on a triangulated domain: harmonic (Laplace) or Bounded Biharmonic Weights. */
export type DomainWeightKind = 'harmonic' | 'bbw';

/** A triangle mesh with point handles at some of its vertices (e.g. a `Domain` from buildDomain). */
export type WeightMesh = Pick<Domain, 'vertices' | 'triangles' | 'handleVertices'>;

/** Options of Bounded Biharmonic Weights (see wasm/core/skin/weights.h, BbwOptions). */
export interface BbwOptions {
  /** Cap on active-set iterations (linear solves) per handle. Default 100. */
  maxIterations?: number;
  /** How far a weight may leave [0, 1] and still count as feasible (the result is clamped). Default 1e-9. */
  boundTolerance?: number;
  /**
   * How wrong-signed a bound's multiplier may be and still keep the bound, relative to the weight
   * change it causes (unit- and resolution-independent). Smaller is closer to the exact optimum
   * and slower; the default 3 keeps weights within ~1e-4 of it.
   */
  multiplierTolerance?: number;
  /** Normalize the weights to sum to 1 at every vertex. Default true. */
  partitionOfUnity?: boolean;
  /** Lumped mass matrix of Q = L M⁻¹ L. Default 'voronoi'. */
  mass?: 'voronoi' | 'barycentric';
}

export const DEFAULT_BBW: Required<BbwOptions> = {
  maxIterations: 100,
  boundTolerance: 1e-9,
  multiplierTolerance: 3,
  partitionOfUnity: true,
  mass: 'voronoi',
};

/**
 * Automatic skinning weights on a triangulated 2D domain, solved in the wasm core: harmonic
 * weights, or Bounded Biharmonic Weights (Jacobson, Baran, Popović & Sorkine 2011). Read them at
 * any points (curve samples, control points) by point location and linear interpolation in the
 * mesh's triangles; points outside the mesh take the value at the nearest point of the mesh.
 * A `WeightSource` for SkinRig. Create with `harmonic`/`bbw`, query, then `dispose()`.
 */
export class SkinWeights implements WeightSource {
  /** Which weights were solved. */
  readonly kind: DomainWeightKind;
  /** Number of handles (#H), one weight function each. */
  readonly handleCount: number;
  /** Number of mesh vertices (#V). */
  readonly vertexCount: number;
  /** Number of mesh triangles (#F). */
  readonly triangleCount: number;
  /** Weights at the mesh vertices: #V × #H, row-major. */
  readonly vertexWeights: Float64Array;
  /** BBW: active-set iterations (linear solves) per handle; empty for harmonic weights. */
  readonly iterations: Int32Array;
  /** BBW: every handle's active set settled within maxIterations (always true for harmonic weights). */
  readonly converged: boolean;
  /** BBW: vertices held at a bound to break an active-set cycle (0 almost always). */
  readonly pinned: number;
  private handle: SkinWeightsHandle | undefined;

  private constructor(handle: SkinWeightsHandle, kind: DomainWeightKind) {
    this.handle = handle;
    this.kind = kind;
    this.handleCount = handle.handleCount();
    this.vertexCount = handle.vertices().length / 2;
    this.triangleCount = handle.triangles().length / 3;
    this.vertexWeights = handle.weights().slice();
    this.iterations = kind === 'bbw' ? handle.iterations().slice() : new Int32Array(0);
    this.converged = handle.converged();
    this.pinned = handle.pinned();
  }

  /** Harmonic weights: Δw_i = 0 with w_i(handle_j) = δ_ij; a partition of unity, not bounded on non-Delaunay meshes. */
  static harmonic(mesh: WeightMesh): SkinWeights {
    return SkinWeights.create(mesh, 'harmonic', (h) => h.harmonic());
  }

  /** Bounded Biharmonic Weights: min ∫(Δw_i)² with w_i(handle_j) = δ_ij and 0 ≤ w_i ≤ 1, normalized. */
  static bbw(mesh: WeightMesh, options: BbwOptions = {}): SkinWeights {
    const o = { ...DEFAULT_BBW, ...options };
    if (!Number.isInteger(o.maxIterations)) throw invalid(`maxIterations must be an integer, got ${o.maxIterations}`);
    if (o.mass !== 'voronoi' && o.mass !== 'barycentric') throw invalid(`mass must be 'voronoi' or 'barycentric', got ${String(o.mass)}`);
    return SkinWeights.create(mesh, 'bbw', (h) =>
      h.bbw(o.maxIterations, o.boundTolerance, o.multiplierTolerance, o.partitionOfUnity, o.mass === 'voronoi' ? 1 : 0),
    );
  }

  /** `harmonic` or `bbw` by name. */
  static solve(mesh: WeightMesh, kind: DomainWeightKind, options: BbwOptions = {}): SkinWeights {
    if (kind === 'harmonic') return SkinWeights.harmonic(mesh);
    if (kind === 'bbw') return SkinWeights.bbw(mesh, options);
    throw invalid(`unknown weight kind ${String(kind)}: expected 'harmonic' or 'bbw'`);
  }

  private static create(mesh: WeightMesh, kind: DomainWeightKind, solve: (h: SkinWeightsHandle) => number): SkinWeights {
    const { vertices, triangles, handleVertices } = mesh;
    if (!(vertices instanceof Float64Array) || vertices.length % 2) throw invalid('vertices must be a Float64Array of x,y pairs');
    if (!(triangles instanceof Int32Array) || triangles.length % 3) throw invalid('triangles must be an Int32Array of index triples');
    if (!(handleVertices instanceof Int32Array)) throw invalid('handleVertices must be an Int32Array');
    const h = new (core().SkinWeightsHandle)();
    try {
      h.resize(vertices.length / 2, triangles.length / 3, handleVertices.length);
      h.vertices().set(vertices);
      h.triangles().set(triangles);
      h.handles().set(handleVertices);
      checkStatus(solve(h), `${kind === 'bbw' ? 'BBW' : 'harmonic'} weights`, () => h.error());
      return new SkinWeights(h, kind);
    } catch (err) {
      h.delete();
      throw err;
    }
  }

  private live(): SkinWeightsHandle {
    if (!this.handle) throw new Error('SkinWeights used after dispose()');
    return this.handle;
  }

  /** Weights at `points` (x,y pairs): #points × #H, row-major, into `out` if given. */
  weightsAt(points: Float64Array, out?: Float64Array): Float64Array {
    return this.query(points, 1, out, (h) => h.weightsAt(), 'weights');
  }

  /**
   * Gradients ∇w_i at `points`: #points × #H × 2 (x, y), row-major, into `out` if given. The
   * weights are piecewise linear, so this is the gradient of the triangle holding each point.
   */
  gradientsAt(points: Float64Array, out?: Float64Array): Float64Array {
    return this.query(points, 2, out, (h) => h.gradientsAt(), 'weight gradients');
  }

  /** The gradient of every weight on every triangle: #F × #H × 2. */
  triangleGradients(): Float64Array {
    return this.live().triangleGradients().slice();
  }

  /** Frees the weights' wasm memory; the object cannot be queried afterwards (a second call does nothing). */
  dispose(): void {
    this.handle?.delete();
    this.handle = undefined;
  }

  private query(points: Float64Array, per: number, out: Float64Array | undefined, run: (h: SkinWeightsHandle) => number, what: string): Float64Array {
    const h = this.live();
    if (!(points instanceof Float64Array) || points.length % 2) throw invalid(`${what}: points must be a Float64Array of x,y pairs`);
    const size = (points.length / 2) * this.handleCount * per;
    if (out && out.length !== size) throw invalid(`${what}: out has length ${out.length}, expected ${size}`);
    h.resizeQueries(points.length / 2);
    h.queries().set(points);
    checkStatus(run(h), what, () => h.error());
    const result = h.result();
    if (!out) return result.slice();
    out.set(result);
    return out;
  }
}

function invalid(message: string): SplinekitError {
  return new SplinekitError('invalid-input', `skin weights: ${message}`);
}
