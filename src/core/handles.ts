/**
 * The package's private links from its wrapper objects to the wasm (embind) objects behind them.
 *
 *   const links = new HandleLinks<SplineSetHandle>(() => new Error('SplineSet used after dispose()'));
 *   links.attach(set, handle);        // in the wrapper's constructor
 *   links.get(set).segmentCount();    // in any module of the package that drives the handle
 *   links.release(set);               // in dispose(): deletes the wasm object
 *
 * A wrapper keeps no field that holds its handle, so the package's types (`dist/**.d.ts`) never
 * mention an embind class and embedders cannot reach the raw core; modules inside the package
 * that need another wrapper's handle (a SurfaceSpline its mesh's, a SkinRig its spline set's)
 * look it up here. This module is not exported from `src/index.ts`.
 */
import type { EmbindObject } from './splinekit-core.mjs';

/** Links wrappers of one kind to their handles (a WeakMap: a dropped wrapper is not kept alive). */
export class HandleLinks<H extends EmbindObject> {
  private readonly links = new WeakMap<object, H>();

  /** @param disposed makes the error `get` throws for a wrapper that has no handle (disposed). */
  constructor(private readonly disposed: () => Error) {}

  /** Links `owner` to `handle`; the handle is deleted by `release(owner)`. */
  attach(owner: object, handle: H): void {
    this.links.set(owner, handle);
  }

  /** The handle of `owner`; throws the `disposed` error once it was released. */
  get(owner: object): H {
    const handle = this.links.get(owner);
    if (!handle) throw this.disposed();
    return handle;
  }

  /** True while `owner` has a handle (created and not yet released). */
  has(owner: object): boolean {
    return this.links.has(owner);
  }

  /** Deletes the wasm object of `owner` and forgets it; false when there was none (already released). */
  release(owner: object): boolean {
    const handle = this.links.get(owner);
    if (!handle) return false;
    this.links.delete(owner);
    handle.delete();
    return true;
  }
}
