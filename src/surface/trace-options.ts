/**
 * How curves on a mesh are traced (b/Surf §4): the options, their defaults, and their encoding for
 * the binding. The core owns the defaults (`default_levels` in wasm/core/surface/curves.h): omitted
 * levels cross as -1. DEFAULT_TRACE_SCHEME / DEFAULT_TRACE_LEVELS state them for the CLI and the
 * editor, and a test keeps them equal to what the core traces.
 */
import { SplinekitError } from '../core/errors.js';

/** Subdivision scheme: Lane–Riesenfeld with geodesic averages (OLR) or repeated de Casteljau (RDC). */
export type SurfaceScheme = 'olr' | 'rdc';

/** The schemes, in the binding's numbering (index = the code `traceArgs` passes). */
export const SURFACE_SCHEMES: readonly SurfaceScheme[] = ['olr', 'rdc'];

/** The scheme used when `TraceOptions.scheme` is omitted. */
export const DEFAULT_TRACE_SCHEME: SurfaceScheme = 'olr';

/**
 * Uniform subdivision levels used when `TraceOptions.levels` is omitted, per scheme: 5 for OLR,
 * 4 for RDC (the configurations BENCHMARKS.md measures and the README shows). The core decides
 * them (`default_levels` in wasm/core/surface/curves.h: an omitted option reaches it unset); these
 * are its numbers, for callers that show or store them, and a test holds the two equal.
 */
export const DEFAULT_TRACE_LEVELS: Readonly<Record<SurfaceScheme, number>> = Object.freeze({ olr: 5, rdc: 4 });

/** Options of traceBezier, SurfaceSpline.trace and the other tracing calls. */
export interface TraceOptions {
  /** Subdivision scheme. Default DEFAULT_TRACE_SCHEME ('olr'). */
  scheme?: SurfaceScheme;
  /** Uniform subdivision levels, 0 to 12. Default DEFAULT_TRACE_LEVELS: 5 for OLR (35 points), 4 for RDC (48 geodesic segments). */
  levels?: number;
  /** Adaptive subdivision instead, with this angle threshold in degrees (the paper uses 5). */
  adaptive?: number;
}

/** The binding's encoding of trace options, checked: [scheme code, levels (-1: the core's default), adaptive degrees (0: off)]. */
export function traceArgs(options: TraceOptions = {}): [number, number, number] {
  const scheme = options.scheme ?? DEFAULT_TRACE_SCHEME;
  const code = SURFACE_SCHEMES.indexOf(scheme);
  if (code < 0) throw new SplinekitError('invalid-input', `unknown scheme "${String(scheme)}" (use "olr" or "rdc")`);
  // Omitted levels cross as -1: the core applies its default for the scheme.
  const levels = options.levels ?? -1;
  if (options.levels !== undefined && (!Number.isInteger(levels) || levels < 0 || levels > 12))
    throw new SplinekitError('invalid-input', `levels must be an integer from 0 to 12 (got ${levels})`);
  const adaptive = options.adaptive ?? 0;
  if (options.adaptive !== undefined && !(adaptive > 0 && adaptive < 180))
    throw new SplinekitError('invalid-input', `the adaptive angle must lie between 0 and 180 degrees (got ${adaptive})`);
  return [code, levels, adaptive];
}
