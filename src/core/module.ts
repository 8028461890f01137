import createSplinekitCore, { type SplinekitCoreModule } from './splinekit-core.mjs';
import { SplinekitError } from './errors.js';
import { loadSimplifier } from '../surface/coarse-guide.js';

let instance: SplinekitCoreModule | undefined;
let loading: Promise<SplinekitCoreModule> | undefined;

/**
 * Loads the WebAssembly core. Call (and await) once before using anything else; later calls
 * return the same instance. The same import works in Node, workers and browsers: the wasm is
 * inlined in the module, so no file has to be located or fetched.
 */
export function init(): Promise<SplinekitCoreModule> {
  // (with the mesh simplifier's, which SurfaceMesh calls synchronously for its coarse guide)
  loading ??= Promise.all([createSplinekitCore(), loadSimplifier()]).then(
    ([m]) => (instance = m),
    (err: unknown) => {
      loading = undefined;
      throw new SplinekitError('internal', `could not load the splinekit WebAssembly core: ${String(err)}`, { cause: err });
    },
  );
  return loading;
}

/** The loaded core; throws a SplinekitError('not-initialized') before `await init()`. */
export function core(): SplinekitCoreModule {
  if (!instance) throw new SplinekitError('not-initialized', 'splinekit is not initialized: call `await init()` first');
  return instance;
}

/**
 * Memory of the wasm core: `used` bytes allocated by malloc now (leak and allocation checks
 * compare it around create/dispose cycles or updates) and the `heap` size (grows, never shrinks).
 */
export function memory(): {
  /** Bytes allocated by malloc in the wasm heap now. */
  used: number;
  /** Size of the wasm heap in bytes (grows, never shrinks). */
  heap: number;
} {
  const m = core();
  return { used: m.heapUsed(), heap: m.HEAP8.length };
}
