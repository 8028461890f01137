import { core } from '../core/module.js';
import type { BezierScratch } from '../core/splinekit-core.mjs';

/**
 * Static kernels on one cubic segment given as 8 numbers (x0 y0 x1 y1 x2 y2 x3 y3), computed by
 * the wasm core. Results go to an optional `target` to avoid allocation.
 */
export class Bezier {
  private static scratch: BezierScratch | undefined;

  private static load(seg: ArrayLike<number>): Float64Array {
    Bezier.scratch ??= new (core().BezierScratch)();
    const data = Bezier.scratch.data();
    for (let i = 0; i < 8; i++) data[i] = seg[i];
    return data;
  }

  /** Point (order 0) or derivative (order 1..3) at t. */
  static derivative(seg: ArrayLike<number>, t: number, order = 0, target: [number, number] = [0, 0]): [number, number] {
    Bezier.load(seg);
    Bezier.scratch!.derivative(t, order);
    const d = Bezier.scratch!.data();
    target[0] = d[8];
    target[1] = d[9];
    return target;
  }

  /** Point at t (the same as `derivative(seg, t, 0, target)`). */
  static point(seg: ArrayLike<number>, t: number, target?: [number, number]): [number, number] {
    return Bezier.derivative(seg, t, 0, target);
  }

  /** de Casteljau split at t: [left, right], each 8 numbers. */
  static split(seg: ArrayLike<number>, t: number): [Float64Array, Float64Array] {
    Bezier.load(seg);
    Bezier.scratch!.split(t);
    const d = Bezier.scratch!.data();
    return [d.slice(0, 8), d.slice(8, 16)];
  }

  /** Arc length over [t0, t1] (adaptive Gauss–Legendre, absolute tolerance). */
  static arcLength(seg: ArrayLike<number>, t0 = 0, t1 = 1, tolerance = 1e-9): number {
    Bezier.load(seg);
    return Bezier.scratch!.arcLength(t0, t1, tolerance);
  }

  /** Tight bounds of the curve: [xmin, ymin, xmax, ymax]. */
  static bounds(seg: ArrayLike<number>): [number, number, number, number] {
    Bezier.load(seg);
    Bezier.scratch!.bounds();
    const d = Bezier.scratch!.data();
    return [d[8], d[9], d[10], d[11]];
  }

  /** The exact Gram matrix of the cubic Bernstein basis, Â = ∫₀¹ b bᵀ dt, row-major 4×4. */
  static gram(): number[] {
    return core().gramMatrix();
  }
}
