import { DEFAULT_MAX_BYTES, SplinekitError, SvgDocument, parseSVG } from '../../src/index.js';
import { parsePrimedMarkup, primeLiveMarkup } from '../view2d/svg-layer.js';
import { contentHash } from './autosave.js';
import { importFailure } from './import-failure.js';
import type { ImportReply, ImportRequest } from './import-protocol.js';
import type { LoadedDocument } from './state.js';
import { messageOf } from './errors.js';
import { WorkerClient } from './worker-client.js';

/**
 * Parses SVG bytes into a document on the main thread, timing the import. `hash` identifies the
 * content for autosave (default: computed from the bytes). Throws an Error with a user-facing
 * message. The editor uses {@link openSVG}; this is its fallback when no worker can run.
 */
export function importSVG(bytes: Uint8Array, file: string, hash = contentHash(bytes)): LoadedDocument {
  const t0 = performance.now();
  try {
    const doc = parseSVG(bytes, { name: file });
    return { doc, file, importMs: performance.now() - t0, bytes: bytes.length, source: bytes, hash };
  } catch (err) {
    throw importFailure(err, file);
  }
}

let worker: WorkerClient<ImportRequest, ImportReply> | null = null;
let workerBroken = typeof Worker === 'undefined';

/**
 * Parses SVG bytes into a document like {@link importSVG}, but in a Web Worker (web/app/import.worker.ts),
 * which also writes the markup the 2D view mounts, so a large file does not freeze the page; the
 * page only rebuilds the document from the worker's data (and primes the view with its markup).
 * Errors have the same messages as importSVG. When a worker cannot be started, parses here instead.
 */
export async function openSVG(bytes: Uint8Array, file: string, hash = contentHash(bytes)): Promise<LoadedDocument> {
  if (workerBroken) return importSVG(bytes, file, hash);
  const t0 = performance.now();
  let reply: ImportReply;
  try {
    worker ??= new WorkerClient<ImportRequest, ImportReply>(
      () => new Worker(new URL('./import.worker.ts', import.meta.url), { type: 'module', name: 'splinekit-import' }),
      'import',
    );
    // Sent as a copy: the editor keeps `bytes` (autosave, revert).
    reply = await worker.request({ type: 'import', bytes, name: file });
  } catch (err) {
    // The worker itself failed (could not start, crashed): open the file here instead.
    console.warn(`splinekit: the import worker failed (${messageOf(err)}); importing on the main thread`);
    workerBroken = true;
    worker?.terminate(new Error('import worker abandoned'));
    worker = null;
    return importSVG(bytes, file, hash);
  }
  if (reply.type === 'failed') {
    throw new Error(reply.message, { cause: reply.code ? new SplinekitError(reply.code, reply.message) : undefined });
  }
  if (reply.type !== 'done') throw new Error(`${file}: the import worker answered ${reply.type}`);
  let doc: SvgDocument;
  try {
    doc = SvgDocument.fromTransfer(reply.transfer);
  } catch (err) {
    throw importFailure(err, file);
  }
  // The import: the worker's parse, the hand-over and the rebuild here (not the view's work after).
  const importMs = performance.now() - t0;
  if (reply.markup !== null) {
    primeLiveMarkup(doc, reply.markup);
    // Rebuilding the document, parsing its live markup and showing it are separate tasks, with a
    // frame between them: a large file keeps the page drawing while it opens.
    await nextFrame();
    parsePrimedMarkup(doc);
    await nextFrame();
  }
  return { doc, file, importMs, bytes: bytes.length, source: bytes, hash };
}

/** Resolves after the next frame (or after 50 ms when the page draws no frames, as in a hidden tab). */
function nextFrame(): Promise<void> {
  return new Promise((resolve) => {
    const fallback = setTimeout(resolve, 50);
    requestAnimationFrame(() => {
      clearTimeout(fallback);
      setTimeout(resolve, 0);
    });
  });
}

/**
 * Reads a user-chosen file (file input, drop). Files over `maxBytes` (by default the SVG limit;
 * meshes pass theirs) are refused before they are read.
 */
export async function readFile(file: File, maxBytes = DEFAULT_MAX_BYTES): Promise<Uint8Array> {
  if (file.size > maxBytes) {
    throw new Error(`${file.name}: ${(file.size / 2 ** 20).toFixed(1)} MiB is larger than the ${(maxBytes / 2 ** 20).toFixed(0)} MiB limit`);
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
