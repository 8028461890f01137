/**
 * Opens an SVG off the main thread: parses it (parseSVG) and writes the markup the 2D view mounts
 * (the two slow steps for a large file), then hands both over as plain data. A file that cannot be
 * opened answers 'failed' with the message and code the main thread would have given.
 */
import { init, parseSVG, SplinekitError } from '../../src/index.js';
import { importFailure } from './import-failure.js';
import type { ImportReply, ImportRequest } from './import-protocol.js';
import { serveRequests, type PostReply } from './worker-host.js';

serveRequests<ImportRequest, ImportReply>(handle);

async function handle(req: ImportRequest, post: PostReply<ImportReply>): Promise<void> {
  await init();
  const t0 = performance.now();
  let transfer, markup, parseMs;
  try {
    const doc = parseSVG(req.bytes, { name: req.name });
    parseMs = performance.now() - t0;
    transfer = doc.toTransfer();
    try {
      markup = doc.toSVG({ rewrite: 'all', tagShapes: true });
    } catch {
      // The document opens; the view writes the markup itself and shows why it cannot draw it.
      markup = null;
    }
  } catch (err) {
    const failure = importFailure(err, req.name);
    post({ type: 'failed', id: req.id, message: failure.message, code: err instanceof SplinekitError ? err.code : null });
    return;
  }
  // The arrays are this reply's own copies: hand them over instead of copying them again.
  const { splines, sources } = transfer;
  const buffers: Transferable[] = [splines.points.buffer, sources.original.buffer];
  post({ type: 'done', id: req.id, transfer, markup, parseMs }, buffers);
}
