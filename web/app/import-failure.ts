import { SplinekitError } from '../../src/index.js';
import { messageOf } from './errors.js';

/**
 * The error the editor shows for a file that could not be parsed: a SplinekitError's own message
 * (it names the file and the problem), anything else wrapped as "could not be read as SVG".
 * Shared by the import worker and the main-thread fallback so both say the same.
 */
export function importFailure(err: unknown, file: string): Error {
  if (err instanceof SplinekitError) return new Error(err.message, { cause: err });
  return new Error(`${file}: could not be read as SVG (${messageOf(err)})`, { cause: err });
}
