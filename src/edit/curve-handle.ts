/**
 * The wasm handles of CatmullRom curves, private to the package (see core/handles.ts): a
 * LocalEdit begins on its curve's handle and hands the result back to it.
 */
import { SplinekitError } from '../core/errors.js';
import { HandleLinks } from '../core/handles.js';
import type { CatmullRomHandle } from '../core/splinekit-core.mjs';

/** CatmullRom → its CatmullRomHandle; `get` throws for a disposed curve. */
export const curveHandles = new HandleLinks<CatmullRomHandle>(() => new SplinekitError('invalid-input', 'CatmullRom used after dispose()'));
