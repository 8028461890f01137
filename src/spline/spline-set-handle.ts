/**
 * The wasm handles of SplineSets, private to the package (see core/handles.ts): other
 * capabilities' bindings that take a spline set (the skin rig's setup) get it here.
 */
import { HandleLinks } from '../core/handles.js';
import type { SplineSetHandle } from '../core/splinekit-core.mjs';

/** SplineSet → its SplineSetHandle; `get` throws for a disposed set. */
export const splineSetHandles = new HandleLinks<SplineSetHandle>(() => new Error('SplineSet used after dispose()'));
