/**
 * The one error type splinekit throws. `code` is stable and machine-readable; `message` names
 * the input that was wrong (file, element, path data, index) so a user can act on it.
 */
export type SplinekitErrorCode =
  | 'not-initialized'
  | 'invalid-input'
  | 'invalid-svg'
  | 'invalid-path-data'
  | 'file-too-large'
  | 'too-complex'
  | 'unsupported'
  | 'internal';

/**
 * The error every splinekit function throws for bad input or a failed load: check `code` (stable)
 * rather than `message` (for people).
 */
export class SplinekitError extends Error {
  /** What went wrong, one of {@link SplinekitErrorCode}; stable across versions. */
  readonly code: SplinekitErrorCode;

  /**
   * @param code what went wrong
   * @param message names the input that was wrong (file, element, path data, index)
   * @param options `cause`: the underlying error, if any
   */
  constructor(code: SplinekitErrorCode, message: string, options?: { cause?: unknown }) {
    super(message, options);
    this.name = 'SplinekitError';
    this.code = code;
  }
}

/** Status codes returned by the wasm bindings (wasm/bindings/*.cpp). */
const STATUS_CODES: Record<number, SplinekitErrorCode> = { 1: 'invalid-input', 2: 'internal' };

/** Throws a SplinekitError for a non-zero binding status, with the binding's message. */
export function checkStatus(status: number, what: string, message: () => string): void {
  if (status === 0) return;
  throw new SplinekitError(STATUS_CODES[status] ?? 'internal', `${what}: ${message()}`);
}
