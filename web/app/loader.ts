import { DEFAULT_MAX_BYTES, SplinekitError, parseSVG } from '../../src/index.js';
import { contentHash } from './autosave.js';
import type { LoadedDocument } from './state.js';
import { messageOf } from './errors.js';

/**
 * Parses SVG bytes into a document, timing the import. `hash` identifies the content for
 * autosave (default: computed from the bytes). Throws an Error with a user-facing message.
 */
export function importSVG(bytes: Uint8Array, file: string, hash = contentHash(bytes)): LoadedDocument {
  const t0 = performance.now();
  try {
    const doc = parseSVG(bytes, { name: file });
    return { doc, file, importMs: performance.now() - t0, bytes: bytes.length, source: bytes, hash };
  } catch (err) {
    if (err instanceof SplinekitError) throw new Error(err.message, { cause: err });
    throw new Error(`${file}: could not be read as SVG (${messageOf(err)})`, { cause: err });
  }
}

/** Reads a user-chosen file (file input, drop). Oversized files are refused before they are read. */
export async function readFile(file: File): Promise<Uint8Array> {
  if (file.size > DEFAULT_MAX_BYTES) {
    throw new Error(`${file.name}: ${(file.size / 2 ** 20).toFixed(1)} MiB is larger than the ${DEFAULT_MAX_BYTES / 2 ** 20} MiB limit`);
  }
  try {
    return new Uint8Array(await file.arrayBuffer());
  } catch (err) {
    throw new Error(`${file.name}: the file could not be read (${messageOf(err)})`, { cause: err });
  }
}

/** Fetches a file shipped with the app (a sample). */
export async function fetchBytes(url: string, name: string): Promise<Uint8Array> {
  let response: Response;
  try {
    response = await fetch(url);
  } catch (err) {
    throw new Error(`${name}: could not be loaded (${messageOf(err)})`, { cause: err });
  }
  if (!response.ok) throw new Error(`${name}: could not be loaded (HTTP ${response.status})`);
  return new Uint8Array(await response.arrayBuffer());
}
